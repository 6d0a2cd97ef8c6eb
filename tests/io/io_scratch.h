#pragma once
// A scratch folder for one io test, under the build tree, emptied at construction and named
// after the test.
#include <gtest/gtest.h>

#include <filesystem>

namespace tumble::io {

inline std::filesystem::path fresh_dir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path dir =
        std::filesystem::path(TUMBLE_TEST_ARTIFACTS) / "io" / info->name();
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace tumble::io
