#include "app/cluster/video_join.h"

#include "io/atomic_file.h"
#include "io/bad_input.h"
#include "render/libav_owners.h"

#include <algorithm>
#include <filesystem>
#include <memory>

namespace tumble::app {

namespace {

struct InputClose {
    void operator()(AVFormatContext* f) const { avformat_close_input(&f); }
};

struct Part {
    std::string file;
    std::unique_ptr<AVFormatContext, InputClose> in;
    AVStream* stream = nullptr;
    ShardTag tag;
};

Part open_part(const std::string& file) {
    const auto bad = [&](const std::string& why) { return io::BadInput(file + ": " + why); };
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
        throw bad(std::filesystem::exists(file, ec) ? "not a regular file" : "no such file");
    Part p;
    p.file = file;
    AVFormatContext* f = nullptr;
    const std::string url = "file:" + file;
    if (const int e = avformat_open_input(&f, url.c_str(), nullptr, nullptr); e < 0)
        throw bad("cannot read it as a video: " + render::libav::error_text(e));
    p.in.reset(f);
    if (const int e = avformat_find_stream_info(f, nullptr); e < 0)
        throw bad("cannot read its streams: " + render::libav::error_text(e));
    if (f->nb_streams != 1 || f->streams[0]->codecpar->codec_id != AV_CODEC_ID_H264)
        throw bad("not a video made by `tumble render` (expected one H.264 stream)");
    p.stream = f->streams[0];
    const AVDictionaryEntry* comment = av_dict_get(f->metadata, "comment", nullptr, 0);
    const auto tag = parse_tag(comment ? comment->value : "", file);
    if (!tag) throw bad("not a shard made by `tumble render` (it has no tumble-shard comment tag)");
    p.tag = *tag;
    if (p.stream->nb_frames != p.tag.range.size())
        throw bad("holds " + std::to_string(p.stream->nb_frames) + " frames, but its tag says " +
                  "frames " + p.tag.range.text() + " (" + std::to_string(p.tag.range.size()) +
                  "); an interrupted render is not a whole shard: render it again");
    return p;
}

bool same_headers(const AVCodecParameters* a, const AVCodecParameters* b) {
    return a->width == b->width && a->height == b->height &&
           a->extradata_size == b->extradata_size &&
           std::equal(a->extradata, a->extradata + a->extradata_size, b->extradata);
}

// Sorted by range; every shard's settings equal the first's, each range starts where the
// previous one ends.
void check_together(std::vector<Part>& parts) {
    std::sort(parts.begin(), parts.end(),
              [](const Part& a, const Part& b) { return a.tag.range.first < b.tag.range.first; });
    const Part& first = parts.front();
    for (std::size_t i = 1; i < parts.size(); ++i) {
        const Part& p = parts[i];
        const Part& prev = parts[i - 1];
        if (const std::string why = tag_mismatch(p.tag, first.tag); !why.empty())
            throw io::BadInput(p.file + " and " + first.file +
                               " are not shards of the same run: " + why);
        if (!same_headers(first.stream->codecpar, p.stream->codecpar))
            throw io::BadInput(p.file + " and " + first.file +
                               " have different stream headers (SPS/PPS)");
        if (p.tag.range.first != prev.tag.range.end)
            throw io::BadInput(
                prev.file + " (frames " + prev.tag.range.text() + ") and " + p.file + " (frames " +
                p.tag.range.text() + ") " +
                (p.tag.range.first < prev.tag.range.end ? "overlap" : "leave a gap") +
                ": shards must follow each other (frames " + std::to_string(prev.tag.range.end) +
                " to " + std::to_string(p.tag.range.first - 1) + ")");
    }
}

class Output {
  public:
    Output(const std::string& output, const Part& model, const ShardTag& tag) : file_(output) {
        const bool stream = file_.streaming();
        if (!stream) {
            try {
                io::ensure_writable_directory(file_.final_path().parent_path());
            } catch (const io::FileError& e) {
                throw io::BadInput(e.what());
            }
        }
        const std::string url = "file:" + file_.temp_path().string();
        AVFormatContext* f = nullptr;
        check(avformat_alloc_output_context2(&f, nullptr, "mp4", url.c_str()), "the muxer");
        out_.reset(f);
        stream_ = avformat_new_stream(f, nullptr);
        if (!stream_) throw std::runtime_error("cannot write '" + output + "': out of memory");
        check(avcodec_parameters_copy(stream_->codecpar, model.stream->codecpar), "the stream");
        stream_->codecpar->codec_tag = 0;
        stream_->time_base = AVRational{1, tag.fps}; // as render/video_sink.cpp
        stream_->avg_frame_rate = AVRational{tag.fps, 1};
        av_dict_set(&f->metadata, "comment", format_tag(tag).c_str(), 0);
        check(avio_open(&f->pb, url.c_str(), AVIO_FLAG_WRITE), "creating the file");
        AVDictionary* settings = nullptr;
        av_dict_set(&settings, "movflags",
                    stream ? "+frag_keyframe+empty_moov+default_base_moof" : "+faststart", 0);
        const int written = avformat_write_header(f, &settings);
        av_dict_free(&settings);
        check(written, "writing the file header");
    }

    // Packets of one shard, moved by `offset` frames; returns how many.
    std::int64_t copy(Part& part, std::int64_t offset, int fps) {
        render::libav::Packet packet(av_packet_alloc());
        const AVRational frame_tick{1, fps};
        std::int64_t n = 0;
        for (int e; (e = av_read_frame(part.in.get(), packet.get())) != AVERROR_EOF; ++n) {
            if (e < 0)
                throw std::runtime_error("cannot read '" + part.file +
                                         "': " + render::libav::error_text(e));
            av_packet_rescale_ts(packet.get(), part.stream->time_base, frame_tick);
            packet->pts += offset;
            packet->dts += offset;
            av_packet_rescale_ts(packet.get(), frame_tick, stream_->time_base);
            packet->stream_index = stream_->index;
            packet->pos = -1;
            check(av_interleaved_write_frame(out_.get(), packet.get()), "writing a packet");
        }
        return n;
    }

    void finish() {
        check(av_write_trailer(out_.get()), "finishing the file");
        check(avio_closep(&out_->pb), "closing the file");
        out_.reset();
        try {
            file_.commit();
        } catch (const io::FileError& e) {
            throw std::runtime_error(e.what());
        }
    }

  private:
    void check(int code, const char* what) const {
        if (code < 0)
            throw std::runtime_error("cannot write '" + file_.final_path().string() + "': " + what +
                                     ": " + render::libav::error_text(code));
    }
    io::AtomicFile file_; // declared first: destroyed after the muxer has closed the file
    std::unique_ptr<AVFormatContext, render::libav::FormatFree> out_;
    AVStream* stream_ = nullptr;
};

} // namespace

JoinResult join_videos(const std::vector<std::string>& files, const std::string& output) {
    if (files.empty()) throw io::BadInput("join: no shards given");
    std::vector<Part> parts;
    for (const std::string& f : files) parts.push_back(open_part(f));
    check_together(parts);
    JoinResult result;
    result.tag = parts.front().tag;
    result.tag.range.end = parts.back().tag.range.end;
    Output out(output, parts.front(), result.tag);
    for (Part& p : parts) {
        const std::int64_t copied =
            out.copy(p, p.tag.range.first - result.tag.range.first, result.tag.fps);
        if (copied != p.tag.range.size())
            throw std::runtime_error("'" + p.file + "' gave " + std::to_string(copied) +
                                     " packets, expected " + std::to_string(p.tag.range.size()));
        result.frames += copied;
        result.order.push_back(p.file);
    }
    out.finish();
    return result;
}

} // namespace tumble::app
