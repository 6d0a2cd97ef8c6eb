#pragma once
// Where rendered frames go. The output name chooses the sink:
//   *.mp4                      H.264 (libx264, yuv420p, BT.709 limited range) in MP4
//   *.webm                     VP9 (libvpx) in WebM (video_sink.h)
//   *.gif                      animated GIF, one palette per video (gif_sink.h)
//   a directory (existing, or a name ending in '/')   PNG sequence dir/000000.png, 000001.png ...
//   a name with a printf integer pattern, e.g. frames/%06d.png or shot_%04d.png   PNG sequence
//   *.png (no pattern)         a single still: exactly one frame
//   null                       nothing: frames are checked and discarded (timing baselines; a
//                              directory called null is written as "null/")
// Every file is written under a temporary name in the same directory and renamed only when it is
// complete, so an interrupted or failed run never leaves a half-written file behind. A missing
// output directory is created, with its parents. A PNG sequence refuses a folder that already
// holds frames of its pattern (a later `ffmpeg -i %06d.png` would mix the stale ones in) unless
// `overwrite`, which first removes exactly those frame files.
//
// Typical use (the app's render loop; Ctrl-C sets a flag, the loop stops and calls finish()):
//   auto sink = open_sink("out/default.mp4", {.width = 1280, .height = 720, .fps = 60});
//   for (...) { renderer.draw(view, image); sink->write(image); }
//   sink->finish();            // on an exception instead, the destructor deletes the partial file
#include "render/frame_sink.h"

#include <memory>
#include <string>

namespace tumble::render {

// Chooses and opens the sink for `output`. Throws SinkError naming the output and the problem
// (odd dimensions for H.264, unwritable directory, unknown extension ...).
std::unique_ptr<FrameSink> open_sink(const std::string& output, const SinkOptions& options);

} // namespace tumble::render
