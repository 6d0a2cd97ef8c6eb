#pragma once
// A one-line progress bar on stderr, redrawn at most ~10 times a second, only when stderr is a
// terminal and --quiet was not given:  [#########.........]  45%  270/600 frames  52 fps  ETA 6s
#include <chrono>
#include <cstdint>
#include <string>

namespace tumble::app {

class Progress {
  public:
    Progress(std::string label, std::int64_t total, bool quiet);
    ~Progress();
    void update(std::int64_t done);
    void finish(); // erases the bar line

  private:
    void draw(std::int64_t done);
    std::string label_;
    std::int64_t total_;
    bool enabled_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_, last_;
};

} // namespace tumble::app
