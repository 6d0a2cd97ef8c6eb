#pragma once
// Key frames of a video: where the encoder starts afresh (render/video_sink.h), so that a video
// splits into shards there whose packets are those of a whole render (app/cluster/frame_range.h).
namespace tumble::app {

// Frames between key frames in a video: one every two seconds, 2 fps frames, where the encoder
// starts afresh. The interval trades shard granularity against bits, measured on the default demo
// at CRF 18 medium (docs/cluster.md, bench/results/vm/keyframes.csv): restarting every 1 s cost
// 51% more bits than one encoder for the whole 10 s at the same PSNR, every 2 s 13%, every 5 s
// 9%. Two seconds still let a 10-minute video split into up to 300 shards.
int key_interval(int fps);

} // namespace tumble::app
