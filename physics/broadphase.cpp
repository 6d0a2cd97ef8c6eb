#include "physics/broadphase.h"

#include <algorithm>
#include <cmath>

namespace tumble::physics {
namespace {

bool overlap(const Aabb& a, const Aabb& b) {
    return a.lo.x() <= b.hi.x() && b.lo.x() <= a.hi.x() && a.lo.y() <= b.hi.y() &&
           b.lo.y() <= a.hi.y() && a.lo.z() <= b.hi.z() && b.lo.z() <= a.hi.z();
}

double largest_extent(const Aabb& b) {
    return (b.hi - b.lo).maxCoeff();
}

} // namespace

std::uint32_t BroadPhase::Grid::bucket(const Cell& c) const {
    if (dense) {
        const std::int64_t x = std::int64_t{c.x} - lo.x, y = std::int64_t{c.y} - lo.y,
                           z = std::int64_t{c.z} - lo.z;
        if (x < 0 || y < 0 || z < 0 || x >= nx || y >= ny || z >= nz) return outside;
        return static_cast<std::uint32_t>((z * ny + y) * nx + x);
    }
    // Large odd multipliers spread neighbouring cells over the table (Teschner et al. 2003).
    const std::uint32_t h = static_cast<std::uint32_t>(c.x) * 73856093u ^
                            static_cast<std::uint32_t>(c.y) * 19349663u ^
                            static_cast<std::uint32_t>(c.z) * 83492791u;
    return h & mask;
}

void BroadPhase::Grid::build(const std::vector<int>& members, const std::vector<Cell>& cell_of,
                             const std::vector<Aabb>& boxes, std::vector<int>& cursor) {
    // Dense when the occupied cells' bounding block has at most 8 cells per member (a pile, a
    // rain): bucket = cell, no hashing and no other cell's entries to skip. Else a hash table.
    Cell hi{};
    lo = hi;
    if (!members.empty()) lo = hi = cell_of[members.front()];
    for (int i : members) {
        const Cell& c = cell_of[i];
        lo = {std::min(lo.x, c.x), std::min(lo.y, c.y), std::min(lo.z, c.z)};
        hi = {std::max(hi.x, c.x), std::max(hi.y, c.y), std::max(hi.z, c.z)};
    }
    nx = std::int64_t{hi.x} - lo.x + 1, ny = std::int64_t{hi.y} - lo.y + 1;
    nz = std::int64_t{hi.z} - lo.z + 1;
    const double cells =
        static_cast<double>(nx) * static_cast<double>(ny) * static_cast<double>(nz);
    dense = !members.empty() && cells <= 8.0 * static_cast<double>(members.size()) + 64.0;
    std::uint32_t size = 16;
    if (dense) {
        outside = static_cast<std::uint32_t>(nx * ny * nz); // an extra bucket, always empty
        size = outside + 1;
    } else {
        while (size < 2 * members.size()) size <<= 1;
        mask = size - 1;
    }
    start.assign(size + 1, 0);
    for (int i : members) ++start[bucket(cell_of[i]) + 1];
    for (std::uint32_t b = 0; b < size; ++b) start[b + 1] += start[b];
    cursor.assign(start.begin(), start.end() - 1);
    body.resize(members.size());
    cell.resize(members.size());
    box.resize(members.size());
    for (int i : members) { // in body order: stable within a bucket
        const int k = cursor[bucket(cell_of[i])]++;
        body[k] = i;
        cell[k] = cell_of[i];
        box[k] = boxes[i];
    }
}

bool BroadPhase::in_grid(const Aabb& b) const {
    // |centre / c| < 2^30 on every axis: a cell index and its neighbours (+-1) fit in 32 bits.
    // False for a box that is not finite (NaN or infinite centre).
    const Vec3 cells = 0.5 * (b.lo + b.hi) / cell_;
    return (cells.array().abs() < kGridRange).all();
}

BroadPhase::Cell BroadPhase::cell_of(const Aabb& b) const {
    // Only for boxes in_grid(): the floor is within +-2^30, exact in an int32.
    auto coord = [&](double lo, double hi) {
        return static_cast<std::int32_t>(std::floor(0.5 * (lo + hi) / cell_));
    };
    return {coord(b.lo.x(), b.hi.x()), coord(b.lo.y(), b.hi.y()), coord(b.lo.z(), b.hi.z())};
}

void BroadPhase::build(const Model& m, const std::vector<Aabb>& box,
                       const std::vector<std::uint8_t>& awake) {
    const int n = m.body_count();
    large_.clear(), planes_.clear(), queries_.clear(), resting_.clear(), extent_.clear();
    is_large_.assign(n, 0);
    querying_.assign(n, 0);
    for (int i = 0; i < n; ++i)
        if (m.shape[i].kind != ShapeKind::Plane && m.is_dynamic(i) &&
            std::isfinite(largest_extent(box[i])))
            extent_.push_back(largest_extent(box[i]));
    // Cell edge: the largest extent among bodies at most 4x the median dynamic extent.
    double limit = 1.0;
    if (!extent_.empty()) {
        auto mid = extent_.begin() + extent_.size() / 2;
        std::nth_element(extent_.begin(), mid, extent_.end());
        limit = 4.0 * *mid;
    }
    cell_ = 0.0;
    std::vector<int>& small_awake = extent_int_;
    small_awake.clear();
    for (int i = 0; i < n; ++i) {
        if (m.shape[i].kind == ShapeKind::Plane) {
            planes_.push_back(i);
            continue;
        }
        const bool querying = m.is_dynamic(i) && awake[i];
        if (querying) queries_.push_back(i), querying_[i] = 1;
        const double e = largest_extent(box[i]);
        if (!(e <= limit)) { // larger than the typical body, or not finite (NaN, infinity)
            large_.push_back(i);
            is_large_[i] = 1;
        } else {
            cell_ = std::max(cell_, e);
            (querying ? small_awake : resting_).push_back(i);
        }
    }
    if (!(cell_ > 0.0)) cell_ = 1.0;
    // A body beyond the grid's range (2^30 cells from the origin: a body thrown or diverging far
    // away) has no cell that fits in 32 bits; it joins the large list, which finds its partners by
    // testing boxes directly. Correct for any body, and rare, so the cost does not matter.
    auto outside = [&](int i) {
        if (in_grid(box[i])) return false;
        large_.push_back(i);
        is_large_[i] = 1;
        ++outside_grid_;
        return true;
    };
    outside_grid_ = 0;
    std::erase_if(small_awake, outside);
    std::erase_if(resting_, outside);
    if (outside_grid_ > 0) std::sort(large_.begin(), large_.end());
    cell_of_body_.resize(n);
    for (int i : small_awake) cell_of_body_[i] = cell_of(box[i]);
    for (int i : resting_) cell_of_body_[i] = cell_of(box[i]);
    awake_grid_.build(small_awake, cell_of_body_, box, cursor_);
    rest_grid_.build(resting_, cell_of_body_, box, cursor_);
}

// Entries of the cells (x0 .. x1, y, z), in cell order: in a dense grid one run of entries, as
// the cells of a row are consecutive buckets (and every entry's cell is its bucket's); hashed, cell
// by cell, skipping the other cells that share a bucket. The same entries in the same order either
// way; the dense run saves the bucket look-up per cell, most of a query's time in a sphere rain.
template <class Visit>
void BroadPhase::Grid::row(std::int32_t x0, std::int32_t x1, std::int32_t y, std::int32_t z,
                           Visit&& visit) const {
    if (!dense) {
        for (std::int32_t x = x0; x <= x1; ++x) {
            const Cell c{x, y, z};
            const std::uint32_t b = bucket(c);
            for (int k = start[b]; k < start[b + 1]; ++k)
                if (cell[k] == c) visit(k);
        }
        return;
    }
    const std::int64_t ry = std::int64_t{y} - lo.y, rz = std::int64_t{z} - lo.z;
    if (ry < 0 || rz < 0 || ry >= ny || rz >= nz) return;
    const std::int64_t rx0 = std::max<std::int64_t>(std::int64_t{x0} - lo.x, 0);
    const std::int64_t rx1 = std::min<std::int64_t>(std::int64_t{x1} - lo.x, nx - 1);
    if (rx0 > rx1) return;
    const std::int64_t row_start = (rz * ny + ry) * nx;
    const int end = start[static_cast<std::size_t>(row_start + rx1 + 1)];
    for (int k = start[static_cast<std::size_t>(row_start + rx0)]; k < end; ++k) visit(k);
}

void BroadPhase::query(const Model& m, const std::vector<Aabb>& box,
                       const std::vector<ShapePose>& pose, const std::vector<double>& plane_margin,
                       int begin, int end, std::vector<std::uint64_t>& pairs) const {
    auto add = [&](int i, int j) { pairs.push_back(i < j ? pair_key(i, j) : pair_key(j, i)); };
    const bool resting = !rest_grid_.body.empty();
    for (int q = begin; q < end; ++q) {
        const int i = queries_[static_cast<std::size_t>(q)];
        const Aabb& bi = box[i];
        if (!is_large_[i]) {
            const Cell c = cell_of_body_[i];
            // Entries of grid g in cells (c.x + dx0 .. c.x + dx1, c.y + dy, c.z + dz) overlapping
            // bi, with a body index above `above`.
            auto scan = [&](const Grid& g, int dx0, int dx1, int dy, int dz, int above) {
                g.row(c.x + dx0, c.x + dx1, c.y + dy, c.z + dz, [&](int k) {
                    if (g.body[k] > above && overlap(bi, g.box[k])) add(i, g.body[k]);
                });
            };
            // Awake partners: own cell (higher index only) and the forward half of the 26
            // neighbours (those whose first non-zero offset, in z, y, x order, is positive: each
            // pair of neighbouring cells is visited from one side only): the three rows above,
            // the row beside, the next cell.
            scan(awake_grid_, 0, 0, 0, 0, i);
            for (int dy = -1; dy <= 1; ++dy) scan(awake_grid_, -1, 1, dy, 1, -1);
            scan(awake_grid_, -1, 1, 1, 0, -1);
            scan(awake_grid_, 1, 1, 0, 0, -1);
            // Resting partners: all 27 cells, row by row.
            if (resting)
                for (int dz = -1; dz <= 1; ++dz)
                    for (int dy = -1; dy <= 1; ++dy) scan(rest_grid_, -1, 1, dy, dz, -1);
        } else {
            // A large body is in no cell: it meets the small resting bodies here (few, or it
            // would not be large); small awake bodies find it in their scan of the large list.
            for (std::size_t k = 0; k < rest_grid_.body.size(); ++k)
                if (overlap(bi, rest_grid_.box[k])) add(i, rest_grid_.body[k]);
        }
        for (int j : large_) {
            if (j == i) continue;
            // Small i meets every large body; two large awake bodies meet once (lower index).
            const bool report = !is_large_[i] || !querying_[j] || j > i;
            if (report && overlap(bi, box[j])) add(i, j);
        }
        for (int p : planes_) {
            const Vec3 n = pose[p].rotation.col(2);
            if (plane_clearance(m, i, pose[i], n, n.dot(pose[p].position)) <= plane_margin[i])
                add(i, p);
        }
    }
}

} // namespace tumble::physics
