#pragma once
// Broad phase: candidate pairs of bodies whose bounding boxes (grown by how far they can move in
// one step) overlap, in time close to linear in the body count. A uniform grid, chosen over sweep
// and prune by measurement (bench/broadphase_bench.cpp): a pile of equal spheres overlaps a sweep
// axis in hundreds of bodies per slab, but a grid cell holds one or two.
//
// Every bounded body sits in the cell of its box centre, with the cell edge c at least the largest
// box extent among "small" bodies; two boxes that overlap then have centres less than c apart on
// every axis, so a body finds all its partners in the 3 x 3 x 3 cells around its own. Cells live
// in a dense block when the occupied cells are compact (at most 8 cells per body), else a hash
// table (either way a counting sort into flat arrays: no per-cell allocation), with each
// body's cell and box copied next to it in sorted order so that a scan reads memory in sequence.
// Awake dynamic bodies (the ones that look for partners) and the others (static, asleep) are in
// two grids: two awake bodies meet through the forward half of the neighbourhood (13 cells and
// the body's own), an awake and a resting body through all 27 cells of the resting grid, which is
// skipped when empty. Bodies much larger than the typical one (a floor slab, a wall, a fast body's
// long box) would force a huge cell, so they go to a short "large" list tested against everything
// instead, as are the rare bodies beyond the grid's range (2^30 cells from the origin) or with a
// box that is not finite (a diverging body): their cells would overflow 32 bits. Planes are tested
// against every awake body by their clearance.
#include "physics/collide.h"
#include "physics/contact_cache.h"
#include "physics/model.h"

#include <cstdint>
#include <vector>

namespace tumble::physics {

class BroadPhase {
  public:
    // Rebuilds the grids. `box` per body (grown for motion; ignored for planes), `awake` per body:
    // only awake dynamic bodies look for partners.
    void build(const Model& m, const std::vector<Aabb>& box,
               const std::vector<std::uint8_t>& awake);

    // Pairs (a < b) found by queries()[begin, end), appended to `pairs` in a fixed order (by
    // querying body, then cell, then body order within the cell). Each pair is reported once.
    void query(const Model& m, const std::vector<Aabb>& box, const std::vector<ShapePose>& pose,
               const std::vector<double>& plane_margin, int begin, int end,
               std::vector<std::uint64_t>& pairs) const;

    const std::vector<int>& queries() const { return queries_; } // awake dynamic bodies
    double cell_size() const { return cell_; }
    // Bodies the last build() found beyond the grid's range (kGridRange cells from the origin,
    // or a box that is not finite): they were tested as large bodies instead.
    int outside_grid() const { return outside_grid_; }
    static constexpr double kGridRange = 1073741824.0; // 2^30 cells

    struct Cell {
        std::int32_t x, y, z;
        bool operator==(const Cell&) const = default;
    };

  private:
    struct Grid {
        bool dense = false; // buckets are the cells of the block lo + [0, n)
        Cell lo{};          // dense: the block's first cell
        std::int64_t nx = 0, ny = 0, nz = 0;
        std::uint32_t outside = 0; // dense: the empty bucket of cells outside the block
        std::uint32_t mask = 0;    // hashed: bucket = hash & mask
        std::vector<int> start;    // bucket b holds entries [start[b], start[b + 1])
        std::vector<int> body;     // entries sorted by bucket, body order within a bucket
        std::vector<Cell> cell;    // per entry
        std::vector<Aabb> box;     // per entry
        void build(const std::vector<int>& members, const std::vector<Cell>& cell_of,
                   const std::vector<Aabb>& boxes, std::vector<int>& cursor);
        std::uint32_t bucket(const Cell& c) const;
        // visit(k) for the entries of cells (x0 .. x1, y, z), in cell order (broadphase.cpp).
        template <class Visit>
        void row(std::int32_t x0, std::int32_t x1, std::int32_t y, std::int32_t z,
                 Visit&& visit) const;
    };
    bool in_grid(const Aabb& b) const;
    Cell cell_of(const Aabb& b) const; // only for boxes in_grid()

    double cell_ = 1.0;
    int outside_grid_ = 0;
    Grid awake_grid_, rest_grid_;
    std::vector<Cell> cell_of_body_;
    std::vector<int> large_, planes_, queries_, resting_, cursor_;
    std::vector<std::uint8_t> is_large_, querying_;
    std::vector<double> extent_;  // scratch
    std::vector<int> extent_int_; // scratch
};

} // namespace tumble::physics
