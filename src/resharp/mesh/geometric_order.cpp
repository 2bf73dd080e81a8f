#include "resharp/mesh/geometric_order.h"

#include <cmath>

namespace resharp {
namespace {

/// The least z of face f's corners: that of its first corner in sweep order.
double lowest_z(const Mesh& mesh, Index f) {
    const Triangle& t = mesh.triangles[f];
    return std::min({mesh.positions[t[0]].z(), mesh.positions[t[1]].z(), mesh.positions[t[2]].z()});
}

}  // namespace

FacesInSweepOrder::FacesInSweepOrder(const Mesh& mesh, std::span<const Index> faces) : mesh_(mesh) {
    if (faces.empty()) {
        slab_start_.assign(1, 0);
        return;
    }
    std::vector<double> z(faces.size());
    for (std::size_t i = 0; i < faces.size(); ++i) z[i] = lowest_z(mesh, faces[i]);
    // Plain values, not a structured binding: clang 14 (the fuzzing lane) refuses to capture
    // one in the lambda below.
    const auto bounds = std::minmax_element(z.begin(), z.end());
    const double low = *bounds.first, high = *bounds.second;
    // About 8 faces a slab. The slab is a non-decreasing function of z (rounding keeps
    // subtraction and multiplication monotone), so sorting slab by slab sorts the whole.
    const std::size_t slabs = std::max<std::size_t>(1, faces.size() / 8);
    const double range = high - low;  // +inf past the doubles: one slab then
    const double per_z =
        range > 0.0 && std::isfinite(range) ? static_cast<double>(slabs) / range : 0.0;
    auto slab_of = [&](double zi) {
        return std::min(slabs - 1, static_cast<std::size_t>((zi - low) * per_z));
    };
    slab_start_.assign(slabs + 1, 0);
    for (double zi : z) ++slab_start_[slab_of(zi) + 1];
    for (std::size_t s = 0; s < slabs; ++s) slab_start_[s + 1] += slab_start_[s];
    by_slab_.resize(faces.size());
    std::vector<std::size_t> fill(slab_start_.begin(), slab_start_.end() - 1);
    for (std::size_t i = 0; i < faces.size(); ++i) by_slab_[fill[slab_of(z[i])]++] = faces[i];
}

FacesInSweepOrder::KeyedFace FacesInSweepOrder::keyed(Index f) const {
    const std::array<Index, 3> corners = corners_in_sweep_order(mesh_, f);
    const Vec3& p = mesh_.positions[corners[0]];
    return {{p.z(), p.y(), p.x()}, corners, f};
}

bool FacesInSweepOrder::before(const KeyedFace& a, const KeyedFace& b) const {
    for (int k = 0; k < 3; ++k) {
        if (a.first_corner[k] != b.first_corner[k]) return a.first_corner[k] < b.first_corner[k];
    }
    return face_swept_before(mesh_, a.corners, b.corners, a.face, b.face);
}

}  // namespace resharp
