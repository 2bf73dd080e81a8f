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
#include "resharp/mesh/connectivity.h"
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
    /// Takes the mesh and its connectivity, the touched faces, per face (#F) its number among
    /// them or kNoIndex, and per touched face the box that holds the face and its points (every
    /// piece it may be cut into lies in it); any other face is boxed by its vertices. Each
    /// touched face searches outwards from its vertices through the faces that meet its box,
    /// so the cost follows the faces near the bands, not the mesh. A separate sheet of the
    /// surface crossing the box with no face joining it to the band inside the box (material
    /// thinner than a chamfer, cut apart from it) is not seen.
    NearbyFaces(const Mesh& mesh, const Connectivity& connectivity, std::span<const Index> touched,
                std::span<const Index> number, std::span<const Box3> boxes);

    /// The faces near touched face number i (its index in `touched`), ascending; touched faces
    /// near each other are in each other's lists.
    std::span<const Index> of(std::size_t i) const { return {faces_.data() + start_[i], size_[i]}; }

private:
    std::vector<std::size_t> start_;
    std::vector<Index> size_;
    std::vector<Index> faces_;
};

}  // namespace resharp
