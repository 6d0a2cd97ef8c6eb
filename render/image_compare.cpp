#include "render/image_compare.h"

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace tumble::render {

namespace {

const std::uint8_t* pixel(const Image& image, int x, int y) {
    return image.row(y) + 3 * x;
}

int channel_delta(const std::uint8_t* p, const std::uint8_t* q) {
    return std::max({std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2])});
}

// Luma (the Y of YIQ, NTSC weights): how bright a colour looks.
double luma(const std::uint8_t* p) {
    return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
}

// Squared colour distance in YIQ, each component weighted by how visible its differences are
// (Kotsarenko and Ramos): brightness matters most, then the orange-blue (I), then purple-green (Q).
double yiq_distance(const std::uint8_t* p, const std::uint8_t* q) {
    const double dr = p[0] - q[0], dg = p[1] - q[1], db = p[2] - q[2];
    const double y = 0.299 * dr + 0.587 * dg + 0.114 * db;
    const double i = 0.596 * dr - 0.274 * dg - 0.322 * db;
    const double iq = 0.211 * dr - 0.523 * dg + 0.312 * db;
    return 0.5053 * y * y + 0.299 * i * i + 0.1957 * iq * iq;
}

// The 8 neighbours of (x, y) that lie inside the image.
template <class Visit>
void for_each_neighbour(const Image& image, int x, int y, Visit visit) {
    for (int ny = std::max(0, y - 1); ny <= std::min(image.height - 1, y + 1); ++ny) {
        for (int nx = std::max(0, x - 1); nx <= std::min(image.width - 1, x + 1); ++nx) {
            if (nx != x || ny != y) visit(nx, ny);
        }
    }
}

// A pixel in a flat area: at least 3 of its neighbours have (within tolerance) its colour.
bool in_flat_area(const Image& image, int x, int y, int tolerance) {
    const std::uint8_t* center = pixel(image, x, y);
    int equal = 0;
    for_each_neighbour(image, x, y, [&](int nx, int ny) {
        equal += channel_delta(pixel(image, nx, ny), center) <= tolerance;
    });
    return equal >= 3;
}

// Does pixel (x, y) of `image` look like the soft edge between two shapes? An anti-aliased edge
// pixel mixes the colours on its two sides, so it is
//  1. not inside a flat area itself (at most 2 neighbours share its colour),
//  2. between a darker and a brighter neighbour, and
//  3. the darkest or the brightest of those neighbours lies inside a flat area (the interior of a
//     shape) in *both* images: the shapes are the same, only the edge between them moved.
bool looks_antialiased(const Image& image, const Image& other, int x, int y, int tolerance) {
    const std::uint8_t* center = pixel(image, x, y);
    const double center_luma = luma(center);
    int equal = 0;
    double darkest = 0, brightest = 0; // luma relative to the center
    int dark_x = -1, dark_y = -1, bright_x = -1, bright_y = -1;
    for_each_neighbour(image, x, y, [&](int nx, int ny) {
        const std::uint8_t* n = pixel(image, nx, ny);
        if (channel_delta(n, center) <= tolerance) {
            ++equal;
            return;
        }
        const double d = luma(n) - center_luma;
        if (d < darkest) darkest = d, dark_x = nx, dark_y = ny;
        if (d > brightest) brightest = d, bright_x = nx, bright_y = ny;
    });
    if (equal > 2 || dark_x < 0 || bright_x < 0) return false;
    const auto flat_in_both = [&](int px, int py) {
        return in_flat_area(image, px, py, tolerance) && in_flat_area(other, px, py, tolerance);
    };
    return flat_in_both(dark_x, dark_y) || flat_in_both(bright_x, bright_y);
}

// A faded grey version of `p`, so that red and yellow marks stand out on the picture.
void write_faded(std::uint8_t* out, const std::uint8_t* p) {
    const auto grey = static_cast<std::uint8_t>(255 - 0.3 * (255 - luma(p)) + 0.5);
    out[0] = out[1] = out[2] = grey;
}

void write_mark(std::uint8_t* out, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    out[0] = r, out[1] = g, out[2] = b;
}

std::string size_text(const Image& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

// The largest 8-connected cluster of the pixels flagged in `differs` (row-major, width x
// height): its size and bounding box, by a flood fill from each unvisited flagged pixel.
void find_largest_cluster(std::vector<std::uint8_t>& differs, int width, int height,
                          CompareResult& r) {
    std::vector<int> stack;
    for (int start = 0; start < width * height; ++start) {
        if (differs[std::size_t(start)] != 1) continue;
        differs[std::size_t(start)] = 2; // visited
        stack.assign(1, start);
        std::int64_t size = 0;
        int x0 = width, y0 = height, x1 = -1, y1 = -1;
        while (!stack.empty()) {
            const int at = stack.back(), x = at % width, y = at / width;
            stack.pop_back();
            ++size;
            x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
            for (int ny = std::max(0, y - 1); ny <= std::min(height - 1, y + 1); ++ny)
                for (int nx = std::max(0, x - 1); nx <= std::min(width - 1, x + 1); ++nx)
                    if (std::uint8_t& n = differs[std::size_t(ny * width + nx)]; n == 1) {
                        n = 2;
                        stack.push_back(ny * width + nx);
                    }
        }
        if (size > r.largest_cluster) {
            r.largest_cluster = size;
            r.cluster_box = {x0, y0, x1 - x0 + 1, y1 - y0 + 1};
        }
    }
}

std::string cluster_text(const CompareResult& r, const CompareOptions& o) {
    const PixelBox& b = r.cluster_box;
    return "largest cluster " + std::to_string(r.largest_cluster) + " pixels (allowed " +
           (o.max_cluster < 0 ? std::string("any") : std::to_string(o.max_cluster)) + ") in the " +
           std::to_string(b.width) + "x" + std::to_string(b.height) + " box at (" +
           std::to_string(b.x) + ", " + std::to_string(b.y) + ")";
}

std::string summarize(const CompareResult& r, const CompareOptions& o) {
    if (r.identical && r.max_channel_delta == 0) return "identical, bit for bit";
    if (r.identical)
        return "identical within the tolerance: every pixel within " + std::to_string(o.tolerance) +
               " levels or too faint to see; largest channel difference " +
               std::to_string(r.max_channel_delta) + " of 255";
    // A match that is not identical: worded so that it does not read as a failure ("0 pixels
    // differ ... max channel delta 24" seemed to contradict itself).
    if (r.matches)
        return "matches, not bit-identical: " + std::to_string(r.different) + " pixels differ (" +
               std::to_string(o.max_different) + " allowed) and " + std::to_string(r.antialiased) +
               " only at anti-aliased edges, which do not count; largest channel difference " +
               std::to_string(r.max_channel_delta) + " of 255 (tolerance " +
               std::to_string(o.tolerance) + ")";
    return std::to_string(r.different) + " pixels differ (allowed " +
           std::to_string(o.max_different) + ")" +
           (r.different > 0 ? ", " + cluster_text(r, o) : std::string()) + ", " +
           std::to_string(r.antialiased) + " anti-aliased; max channel delta " +
           std::to_string(r.max_channel_delta) + ", tolerance " + std::to_string(o.tolerance);
}

} // namespace

CompareResult compare_images(const Image& a, const Image& b, const CompareOptions& options) {
    CompareResult result;
    if (a.width != b.width || a.height != b.height) {
        result.summary = "sizes differ: " + size_text(a) + " vs " + size_text(b);
        return result;
    }
    result.same_size = true;
    const int tolerance = std::clamp(options.tolerance, 0, 255);
    // The threshold is a fraction of the distance from black to white; distances are squared.
    const std::uint8_t black[3] = {0, 0, 0}, white[3] = {255, 255, 255};
    const double t = std::clamp(options.perceptual_threshold, 0.0, 1.0);
    const double min_distance = t * t * yiq_distance(black, white);
    result.diff = Image(a.width, a.height);
    std::vector<std::uint8_t> differs(std::size_t(a.width) * std::size_t(a.height), 0);
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const std::uint8_t *p = pixel(a, x, y), *q = pixel(b, x, y);
            std::uint8_t* out = result.diff.row(y) + 3 * x;
            const int delta = channel_delta(p, q);
            result.max_channel_delta = std::max(result.max_channel_delta, delta);
            const bool changed = delta > tolerance && (t == 0 || yiq_distance(p, q) > min_distance);
            if (!changed) {
                write_faded(out, p);
            } else if (options.detect_antialiasing && (looks_antialiased(a, b, x, y, tolerance) ||
                                                       looks_antialiased(b, a, x, y, tolerance))) {
                ++result.antialiased;
                write_mark(out, 255, 255, 0);
            } else {
                ++result.different;
                differs[std::size_t(y) * std::size_t(a.width) + std::size_t(x)] = 1;
                write_mark(out, 255, 0, 0);
            }
        }
    }
    find_largest_cluster(differs, a.width, a.height, result);
    result.identical = result.different == 0 && result.antialiased == 0;
    result.matches = result.different <= options.max_different &&
                     (options.max_cluster < 0 || result.largest_cluster <= options.max_cluster);
    result.summary = summarize(result, options);
    return result;
}

} // namespace tumble::render
