#pragma once
// Which build of Tumble is running: the GNU build ID that the linker writes into the executable
// (a hash of its contents, shown by `readelf -n` or `file`), as hex. Two processes running the
// same binary (one installed package on every cluster node) share it; any rebuild that changes
// the code changes it. Checkpoints and video shards record it, because the determinism promise
// (README, "Determinism") is per build: another binary may step or draw the same scene with
// other bits. A binary linked without the note (--build-id=none) is identified by an FNV-1a hash
// of its own file (/proc/self/exe) instead, prefixed "file-".
#include <string>

namespace tumble::app {

// Computed once per process.
const std::string& build_id();

} // namespace tumble::app
