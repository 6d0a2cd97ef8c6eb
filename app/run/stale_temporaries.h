#pragma once
// Before a command writes an output, it removes the temporary files that runs killed outright
// (SIGKILL, a crash) left for that same output, and says so on standard error:
//   tumble: note: removed 'out/.run.mp4.4242.partial', left by process 4242, no longer running
// Only files named as Tumble names its temporaries, for this output, of a dead process
// (io/temporary_files.h).
#include <filesystem>
#include <string>

namespace tumble::app {

// `output` as a command takes it: a file, or for frames a folder ("frames/") or a pattern
// ("frames/%06d.png"), whose frame files' temporaries are removed.
void remove_stale_temporaries_for(const std::string& output, bool quiet);

} // namespace tumble::app
