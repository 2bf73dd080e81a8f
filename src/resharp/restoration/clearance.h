#pragma once
/// The intersection half of the split's guard: tests whether a new piece cuts through, or
/// touches, a triangle near it, and finds which faces lie near each face that gets points.
///
/// Why hand-written tests and not CGAL's exact ones (which resharp::eval uses to score): the
/// library pulls in nothing beyond Eigen and oneTBB, and the guard runs on every piece of every
/// split face in a stage budgeted at a few milliseconds. Exactness is replaced by a tolerance
/// far above rounding: two triangles closer than it count as meeting, so where floating point
/// cannot tell, a point is refused rather than risked.

#include <array>
#include <span>
#include <vector>

#include <Eigen/Geometry>

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

/// Per face that gets points ("touched"), the other faces of the mesh whose boxes meet its box.
class NearbyFaces {
public:
    /// Takes the mesh, the touched faces in ascending order and, for each, the box that holds
    /// the face and its points (every piece it may be cut into lies in it). Each face is boxed
    /// by its vertices, a touched face by its given box. A uniform grid over the touched boxes
    /// keeps the search to one pass over the faces.
    NearbyFaces(const Mesh& mesh, std::span<const Index> touched, std::span<const Box3> boxes);

    /// The faces near touched face number i (its index in `touched`), ascending.
    std::span<const Index> of(std::size_t i) const {
        return {faces_.data() + start_[i], start_[i + 1] - start_[i]};
    }

private:
    std::vector<std::size_t> start_;
    std::vector<Index> faces_;
};

}  // namespace resharp
