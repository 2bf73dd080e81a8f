#pragma once
/// Ideal points on the exact junction (issue #13's decision on #4): each crossing edge's ideal
/// point is the point of the curve where the exact surfaces of its two vertices meet nearest the
/// edge's midpoint (eq. 5.2's point where the surfaces are planes); each corner
/// triangle's is where the three surfaces of its vertices meet. The eq. 5.2/5.3 points of
/// find_ideal_points() only start the search. Junctions the method cannot be scored on are
/// counted apart, by cause.

#include <array>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "resharp/eval/ideal_points.h"
#include "resharp/eval/machined_solid.h"
#include "resharp/surfaces/junction.h"

namespace resharp::eval {

/// What became of an ideal point off the boundary.
enum class JunctionStatus : std::uint8_t {
    Exact,           ///< placed on the exact junction: in the rate
    SampledSurface,  ///< a surface is a bull-nose ramp's, which the simulator samples: apart
    NotBounding,     ///< the surfaces meet, but not both bound the solid there (nor do
                     ///< surfaces continuing them smoothly): apart
    Unsolved,        ///< no junction of the vertices' surfaces within reach of the edge,
                     ///< or a vertex off its surface (after a hand-over: NotBounding)
};
inline constexpr std::size_t kJunctionStatusCount = 4;

/// "exact", "sampled_surface", "not_bounding", "unsolved".
std::string_view junction_status_name(JunctionStatus status);

struct ExactJunctionOptions {
    JunctionSolverOptions solver;  ///< its pitch is h, the unit of every length below
    /// In h: each surface must bound the solid this far from the junction, towards its vertex
    /// (the solid's boundary passes there with that surface's normal).
    double probe_distance = 0.05;
    /// In h: how near the probe the boundary must pass. Below the 0.01 h the junction is exact
    /// to, so that a surface covered by a nearly coincident one (a pocket's corner arc under the
    /// next pass's straight wall, 0.0007 h inside it) still counts.
    double probe_tolerance = 2e-3;
    double probe_normal_angle_deg = 2.0;  ///< largest angle between boundary and surface normal
    /// Degrees: where the boundary beside a junction is another surface within this angle of a
    /// side's surface (the next move of the same pass, which meets it tangentially, or any
    /// surface meeting it at no sharp junction), that surface continues the side and the
    /// junction is solved again with it. theta_s (IdealPointOptions::sharp_angle_deg).
    double smooth_angle_deg = 30.0;
    int max_continuations = 4;  ///< bound on such hand-overs per ideal point
    /// In h: a junction farther than this from its edge's midpoint (corner: from its triangle's
    /// centroid) is Unsolved: another branch of the surfaces' intersection.
    double max_distance = 2.0;
    /// In h: a vertex farther than this from its own surface's reconstruction is Unsolved (the
    /// job and the oracle disagree there). Binary STL rounds positions to float, about 1e-5 h on
    /// a part 100 mm long.
    double on_surface_tolerance = 1e-3;
    /// In h: the same for the surface points of an off-surface mesher, which lie on the tangent
    /// plane at a crossing near the vertex (up to 0.3 h off near edges, docs/oracle.md).
    double off_surface_tolerance = 0.5;
};

struct ExactIdealPoints {
    /// The Exact ones, in the order of `first_order`, each a copy of its eq. 5.2/5.3 point with
    /// the junction as position and beyond_chord for that position (is_beyond_chord).
    std::vector<IdealPoint> points;
    /// Per JunctionStatus (indexed by it): how many edge and corner points off the boundary got
    /// it. Exact counts points.size() split by kind.
    std::array<std::size_t, kJunctionStatusCount> edges{}, corners{};
};

/// Takes `mesh` with its `oracle`, its first-order ideal points (find_ideal_points) and the
/// solid the job mills; gives the ideal points on the exact junction. Boundary points are left
/// out (they are never scored).
/// \throws InvalidInput if a vertex's surface id names no surface of `solid` (the oracle comes
/// from another job), or the oracle does not fit the mesh.
ExactIdealPoints find_exact_ideal_points(const Mesh& mesh, const Oracle& oracle,
                                         std::span<const IdealPoint> first_order,
                                         const MachinedSolid& solid,
                                         const ExactJunctionOptions& options = {});

}  // namespace resharp::eval
