// The command lines the lessons give (docs/lessons/NN-*.md, the sh block after "# video:" and
// "# figure:") run as a teacher would paste them, in an empty folder: each figure is made, and
// each video's first second renders (one still, at preview size, instead of the whole video).
#include "lesson_support.h"

#include "render/png_io.h"

#include <algorithm>
#include <cctype>
#include <regex>
#include <sstream>

namespace tumble::test {
namespace {

// Every lesson, NN-name.md in docs/lessons/, in order: a new lesson is checked without being
// listed here.
std::vector<std::string> lessons() {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(lesson_file("")))
        if (const std::string name = e.path().filename().string();
            name.size() > 3 && std::isdigit(static_cast<unsigned char>(name[0])) &&
            std::isdigit(static_cast<unsigned char>(name[1])) && name[2] == '-' &&
            name.ends_with(".md"))
            out.push_back(name);
    std::sort(out.begin(), out.end());
    return out;
}

// The command line after the comment "# <what>:" (and any further comment lines) in a lesson.
std::string command_after(const std::string& lesson, const std::string& what) {
    std::istringstream in(read_text(lesson_file(lesson)));
    bool found = false;
    for (std::string line; std::getline(in, line);) {
        if (line.starts_with("# " + what + ":"))
            found = true;
        else if (found && !line.starts_with("#"))
            return line;
    }
    return "";
}

// `tumble` as the binary under test, wherever the line runs it.
std::string with_binary(const std::string& line) {
    return std::regex_replace(line, std::regex(R"((^|&& |do )tumble )"), "$1\"$$TUMBLE\" ");
}

std::string last_output(const std::string& line) {
    const std::size_t at = line.rfind(" -o ");
    return at == std::string::npos ? "" : line.substr(at + 4, line.find(' ', at + 4) - at - 4);
}

TEST(Lessons, EveryFigureCommandMakesItsFigure) {
    const auto scratch = scratch_dir();
    const std::vector<std::string> all = lessons();
    ASSERT_GE(all.size(), 10u);
    for (const std::string& lesson : all) {
        const std::string line = command_after(lesson, "figure");
        ASSERT_FALSE(line.empty()) << lesson << " gives no figure command";
        if (line.starts_with("tumble study")) continue; // a minute of work: the Study.* tests
        SCOPED_TRACE(lesson + ": " + line);
        const auto dir = scratch / std::filesystem::path(lesson).stem();
        std::filesystem::create_directories(dir);
        const CliResult r = run_shell(dir, with_binary(line));
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const std::filesystem::path figure = dir / last_output(line);
        EXPECT_GT(render::read_png(figure).width, 0);
        // A plot's series are each drawn once (runs/*.csv names both tables of every run).
        if (!std::filesystem::exists(std::filesystem::path(figure).replace_extension(".dat")))
            continue;
        std::istringstream data(read_text(std::filesystem::path(figure).replace_extension(".dat")));
        std::vector<std::string> titles;
        for (std::string l; std::getline(data, l);)
            if (l.starts_with("# ") && l != "# t value") titles.push_back(l);
        std::sort(titles.begin(), titles.end());
        EXPECT_EQ(std::adjacent_find(titles.begin(), titles.end()), titles.end())
            << "a series drawn twice";
    }
}

TEST(Lessons, EveryVideoCommandRendersItsFirstSecond) {
    const auto scratch = scratch_dir();
    for (const std::string& lesson : lessons()) {
        std::string line = command_after(lesson, "video");
        ASSERT_FALSE(line.empty()) << lesson << " gives no video command";
        SCOPED_TRACE(lesson + ": " + line);
        const std::string video = last_output(line);
        ASSERT_TRUE(video.ends_with(".mp4")) << line;
        line.replace(line.rfind(" -o " + video), 4 + video.size(),
                     " --preview --frame 60 -o still.png");
        const auto dir = scratch / std::filesystem::path(lesson).stem();
        std::filesystem::create_directories(dir);
        const CliResult r = run_shell(dir, with_binary(line));
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_GT(render::read_png(dir / "still.png").width, 0);
    }
}

} // namespace
} // namespace tumble::test
