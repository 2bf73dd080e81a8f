#include "resharp/near/tangent_plane.h"

#include <limits>

namespace resharp {

std::optional<PlaneFit> tangent_plane_at_nearest(const InputSurface& surface,
                                                 const std::vector<Index>& vertex_patch,
                                                 const std::vector<std::uint8_t>& in_band,
                                                 std::span<const Index> candidates, const Vec3& x,
                                                 Index patch) {
    Index nearest = kNoIndex;
    double least = std::numeric_limits<double>::infinity();
    for (Index j : candidates) {
        if (vertex_patch[j] != patch || in_band[j]) continue;
        const double d = (surface.mesh.positions[j] - x).squaredNorm();
        if (d < least) least = d, nearest = j;
    }
    if (nearest == kNoIndex) return std::nullopt;
    const Vec3& c = surface.mesh.positions[nearest];
    const Vec3& n = surface.normals.vertex[nearest];
    return PlaneFit{{n, n.dot(c)}, c, 0.0};
}

}  // namespace resharp
