#pragma once
// Compares two decoded images (never file bytes: two PNG encoders give different bytes for the
// same pixels) and tells how they differ, for golden-image tests and `tumble diff`.
//
// A pixel is *changed* when some channel differs by more than `tolerance` and, if a perceptual
// threshold is set, the colour difference in YIQ space (the NTSC luma/chroma space, weighted for
// how visible each component is) exceeds it too. A changed pixel is then either
//   * anti-aliased: it looks like the soft edge of a shape that moved by a pixel or changed its
//     coverage slightly (it lies between a darker and a brighter neighbour, and one of those sits
//     inside a flat area in both images), which is what different GPU drivers, Mesa versions or
//     rounding produce along edges; counted apart, not held against the images; or
//   * different: everything else. Counted against `max_different`.
// Differing pixels that touch (8-connected) form a *cluster*. The count alone cannot tell a small
// object missing or moved (10 pixels at one place) from renderer noise (10 single pixels along
// edges all over the picture); the size of the largest cluster can, so it is bounded beside the
// count (`max_cluster`), the way a connected-component pass over a diff mask separates blobs
// from speckle in visual regression tools.
// The idea is that of pixelmatch (Mapbox) and of the paper it follows, Kotsarenko and Ramos,
// "Measuring perceived color difference using YIQ NTSC transmission color space"; this is an
// independent implementation of it for 8-bit RGB.
#include "render/image.h"

#include <cstdint>
#include <string>

namespace tumble::render {

struct CompareOptions {
    int tolerance = 0; // per channel, 0..255: differences up to this are no change at all
    // 0..1, the fraction of the largest possible YIQ difference (black vs white) a change must
    // exceed to count; 0 = any change beyond `tolerance` counts. pixelmatch's default is 0.1.
    double perceptual_threshold = 0;
    std::int64_t max_different = 0;  // the images match when at most this many pixels differ
    bool detect_antialiasing = true; // false: every changed pixel is "different"
    // The images match only when no cluster of touching differing pixels is larger than this;
    // negative: no bound beyond max_different.
    std::int64_t max_cluster = -1;
};

// Pixels from the image's top-left corner, for the largest cluster's bounding box.
struct PixelBox {
    int x = 0, y = 0, width = 0, height = 0;
};

struct CompareResult {
    bool same_size = false;
    bool identical = false;    // same size and no changed pixel at all (within tolerance)
    bool matches = false;      // same size, different <= max_different and, when bounded,
                               // largest_cluster <= max_cluster (AA pixels allowed)
    int max_channel_delta = 0; // largest |a - b| over all pixels and channels
    std::int64_t different = 0;
    std::int64_t antialiased = 0;
    std::int64_t largest_cluster = 0; // differing pixels in the largest 8-connected cluster
    PixelBox cluster_box;             // that cluster's bounding box (empty without one)
    // Same size as the inputs: a faded grey copy of the first image, with different pixels red
    // and anti-aliased ones yellow. Empty when the sizes differ.
    Image diff;
    std::string summary; // one line for people: "identical, bit for bit", "matches, not
                         // bit-identical: ...", or "12 pixels differ (allowed 0), ..."
};

CompareResult compare_images(const Image& a, const Image& b, const CompareOptions& options = {});

} // namespace tumble::render
