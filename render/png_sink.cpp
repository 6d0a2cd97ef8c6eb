#include "render/png_sink.h"

#include <algorithm>
#include <cctype>
#include <system_error>

namespace tumble::render {

namespace fs = std::filesystem;

// ---- FramePattern ------------------------------------------------------------------------------

std::string FramePattern::name(std::int64_t frame) const {
    std::string number = std::to_string(frame);
    if (static_cast<int>(number.size()) < width) {
        number.insert(0, static_cast<std::size_t>(width) - number.size(), zero_pad ? '0' : ' ');
    }
    return prefix + number + suffix;
}

std::optional<FramePattern> FramePattern::parse(const std::string& text) {
    const auto fail = [&](const std::string& why) -> SinkError {
        return SinkError("bad output pattern '" + text + "': " + why);
    };
    FramePattern pattern;
    pattern.text = text;
    bool found = false;
    std::string* out = &pattern.prefix; // text before the conversion, then after it
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '%') {
            *out += text[i];
            continue;
        }
        if (i + 1 < text.size() && text[i + 1] == '%') { // "%%" is a literal '%'
            *out += '%';
            ++i;
            continue;
        }
        // A conversion: '%', an optional '0', up to two width digits, 'd'.
        std::size_t j = i + 1;
        const bool zero_pad = j < text.size() && text[j] == '0';
        if (zero_pad) ++j;
        int width = 0;
        for (int digits = 0; j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]));
             ++j, ++digits) {
            if (digits == 2) throw fail("the frame number width must be at most 99");
            width = width * 10 + (text[j] - '0');
        }
        if (j >= text.size() || text[j] != 'd') {
            throw fail("'%' must start an integer conversion such as %d or %06d (%% for a '%')");
        }
        if (found) throw fail("it has more than one frame number (%d)");
        if (text.find('/', j) != std::string::npos) {
            throw fail("the frame number must be in the file name, not in a directory");
        }
        found = true;
        pattern.zero_pad = zero_pad;
        pattern.width = width;
        out = &pattern.suffix;
        i = j;
    }
    if (!found) return std::nullopt;
    return pattern;
}

FramePattern FramePattern::in_directory(const fs::path& dir) {
    FramePattern pattern;
    pattern.prefix = (dir / "").string(); // "frames" and "frames/" both give "frames/"
    pattern.suffix = ".png";
    pattern.width = 6;
    pattern.zero_pad = true;
    pattern.text = pattern.prefix + "%06d.png";
    return pattern;
}

std::optional<FramePattern> FramePattern::of_output(const std::string& output) {
    std::error_code ec;
    if (!output.empty() && (output.back() == '/' || fs::is_directory(output, ec)))
        return in_directory(output);
    return parse(output);
}

std::vector<fs::path> FramePattern::existing_frames() const {
    const fs::path first(name(0));
    const fs::path dir = first.parent_path().empty() ? fs::path(".") : first.parent_path();
    const std::string head = fs::path(prefix + "0").filename().string();
    const std::string lead = head.substr(0, head.size() - 1); // the prefix's file-name part
    std::vector<fs::path> out;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string file = it->path().filename().string();
        if (file.size() <= lead.size() + suffix.size() || !file.starts_with(lead) ||
            !file.ends_with(suffix))
            continue;
        const std::string digits =
            file.substr(lead.size(), file.size() - lead.size() - suffix.size());
        const bool numeric =
            std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
        const bool spaced = digits.find_first_not_of(' ') != std::string::npos;
        if ((numeric || (!zero_pad && spaced)) && (!zero_pad || (int)digits.size() >= width) &&
            it->is_regular_file(ec))
            out.push_back(it->path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// ---- PngSequenceSink ---------------------------------------------------------------------------

namespace {

// The existing files a run would mix with its own: any frame of the pattern for a whole run, the
// frames of its own range for a shard (SinkOptions::end_frame).
std::vector<fs::path> frames_in_the_way(const FramePattern& pattern, const SinkOptions& o) {
    if (o.end_frame < 0) return pattern.existing_frames();
    std::vector<fs::path> out;
    std::error_code ec;
    for (std::int64_t k = o.first_frame; k < o.end_frame; ++k)
        if (fs::is_regular_file(pattern.name(k), ec)) out.emplace_back(pattern.name(k));
    return out;
}

} // namespace

PngSequenceSink::PngSequenceSink(FramePattern pattern, const SinkOptions& options)
    : pattern_(std::move(pattern)), options_(options) {
    const fs::path dir = fs::path(pattern_.name(0)).parent_path();
    try {
        if (io::ensure_writable_directory(dir)) created_directory_ = dir;
    } catch (const io::FileError& e) {
        throw SinkError("cannot write '" + pattern_.text + "': " + e.what());
    }
    // Frames of an earlier run: fewer new frames would leave the rest behind, and a later
    // `ffmpeg -i frames/%06d.png` would play them as if they were this run's.
    const std::vector<fs::path> stale = frames_in_the_way(pattern_, options_);
    if (!stale.empty() && !options_.overwrite)
        throw SinkError("'" + pattern_.text + "': the folder already holds " +
                        std::to_string(stale.size()) + " frame" + (stale.size() == 1 ? "" : "s") +
                        " of this pattern (" + stale.front().string() +
                        (stale.size() > 1 ? " ... " + stale.back().string() : "") +
                        "); choose another folder, or pass --overwrite to remove them first");
    for (const fs::path& f : stale) {
        std::error_code ec;
        fs::remove(f, ec);
        if (ec) throw SinkError("cannot remove '" + f.string() + "': " + ec.message());
    }
}

void PngSequenceSink::write(const Image& image) {
    detail::check_open(*this, done_);
    detail::check_frame(describe(), image, options_.width, options_.height);
    options_.width = image.width; // later frames must have the size of the first
    options_.height = image.height;
    try {
        write_png(pattern_.name(options_.first_frame + frames_), image, options_.png);
    } catch (const PngError& e) {
        throw SinkError(e.what());
    }
    ++frames_;
}

void PngSequenceSink::finish() {
    detail::finish_sink(*this, done_, frames_, [] {}); // every frame is complete on disk
}

void PngSequenceSink::abort() noexcept {
    if (done_) return;
    std::error_code ignored;
    for (std::int64_t k = 0; k < frames_; ++k)
        fs::remove(pattern_.name(options_.first_frame + k), ignored);
    if (!created_directory_.empty()) fs::remove(created_directory_, ignored); // only if empty
    done_ = true;
}

// ---- PngStillSink ------------------------------------------------------------------------------

PngStillSink::PngStillSink(const fs::path& path, const SinkOptions& options)
    : file_(path), options_(options) {
    try {
        if (!file_.streaming()) io::ensure_writable_directory(path.parent_path());
    } catch (const io::FileError& e) {
        throw SinkError("cannot write '" + path.string() + "': " + e.what());
    }
}

void PngStillSink::write(const Image& image) {
    detail::check_open(*this, done_);
    if (frames_ > 0) {
        throw SinkError("'" + describe() +
                        "' is a single still and already has its frame; for a sequence use a "
                        "directory (frames/) or a pattern (frames/%06d.png)");
    }
    detail::check_frame(describe(), image, options_.width, options_.height);
    try {
        // write_png is itself atomic, so the temporary file is never seen half-written either.
        write_png(file_.temp_path(), image, options_.png);
    } catch (const PngError& e) { // named as the user named it, not by its temporary name
        throw SinkError("cannot write '" + describe() + "': " + e.reason);
    }
    ++frames_;
}

void PngStillSink::finish() {
    detail::finish_sink(*this, done_, frames_, [&] { file_.commit(); });
}

void PngStillSink::abort() noexcept {
    if (done_) return;
    file_.discard();
    done_ = true;
}

} // namespace tumble::render
