#include "resharp/mesh/uniform_grid.h"

#include <cmath>
#include <limits>

namespace resharp::detail {

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
