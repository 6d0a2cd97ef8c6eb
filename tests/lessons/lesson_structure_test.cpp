// What makes the lessons (docs/lessons/) a course another teacher can adopt, checked for every
// lesson at once: each says what it needs first (prerequisites), sets exercises with answers, and
// quotes no number that no test checks; the index lists each lesson with its track; and each
// lesson scene is guarded by the project's golden suite with a state check.
#include "lesson_support.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <regex>
#include <set>

namespace tumble::test {
namespace {

const std::filesystem::path kSource = TUMBLE_SOURCE_DIR;

std::vector<std::string> lesson_names() {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(lesson_file("")))
        if (const std::string name = e.path().filename().string();
            name.size() > 3 && std::isdigit(static_cast<unsigned char>(name[0])) &&
            name[2] == '-' && name.ends_with(".md"))
            out.push_back(name);
    std::sort(out.begin(), out.end());
    return out;
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

// The text of section `heading` ("## Exercises") up to the next "## ".
std::string section(const std::string& text, const std::string& heading) {
    const std::size_t at = text.find("\n" + heading + "\n");
    if (at == std::string::npos) return "";
    const std::size_t end = text.find("\n## ", at + heading.size() + 2);
    return text.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

TEST(Lessons, EveryLessonHasPrerequisitesExercisesAndAnswers) {
    const auto lessons = lesson_names();
    EXPECT_GE(lessons.size(), 10u) << "the course has ten lessons or more";
    for (const std::string& lesson : lessons) {
        SCOPED_TRACE(lesson);
        const std::string text = read_text(lesson_file(lesson));
        EXPECT_NE(text.find("\n**Prerequisites.**"), std::string::npos);
        const std::string exercises = section(text, "## Exercises");
        ASSERT_FALSE(exercises.empty()) << "no \"## Exercises\" section";
        const std::size_t asked = count(exercises, "\n**Exercise "),
                          answered = count(exercises, "\n*Answer.*");
        EXPECT_GE(asked, 2u);
        EXPECT_EQ(answered, asked) << "every exercise has its answer";
        EXPECT_FALSE(section(text, "## Numbers, checked").empty());
    }
}

// Every row of every lesson's "Numbers, checked" table is quoted by name in a lesson test, where
// expect_quoted() compares it with the measurement: a number nobody checks cannot be added.
TEST(Lessons, EveryNumberInALessonTableIsCheckedByALessonTest) {
    std::string sources;
    for (const auto& e : std::filesystem::directory_iterator(kSource / "tests/lessons"))
        if (const std::string n = e.path().filename().string();
            n.starts_with("lesson_") && n.ends_with("_test.cpp"))
            sources += read_text(e.path());
    std::size_t rows = 0;
    std::set<std::string> seen;
    for (const std::string& lesson : lesson_names())
        for (const std::string& key : table_keys(lesson)) {
            ++rows;
            EXPECT_TRUE(seen.insert(lesson + ":" + key).second)
                << lesson << ": `" << key << "` is in its table twice";
            EXPECT_NE(sources.find("\"" + key + "\""), std::string::npos)
                << lesson << ": no lesson test quotes `" << key << "`";
        }
    std::printf("[lessons] %zu numbers and answers in the lessons' tables\n", rows);
    EXPECT_GE(rows, 100u);
}

TEST(Lessons, TheIndexListsEveryLessonWithItsTrack) {
    const std::string index = read_text(lesson_file("README.md"));
    for (const std::string& lesson : lesson_names()) {
        SCOPED_TRACE(lesson);
        const std::size_t at = index.find("](" + lesson + ")");
        ASSERT_NE(at, std::string::npos) << "not in docs/lessons/README.md";
        const std::string row = index.substr(at, index.find('\n', at) - at);
        EXPECT_TRUE(row.find("| physics |") != std::string::npos ||
                    row.find("| numerics |") != std::string::npos)
            << "no track (physics or numerics) in its row: " << row;
    }
}

// Each scene in assets/scenes/lessons/ is an entry of tests/goldens/suite.json with a state check,
// so that a change in the physics that moves a lesson's motion is seen by the project's suite as
// well as by the lesson's own test.
TEST(Lessons, EveryLessonSceneIsInTheGoldenSuiteWithAStateCheck) {
    const auto suite = nlohmann::json::parse(read_text(kSource / "tests/goldens/suite.json"));
    std::set<std::string> with_states;
    for (const auto& entry : suite.at("scenes"))
        if (entry.contains("states") && !entry.at("states").empty())
            with_states.insert(entry.at("scene").get<std::string>());
    std::size_t scenes = 0;
    for (const auto& e : std::filesystem::directory_iterator(kSource / "assets/scenes/lessons")) {
        if (e.path().extension() != ".json") continue;
        ++scenes;
        const std::string name = "lessons/" + e.path().stem().string();
        EXPECT_TRUE(with_states.count(name)) << name << " has no state check in the golden suite";
    }
    EXPECT_GE(scenes, 10u);
}

} // namespace
} // namespace tumble::test
