#pragma once
/// The intersection half of the split's guard: tests whether a new piece cuts through, or
/// touches, a triangle near it, and finds which faces lie near each face that gets points.
///
/// Why hand-written tests and not CGAL's exact ones (which resharp::eval uses to score): the
/// library pulls in nothing beyond Eigen and oneTBB, and the guard runs on every piece of every
/// split face in a stage budgeted at a few milliseconds. Exactness is replaced by a tolerance
/// far above rounding: two triangles closer than it count as meeting, so where floating point
/// cannot tell, a point is refused rather than risked.

#include <Eigen/Geometry>
#include <array>
#include <span>
#include <vector>

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

/// A face that gets points ("touched"), as the search for its neighbours sees it.
struct TouchedFace {
    Box3 box;  ///< holds the face and its points: every piece it may be cut into
    /// Its pieces lie where cap_normal . x >= cap_offset: the face's plane, when all its points
    /// lie more than `tolerance` to one side of it (zero normal otherwise). Points are only
    /// ever dropped, so this holds for every split the face may get.
    Vec3 cap_normal = Vec3::Zero();
    double cap_offset = 0.0;
    double tolerance = 0.0;
};

/// Per touched face, the other faces of the mesh its pieces may meet.
class NearbyFaces {
public:
    /// Takes the mesh and its connectivity, the touched faces, per face (#F) its number among
    /// them or kNoIndex, and per touched face its TouchedFace. Lists every face whose box (a
    /// touched face's: TouchedFace::box) meets the touched face's box, except untouched faces
    /// lying beyond its cap plane but for the vertices they share with it: the input being free
    /// of self-intersections, such a face meets the pieces only in those vertices (and the
    /// pieces lie on the other side of that plane but for the face's own vertices and edges).
    /// Each touched face searches outwards from its vertices through the faces that meet its
    /// box, so the cost follows the faces near the bands, not the mesh. A separate sheet of the
    /// surface crossing the box with no face joining it to the band inside the box (material
    /// thinner than a chamfer, cut apart from it) is not seen.
    NearbyFaces(const Mesh& mesh, const Connectivity& connectivity, std::span<const Index> touched,
                std::span<const Index> number, std::span<const TouchedFace> faces);

    /// The faces near touched face number i (its index in `touched`), ascending; touched faces
    /// near each other are in each other's lists.
    std::span<const Index> of(std::size_t i) const { return {faces_.data() + start_[i], size_[i]}; }

private:
    std::vector<std::size_t> start_;
    std::vector<Index> size_;
    std::vector<Index> faces_;
};

}  // namespace resharp
