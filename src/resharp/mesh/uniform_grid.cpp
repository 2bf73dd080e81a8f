#include "resharp/mesh/uniform_grid.h"

#include <cmath>
#include <limits>

namespace resharp::detail {

UniformGrid::UniformGrid(std::size_t count, const std::function<Box3(std::size_t)>& box_of,
                         double cell, std::size_t max_cells) {
    std::vector<Box3> boxes(count);
    Box3 bounds;
    for (std::size_t i = 0; i < count; ++i) {
        boxes[i] = box_of(i);
        bounds.extend(boxes[i]);
    }
    if (count == 0) {
        start_.assign(2, 0);
        return;
    }
    const Vec3 extent = bounds.sizes();
    cell_ = cell;
    for (;;) {
        dims_ = ((extent / cell_).array().floor() + 1.0).cast<int>().matrix();
        if (static_cast<double>(dims_.x()) * dims_.y() * dims_.z() <= double(max_cells)) break;
        cell_ *= 1.5;
    }
    origin_ = bounds.min();
    // Two passes, count then scatter, so no cell owns an allocation.
    start_.assign(static_cast<std::size_t>(dims_.prod()) + 1, 0);
    auto for_cells = [&](const Box3& b, auto&& f) {
        const Eigen::Vector3i lo = cell_of(b.min()), hi = cell_of(b.max());
        for (int z = lo.z(); z <= hi.z(); ++z)
            for (int y = lo.y(); y <= hi.y(); ++y)
                for (int x = lo.x(); x <= hi.x(); ++x) f(linear(x, y, z));
    };
    for (const Box3& b : boxes) for_cells(b, [&](std::size_t c) { ++start_[c + 1]; });
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    items_.resize(start_.back());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < count; ++i) {
        for_cells(boxes[i], [&](std::size_t c) { items_[fill[c]++] = static_cast<Index>(i); });
    }
}

Eigen::Vector3i UniformGrid::cell_of(const Vec3& p) const {
    const Eigen::Array3d c = ((p - origin_) / cell_).array().floor();
    const Eigen::Array3d top = (dims_.array() - 1).cast<double>();
    return c.max(0.0).min(top).cast<int>().matrix();
}

double UniformGrid::distance_to_box_boundary(const Vec3& p, const Eigen::Vector3i& lo,
                                             const Eigen::Vector3i& hi) const {
    double d = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (lo[a] > 0) d = std::min(d, p[a] - (origin_[a] + lo[a] * cell_));
        if (hi[a] < dims_[a] - 1) d = std::min(d, origin_[a] + (hi[a] + 1) * cell_ - p[a]);
    }
    return std::max(d, 0.0);
}

Box3 face_box(const Mesh& mesh, Index f) {
    const Triangle& t = mesh.triangles[f];
    Box3 box(mesh.positions[t[0]], mesh.positions[t[0]]);
    return box.extend(mesh.positions[t[1]]).extend(mesh.positions[t[2]]);
}

UniformGrid face_grid(const Mesh& mesh, double cell) {
    return UniformGrid(
        mesh.face_count(), [&](std::size_t f) { return face_box(mesh, Index(f)); }, cell);
}

}  // namespace resharp::detail
