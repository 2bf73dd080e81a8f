#pragma once
/// Internal to resharp: a uniform grid of axis-aligned boxes for nearest-item, radius and box
/// queries over millions of samples or triangles (the evaluator's distances, the harm check's
/// input faces beyond the rings it walks).
///
/// Why our own grid and not CGAL's AABB tree: every query here starts within a cell or two of its
/// answer (samples lie on or next to the surface they are measured against, at spacing below the
/// cell), so a dense grid answers in a few cell visits without the tree's descent, builds in two
/// linear passes (count, scatter: no per-cell allocation) and is trivially shared by threads.

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <limits>
#include <utility>
#include <vector>

#include "resharp/core/types.h"
#include "resharp/mesh/mesh.h"

namespace resharp::detail {

using Box3 = Eigen::AlignedBox3d;

class UniformGrid {
public:
    UniformGrid() = default;  ///< empty: no items

    /// Files items 0..count-1 by their boxes (`box_of(i)`, asked three times an item: keeping
    /// the boxes would take 48 bytes an item) into cells of edge about `cell` (enlarged so that
    /// the grid has at most `max_cells` cells).
    template <class BoxOf>
    UniformGrid(std::size_t count, BoxOf&& box_of, double cell,
                std::size_t max_cells = std::size_t{1} << 26);

    /// The item with the smallest `distance(item)` from p, as (item, distance), searched in
    /// growing shells of cells. `distance` must be a true distance from p to the item (a lower
    /// bound by cells is what stops the search). (kNoIndex, inf) if the grid is empty.
    template <class Distance>
    std::pair<Index, double> nearest(const Vec3& p, Distance&& distance) const;

    /// Calls visit(item) for every item filed in a cell that meets the cube of half-edge
    /// `radius` around p (a superset of the items within radius; an item may come twice when
    /// its box spans cells).
    template <class Visit>
    void for_each_near(const Vec3& p, double radius, Visit&& visit) const {
        const Vec3 r = Vec3::Constant(radius);
        for_each_meeting(Box3(p - r, p + r), visit);
    }

    /// Whether some item is filed in a cell that meets `box` (so, a box meeting an item's box
    /// always answers true).
    bool any_filed_meeting(const Box3& box) const {
        bool any = false;
        for_cells(box, [&](std::size_t c) { any = any || start_[c + 1] > start_[c]; });
        return any;
    }

    /// Calls visit(item) for every item filed in a cell that meets `box` (a superset of the
    /// items whose boxes meet it; an item may come twice when its box spans cells).
    template <class Visit>
    void for_each_meeting(const Box3& box, Visit&& visit) const;

private:
    /// The cell holding p, clamped to the grid (NaN coordinates to 0).
    Eigen::Vector3i cell_of(const Vec3& p) const {
        Eigen::Vector3i c;
        for (int a = 0; a < 3; ++a) {
            // Truncation is the floor where it is not clamped: above 0.
            const double t = (p[a] - origin_[a]) / cell_;
            c[a] = !(t > 0.0) ? 0 : t >= dims_[a] - 1 ? dims_[a] - 1 : static_cast<int>(t);
        }
        return c;
    }
    /// Calls f(linear cell) for every cell that box b meets.
    template <class F>
    void for_cells(const Box3& b, F&& f) const {
        const Eigen::Vector3i lo = cell_of(b.min()), hi = cell_of(b.max());
        for (int z = lo.z(); z <= hi.z(); ++z)
            for (int y = lo.y(); y <= hi.y(); ++y)
                for (int x = lo.x(); x <= hi.x(); ++x) f(linear(x, y, z));
    }
    /// How far p may move before it leaves the box of cells [lo, hi], ignoring sides where the
    /// box reaches the end of the grid (no items lie beyond them).
    double distance_to_box_boundary(const Vec3& p, const Eigen::Vector3i& lo,
                                    const Eigen::Vector3i& hi) const;
    std::size_t linear(int x, int y, int z) const {
        return (static_cast<std::size_t>(z) * dims_.y() + y) * dims_.x() + x;
    }
    template <class Visit>
    void visit_cell(int x, int y, int z, Visit&& visit) const {
        const std::size_t c = linear(x, y, z);
        for (std::size_t k = start_[c]; k < start_[c + 1]; ++k) visit(items_[k]);
    }

    Vec3 origin_ = Vec3::Zero();
    double cell_ = 1.0;
    Eigen::Vector3i dims_{1, 1, 1};
    std::vector<std::size_t> start_{0, 0};  // CSR: cell c holds items_[start_[c] .. start_[c + 1])
    std::vector<Index> items_;
};

template <class BoxOf>
UniformGrid::UniformGrid(std::size_t count, BoxOf&& box_of, double cell, std::size_t max_cells) {
    if (count == 0) return;
    Box3 bounds;
    for (std::size_t i = 0; i < count; ++i) bounds.extend(box_of(i));
    const Vec3 extent = bounds.sizes();
    cell_ = cell;
    for (;;) {  // Bound: the cell grows by half each time until the cells fit
        dims_ = ((extent / cell_).array().floor() + 1.0).cast<int>().matrix();
        if (static_cast<double>(dims_.x()) * dims_.y() * dims_.z() <= double(max_cells)) break;
        cell_ *= 1.5;
    }
    origin_ = bounds.min();
    // Two passes, count then scatter, so no cell owns an allocation.
    start_.assign(static_cast<std::size_t>(dims_.prod()) + 1, 0);
    for (std::size_t i = 0; i < count; ++i)
        for_cells(box_of(i), [&](std::size_t c) { ++start_[c + 1]; });
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    items_.resize(start_.back());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < count; ++i) {
        for_cells(box_of(i), [&](std::size_t c) { items_[fill[c]++] = static_cast<Index>(i); });
    }
}

template <class Visit>
void UniformGrid::for_each_meeting(const Box3& box, Visit&& visit) const {
    for_cells(box, [&](std::size_t c) {
        for (std::size_t k = start_[c]; k < start_[c + 1]; ++k) visit(items_[k]);
    });
}

template <class Distance>
std::pair<Index, double> UniformGrid::nearest(const Vec3& p, Distance&& distance) const {
    std::pair<Index, double> best{kNoIndex, std::numeric_limits<double>::infinity()};
    if (items_.empty()) return best;
    auto consider = [&](Index item) {
        const double d = distance(item);
        if (d < best.second || (d == best.second && item < best.first)) best = {item, d};
    };
    const Eigen::Vector3i home = cell_of(p);
    for (int k = 0;; ++k) {
        const Eigen::Vector3i lo = (home.array() - k).max(0).matrix();
        const Eigen::Vector3i hi = (home.array() + k).min(dims_.array() - 1).matrix();
        const double cells =
            double(hi.x() - lo.x() + 1) * (hi.y() - lo.y() + 1) * (hi.z() - lo.z() + 1);
        const bool whole_grid = (lo.array() == 0).all() && (hi.array() == dims_.array() - 1).all();
        if (cells > double(items_.size()) || whole_grid) {
            // Far from everything (a sparse set): a plain scan costs less than more shells.
            best = {kNoIndex, std::numeric_limits<double>::infinity()};
            for (Index item : items_) consider(item);
            return best;
        }
        // Shell k: the cells of the box [lo, hi] at Chebyshev distance k from home.
        for (int z = lo.z(); z <= hi.z(); ++z)
            for (int y = lo.y(); y <= hi.y(); ++y) {
                const bool face = std::abs(z - home.z()) == k || std::abs(y - home.y()) == k;
                const int step = face ? 1 : std::max(1, hi.x() - lo.x());
                for (int x = lo.x(); x <= hi.x(); x += step) {
                    const int ring = std::max(
                        {std::abs(x - home.x()), std::abs(y - home.y()), std::abs(z - home.z())});
                    if (ring == k) visit_cell(x, y, z, consider);
                }
            }
        // Every item not yet seen lies outside the box [lo, hi] (or beyond the grid, where
        // nothing is), so at least as far from p as p is from that box's nearest inner face.
        if (best.second <= distance_to_box_boundary(p, lo, hi)) return best;
    }
}
/// The bounding box of face f of `mesh`.
Box3 face_box(const Mesh& mesh, Index f);

/// The faces of `mesh` filed by their boxes, for nearest-face and radius queries.
UniformGrid face_grid(const Mesh& mesh, double cell);

}  // namespace resharp::detail
