#pragma once
/// The intersection test of the harm check: whether a new piece cuts through, or touches, a
/// triangle near it.
///
/// Why hand-written tests and not CGAL's exact ones (which resharp::eval uses to score): the
/// library pulls in nothing beyond Eigen and oneTBB, and the harm check runs on every piece of
/// every split face in a stage budgeted at a few milliseconds. Exactness is replaced by a tolerance
/// far above rounding: two triangles closer than it count as meeting, so where floating point
/// cannot tell, a point is refused rather than risked.

#include <Eigen/Geometry>
#include <array>

#include "resharp/core/types.h"
#include "resharp/mesh/mesh.h"

namespace resharp {

using Box3 = Eigen::AlignedBox3d;

/// A triangle with the ids of its vertices (triangles that share an id share that vertex, and
/// meeting there is no intersection), its unit normal (zero if degenerate) and its box.
struct IdTriangle {
    std::array<Index, 3> id{};
    std::array<Vec3, 3> p;
    Vec3 n = Vec3::Zero();
    Box3 box;

    /// The triangle of ids `id` at a, b, c; its normal computed, or given (unit) if known.
    static IdTriangle make(const Triangle& id, const Vec3& a, const Vec3& b, const Vec3& c);
    static IdTriangle make(const Triangle& id, const Vec3& a, const Vec3& b, const Vec3& c,
                           const Vec3& unit_normal);
};

/// True when s and t meet, or come within `tolerance` of each other, anywhere but in what they
/// share: a shared vertex, or a shared edge (where they meet beyond the edge only if they fold
/// flat onto each other). Degenerate triangles meet nothing.
bool triangles_meet(const IdTriangle& s, const IdTriangle& t, double tolerance);

}  // namespace resharp
