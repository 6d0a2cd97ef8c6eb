#pragma once
// Checkpoint files: the complete State of a run at one frame, so that a later process (a shard
// of a render on another machine) continues from it bit-identically (physics/state_fields.h lists
// what "complete" means). One small binary file per frame, little-endian, written atomically:
//
//   "TUMBLECK"                  8 bytes, the magic
//   u32 format version          kCheckpointVersion; another version is refused
//   header                      scene hash (u64), build (string), integrator (string),
//                               h (f64 bits), fps (i32), steps per frame (i32), frame (i64),
//                               body count (i64)
//   u32 field count, then each field of the State in for_each_field order:
//     name (string), element count (u64), element size in bytes (u32), the elements
//   u64 checksum                FNV-1a of every byte before it (a truncated or damaged file)
//
// where a string is a u32 length and its bytes. Doubles are stored as their bits, so a restored
// State is the saved one bit for bit. A checkpoint is only good for the run that made it: the
// same scene inputs (Scene::content_hash), the same build of Tumble (the determinism promise is
// per build: README, "Determinism"), the same integrator, step and frame rate. The header says
// which; header_mismatch() compares it with the run at hand.
#include "io/bad_input.h"
#include "physics/state.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace tumble::app {

inline constexpr std::uint32_t kCheckpointVersion = 1;

struct CheckpointHeader {
    std::uint64_t scene_hash = 0; // Scene::content_hash of the scene the run loaded
    std::string build;            // build_id() of the binary that wrote it
    std::string integrator;       // the integrator's name
    double h = 0.0;               // the step used, s
    int fps = 0;
    int steps_per_frame = 0;
    std::int64_t frame = 0; // the state is frame `frame`'s: step = frame * steps_per_frame
    std::int64_t bodies = 0;
};

struct Checkpoint {
    CheckpointHeader header;
    physics::State state;
};

// A file that is not a checkpoint Tumble can read (damaged, truncated, another format version)
// or one made for another run: bad input, exit 2. The message names the file.
struct CheckpointError : io::BadInput {
    using io::BadInput::BadInput;
};

// The bytes of a checkpoint (the format above).
std::string encode_checkpoint(const CheckpointHeader& header, const physics::State& state);

// Reads the bytes back. `file` names the source in messages. Throws CheckpointError.
Checkpoint decode_checkpoint(const std::string& bytes, const std::string& file);

// Writes `path` atomically (temporary name, then rename). Throws std::runtime_error naming the
// file when it cannot be written (a full disk: a failed run).
void write_checkpoint(const std::filesystem::path& path, const CheckpointHeader& header,
                      const physics::State& state);

// Reads `path` (at most kMaxInputFileBytes, a regular file). Throws CheckpointError.
Checkpoint read_checkpoint(const std::filesystem::path& path);

// Why a checkpoint with header `found` cannot continue the run described by `run` (every field
// but the frame), or "" when it can: "it was made from another scene (scene hash 1a2b... , this
// run's is 3c4d...)", "... by another build of tumble ...", "... with integrator euler, this run
// uses rk4", and so on.
std::string header_mismatch(const CheckpointHeader& found, const CheckpointHeader& run);

} // namespace tumble::app
