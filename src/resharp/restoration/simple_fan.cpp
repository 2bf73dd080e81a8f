#include "resharp/restoration/simple_fan.h"

#include <cmath>
#include <span>

namespace resharp {
namespace {

/// A fan face must face its fan's axis by at least this cosine to count as seen from the front
/// (about 89.9999 degrees): far above the rounding of a unit normal, so that the sign of its
/// turn about the axis is certain (see is_simple_fan()).
constexpr double kFrontCosine = 1e-6;

/// A fan edge must stand off the counting line by at least this share of its length for its
/// side of the line to be certain (see is_simple_fan()).
constexpr double kOffLineRatio = 1e-9;

}  // namespace

bool is_simple_fan(const std::vector<Vec3>& x, Index apex, const Fan& fan) {
    if (fan.overflow || fan.size < 3) return false;
    const std::span<const Wedge> wedges(fan.wedges.data(), fan.size);
    Vec3 axis = Vec3::Zero();
    for (const Wedge& w : wedges) axis += *w.normal;
    const double length = axis.norm();
    if (!(length > 0.0)) return false;
    axis /= length;
    for (const Wedge& w : wedges) {
        if (!(w.normal->dot(axis) > kFrontCosine)) return false;
    }
    // A direction across the counting line, perpendicular to the axis. Made from a direction
    // of no symmetry of the grid, not from a coordinate axis: grid meshes have many edges along
    // the axes, which would lie on the line.
    const Vec3 generic_a(0.267, 0.534, 0.802), generic_b(0.802, -0.267, 0.534);
    const Vec3& off =
        std::abs(axis.dot(generic_a)) < std::abs(axis.dot(generic_b)) ? generic_a : generic_b;
    const Vec3 across = axis.cross(off).normalized();
    std::array<bool, kMaxFan> left{};  // per wedge: its `next` edge lies left of the line
    for (std::size_t i = 0; i < wedges.size(); ++i) {
        const Vec3 edge = x[wedges[i].next] - x[apex];
        const double side = edge.dot(across);
        if (side * side <= kOffLineRatio * kOffLineRatio * edge.squaredNorm()) return false;
        left[i] = side > 0.0;
    }
    int crossings = 0;
    std::array<bool, kMaxFan> followed{};  // per wedge: it is some wedge's follower
    for (std::size_t i = 0; i < wedges.size(); ++i) {
        int followers = 0;  // wedges whose `next` edge is this one's `prev` edge
        std::size_t follower = 0;
        for (std::size_t j = 0; j < wedges.size(); ++j) {
            if (wedges[j].next != wedges[i].prev) continue;
            ++followers;
            follower = j;
        }
        if (followers != 1 || followed[follower]) return false;
        followed[follower] = true;
        crossings += !left[i] && left[follower];
    }
    return crossings == 1;
}

}  // namespace resharp
