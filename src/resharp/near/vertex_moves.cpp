#include "resharp/near/vertex_moves.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <optional>

#include "resharp/core/errors.h"
#include "resharp/core/parallel.h"
#include "resharp/mesh/geometry.h"
#include "resharp/near/occupied_cells.h"
#include "resharp/near/tangent_plane.h"
#include "resharp/surfaces/local_quadric.h"
#include "resharp/surfaces/plane_fit.h"

namespace resharp {
namespace {

/// A vertex takes part in at most this many patches' fits (a corner joins three).
constexpr std::size_t kMaxSides = 4;
/// At most this many vertices are gathered around a vertex, nearest rings first: for the
/// planes a vertex moves onto, and for its other sides where they are fitted farther out
/// (VertexMoveOptions::other_side_fit_rings).
constexpr std::size_t kMaxGathered = 64;
constexpr std::size_t kMaxOtherSideGathered = 160;
/// Midpoint (whole_patch_plane()): a patch with fewer vertices off the bands gets no plane of
/// its own as a whole (its vertices' fits around them take in most of it anyway); the mean
/// square of its vertices' distances to its plane may exceed what midpoint errors alone give by
/// this factor (the sample's own spread: a few tens of points scatter by up to about half as
/// much again); and at most this share of them may lie farther from it than their grid edges
/// allow, with this much room (in pitches) for the plane's own error.
constexpr std::size_t kMinWholePatchPoints = 32;
constexpr double kWholePatchScatter = 2.0;
constexpr double kWholePatchBeyondShare = 0.001;
constexpr double kWholePatchFitError = 0.02;
/// ... the last two on faces within about 11 degrees of a grid plane only (the cosine of the
/// normal's largest component above this), whose midpoints are too alike for the mean square:
/// off the axes, where the plane's own error is a larger share of the bound, they refused the
/// planes of most slanted faces (stepped_block turned: Edge F-score 0.58 -> 0.37).
constexpr double kAcrossAnAxisCosine = 0.98;
/// Midpoint: a fit is bent, and no plane, where a quadratic height over it takes out more than
/// this share of its points' mean square distance, and more than this distance (in pitches)
/// squared (is_bent(); docs/method.md; with 0.4, mech's midpoint Edge F-score fell 0.629 ->
/// 0.566 and frogface's 0.774 -> 0.663).
constexpr double kSagShare = 0.5;
constexpr double kMinSag = 0.03;
/// Midpoint: a plane found within every vertex's grid edge (plane_within_edges()) is bent where
/// the quadratic takes out more than this share: of a few treads' stairs near a grid plane it
/// takes out about half (0.52 to 0.59 on hex_prism turned's pocket wall), of a curved strip
/// most (0.77 to 1.0 on spool aligned's hub and rims). The least-squares weight of the whole
/// fit there, and the most passes of its iteration.
constexpr double kWithinEdgesSagShare = 0.7;
constexpr double kWithinEdgesWeight = 1e-3;
constexpr int kWithinEdgesPasses = 50;
/// Midpoint: a curved face's vertices go onto the quadratic height fitted to them
/// (point_on_bent_face()) only where they scatter about it by at most this many times what
/// midpoints alone give (h^2 / 12 times the square of the normal's component along their grid
/// edges, on average): more is a fold or an edge within the fit rings that no quadratic follows;
/// ... and where it curves by at most this (in 1 / h): radii below 3 h are below what issue 13
/// takes for a smooth surface, and a quadratic over a sharp edge of a few pitches' reach curves
/// by about 0.6 tan(half its turn) / h.
constexpr double kBentNoise = 2.0;
constexpr double kBentMaxCurvature = 1.0 / 3.0;
/// Midpoint: the most Newton steps along a grid edge onto a quadratic height (along_edge_onto()).
constexpr int kEdgeNewtonSteps = 8;
/// Midpoint: how far short of its grid edge's ends a vertex stops (on an edge along the
/// surface's normal; farther on edges across it), and how far beyond them a plane may meet the
/// edge's line and still be taken for crossing it, in pitches (within_edge()).
constexpr double kEdgeEndMargin = 0.01;
constexpr double kEdgeOvershoot = 0.25;
/// Near: the most (root mean square, in pitches) a curved side's vertices may scatter about the
/// second-order surface fitted to them for a vertex between patches to move onto its junction
/// with the other sides (point_on_curved_junction()). Cell means of crossings on a curved face
/// lie inside it by about its sag over a cell, h / 8r pitches (0.02 at r = 6 h), and over the
/// fit rings the surface's own terms beyond the second add as much again.
constexpr double kCurvedJunctionScatter = 0.03;
/// Near: a fit is a flat face's plane where its points scatter about it by at most this (root
/// mean square, in pitches). Cell means of crossings on a plane lie on it to rounding; where a
/// fit scatters more but most of its points lie on one plane to this (fit_plane_of_most()), the
/// rest are vertices the mesher put off the face, and that plane is the face's: OpenVDB's beside
/// a concave edge lie up to a quarter of a pitch off it over two or three cells, and a plane
/// through them all leans by degrees (chamfered_block turned at 100 cells, a pocket's wall:
/// 5.7 degrees).
constexpr double kFlatFaceScatter = 0.002;
/// Near: a flat face's vertices around a vertex that do not half lie on its plane still take it
/// (fit_side()) where they all lie within this of it (in pitches): OpenVDB's beside a concave
/// edge lie up to a quarter of a pitch off their face over two or three cells, so that around
/// a vertex of the bevel between the faces most of them may be off. On stepped_block turned at
/// 100 cells, of the 193 vertices of no patch within 1.5 pitches of a concave edge, 138 had a
/// plane around them scattering by more than the junction scatter and 33 came within 0.15
/// pitches of the edge; with this, 118 (their median distance 0.82 -> 0.02 pitches). Off the
/// grid axes the rows beside a vertical concave edge lie up to 0.7 pitches off (stepped_block
/// turned: 64 of the 541 fits within kBehindFaceReach behind have their farthest point 0.5 to
/// 0.7 pitches in front, none farther; spool aligned has 48 at 0.75 to 0.85, its flanges' patches
/// holding vertices of the hub); at half a pitch those band vertices took planes 13 degrees off
/// their face (stepped_block turned's Edge F-score 0.812 -> 0.839 with this, chamfered_block
/// turned 0.873 -> 0.895, spool aligned 0.766 -> 0.763).
constexpr double kOffFaceReach = 0.7;
/// ... and on a band vertex's own side (OffFace::InFront), where they may lie behind the plane
/// by at most this (in pitches): OpenVDB's vertices a pitch or two along a face from a concave
/// edge lie on it to a hundredth of a pitch, some behind (stepped_block turned at 100 cells, a
/// slot's wall 0.013 pitches), and with the bound at kFlatFaceScatter the bevel's vertices took
/// planes through the displaced rows, 8 to 15 degrees off their face, and stayed in the empty
/// corner (Edge F-score 0.791 -> 0.812, chamfered_block turned 0.839 -> 0.873). Of the fits
/// refused for points behind the face, 477 of 483 there lie within this, and 178 of 198 on the
/// impeller, whose curved faces leave its stock's sides at a shallow angle, beyond it.
constexpr double kBehindFaceReach = 0.05;
/// Near: a fit its points lie on exactly (within on_plane_tolerance()) is taken only where they
/// spread over the plane at least this much (in_plane_spread()): near a band a patch's
/// vertices within the fit rings may be a row and one vertex beside it (pocketed block by
/// surface nets: five along the bottom edge and one a row in, whose plane leans 12 degrees and
/// took a vertex beside it to 0.12 mm below the bottom once the side's plane was its face's).
constexpr double kMinExactFitSpread = 0.05;
/// Near: a vertex between two patches goes onto their junction only where its normal lies
/// within this (cosine) of the plane across the junction line: one whose normal runs along the
/// line lies on a third face at the end of the edge (a corner of the tilted wedge by surface
/// nets: 0.92, its junction point half a millimetre off the solid).
constexpr double kMaxNormalAlongJunction = 0.5;
/// ... and the surface must fit them this many times as closely as their plane: a bent face
/// explains its vertices' scatter about the plane, a flat face that took in a few vertices off
/// it (a hole's rim) does not, and its surface, bent towards them, meets the others off the edge.
constexpr double kBendShare = 3.0;
/// Near: how far from a flat side's plane (in pitches) a curved side's vertices may be ones a
/// dual mesher displaced along their concave edge (curved_side()): OpenVDB's two rows beside
/// the edge lie within 1.4 pitches of the other face (one cell along, one out), the next on
/// their face (spool at 100 cells, the hub beside a flange: 1.2 and 1.9 pitches).
constexpr double kDisplacedRows = 1.5;
/// Near: how far (in pitches) a vertex in the empty corner of a concave edge may go to stand
/// for a cell along the edge that its mesher left without a vertex (into_lost_cell()): OpenVDB's
/// bevel across an edge whose faces open at 60 degrees has its middle row 1.7 pitches from it.
constexpr double kLostCellReach = 2.0;

/// Near: where a flat face's vertices around a vertex may lie off its plane for it to be taken
/// as theirs (fit_side()).
enum class OffFace : std::uint8_t {
    /// On either side: the sides of a sharp junction (junction_target(), which holds them
    /// to flat planes parting sharply).
    EitherSide,
    /// In front only (behind by at most kBehindFaceReach), the side the face faces: a band vertex's
    /// own side. OpenVDB's error beside a concave edge lies in the empty corner, in front of both
    /// faces (stepped_block turned: 340 of the 504 fits whose points all lie within half a pitch
    /// of the face). Where a curved face leaves a flat one at a shallow angle, its vertices lie
    /// behind the plane (the impeller by OpenVDB, its stock's sides where the channels' walls leave
    /// them: all 198 such fits), and the face's plane there led band vertices past the edge: 149 ->
    /// 275 split pieces flipped against the exact surface (149 with in front only).
    InFront,
};

/// One side of a vertex: a patch and the plane fitted to its vertices around the vertex.
struct Side {
    Index patch = kNoIndex;
    PlaneFit fit;
};

/// The nearest to a vertex of the points offered on its sides' faces, with the face's patch.
struct FacePoint {
    std::optional<Vec3> point;
    Index patch = kNoIndex;

    void offer(const Vec3& x, const Vec3& y, Index face_patch) {
        if (point && (*point - x).squaredNorm() <= (y - x).squaredNorm()) return;
        point = y;
        patch = face_patch;
    }
};

/// Where a vertex may go.
struct Target {
    std::optional<Vec3> point;  ///< where it goes unless it takes the junction below
    /// Near, a band vertex of a patch whose cell the junction of its sides crosses: its point
    /// there, taken where every face around the vertex then lies on one side
    /// (keep_one_sided_junctions()).
    std::optional<Vec3> junction;
    bool between_patches = false;  ///< `point` is on (or beside) the junction of its patches
    Index other_patch = kNoIndex;  ///< the patch whose face `point` is on, where not its own
};

struct Scratch {
    std::vector<Index> reached;  ///< the vertices within the rings, nearest rings first
    std::vector<Vec3> points;
    /// A curved side's vertices nearby, then those of them near its flat sides (curved_side()).
    std::vector<Vec3> near_rows;
    /// Per vertex (#V): the number of the gathering that last reached it (0: none). A new
    /// gathering takes the next number, so no marks are cleared.
    std::vector<std::uint32_t> reached_in;
    std::uint32_t gathering = 0;  ///< the number of the current gathering
    int rings = 0;  ///< how many rings `reached` holds, all of each (0: none, or cut short)
    std::size_t last_ring_begin = 0;  ///< where the outermost of them begins in `reached`
    /// How many of `reached` lie within the fit rings: the vertex's own plane is fitted to
    /// these, and so is what is compared with it, even after the others are gathered farther.
    std::size_t fit_reached = 0;
};

/// The vertices that share a face with each vertex, each once, in the order
/// for_each_ring_vertex() first meets them. Midpoint moves gather three rings around every
/// vertex, and in the two passes after around every vertex whose patch has no plane as a
/// whole: there the neighbours are listed first (CSR), and a ring walk visits the six or so of
/// a vertex rather than the dozen corners of its faces, reaching the same vertices in the same
/// order (the fits sum their points in it). Near moves gather around band vertices only, where
/// listing every vertex's neighbours costs more than it saves: they walk the faces.
class Neighbours {
public:
    /// Bound (listed): the corners of every face around every vertex, once.
    Neighbours(const Mesh& mesh, const Connectivity& connectivity, bool listed)
        : mesh_(mesh), connectivity_(connectivity) {
        if (!listed) return;
        first_.assign(mesh.vertex_count() + 1, 0);
        vertex_.reserve(connectivity.ring_faces.size());
        std::vector<Index> listed_for(mesh.vertex_count(), kNoIndex);
        for (Index v = 0; v < mesh.vertex_count(); ++v) {
            for_each_ring_vertex(mesh, connectivity, v, [&](Index j) {
                if (listed_for[j] == v) return;
                listed_for[j] = v;
                vertex_.push_back(j);
            });
            first_[v + 1] = static_cast<Index>(vertex_.size());
        }
    }

    std::size_t vertex_count() const { return mesh_.vertex_count(); }

    /// Calls visit(j) for the neighbours j of v, each at least once, first meetings in order.
    template <class Visit>
    void for_each(Index v, Visit&& visit) const {
        if (first_.empty()) return for_each_ring_vertex(mesh_, connectivity_, v, visit);
        // The ends read once: visit's stores may, for all the compiler knows, change them.
        const Index* const end = vertex_.data() + first_[v + 1];
        for (const Index* j = vertex_.data() + first_[v]; j != end; ++j) visit(*j);
    }

private:
    const Mesh& mesh_;
    const Connectivity& connectivity_;
    std::vector<Index> first_;   ///< listed: #V + 1, v's neighbours are vertex_[first_[v], ...)
    std::vector<Index> vertex_;  ///< listed: about 6 per vertex
};

/// Collects into scratch.reached v and the vertices within `rings` rings of it, ring by ring,
/// at most `cap`. Where scratch.reached holds fewer rings of v, all of each, and fewer vertices
/// than `cap`, it goes on from there: a vertex whose planes have too few points within the fit
/// rings is gathered again farther out, and the rings it has are the first ones it would
/// gather. Bound: rings * cap neighbour lists.
void gather_rings(const Neighbours& neighbours, Index v, int rings, std::size_t cap,
                  Scratch& scratch) {
    std::vector<Index>& reached = scratch.reached;
    if (scratch.reached_in.size() != neighbours.vertex_count())
        scratch.reached_in.assign(neighbours.vertex_count(), 0);
    const bool goes_on =
        scratch.rings > 0 && reached[0] == v && scratch.rings <= rings && reached.size() < cap;
    if (!goes_on) {
        // Bound: the marks are cleared once in 2^32 - 1 gatherings, when the numbers run out.
        if (++scratch.gathering == 0) {
            std::fill(scratch.reached_in.begin(), scratch.reached_in.end(), 0);
            scratch.gathering = 1;
        }
        reached.assign(1, v);
        scratch.reached_in[v] = scratch.gathering;
        scratch.rings = 0;
        scratch.last_ring_begin = 0;
    }
    // Plain pointers and a count: appending through the vector made every visit read its size
    // and the marks' address again (then a third of the midpoint moves' instructions).
    std::uint32_t* const reached_in = scratch.reached_in.data();
    const std::uint32_t gathering = scratch.gathering;
    std::size_t count = reached.size();
    reached.resize(std::max(cap, count));
    Index* const out = reached.data();
    for (; scratch.rings < rings && count < cap; ++scratch.rings) {
        const std::size_t ring_end = count;
        for (std::size_t i = scratch.last_ring_begin; i < ring_end; ++i) {
            neighbours.for_each(out[i], [&](Index j) {
                if (reached_in[j] == gathering || count == cap) return;
                reached_in[j] = gathering;
                out[count++] = j;
            });
        }
        scratch.last_ring_begin = ring_end;
    }
    reached.resize(count);
    // Rings cut short by the cap are not whole: the next gathering starts anew.
    if (count >= cap) scratch.rings = 0, scratch.last_ring_begin = 0;
}

class MovePlanner {
public:
    /// The planes of a vertex's sides, fits[i] for its patches[i] (none where a side has none).
    using Fits = std::array<std::optional<PlaneFit>, kMaxSides>;

    /// A closed grid cell.
    struct Cell {
        Vec3 low, high;
        Vec3 clamp(const Vec3& y) const { return y.cwiseMax(low).cwiseMin(high); }
        /// Whether y lies in the box (its boundary included).
        bool holds(const Vec3& y) const {
            return (y.array() >= low.array()).all() && (y.array() <= high.array()).all();
        }
        /// The box with the cells around it: `pitch` wider on every side.
        Cell with_neighbours(double pitch) const {
            const Vec3 one = Vec3::Constant(pitch);
            return {low - one, high + one};
        }
        /// Whether the plane passes through the box (touching it counts).
        bool crossed_by(const Plane& plane) const {
            const Vec3 half = 0.5 * (high - low);
            return std::abs(plane.signed_distance(0.5 * (low + high))) <=
                   plane.normal.cwiseAbs().dot(half);
        }
    };

    MovePlanner(const InputSurface& current, const std::vector<Vec3>& input,
                const std::vector<Index>& vertex_patch, const BandClassification& bands,
                const MoveRule& rule, const VertexMoveOptions& options)
        : current_(current),
          input_(input),
          vertex_patch_(vertex_patch),
          rule_(rule),
          options_(options),
          max_scatter_(rule.grid.pitch * (rule.placement == VertexPlacement::Midpoint
                                              ? options.max_scatter_midpoint
                                              : options.max_scatter_near)),
          neighbours_(current.mesh, current.connectivity,
                      rule.placement == VertexPlacement::Midpoint),
          in_band_(rule.scope == FitScope::Patches
                       ? band_vertices(current.mesh, bands)
                       : std::vector<std::uint8_t>(current.mesh.vertex_count(), 0)) {
        if (rule.scope != FitScope::Patches) return;
        if (rule.placement == VertexPlacement::Midpoint) patch_plane_ = whole_patch_planes();
        if (rule.placement != VertexPlacement::Near) return;
        flat_face_ = flat_faces();
        occupied_.emplace(band_places(), rule.grid);
    }

    /// Where v may go; nothing if it stays.
    Target target(Index v, Scratch& scratch) const {
        if (rule_.scope == FitScope::Patches && is_between_patches(v))
            return junction_target(v, scratch);
        if (!patch_plane_.empty() && vertex_patch_[v] == kNoIndex)
            return {point_between_planes(v, scratch), std::nullopt, false};
        if (rule_.scope == FitScope::Patches && !may_move(v)) {
            if (const std::optional<std::array<Side, 2>> sides =
                    unbanded_border_sides(v, scratch)) {
                if (const std::optional<Vec3> edge = onto_unbanded_convex_edge(v, *sides))
                    return on_junction(edge);
                if (const std::optional<Vec3> corner =
                        onto_unbanded_curved_concave_edge(v, *sides, scratch))
                    return on_junction(corner);
            }
            return {onto_flat_face(v, scratch)};
        }
        if (const std::optional<Vec3> bent = point_on_bent_face(v, scratch)) return {bent};
        std::array<Side, kMaxSides> sides;
        bool own_fitted_farther = false;
        const std::size_t count = rule_.scope == FitScope::Patches
                                      ? patch_sides(v, scratch, sides, own_fitted_farther)
                                      : neighbourhood_side(v, scratch, sides);
        if (count == 0) return {};
        const std::span<const Side> around(sides.data(), count);
        // A plane fitted farther out leads only onto a junction (patch_sides()).
        FacePoint onto;
        if (!own_fitted_farther) onto.point = point_on_own_side(v, around, scratch);
        if (!own_fitted_farther && !onto.point) onto = point_on_other_side(v, around, scratch);
        if (const std::optional<Vec3> corner =
                into_curved_concave_corner(v, around, onto.point, true, scratch))
            return on_junction(corner);
        return {onto.point, point_on_sides_junction(v, around), false, onto.patch};
    }

private:
    /// How near a point must be to a plane or junction to count as on it, and how close to a
    /// plane a fit's points must be to count as lying on it: a thousandth of a pitch, far above
    /// rounding and far below anything a mesher gets wrong.
    double on_plane_tolerance() const { return 1e-3 * rule_.grid.pitch; }

    /// The vertices within the fit rings of v into scratch.reached.
    void gather_fit_rings(Index v, Scratch& scratch) const {
        gather_rings(neighbours_, v, options_.fit_rings, kMaxGathered, scratch);
        scratch.fit_reached = scratch.reached.size();
    }

    /// Near, a vertex of a flat face off the bands: the point of the face's plane nearest it
    /// within its input cell (where the plane misses the cell, within the cells around:
    /// nearest_beyond_cell(); on hex_prism turned by OpenVDB, rows of its pocket's floor 0.2 to
    /// 0.35 pitches in front of it, in cells it misses), where it lies in front of the plane by at
    /// most kOffFaceReach and in front of another face within the fit rings (a flat face's plane,
    /// or a curved one's tangent plane at its vertex off the bands nearest: a boss standing on
    /// the face, a hub on a flange), within two pitches, the two parting by more than the
    /// junction angle: in the empty corner of a concave edge, where OpenVDB puts the rows beside
    /// the edge up to a quarter of a pitch off their face (stepped_block turned at 100 cells: 47 of
    /// the 194 vertices within two pitches of its pocket's floor edge lay more than 0.05 pitches
    /// off the surface after the moves, 9 with this). Anywhere else a vertex in front of a flat
    /// face may be one of a curved face beside it that segmentation gave the flat one (sphere_part
    /// by OpenVDB, aligned: Edge F-score 0.849 -> 0.832 with the face's plane taken for every such
    /// vertex). None elsewhere: the vertex stays.
    std::optional<Vec3> onto_flat_face(Index v, Scratch& scratch) const {
        if (rule_.placement != VertexPlacement::Near || vertex_patch_[v] == kNoIndex ||
            !is_flat_face(vertex_patch_[v]))
            return std::nullopt;
        const Plane& face = flat_face_[vertex_patch_[v]]->plane;
        const Vec3& x = current_.mesh.positions[v];
        const double d = face.signed_distance(x);
        if (d <= on_plane_tolerance() || d > kOffFaceReach * rule_.grid.pitch) return std::nullopt;
        std::array<Index, kMaxSides> patches{};
        patches[0] = vertex_patch_[v];
        const std::size_t count = std::min(add_reached_patches(v, patches, 1, scratch), kMaxSides);
        const auto in_corner_with = [&](Index other_patch) {
            const std::optional<PlaneFit> near =
                is_flat_face(other_patch)
                    ? flat_face_[other_patch]
                    : tangent_plane_at_nearest(current_, vertex_patch_, in_band_, scratch.reached,
                                               x, other_patch);
            if (!near) return false;
            const Plane& other = near->plane;
            const double e = other.signed_distance(x);
            const std::array<Vec3, 2> normals = {face.normal, other.normal};
            return e > on_plane_tolerance() && e <= 2.0 * rule_.grid.pitch && part_sharply(normals);
        };
        if (std::none_of(patches.begin() + 1, patches.begin() + count, in_corner_with))
            return std::nullopt;
        const std::optional<Vec3> y = nearest_in_cell(x, face, input_[v]);
        return y ? y : nearest_beyond_cell(x, face, input_[v]);
    }

    /// Whether a vertex of v's ring has a patch other than v's. A lean walk: asked of every vertex
    /// off the bands, most inside their patch, where add_ring_patches() cost restore() 5 % of its
    /// instructions on mech by surface nets.
    bool on_patch_border(Index v) const {
        const Index own = vertex_patch_[v];
        for (Index f : current_.connectivity.faces_around(v)) {
            for (Index j : current_.mesh.triangles[f]) {
                const Index p = vertex_patch_[j];
                if (p != own && p != kNoIndex) return true;
            }
        }
        return false;
    }

    /// Near, a vertex off the bands on the border of its patch and one other, both flat, that
    /// lies behind both planes: the vertex a dual mesher puts in the cell a convex edge crosses,
    /// where the faces part by too little for classification to find a band (a 45-degree
    /// chamfer: each face around the vertex turns by half that). It goes to the planes' junction,
    /// within its cell, as a vertex between patches does (junction_target()'s tests: planes
    /// trusted within the junction scatter, parting by the junction angle, the edge not turning
    /// along them); none elsewhere. chamfered_block turned at 100 cells: Edge F-score 0.826 ->
    /// 0.836 by OpenVDB, 0.936 -> 0.943 by surface nets.
    std::optional<Vec3> onto_unbanded_convex_edge(Index v, const std::array<Side, 2>& sides) const {
        const std::array<PlaneFit, 2> planes{sides[0].fit, sides[1].fit};
        const Vec3& x = current_.mesh.positions[v];
        const double tolerance = on_plane_tolerance();
        if (planes[0].plane.signed_distance(x) >= -tolerance ||
            planes[1].plane.signed_distance(x) >= -tolerance)
            return std::nullopt;
        const std::optional<Junction> junction = sharp_junction(planes);
        if (!junction || turns_along(v, planes[0].plane, planes[1].plane)) return std::nullopt;
        return junction_in_cell(v, *junction);
    }

    /// Near, a vertex off the bands on the border of its patch and one other, one of them curved,
    /// in the empty corner of the concave edge between them: into_curved_concave_corner() as for
    /// a band vertex with no point of its own, where it lies in front of the curved side's surface
    /// fitted nearby (or none fits there) and the flat side's rows are displaced too. OpenVDB
    /// bevels a concave edge that turns by under 90 degrees over two rows whose faces turn by
    /// under the sharp angle each, and classification finds no band: sphere_part aligned at 100
    /// cells had 3.7 % of its true edge length in no band, its dome's circle (44 degrees) among
    /// it; 45 vertices there now move (Edge F-score 0.843 -> 0.851). None elsewhere: a
    /// surface-nets vertex there lies on the curved face (with the face's surface nearby not
    /// asked, sphere_part turned by surface nets 0.895 -> 0.891, one vertex 0.21 mm into it).
    std::optional<Vec3> onto_unbanded_curved_concave_edge(Index v, const std::array<Side, 2>& sides,
                                                          Scratch& scratch) const {
        return into_curved_concave_corner(v, sides, std::nullopt, false, scratch);
    }

    /// Near: the sides of a vertex off the bands on the border of its patch and exactly one
    /// other, its own first, each with its plane fitted within the fit rings (as a junction's
    /// sides: OffFace::EitherSide); none elsewhere, or where a side has no plane.
    std::optional<std::array<Side, 2>> unbanded_border_sides(Index v, Scratch& scratch) const {
        if (rule_.placement != VertexPlacement::Near || vertex_patch_[v] == kNoIndex ||
            !on_patch_border(v))
            return std::nullopt;
        std::array<Index, kMaxSides> patches{};
        patches[0] = vertex_patch_[v];
        if (add_ring_patches(v, patches, 1) != 2) return std::nullopt;
        Fits fits;
        if (fit_sides(v, std::span(patches.data(), 2), OffFace::EitherSide, fits, scratch) < 2)
            return std::nullopt;
        return std::array<Side, 2>{Side{patches[0], *fits[0]}, Side{patches[1], *fits[1]}};
    }

    /// Whether v has a patch and is one to move: near meshes move band vertices only (of the
    /// others, onto_unbanded_convex_edge(), onto_unbanded_curved_concave_edge() and
    /// onto_flat_face() move a few).
    bool may_move(Index v) const {
        return vertex_patch_[v] != kNoIndex &&
               (in_band_[v] || rule_.placement == VertexPlacement::Midpoint);
    }

    /// Whether v is a near vertex that segmentation left in a band: no patch of its own.
    bool is_between_patches(Index v) const {
        return rule_.placement == VertexPlacement::Near && vertex_patch_[v] == kNoIndex;
    }

    /// Where the planes of the two or three patches around v meet (the sharp edge or corner
    /// between them; the planes fitted farther out where they have none within the fit rings):
    /// the point of their junction nearest v's current place within v's input cell, or, where
    /// the junction misses the cell, the cell's point nearest it (in front of both of two planes,
    /// the nearer plane's point instead, nearer_face()). None unless each patch has a
    /// plane its vertices scatter about by at most the junction scatter and each two planes part by
    /// more than the junction angle; where a patch is curved, their surfaces' junction instead
    /// (point_on_curved_junction()). Dual meshers place a vertex of the cell a sharp edge crosses
    /// between the faces, off both; the edge itself is where it belongs (dual contouring's vertex).
    Target junction_target(Index v, Scratch& scratch) const {
        std::array<Index, kMaxSides> patches{};
        std::size_t count = add_ring_patches(v, patches, 0);
        const bool beyond_ring = count < 2;
        if (beyond_ring) count = add_reached_patches(v, patches, count, scratch);
        if (count < 2 || count > 3) return {};
        const std::span<const Index> around(patches.data(), count);
        Fits fits;
        if (fit_sides(v, around, OffFace::EitherSide, fits, scratch) < count) {
            fit_missing_farther(v, around, OffFace::EitherSide, fits, scratch);
            add_flat_faces_in_bands(around, fits, scratch);
        }
        std::array<PlaneFit, 3> planes;
        for (std::size_t i = 0; i < count; ++i) {
            if (!fits[i]) return on_junction(point_on_curved_junction(v, around, fits, scratch));
            planes[i] = *fits[i];
        }
        const Vec3& x = current_.mesh.positions[v];
        const std::size_t sides_met = count;
        if (beyond_ring && count == 3 && !corner_within_reach(v, planes))
            count = nearest_two_first(x, planes, patches, fits);
        if (!flat_enough(std::span(planes.data(), count)))
            return on_junction(
                point_on_curved_junction(v, std::span(patches.data(), count), fits, scratch));
        const std::optional<Junction> junction = sharp_junction(std::span(planes.data(), count));
        if (!junction) return {};
        const Cell reach = junction_reach(input_[v], std::span(planes.data(), count));
        if (count == 2 && turns_along(v, planes[0].plane, planes[1].plane)) return {};
        const Vec3 y = nearest_to_cell(
            x, [&](const Vec3& p) { return junction->projection(p); }, reach);
        // A cell-mean vertex may be wrong by its cell and no more. Where the edge passes
        // beside the cell (off the grid axes, the cells along a convex edge whose corners all
        // lie outside make no vertex; the vertex beside them stands for their part of the
        // edge), it goes as near the edge as its cell allows; in front of both faces (the empty
        // corner of a concave edge), onto the nearer face instead.
        const Vec3 nearest = reach.clamp(y);
        const bool off_junction =
            (junction->projection(nearest) - nearest).norm() > on_plane_tolerance();
        if (count == 2 && off_junction && in_front_of_both(x, planes[0], planes[1])) {
            const std::optional<Vec3> lost =
                sides_met == 2 ? into_lost_cell(v, *junction, std::span(planes.data(), 2))
                               : std::nullopt;
            if (lost) return on_junction(lost);
            const Target onto_face = nearer_face(x, planes, patches, reach);
            if (onto_face.point) return onto_face;
        }
        return on_junction(nearest);
    }

    /// A vertex between patches going to `point` on (or beside) their junction.
    static Target on_junction(const std::optional<Vec3>& point) {
        return {point, std::nullopt, true};
    }

    /// Whether x lies in front of both planes: in the empty corner where they meet concavely.
    bool in_front_of_both(const Vec3& x, const PlaneFit& a, const PlaneFit& b) const {
        return a.plane.signed_distance(x) > on_plane_tolerance() &&
               b.plane.signed_distance(x) > on_plane_tolerance();
    }

    /// Near, a vertex between two patches in front of both their planes whose junction misses
    /// its reach: the point of the nearer plane within the reach that bounds the solid next to
    /// the other, with that plane's patch (none where neither plane has one). OpenVDB's bevel
    /// across a concave edge off the grid axes puts rows of vertices between the patches in the
    /// empty corner, up to a pitch or more from the edge; brought as near the edge as their cells
    /// allow, they stayed off both faces, a crease each side of them (hex_prism turned at 100
    /// cells: its triangular pocket's edges).
    Target nearer_face(const Vec3& x, const std::array<PlaneFit, 3>& planes,
                       const std::array<Index, kMaxSides>& patches, const Cell& reach) const {
        FacePoint nearest;
        for (int i = 0; i < 2; ++i) {
            const Side side{patches[i], planes[i]}, other{patches[1 - i], planes[1 - i]};
            const std::optional<Vec3> y = nearest_within(x, side.fit.plane, reach);
            if (y && bounds_solid(*y, side, other, on_plane_tolerance()))
                nearest.offer(x, *y, patches[i]);
        }
        return {nearest.point, std::nullopt, false, nearest.patch};
    }

    /// Midpoint: a vertex that segmentation left in a band with no patch of its own, among two
    /// to four patches within the fit rings, each with a plane (its whole plane,
    /// whole_patch_planes(), else the plane of its vertices within the fit rings): where its
    /// grid edge meets the solid's boundary as those planes make it, the point on one of them
    /// that bounds the solid next to the others (nearest its place where more than one does,
    /// as on the edge line itself). The mesher put it on that edge because the edge crosses the
    /// boundary there. None where a patch around it has no plane. A patch's plane near the
    /// corner of a block is often only its local one: the whole-plane test refused a face
    /// whose stairs a pocket interrupts (stepped_block turned at 100 cells: 65 of the 144 band
    /// vertices left more than a tenth of a pitch off both faces within a pitch and a half of
    /// an edge).
    std::optional<Vec3> point_between_planes(Index v, Scratch& scratch) const {
        std::array<Index, kMaxSides> patches{};
        gather_fit_rings(v, scratch);
        std::size_t count = 0;
        for (Index j : scratch.reached) {
            if (!add_patch_of(j, patches, count)) return std::nullopt;
        }
        if (count < 2) return std::nullopt;
        std::array<Side, kMaxSides> sides;
        for (std::size_t i = 0; i < count; ++i) {
            const std::optional<PlaneFit> fit =
                has_whole_plane(patches[i]) ? whole_plane_near(patches[i], scratch)
                                            : fit_side(patches[i], OffFace::EitherSide, scratch);
            if (!fit) return std::nullopt;
            sides[i] = {patches[i], *fit};
        }
        const double tolerance = on_plane_tolerance();
        const Vec3& x = current_.mesh.positions[v];
        std::optional<Vec3> best;
        for (std::size_t a = 0; a < count; ++a) {
            const std::optional<Vec3> y = point_on(v, sides[a]);
            if (!y || !within_reach(input_[v], *y)) continue;
            bool bounds = true;
            for (std::size_t b = 0; b < count && bounds; ++b) {
                bounds = b == a || bounds_solid(*y, sides[a], sides[b], tolerance);
            }
            if (bounds && (!best || (*y - x).squaredNorm() < (*best - x).squaredNorm())) best = y;
        }
        return best;
    }

    /// Near, a band vertex of a patch that lies off its own plane (its cell holds crossings of
    /// another face too: dual meshers place it between the faces, like a vertex between
    /// patches): the point of its sides' junction nearest it within its cell, where the junction
    /// crosses the cell and is a sharp edge or corner (sharp_junction()). None elsewhere: a
    /// vertex on its plane, or a junction that passes beside the cell.
    std::optional<Vec3> point_on_sides_junction(Index v, std::span<const Side> sides) const {
        const double tolerance = on_plane_tolerance();
        const Vec3& x = current_.mesh.positions[v];
        if (rule_.placement != VertexPlacement::Near || sides.size() < 2 || sides.size() > 3 ||
            std::abs(sides[0].fit.plane.signed_distance(x)) <= tolerance)
            return std::nullopt;
        std::array<PlaneFit, 3> planes;
        for (std::size_t i = 0; i < sides.size(); ++i) planes[i] = sides[i].fit;
        const std::optional<Junction> junction =
            sharp_junction(std::span(planes.data(), sides.size()));
        return junction ? junction_in_cell(v, *junction) : std::nullopt;
    }

    /// The points on every one of two or three planes (a line or a point): x goes to the
    /// nearest of them by the least change that puts it on all, x - N^T (N N^T)^-1 (N x - d) for
    /// the planes' normals N and offsets d.
    class Junction {
    public:
        /// None where three normals do not span space (the Gram matrix is singular).
        static std::optional<Junction> of(std::span<const Plane> planes) {
            Junction j;
            const Eigen::Index k = static_cast<Eigen::Index>(planes.size());
            j.normals_.resize(k, 3);
            j.offsets_.resize(k);
            for (Eigen::Index i = 0; i < k; ++i) {
                j.normals_.row(i) = planes[static_cast<std::size_t>(i)].normal.transpose();
                j.offsets_[i] = planes[static_cast<std::size_t>(i)].offset;
            }
            const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3> gram =
                j.normals_ * j.normals_.transpose();
            // Unit normals: the Gram determinant is the squared volume (area) they span; the
            // angle test keeps two apart, three must not lie near one plane.
            if (std::abs(gram.determinant()) < 1e-6) return std::nullopt;
            j.gram_ = gram.partialPivLu();
            return j;
        }

        Vec3 projection(const Vec3& x) const {
            return x - normals_.transpose() * gram_.solve(normals_ * x - offsets_);
        }

    private:
        Eigen::Matrix<double, Eigen::Dynamic, 3, 0, 3, 3> normals_;
        Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1> offsets_;
        Eigen::PartialPivLU<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>> gram_;
    };

    /// Near, a vertex between two patches in front of both their planes (the empty corner of a
    /// concave edge; no third met, as in a pocket's corner) whose junction misses its reach: the
    /// junction's point nearest it, where that lies within kLostCellReach pitches, in a cell that
    /// holds no input vertex in a band or between patches (band_places(): an edge lost there),
    /// nearer v than every vertex of v's ring between patches too (those of
    /// a patch go onto its face) and out of their reach (junction_reach(): where it lies within
    /// one's, that one stands for the cell); none elsewhere. A dual mesher puts a vertex in every
    /// cell the surface crosses where its samples show the crossing. Across a concave edge whose
    /// faces meet at an acute angle no sample near the edge lies in the empty corner, and OpenVDB
    /// leaves the cells along it with none: hex_prism's triangular pocket at 100 cells, whose
    /// corners open at 60 degrees, has its bevel's middle row 1.7 pitches from the edge, two cells
    /// off, and the cells between empty. The vertex nearest a lost cell stands for it, as in dual
    /// contouring the vertex of a cell a feature crosses goes onto the feature; the others of the
    /// bevel's cross-section go onto the faces (nearer_face()), and no two vertices of a face meet
    /// there.
    std::optional<Vec3> into_lost_cell(Index v, const Junction& junction,
                                       std::span<const PlaneFit> planes) const {
        if (!occupied_) return std::nullopt;
        const Vec3& x = current_.mesh.positions[v];
        const Vec3 y = junction.projection(x);
        const double distance = (y - x).norm();
        if (distance > kLostCellReach * rule_.grid.pitch || occupied_->holds_vertex(y))
            return std::nullopt;
        for (Index f : current_.connectivity.faces_around(v)) {
            for (Index j : current_.mesh.triangles[f]) {
                if (j == v || !is_between_patches(j)) continue;
                if ((y - current_.mesh.positions[j]).norm() <= distance ||
                    junction_reach(input_[j], planes).holds(y))
                    return std::nullopt;
            }
        }
        return y;
    }

    /// The point of `junction` nearest v's current place within v's input cell; none where the
    /// junction misses the cell (the cell's point nearest it lies off it by more than the
    /// on-plane tolerance).
    std::optional<Vec3> junction_in_cell(Index v, const Junction& junction) const {
        const auto project = [&](const Vec3& p) { return junction.projection(p); };
        const Cell cell = cell_of(input_[v]);
        const Vec3 y = cell.clamp(nearest_to_cell(current_.mesh.positions[v], project, cell));
        if ((project(y) - y).norm() > on_plane_tolerance()) return std::nullopt;
        return y;
    }

    /// Whether each plane's points scatter about it by at most the junction scatter.
    bool flat_enough(std::span<const PlaneFit> fits) const {
        return std::all_of(fits.begin(), fits.end(), [&](const PlaneFit& fit) {
            return fit.rms_distance <= options_.max_junction_scatter * rule_.grid.pitch;
        });
    }

    /// Whether every two of the unit normals part by more than the junction angle.
    bool part_sharply(std::span<const Vec3> normals) const {
        const double max_cosine = std::cos(options_.junction_angle_deg * std::numbers::pi / 180.0);
        for (std::size_t i = 0; i < normals.size(); ++i) {
            for (std::size_t j = i + 1; j < normals.size(); ++j) {
                if (normals[i].dot(normals[j]) >= max_cosine) return false;
            }
        }
        return true;
    }

    /// The junction of two or three fitted planes where it is a sharp edge or corner: none
    /// unless each plane's points scatter about it by at most the junction scatter and each two
    /// planes part by more than the junction angle.
    std::optional<Junction> sharp_junction(std::span<const PlaneFit> fits) const {
        if (!flat_enough(fits)) return std::nullopt;
        std::array<Plane, 3> planes;
        std::array<Vec3, 3> normals;
        for (std::size_t i = 0; i < fits.size(); ++i) {
            planes[i] = fits[i].plane;
            normals[i] = planes[i].normal;
        }
        if (!part_sharply(std::span(normals.data(), fits.size()))) return std::nullopt;
        return Junction::of(std::span(planes.data(), fits.size()));
    }

    /// One side's surface near a vertex: its plane, or the second-order surface fitted over it
    /// where its vertices lie on a curve of it.
    struct SideSurface {
        Plane plane;
        std::optional<HeightFit> bent;
        SurfaceValue evaluate(const Vec3& p) const {
            return bent ? bent->evaluate(p) : SurfaceValue{plane.signed_distance(p), plane.normal};
        }
        /// Whether the surface may pass through the cell: a plane as Cell::crossed_by(), a
        /// second-order surface where its tangent plane at the foot of the cell's centre does
        /// (to first order, the plane at its distance from the centre along its normal there).
        bool crosses(const Cell& cell) const {
            if (!bent) return cell.crossed_by(plane);
            const Vec3 centre = 0.5 * (cell.low + cell.high);
            const SurfaceValue at = evaluate(centre);
            const double slope = at.gradient.norm();
            if (!(slope > 0.0)) return true;
            const Vec3 normal = at.gradient / slope;
            return cell.crossed_by({normal, normal.dot(centre) - at.value / slope});
        }
    };

    /// Side `patch` near x, the vertex gathered around, as a curved junction takes it: `fit`,
    /// flat, where it is its flat face's plane (fit_side() took that) and x lies in front of it;
    /// else the plane of its vertices nearby (collect_nearby_side_points(), left in
    /// scratch.points; none with fewer than the fit's minimum), flat where they scatter about it
    /// by at most the junction scatter. In front of both faces, x lies in the empty corner of a
    /// concave edge, where OpenVDB's error puts the face's vertices around off it
    /// (near/concave_bevels.h). Behind one, at a convex edge, the face's plane is taken only as
    /// its vertices around give it: on the pocketed block by surface nets, the top's vertices
    /// beside the hole's rim (a cylinder of 3.8 pitches) lie off the top, and its plane met the
    /// wall's surface off the rim (15 of the 158 vertices between patches then off their edges).
    struct NearbySide {
        bool flat = false;
        std::optional<PlaneFit> fit;
    };
    NearbySide nearby_side(Index patch, const std::optional<PlaneFit>& fit, const Vec3& x,
                           Scratch& scratch) const {
        if (fit && is_face_plane(patch, fit->plane) && fit->plane.signed_distance(x) >= 0.0)
            return {true, fit};
        const Vec3 facing = collect_nearby_side_points(patch, scratch);
        const std::optional<PlaneFit> own = plane_of(scratch.points, facing);
        return {own && own->rms_distance <= options_.max_junction_scatter * rule_.grid.pitch, own};
    }

    /// collect_side_points() of the vertices within the fit rings where the side has enough of
    /// them (the surface's own higher-order terms grow with the reach), else of all gathered.
    Vec3 collect_nearby_side_points(Index patch, Scratch& scratch) const {
        const Vec3 facing = collect_side_points(patch, scratch, scratch.fit_reached);
        if (scratch.points.size() >= static_cast<std::size_t>(options_.min_fit_points))
            return facing;
        return collect_side_points(patch, scratch);
    }

    /// The plane of the points (facing `facing`); none with fewer than the fit's minimum.
    std::optional<PlaneFit> plane_of(std::span<const Vec3> points, const Vec3& facing) const {
        if (points.size() < static_cast<std::size_t>(options_.min_fit_points)) return std::nullopt;
        return fit_plane(points, facing);
    }

    /// The second-order surface over the points near x, over their plane `plane`: none unless
    /// it fits them within kCurvedJunctionScatter and kBendShare times as closely as the plane.
    std::optional<SideSurface> bent_surface(const std::optional<PlaneFit>& plane, const Vec3& x,
                                            std::span<const Vec3> points) const {
        if (!plane) return std::nullopt;
        SideSurface s{plane->plane, fit_height_quadric(points, plane->plane, x)};
        if (!s.bent || s.bent->rms_distance > kCurvedJunctionScatter * rule_.grid.pitch ||
            !(s.bent->rms_distance * kBendShare < plane->rms_distance))
            return std::nullopt;
        return s;
    }

    /// The curved side `patch` of v near x: `nearby`, bent_surface() of its vertices nearby
    /// (which scratch.near_rows holds on entry). Next to flat sides (`flat`), also that of its
    /// vertices gathered within the other side fit rings and farther than kDisplacedRows from
    /// every flat plane, taken instead where the nearer ones do not lie on it (within
    /// kCurvedJunctionScatter, rms): OpenVDB's vertices along a concave edge lie up to a quarter
    /// of a pitch in front of their face over two cells (near/concave_bevels.h), and a quadric
    /// bends to them (spool by OpenVDB, a flange's edge on the hub: the junction 0.4 mm off it
    /// at pitch 0.4). Surface nets' lie on the face there, and their nearer fit stays.
    std::optional<SideSurface> curved_side(Index v, Index patch, const Vec3& x,
                                           std::span<const Plane* const> flat,
                                           const std::optional<SideSurface>& nearby,
                                           Scratch& scratch) const {
        const double h = rule_.grid.pitch;
        const auto displaced = [&](const Vec3& q) {
            return std::any_of(flat.begin(), flat.end(), [&](const Plane* p) {
                return std::abs(p->signed_distance(q)) < kDisplacedRows * h;
            });
        };
        std::vector<Vec3>& near_rows = scratch.near_rows;
        std::erase_if(near_rows, [&](const Vec3& q) { return !displaced(q); });
        if (near_rows.empty()) return nearby;
        gather_rings(neighbours_, v, options_.other_side_fit_rings, kMaxOtherSideGathered, scratch);
        const Vec3 facing = collect_side_points(patch, scratch);
        std::erase_if(scratch.points, displaced);
        const std::optional<SideSurface> far =
            bent_surface(plane_of(scratch.points, facing), x, scratch.points);
        if (!far || (nearby && rms_off(*far, near_rows) <= kCurvedJunctionScatter * h))
            return nearby;
        return far;
    }

    /// The root mean square distance of the points from the surface, to first order.
    static double rms_off(const SideSurface& surface, std::span<const Vec3> points) {
        double sum = 0.0;
        for (const Vec3& q : points) {
            const SurfaceValue at = surface.evaluate(q);
            sum += at.value * at.value / std::max(at.gradient.squaredNorm(), 1e-300);
        }
        return std::sqrt(sum / static_cast<double>(points.size()));
    }

    /// Near, a vertex between two or three patches one of which is curved (its vertices scatter
    /// about any plane by their sag: a cylinder of 20 pitches' radius by 0.02 pitch over the fit
    /// rings, one of 6 by more than the trusted 0.1): where the surfaces fitted to each side's
    /// vertices off the bands meet, second-order where a plane leaves them (fit_height_quadric()
    /// over the plane, as point_on_curved() takes), nearest the vertex and clamped to its input
    /// cell, or where no surface crosses that cell and the vertex lies in front of them all, to
    /// the cells around it too (as junction_reach(): OpenVDB's bevel across a flange's edge on a
    /// hub puts its middle vertex in the empty corner). None unless each surface fits its vertices
    /// within kCurvedJunctionScatter, one side at most is curved, and the surfaces part there by
    /// more than the junction angle. One curved side: where two meet, both fits' errors add, and no
    /// part measured gains from them (with two allowed the Edge F-scores of docs/results.md's
    /// surface-nets and OpenVDB rows agreed with these within 0.002). Each side as
    /// nearby_side() gives it; the curved side's surface curved_side()'s.
    std::optional<Vec3> point_on_curved_junction(Index v, std::span<const Index> patches,
                                                 const Fits& fits, Scratch& scratch) const {
        std::optional<SideSurfaces> surfaces = nearby_surfaces(v, patches, fits, scratch);
        if (!surfaces || !fit_curved_side(v, patches, *surfaces, scratch)) return std::nullopt;
        return point_on_surfaces_junction(v, *surfaces);
    }

    /// The surfaces of two or three sides for point_on_curved_junction(), side[i] for
    /// patches[i].
    struct SideSurfaces {
        std::array<SideSurface, 3> side;
        std::size_t count = 0;
        std::size_t curved = 3;  ///< which side is curved (count where none is)
        /// The curved side's surface over its vertices nearby (bent_surface()), where it has one.
        std::optional<SideSurface> curved_nearby;
        std::span<const SideSurface> all() const { return std::span(side.data(), count); }
    };

    /// Each side as nearby_side() gives it: a flat side's plane in side[], the curved side's
    /// surface over its vertices nearby in curved_nearby (and those vertices in
    /// scratch.near_rows). None where two are curved.
    std::optional<SideSurfaces> nearby_surfaces(Index v, std::span<const Index> patches,
                                                const Fits& fits, Scratch& scratch) const {
        const Vec3& x = current_.mesh.positions[v];
        SideSurfaces surfaces;
        surfaces.count = surfaces.curved = patches.size();
        for (std::size_t i = 0; i < patches.size(); ++i) {
            const NearbySide side = nearby_side(patches[i], fits[i], x, scratch);
            if (side.flat) {
                surfaces.side[i].plane = side.fit->plane;
                continue;
            }
            if (surfaces.curved < patches.size()) return std::nullopt;
            surfaces.curved = i;
            surfaces.curved_nearby = bent_surface(side.fit, x, scratch.points);
            scratch.near_rows.assign(scratch.points.begin(), scratch.points.end());
        }
        return surfaces;
    }

    /// The curved side's surface as curved_side() gives it, next to the flat sides' planes, into
    /// side[]; false where it has none. (Nothing to do where every side is flat.)
    bool fit_curved_side(Index v, std::span<const Index> patches, SideSurfaces& surfaces,
                         Scratch& scratch) const {
        if (surfaces.curved == surfaces.count) return true;
        std::array<const Plane*, 3> flat{};
        std::size_t flat_count = 0;
        for (std::size_t i = 0; i < surfaces.count; ++i) {
            if (i != surfaces.curved) flat[flat_count++] = &surfaces.side[i].plane;
        }
        const std::optional<SideSurface> bent =
            curved_side(v, patches[surfaces.curved], current_.mesh.positions[v],
                        std::span(flat.data(), flat_count), surfaces.curved_nearby, scratch);
        if (bent) surfaces.side[surfaces.curved] = *bent;
        return bent.has_value();
    }

    /// point_on_curved_junction() on the sides' surfaces.
    std::optional<Vec3> point_on_surfaces_junction(Index v, const SideSurfaces& surfaces) const {
        const double h = rule_.grid.pitch;
        const Vec3& x = current_.mesh.positions[v];
        const std::span<const SideSurface> sides = surfaces.all();
        const JunctionSolverOptions solver{.pitch = h};
        const std::optional<Vec3> y =
            sides.size() == 2 ? edge_junction(sides[0], sides[1], x, x, solver)
                              : corner_junction(sides[0], sides[1], sides[2], x, solver);
        if (!y) return std::nullopt;
        std::array<Vec3, 3> normals;
        for (std::size_t i = 0; i < sides.size(); ++i)
            normals[i] = sides[i].evaluate(*y).gradient.normalized();
        if (!part_sharply(std::span(normals.data(), sides.size()))) return std::nullopt;
        const Cell cell = cell_of(input_[v]);
        // Beyond its cell only where no side's surface crosses the cell, the vertex lies in
        // front of every side (in the empty corner of a concave edge, where OpenVDB's bevel puts
        // it) and the junction lies within the cells around. Behind a side, the vertex may be
        // one of a curved face the sides' surfaces miss: on the pocketed block by surface nets,
        // a vertex of the hole's wall 1.1 pitches below the top would have gone to the rim's
        // junction of a quadric 0.2 mm inside the wall, out of its cell.
        const bool held = std::any_of(sides.begin(), sides.end(), [&](const SideSurface& s) {
            return s.crosses(cell) || s.evaluate(x).value <= 0.0;
        });
        if (held || !cell.with_neighbours(h).holds(*y)) return cell.clamp(*y);
        return y;
    }

    /// Near, a band vertex of a patch beside one other, one of them curved, in the empty corner of
    /// the concave edge between them where OpenVDB displaces the rows beside the edge: the vertex
    /// lies in front of both sides' surfaces by more than kCurvedJunctionScatter (the curved one
    /// fitted beyond those rows, curved_side()), but behind the curved side's surface fitted to
    /// its vertices nearby or in front of it by at most the trusted scatter (the displaced rows
    /// drag that fit out to it); and the point it would take (`taken`: on its own side's plane, or
    /// another side's) lies off its own side's surface by more than the trusted scatter, or it has
    /// none. Its own plane, fitted over the displaced rows too, tilts away from the surface. Such
    /// a vertex goes to the sides' junction as a vertex between patches does
    /// (point_on_curved_junction()): on cone_part by OpenVDB, aligned at 100 cells, the top's edge
    /// on the frustum, a concave circle of radius 14 mm at pitch 0.4, its vertex at (r, z) =
    /// (14.092, 8.108), 0.11 and 0.13 mm in front of the faces, went to (14.106, 8.119) on the
    /// plane tilted 5 degrees; now it goes to (13.997, 8.000). Surface nets' rows there lie on the
    /// faces, and the surface fitted beyond them may not (on a boss of 6.3 pitches' radius it met
    /// the plate 0.3 mm inside the boss); the vertex there lies 0.13 pitches in front of the
    /// surface fitted nearby, and keeps its plane's point. Where no second-order surface fits the
    /// curved side's vertices nearby (the displaced rows scatter them by more than
    /// kCurvedJunctionScatter), the surface fitted beyond the rows decides alone, but only where
    /// the flat side's rows off the bands are displaced too (flat_rows_displaced()): on spool
    /// turned by OpenVDB, 37 hub vertices in the empty corner of its flanges' edges had no such
    /// surface nearby (one 0.27 and 0.24 mm in front of the flange and the hub now goes within
    /// 0.04 mm of the edge, 0.14 mm before); surface nets' boss on a plate had one there, 0.25
    /// pitches in front of both faces, whose surface beyond, fitted over the boss's cylinder and
    /// the cone above it, met the plate 0.16 mm inside the boss. `in_band`: false for a vertex off
    /// the bands (onto_unbanded_curved_concave_edge()), which must lie in front of the curved
    /// side's surface nearby by more than kCurvedJunctionScatter where one fits, and next to
    /// displaced flat rows always.
    std::optional<Vec3> into_curved_concave_corner(Index v, std::span<const Side> sides,
                                                   const std::optional<Vec3>& taken, bool in_band,
                                                   Scratch& scratch) const {
        if (rule_.placement != VertexPlacement::Near || sides.size() != 2) return std::nullopt;
        const std::array<PlaneFit, 2> planes{sides[0].fit, sides[1].fit};
        if (flat_enough(planes)) return std::nullopt;
        const std::array<Index, kMaxSides> patches{sides[0].patch, sides[1].patch};
        const Fits fits{sides[0].fit, sides[1].fit};
        // The surfaces fitted nearby first: most band vertices fail the tests on them, and the
        // curved side fitted farther out (curved_side()) costs a wider gathering and fit.
        std::optional<SideSurfaces> surfaces =
            nearby_surfaces(v, std::span(patches.data(), 2), fits, scratch);
        if (!surfaces || surfaces->curved == surfaces->count) return std::nullopt;
        const double h = rule_.grid.pitch;
        const double scatter = kCurvedJunctionScatter * h;
        const Vec3& x = current_.mesh.positions[v];
        const auto distance = [](const SideSurface& s, const Vec3& p) {
            const SurfaceValue at = s.evaluate(p);
            return at.value / std::max(at.gradient.norm(), 1e-300);
        };
        const double trusted = options_.max_scatter_near * h;
        const auto taken_on_own = [&] {
            return taken && std::abs(distance(surfaces->side[0], *taken)) <= trusted;
        };
        const bool own_curved = surfaces->curved == 0;
        const std::optional<SideSurface>& nearby = surfaces->curved_nearby;
        const double off_nearby = nearby ? distance(*nearby, x) : 0.0;
        if (distance(surfaces->side[1 - surfaces->curved], x) <= scatter ||
            (nearby && off_nearby > trusted) || (!own_curved && taken_on_own()) ||
            (!in_band && nearby && off_nearby <= scatter))
            return std::nullopt;
        if ((!in_band || !nearby) &&
            !flat_rows_displaced(patches[1 - surfaces->curved],
                                 surfaces->side[1 - surfaces->curved].plane, scratch))
            return std::nullopt;
        if (!fit_curved_side(v, std::span(patches.data(), 2), *surfaces, scratch) ||
            distance(surfaces->side[surfaces->curved], x) <= scatter ||
            (own_curved && taken_on_own()))
            return std::nullopt;
        return point_on_surfaces_junction(v, *surfaces);
    }

    /// Whether a vertex of flat side `patch` off the bands within the fit rings of the vertex being
    /// planned (collect_side_points(), into scratch.points) lies in front of its face's plane
    /// (flat_faces(); else `side_plane`) by more than kFlatFaceScatter: OpenVDB displaces a flat
    /// face's rows beside a concave edge, and cell means of crossings on a plane (surface nets')
    /// lie on it to rounding.
    bool flat_rows_displaced(Index patch, const Plane& side_plane, Scratch& scratch) const {
        const Plane& plane = is_flat_face(patch) ? flat_face_[patch]->plane : side_plane;
        const double off = kFlatFaceScatter * rule_.grid.pitch;
        collect_side_points(patch, scratch, scratch.fit_reached);
        return std::any_of(scratch.points.begin(), scratch.points.end(),
                           [&](const Vec3& q) { return plane.signed_distance(q) > off; });
    }

    /// The sides of v's patches: its own first; for a band vertex the others around it too, and
    /// then only if its own and another have a plane (else it cannot tell where it belongs).
    /// Near: where no other side has a plane within the fit rings, the others are fitted again
    /// farther out; they only tell which part of its own plane bounds the solid, and its own
    /// plane stays the one fitted nearby. Where its own has none there (the last cell along a
    /// block's edge before its corner: three bands leave its face few vertices off them nearby),
    /// it too is fitted farther out and `own_fitted_farther` set: such a plane may lead only onto
    /// a junction, whose planes must be flat within the junction scatter (a plane fitted that
    /// wide leaves a curved face). Left where it was, that vertex left a face across the edge
    /// beside it, and keep_one_sided_junctions() then took the edge from every vertex along it
    /// (OpenVDB, stepped_block aligned at 100 cells: Edge F-score 0.650 -> 0.676).
    std::size_t patch_sides(Index v, Scratch& scratch, std::array<Side, kMaxSides>& sides,
                            bool& own_fitted_farther) const {
        std::array<Index, kMaxSides> patches{};
        const std::span<const Index> around(patches.data(), patches_at(v, patches));
        Fits fits;
        const std::size_t fitted = fit_sides(v, around, OffFace::InFront, fits, scratch);
        const bool near_band = in_band_[v] && rule_.placement == VertexPlacement::Near;
        own_fitted_farther = near_band && !fits[0];
        if (!fits[0] && !near_band) return 0;
        if (near_band && (fitted < 2 || !fits[0])) {
            fit_missing_farther(v, around, OffFace::InFront, fits, scratch);
            if (!fits[0]) return 0;
        }
        std::size_t count = 0;
        for (std::size_t i = 0; i < around.size(); ++i) {
            if (fits[i]) sides[count++] = {around[i], *fits[i]};
        }
        if (in_band_[v] && count < 2) return 0;
        return count;
    }

    /// The planes of `patches` around v (fits[i] for patches[i]): each fitted to its vertices
    /// within the fit rings of v, gathered when a patch first needs them, or a midpoint patch's
    /// whole plane (then none are gathered for one side alone: on mech by midpoints most
    /// vertices' patches have one; for two or more, its centroid is taken near v,
    /// whole_plane_near()). Gives how many have a plane. `off_face`: as fit_side().
    std::size_t fit_sides(Index v, std::span<const Index> patches, OffFace off_face, Fits& fits,
                          Scratch& scratch) const {
        std::size_t fitted = 0;
        bool gathered = false;
        for (std::size_t i = 0; i < patches.size(); ++i) {
            const bool whole = has_whole_plane(patches[i]);
            if (!gathered && (!whole || patches.size() > 1)) {
                gather_fit_rings(v, scratch);
                gathered = true;
            }
            fits[i] = whole && gathered ? whole_plane_near(patches[i], scratch)
                                        : fit_side(patches[i], off_face, scratch);
            fitted += fits[i].has_value();
        }
        return fitted;
    }

    /// Fits again, within the other side fit rings around v, the planes of `patches` that have
    /// none: a band off the grid axes winds two or three faces wide, and within the fit rings a
    /// side across it often has too few vertices off the band.
    void fit_missing_farther(Index v, std::span<const Index> patches, OffFace off_face, Fits& fits,
                             Scratch& scratch) const {
        gather_rings(neighbours_, v, options_.other_side_fit_rings, kMaxOtherSideGathered, scratch);
        for (std::size_t i = 0; i < patches.size(); ++i) {
            if (!fits[i]) fits[i] = fit_side(patches[i], off_face, scratch);
        }
    }

    /// Near: the input places of the vertices in bands or between patches: the cells whose
    /// vertex may stand for an edge there. A cell whose vertex lies off the bands, on one face,
    /// lost the edge as much as an empty one (into_lost_cell()). And four in five vertices need
    /// not be sorted (mech by OpenVDB: the sort of all of them cost restore() 3 % of its time).
    std::vector<Vec3> band_places() const {
        std::vector<Vec3> places;
        for (Index v = 0; v < input_.size(); ++v) {
            if (in_band_[v] || vertex_patch_[v] == kNoIndex) places.push_back(input_[v]);
        }
        return places;
    }

    /// Near: to the sides of `patches` that still have no plane, the flat face's plane
    /// (flat_faces()) where the face has vertices among those gathered (with_centroid_near() of
    /// theirs, in the bands, as a rule, or too few off them for a fit): across a bevel over an
    /// acute concave edge a vertex beside one face lies five rings and more from the other's
    /// vertices off the bands (hex_prism's triangular pocket, whose corners open at 60 degrees, at
    /// 100 cells by OpenVDB), and without that face's plane its junction was taken for one with a
    /// curved face: it went to the edge of its cell beside the junction, past its neighbour, and
    /// turned their faces over.
    void add_flat_faces_in_bands(std::span<const Index> patches, Fits& fits,
                                 Scratch& scratch) const {
        for (std::size_t i = 0; i < patches.size(); ++i) {
            if (fits[i] || !is_flat_face(patches[i])) continue;
            scratch.points.clear();
            for (Index j : scratch.reached) {
                if (vertex_patch_[j] == patches[i])
                    scratch.points.push_back(current_.mesh.positions[j]);
            }
            if (!scratch.points.empty()) fits[i] = face_plane_near(patches[i], scratch.points);
        }
    }

    /// One side: the plane of every vertex within the fit rings of v, where they scatter about
    /// it as one face.
    std::size_t neighbourhood_side(Index v, Scratch& scratch,
                                   std::array<Side, kMaxSides>& sides) const {
        gather_fit_rings(v, scratch);
        const Vec3 facing = collect_reached_points(scratch);
        const std::optional<PlaneFit> fit = trusted_fit(scratch.points, facing);
        if (!fit) return 0;
        sides[0] = {kNoIndex, *fit};
        return 1;
    }

    /// v's own patch first, then (for a band vertex) the other patches of its ring's vertices,
    /// in the order met; at most kMaxSides.
    std::size_t patches_at(Index v, std::array<Index, kMaxSides>& patches) const {
        patches[0] = vertex_patch_[v];
        return in_band_[v] ? add_ring_patches(v, patches, 1) : 1;
    }

    /// patches[0, count) and then the other patches of v's ring's vertices, in the order met;
    /// at most kMaxSides in all. Gives the count.
    std::size_t add_ring_patches(Index v, std::array<Index, kMaxSides>& patches,
                                 std::size_t count) const {
        for_each_ring_vertex(current_.mesh, current_.connectivity, v,
                             [&](Index j) { add_patch_of(j, patches, count); });
        return count;
    }

    /// patches[0, count) and then the other patches of the vertices within the fit rings of v
    /// (gathered into scratch), in the order met; kMaxSides + 1 where there are more than
    /// kMaxSides. A band two faces wide or more (a dual mesher's bevel across a concave edge,
    /// near/concave_bevels.h) leaves vertices of no patch between vertices of none.
    std::size_t add_reached_patches(Index v, std::array<Index, kMaxSides>& patches,
                                    std::size_t count, Scratch& scratch) const {
        gather_fit_rings(v, scratch);
        for (Index j : scratch.reached) {
            if (!add_patch_of(j, patches, count)) return kMaxSides + 1;
        }
        return count;
    }

    /// Adds vertex j's patch to patches[0, count) unless it has none or is there already;
    /// false where it is new but kMaxSides are there (it is then left out).
    bool add_patch_of(Index j, std::array<Index, kMaxSides>& patches, std::size_t& count) const {
        const Index p = vertex_patch_[j];
        if (p == kNoIndex ||
            std::find(patches.begin(), patches.begin() + count, p) != patches.begin() + count)
            return true;
        if (count == kMaxSides) return false;
        patches[count++] = p;
        return true;
    }

    /// The plane of `patch` through its gathered vertices. Near: only vertices off the bands,
    /// which lie on their surface; band vertices are what is to be corrected; and on a flat face
    /// (flat_faces()) whose gathered vertices do not all lie on one plane, the face's plane where
    /// at least half of them lie on it (to kFlatFaceScatter), or where they all lie within
    /// kOffFaceReach of it, on the side `off_face` allows: the rest are vertices the mesher put
    /// off the face. For the sides of a junction (EitherSide), the face's plane too where the
    /// vertices are fewer than a fit takes but all lie on it: beside a pocket's corner OpenVDB's
    /// bevels leave a face three vertices off the band within the rings gathered (stepped_block
    /// at 100 cells), and the vertex between the faces stayed off both. Not for a band vertex's
    /// own side: where a face's plane holds only part of it (the impeller's top, scalloped 0.1 mm
    /// below the plane its other vertices lie on), a vertex moved onto it left the surface (the
    /// impeller by OpenVDB, Edge F-score 0.570 -> 0.532).
    /// Midpoint: the plane of the whole patch where it has one (whole_patch_planes()).
    std::optional<PlaneFit> fit_side(Index patch, OffFace off_face, Scratch& scratch) const {
        if (has_whole_plane(patch)) return patch_plane_[patch];
        const Vec3 facing = collect_side_points(patch, scratch);
        const std::optional<PlaneFit> fit = trusted_fit(scratch.points, facing);
        if (!is_flat_face(patch) || (fit && fit->rms_distance <= on_plane_tolerance())) return fit;
        const Plane& face = flat_face_[patch]->plane;
        const double near = kFlatFaceScatter * rule_.grid.pitch;
        const auto on_face = [&](const Vec3& q) {
            return std::abs(face.signed_distance(q)) <= near;
        };
        const std::span<const Vec3> points = scratch.points;
        if (!fit) {
            const bool few_on_face = off_face == OffFace::EitherSide && !points.empty() &&
                                     std::all_of(points.begin(), points.end(), on_face);
            return few_on_face ? face_plane_near(patch, points) : fit;
        }
        const auto on = std::count_if(points.begin(), points.end(), on_face);
        if (2 * static_cast<std::size_t>(on) >= points.size())
            return face_plane_near(patch, points);
        const double reach = kOffFaceReach * rule_.grid.pitch;
        const double behind =
            off_face == OffFace::InFront ? kBehindFaceReach * rule_.grid.pitch : reach;
        const bool within = std::all_of(points.begin(), points.end(), [&](const Vec3& q) {
            const double d = face.signed_distance(q);
            return d >= -behind && d <= reach;
        });
        return within ? face_plane_near(patch, points) : fit;
    }

    /// Flat face `patch`'s plane (flat_faces()) as a side whose vertices near the vertex are
    /// `points` (not empty): with_centroid_near().
    PlaneFit face_plane_near(Index patch, std::span<const Vec3> points) const {
        return with_centroid_near(*flat_face_[patch], points);
    }

    /// Midpoint: `patch`'s whole plane (whole_patch_planes()) as a side of the vertex whose
    /// vertices scratch holds: with_centroid_near() of the patch's among them within the fit
    /// rings. On stepped_block turned at 100 cells the top face's centroid lay in its pocket,
    /// and its convex edges with the pocket's walls were taken for concave: 71 band vertices,
    /// most of them the top's beside the pocket, found no point and stayed on their stairs
    /// (Edge F-score 0.60 -> 0.74).
    PlaneFit whole_plane_near(Index patch, Scratch& scratch) const {
        collect_side_points(patch, scratch, scratch.fit_reached);
        if (scratch.points.empty()) return *patch_plane_[patch];
        return with_centroid_near(*patch_plane_[patch], scratch.points);
    }

    /// `fit` with its centroid that of `points` (not empty), brought onto its plane. A whole
    /// face's centroid may lie anywhere, and bounds_solid() reads a side's centroid as a point
    /// of it beside the edge: a flange ringing a hub has its centroid on the axis, behind the
    /// hub's plane, and its concave edge with the hub was taken for convex (spool turned by
    /// OpenVDB at 100 cells: 152 of the flanges' band vertices in front of them refused their
    /// face).
    static PlaneFit with_centroid_near(PlaneFit fit, std::span<const Vec3> points) {
        Vec3 mean = Vec3::Zero();
        for (const Vec3& q : points) mean += q;
        fit.centroid = fit.plane.projection(mean / static_cast<double>(points.size()));
        return fit;
    }

    /// Near: whether `plane` is flat face `patch`'s plane (flat_faces()), as fit_side() gives it.
    bool is_face_plane(Index patch, const Plane& plane) const {
        if (!is_flat_face(patch)) return false;
        const Plane& face = flat_face_[patch]->plane;
        return face.normal == plane.normal && face.offset == plane.offset;
    }

    /// Near: whether `patch` is a flat face (flat_faces()).
    bool is_flat_face(Index patch) const {
        return !flat_face_.empty() && flat_face_[patch].has_value();
    }

    /// Midpoint: whether `patch` has a plane as a whole (whole_patch_planes()).
    bool has_whole_plane(Index patch) const {
        return !patch_plane_.empty() && patch_plane_[patch].has_value();
    }

    /// Midpoint: per patch, the plane of all its vertices off the bands at their input places,
    /// where they scatter about it as midpoints of one plane's crossings do; none elsewhere. A
    /// midpoint lies off the true crossing along its grid edge by up to half a pitch, about
    /// evenly spread where a face runs off the grid axes, so it lies off the face by u n_a for
    /// u uniform in [-h/2, h/2] and n_a the normal's component along the edge: its mean square
    /// is h^2 n_a^2 / 12. Fitted over the whole face, those errors average out (the plane is off
    /// by about their root mean square over the root of the count); fitted over three rings,
    /// as elsewhere, the planes of neighbouring vertices part by a tenth of a pitch and leave
    /// the face stepped. A curved patch scatters more than that about any plane (its sag), or
    /// a patch that took in part of another face, and keeps the fits around each vertex. The
    /// mean square alone misses that on a face across a grid axis, whose midpoints all lie at
    /// one offset (no spread, where the uniform model expects h^2 / 12): there the bound each
    /// midpoint keeps, |n_a| h / 2 from the face, tells (mech: a patch of 1,167 vertices about
    /// a plane within a degree of an axis plane, 87 of them up to 2.8 pitches beyond it).
    std::vector<std::optional<PlaneFit>> whole_patch_planes() const {
        const std::vector<std::vector<Index>> members = off_band_members();
        std::vector<std::optional<PlaneFit>> planes(members.size());
        for_each_index(members.size(), 1,
                       [&](std::size_t p) { planes[p] = whole_patch_plane(members[p]); });
        return planes;
    }

    /// Near: per patch id, the plane most of its vertices off the bands lie on, to
    /// kFlatFaceScatter (fit_plane_of_most()), where there is one: a flat face, whose vertices a
    /// mesher may have put off it beside its edges; none on a curved patch. Taken for the whole
    /// face, not around each vertex: there a few vertices of a curved face may lie on a plane by
    /// chance (down a bore of radius 3.4 pitches along a grid axis, surface nets' columns; with
    /// the plane most of the points around each vertex lay on, cone_part aligned at 100 cells
    /// had its Edge Chamfer Distance 8.1e-5 -> 4.1e-4). Bound: a pass over the vertices, and per
    /// patch a plane fit and at most about seven more.
    std::vector<std::optional<PlaneFit>> flat_faces() const {
        const std::vector<std::vector<Index>> members = off_band_members();
        std::vector<std::optional<PlaneFit>> flat(members.size());
        const auto min_points = static_cast<std::size_t>(options_.min_fit_points);
        const double exact = kFlatFaceScatter * rule_.grid.pitch;
        for_each_index(members.size(), 1, [&](std::size_t p) {
            if (members[p].size() < min_points) return;
            std::vector<Vec3> points;
            const Vec3 facing = points_of(members[p], current_.mesh.positions, points);
            const std::optional<PlaneFit> fit = fit_plane(points, facing);
            if (!fit) return;
            std::vector<Vec3> kept;
            flat[p] = fit->rms_distance <= exact
                          ? fit
                          : fit_plane_of_most(points, facing, *fit, exact, min_points, kept);
        });
        return flat;
    }

    /// The places of `vertices` in `positions`, into `points`; gives the sum of their normals,
    /// the side a plane fitted to them faces.
    Vec3 points_of(const std::vector<Index>& vertices, const std::vector<Vec3>& positions,
                   std::vector<Vec3>& points) const {
        points.clear();
        points.reserve(vertices.size());
        Vec3 facing = Vec3::Zero();
        for (Index v : vertices) {
            points.push_back(positions[v]);
            facing += current_.normals.vertex[v];
        }
        return facing;
    }

    /// Per patch id, its vertices off the bands, ascending. Bound: one pass over the vertices.
    std::vector<std::vector<Index>> off_band_members() const {
        Index patches = 0;
        for (Index p : vertex_patch_) {
            if (p != kNoIndex) patches = std::max(patches, p + 1);
        }
        std::vector<std::vector<Index>> members(patches);
        for (Index v = 0; v < vertex_patch_.size(); ++v) {
            if (vertex_patch_[v] != kNoIndex && !in_band_[v])
                members[vertex_patch_[v]].push_back(v);
        }
        return members;
    }

    std::optional<PlaneFit> whole_patch_plane(const std::vector<Index>& vertices) const {
        if (vertices.size() < kMinWholePatchPoints) return std::nullopt;
        std::vector<Vec3> points;
        const Vec3 facing = points_of(vertices, input_, points);
        const std::optional<PlaneFit> fit = fit_plane(points, facing);
        if (!fit) return std::nullopt;
        double expected = 0.0;   // the mean square of the midpoints' distances to the face
        std::size_t beyond = 0;  // midpoints farther from it than their edge lets them be
        const double h = rule_.grid.pitch;
        for (Index v : vertices) {
            const int axis = grid_edge_axis(input_[v]);
            if (axis < 0) return std::nullopt;  // not a midpoint mesh's vertex
            const double along = fit->plane.normal[axis];
            expected += along * along;
            const double d = std::abs(fit->plane.signed_distance(input_[v]));
            beyond += d > 0.5 * h * std::abs(along) + kWholePatchFitError * h;
        }
        const bool across_an_axis = fit->plane.normal.cwiseAbs().maxCoeff() > kAcrossAnAxisCosine;
        std::optional<PlaneFit> plane = fit;
        double sag_share = kSagShare;
        if (across_an_axis && static_cast<double>(beyond) >
                                  kWholePatchBeyondShare * static_cast<double>(vertices.size())) {
            plane = plane_within_edges(vertices, points, *fit);
            if (!plane) return std::nullopt;
            sag_share = kWithinEdgesSagShare;
        }
        expected *= h * h / 12.0 / static_cast<double>(vertices.size());
        const double square = plane->rms_distance * plane->rms_distance;
        if (!(square <= kWholePatchScatter * expected + 1e-6 * h * h)) return std::nullopt;
        if (is_bent(points, *plane, sag_share)) return std::nullopt;
        return plane;
    }

    /// Midpoint, a patch across a grid axis whose least-squares plane `fit` leaves some of its
    /// vertices (`points`, their input places) beyond their grid edges: the plane nearest `fit`
    /// that passes within every vertex's edge (off it by at most |n_a| h / 2, n_a the normal's
    /// component along the edge), where there is one to kWholePatchFitError h; none elsewhere (a
    /// patch that took in part of another face). Near a grid plane a face's midpoints lie on
    /// few levels in long treads, and over a small patch the least-squares plane tilts by
    /// degrees: on hex_prism turned at 100 cells a pocket wall 8.6 degrees off a grid plane
    /// broke into patches of 64 to 124 vertices, their planes 3 degrees off the wall with 6 to 14
    /// vertices beyond their edges each, and the wall kept its stairs (Edge F-score 0.709; with
    /// these planes, 2 degrees off, 0.832). The edges pin the plane where the mean does not: a
    /// riser between two treads lies within a pitch of where the face crosses the grid plane.
    /// Found as the least squares of the violations, the whole fit kept at kWithinEdgesWeight so
    /// that the nearest such plane is the one found: an active-set iteration (the violated bounds
    /// taken as targets, a 3 x 3 solve each pass) until the set stays the same, at most
    /// kWithinEdgesPasses passes.
    std::optional<PlaneFit> plane_within_edges(const std::vector<Index>& vertices,
                                               std::span<const Vec3> points,
                                               const PlaneFit& fit) const {
        const double h = rule_.grid.pitch;
        const Eigen::Matrix3d frame = tangent_frame(fit.plane.normal);
        const std::size_t n = points.size();
        // Per point: (u, v, 1) in the plane's frame (in pitches), its height over the plane,
        // and how far off the face its grid edge lets it be.
        std::vector<Eigen::Vector3d> row(n);
        std::vector<double> height(n), bound(n);
        std::vector<int> axis(n);
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3 local = frame.transpose() * (points[i] - fit.centroid);
            row[i] = Eigen::Vector3d(local.x() / h, local.y() / h, 1.0);
            height[i] = local.z();
            axis[i] = grid_edge_axis(input_[vertices[i]]);
            bound[i] = 0.5 * h * std::abs(fit.plane.normal[axis[i]]);
        }
        Eigen::Vector3d height_over = Eigen::Vector3d::Zero();  // slopes and offset of the plane
        std::vector<signed char> side(n, 0), last(n, 2);        // beyond which bound, if any
        for (int pass = 0; pass < kWithinEdgesPasses; ++pass) {
            for (std::size_t i = 0; i < n; ++i) {
                const double off = height[i] - row[i].dot(height_over);
                side[i] = off > bound[i] ? 1 : (off < -bound[i] ? -1 : 0);
            }
            if (side == last) break;
            last = side;
            Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
            Eigen::Vector3d moment = Eigen::Vector3d::Zero();
            for (std::size_t i = 0; i < n; ++i) {
                const double weight = side[i] == 0 ? kWithinEdgesWeight : 1.0 + kWithinEdgesWeight;
                const double target = (kWithinEdgesWeight * height[i] +
                                       (side[i] == 0 ? 0.0 : height[i] - side[i] * bound[i])) /
                                      weight;
                normal_matrix += weight * row[i] * row[i].transpose();
                moment += weight * target * row[i];
            }
            height_over = normal_matrix.ldlt().solve(moment);
        }
        const Vec3 normal =
            (frame * Vec3(-height_over.x() / h, -height_over.y() / h, 1.0)).normalized();
        const Vec3 origin = fit.centroid + height_over.z() * frame.col(2);
        double square = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const double d = normal.dot(points[i] - origin);
            const double allowed = 0.5 * h * std::abs(normal[axis[i]]);
            if (std::abs(d) > allowed + kWholePatchFitError * h) return std::nullopt;
            square += d * d;
        }
        PlaneFit within;
        within.plane = {normal, normal.dot(origin)};
        within.centroid = within.plane.projection(fit.centroid);
        within.rms_distance = std::sqrt(square / static_cast<double>(n));
        return within;
    }

    /// Whether the points scatter about their plane `fit` mostly by its sag: a quadratic height
    /// over the plane takes out more than kSagShare of their mean square, and more than
    /// (kMinSag h)^2 (below that the plane is as good as the surface; on planes whose midpoints
    /// all lie on them, rounding alone parts the two fits). A flat face's midpoints scatter in
    /// stairs no quadratic follows.
    bool is_bent(std::span<const Vec3> points, const PlaneFit& fit,
                 double sag_share = kSagShare) const {
        const std::optional<Bend> bend = bend_of(points, fit);
        // (kSagShare * rms) * rms, not kSagShare * square: rounded as before, the same verdicts.
        return bend && bend->sag > sag_share * fit.rms_distance * fit.rms_distance &&
               bend->sag > least_sag();
    }

    /// (kMinSag h)^2: the least mean square a bent surface must take out of its points'
    /// distances to their plane.
    double least_sag() const {
        const double h = rule_.grid.pitch;
        return kMinSag * kMinSag * h * h;
    }

    /// A quadratic height over a plane, and the mean square it takes out of the points'
    /// distances to the plane.
    struct Bend {
        HeightFit surface;
        double sag = 0.0;
    };

    /// The quadratic height over the points' plane `fit`; none where they lie within
    /// least_sag() of the plane (mean square): a plane this close needs no surface fitted to say
    /// so (most fits of a midpoint mesh of an axis-aligned part, whose faces' midpoints lie on
    /// their planes; is_bent()'s verdicts the same to the bit), or where no quadratic fits them.
    std::optional<Bend> bend_of(std::span<const Vec3> points, const PlaneFit& fit) const {
        const double square = fit.rms_distance * fit.rms_distance;
        if (!(square > least_sag())) return std::nullopt;
        const std::optional<HeightFit> bent = fit_height_quadric(points, fit.plane, fit.centroid);
        if (!bent) return std::nullopt;
        return Bend{*bent, square - bent->rms_distance * bent->rms_distance};
    }

    /// Midpoint, patch scope: a vertex of a patch with no whole plane (whole_patch_planes())
    /// whose vertices around lie on a bent face (bent_face()): the point where its grid edge
    /// meets that face's quadratic height. Cylinders, cones and spheres of a few pitches and
    /// more in radius; segmentation breaks their stairs into strips, each with a plane of its
    /// own, and vertices moved onto those planes left the strips' borders creases over 30
    /// degrees (spool at 100 cells, aligned: 3,837 mm of crease against about 740 mm of true
    /// edge, 2,300 mm of it on its hub, bore and rims). The face is fitted to all vertices within
    /// the fit rings where no band vertex is among them, else to the patch's own: a strip's
    /// vertices alone span too little of its curve. None elsewhere: the vertex takes a plane, as
    /// before.
    std::optional<Vec3> point_on_bent_face(Index v, Scratch& scratch) const {
        if (rule_.placement != VertexPlacement::Midpoint || rule_.scope != FitScope::Patches ||
            vertex_patch_[v] == kNoIndex || has_whole_plane(vertex_patch_[v]))
            return std::nullopt;
        gather_fit_rings(v, scratch);
        const bool near_band = std::any_of(scratch.reached.begin(), scratch.reached.end(),
                                           [&](Index j) { return in_band_[j] != 0; });
        const Vec3 facing = near_band ? collect_side_points(vertex_patch_[v], scratch)
                                      : collect_reached_points(scratch);
        const std::optional<HeightFit> surface = bent_face(scratch.points, facing);
        return surface ? along_edge_onto(v, *surface) : std::nullopt;
    }

    /// Into scratch.points every vertex gathered; gives the sum of their normals.
    Vec3 collect_reached_points(Scratch& scratch) const {
        scratch.points.clear();
        Vec3 facing = Vec3::Zero();
        for (Index j : scratch.reached) {
            scratch.points.push_back(current_.mesh.positions[j]);
            facing += current_.normals.vertex[j];
        }
        return facing;
    }

    /// Midpoint: the quadratic height of the points where they lie on a bent face: within the
    /// midpoint scatter of a plane (max_scatter_) that the height bends away from by more than
    /// least_sag() (mean square taken out), scattering about the height by no more than
    /// midpoints do (kBentNoise), curving by at most kBentMaxCurvature. None elsewhere.
    std::optional<HeightFit> bent_face(std::span<const Vec3> points, const Vec3& facing) const {
        if (points.size() < static_cast<std::size_t>(options_.min_fit_points)) return std::nullopt;
        const std::optional<PlaneFit> fit = fit_plane(points, facing);
        if (!fit || fit->rms_distance > max_scatter_) return std::nullopt;
        const std::optional<Bend> bend = bend_of(points, *fit);
        if (!bend || !(bend->sag > least_sag())) return std::nullopt;
        const double h = rule_.grid.pitch;
        double expected = 0.0;  // the mean square midpoint error across the plane
        for (const Vec3& p : points) {
            const int axis = grid_edge_axis(p);
            if (axis < 0) return std::nullopt;  // not a midpoint mesh's vertex
            expected += fit->plane.normal[axis] * fit->plane.normal[axis];
        }
        expected *= h * h / 12.0 / static_cast<double>(points.size());
        const HeightFit& surface = bend->surface;
        if (!(surface.rms_distance * surface.rms_distance <= kBentNoise * expected))
            return std::nullopt;
        // The height's second derivatives [[2 c3, c4], [c4, 2 c5]] / scale^2: its largest
        // principal curvature in size is |their mean| + the half spread of the two.
        const Eigen::Vector<double, 6>& c = surface.coefficients;
        const double curvature = (std::abs(c[3] + c[5]) + std::hypot(c[3] - c[5], c[4])) /
                                 (surface.scale * surface.scale);
        if (!(curvature * h <= kBentMaxCurvature)) return std::nullopt;
        return surface;
    }

    /// Midpoint: where v's grid edge meets `surface`, by Newton steps along the edge from v's
    /// place (at most kEdgeNewtonSteps; a quadratic height, so a few), brought within the edge.
    /// None where the edge runs along the surface or v's input place is on no grid edge.
    std::optional<Vec3> along_edge_onto(Index v, const HeightFit& surface) const {
        const int axis = grid_edge_axis(input_[v]);
        if (axis < 0) return std::nullopt;
        const double h = rule_.grid.pitch;
        Vec3 y = current_.mesh.positions[v];
        SurfaceValue s = surface.evaluate(y);
        for (int step = 0; step < kEdgeNewtonSteps; ++step) {
            const double slope = s.gradient[axis];
            if (!(std::abs(slope) > 1e-3 * s.gradient.norm())) return std::nullopt;
            const double change = s.value / slope;
            y[axis] -= change;
            s = surface.evaluate(y);
            if (std::abs(change) < 1e-9 * h) break;
        }
        return within_edge(v, axis, y, s.gradient.normalized());
    }

    /// Into scratch.points the gathered vertices of `patch` (near: off the bands, whose
    /// vertices lie off their face), of the first `count` gathered (all by default); gives the
    /// sum of their normals, the side the fit faces.
    Vec3 collect_side_points(Index patch, Scratch& scratch,
                             std::size_t count = std::numeric_limits<std::size_t>::max()) const {
        scratch.points.clear();
        Vec3 facing = Vec3::Zero();
        const std::size_t end = std::min(count, scratch.reached.size());
        for (std::size_t i = 0; i < end; ++i) {
            const Index j = scratch.reached[i];
            if (vertex_patch_[j] != patch) continue;
            if (rule_.placement == VertexPlacement::Near && in_band_[j]) continue;
            scratch.points.push_back(current_.mesh.positions[j]);
            facing += current_.normals.vertex[j];
        }
        return facing;
    }

    std::optional<PlaneFit> trusted_fit(std::span<const Vec3> points, const Vec3& facing) const {
        if (points.size() < static_cast<std::size_t>(options_.min_fit_points)) return std::nullopt;
        std::optional<PlaneFit> fit = fit_plane(points, facing);
        if (!fit || fit->rms_distance > max_scatter_) return std::nullopt;
        if (rule_.placement == VertexPlacement::Near && fit->rms_distance <= on_plane_tolerance() &&
            in_plane_spread(points, *fit) < kMinExactFitSpread)
            return std::nullopt;
        if (rule_.placement == VertexPlacement::Midpoint && is_bent(points, *fit))
            return std::nullopt;
        return fit;
    }

    /// Whether x lies on the part of side a's plane that bounds the solid next to side b: behind
    /// b's plane where the edge between them is convex (a's vertices lie behind b's plane), in
    /// front of it where it is concave.
    static bool bounds_solid(const Vec3& x, const Side& a, const Side& b, double tolerance) {
        const bool convex = b.fit.plane.signed_distance(a.fit.centroid) < 0.0;
        const double d = b.fit.plane.signed_distance(x);
        return convex ? d <= tolerance : d >= -tolerance;
    }

    /// The candidate point on side a's plane for v: the foot of the perpendicular from its
    /// current place (near), or where its input grid edge meets the plane (midpoint). None if
    /// the edge runs along the plane or v's input place is on no grid edge.
    std::optional<Vec3> point_on(Index v, const Side& a) const {
        const Vec3& x = current_.mesh.positions[v];
        if (rule_.placement != VertexPlacement::Midpoint)
            return nearest_in_cell(x, a.fit.plane, input_[v]);
        const int axis = grid_edge_axis(input_[v]);
        if (axis < 0) return std::nullopt;
        const double along = a.fit.plane.normal[axis];
        if (std::abs(along) < 1e-3) return std::nullopt;  // the edge runs along the plane
        Vec3 y = x;
        y[axis] -= a.fit.plane.signed_distance(x) / along;
        return within_edge(v, axis, y, a.fit.plane.normal);
    }

    /// y (on v's grid edge's line, on a surface of unit `normal` there) brought within the
    /// edge, short of its ends, where it lies beyond them by at most kEdgeOvershoot; else y as
    /// it is (out of reach). The true crossing lies on the edge, but a fitted plane off by a
    /// hundredth of a pitch meets the line of an edge that runs nearly along it well beyond:
    /// the edge's end is then the nearest the crossing can be. Short of the end: the crossings
    /// of the edges around a grid node near the face make a small triangle, which has the
    /// orientation of the crossings' signs only while each stays off the node; on the node it
    /// has no area, and the harm check undoes its vertices' moves (stepped_block turned: 702
    /// moves undone against 33). How far short: to the surface moved kEdgeEndMargin h |normal|
    /// (its largest component) off the node, so the crossings around one node stay on a plane
    /// parallel to the surface. Each kEdgeEndMargin h along its own edge, they made a small
    /// triangle turned by up to 55 degrees from the face, and the slivers beside it creases of
    /// 30 degrees and more (stepped_block turned at 100 cells: 164 mm of false crease beyond a
    /// pitch from every true edge, Edge F-score 0.79 -> 0.85).
    Vec3 within_edge(Index v, int axis, Vec3 y, const Vec3& normal) const {
        const double h = rule_.grid.pitch;
        const double low = rule_.grid.origin[axis] +
                           h * std::floor((input_[v][axis] - rule_.grid.origin[axis]) / h);
        if (y[axis] < low - kEdgeOvershoot * h || y[axis] > low + (1.0 + kEdgeOvershoot) * h)
            return y;
        const Vec3 size = normal.cwiseAbs();
        const double margin =
            size[axis] > 0.0 ? std::min(0.5, kEdgeEndMargin * size.maxCoeff() / size[axis]) : 0.5;
        y[axis] = std::clamp(y[axis], low + margin * h, low + (1.0 - margin) * h);
        return y;
    }

    /// The point of `plane` nearest x within the grid cell of input place `from`: the foot of
    /// the perpendicular where that is in the cell, else the point nearest_to_cell() finds.
    /// A vertex of a cell the edge crosses may sit nearer another face's plane than its own, so
    /// its foot on its own plane can leave the cell where the plane, crossing the cell, does
    /// not. None if the point found, brought into the cell, is farther than a thousandth of a
    /// pitch off the plane (the plane misses the cell).
    std::optional<Vec3> nearest_in_cell(const Vec3& x, const Plane& plane, const Vec3& from) const {
        const Vec3 y = plane.projection(x);
        if (within_reach(from, y)) return y;
        return nearest_within(x, plane, cell_of(from));
    }

    /// The point of `plane` nearest x within `box` (nearest_to_cell(), brought into the box);
    /// none if that is farther than a thousandth of a pitch off the plane (the plane misses it).
    std::optional<Vec3> nearest_within(const Vec3& x, const Plane& plane, const Cell& box) const {
        const Vec3 y = box.clamp(nearest_to_cell(
            x, [&](const Vec3& p) { return plane.projection(p); }, box));
        if (std::abs(plane.signed_distance(y)) > on_plane_tolerance()) return std::nullopt;
        return y;
    }

    Cell cell_of(const Vec3& from) const {
        const double h = rule_.grid.pitch;
        const Vec3 low =
            rule_.grid.origin + h * ((from - rule_.grid.origin) / h).array().floor().matrix();
        return {low, low + Vec3::Constant(h)};
    }

    /// The two of three planes nearest x first, their patches with them; gives 2. A vertex
    /// between patches that meets them only beyond its ring lies in a band several faces wide
    /// (a dual mesher's bevel across a concave edge, near/concave_bevels.h), and a third face
    /// within the fit rings is where the bevel ends (the part's side), not a corner of it: the
    /// junction of all three took the bevel's last cells towards the corner, out of reach. (Not
    /// called where the corner is what the vertex stands for: corner_within_reach().)
    static std::size_t nearest_two_first(const Vec3& x, std::array<PlaneFit, 3>& planes,
                                         std::array<Index, kMaxSides>& patches, Fits& fits) {
        std::size_t farthest = 0;
        for (std::size_t i = 1; i < 3; ++i) {
            if (std::abs(planes[i].plane.signed_distance(x)) >
                std::abs(planes[farthest].plane.signed_distance(x)))
                farthest = i;
        }
        std::swap(planes[farthest], planes[2]);
        std::swap(patches[farthest], patches[2]);
        std::swap(fits[farthest], fits[2]);
        return 2;
    }

    /// Whether v lies in front of all three planes and they meet in a sharp corner within its
    /// reach (junction_reach()): a vertex in the empty corner of a pocket, where OpenVDB rounds
    /// three concave edges over one to two cells (stepped_block at 100 cells, the pocket's floor
    /// corners: the vertex 1.2 mm = 2 pitches from the corner, in a cell no face crosses). Where
    /// a bevel ends at the part's side, its last vertex lies on or behind the side's plane, and
    /// stays on the edge (taken to the corner, it left the L-block's concave edge without a
    /// crease along its last pitch).
    bool corner_within_reach(Index v, const std::array<PlaneFit, 3>& planes) const {
        const Vec3& x = current_.mesh.positions[v];
        const bool in_front_of_all =
            std::all_of(planes.begin(), planes.end(), [&](const PlaneFit& fit) {
                return fit.plane.signed_distance(x) > on_plane_tolerance();
            });
        if (!in_front_of_all) return false;
        const std::optional<Junction> corner = sharp_junction(planes);
        return corner && junction_reach(input_[v], planes).holds(corner->projection(x));
    }

    /// Whether v's surface turns along the junction line of planes a and b, not across it: its
    /// normal runs along the line by more than kMaxNormalAlongJunction (a third face there).
    bool turns_along(Index v, const Plane& a, const Plane& b) const {
        const Vec3 along = a.normal.cross(b.normal).normalized();
        return std::abs(current_.normals.vertex[v].normalized().dot(along)) >
               kMaxNormalAlongJunction;
    }

    /// How far a vertex between patches may go towards the junction of `planes`: its input
    /// cell, or where no plane crosses that cell, the cells around it too. A cell-mean vertex
    /// in a cell the surface does not cross was not placed by the surface but by a distance
    /// the mesher got wrong by more than a cell: OpenVDB's, interpolated across a concave
    /// corner (near/concave_bevels.h), puts the middle vertex of its bevel in the empty corner,
    /// a cell beyond the edge's own.
    Cell junction_reach(const Vec3& from, std::span<const PlaneFit> planes) const {
        const Cell cell = cell_of(from);
        const bool crossed = std::any_of(planes.begin(), planes.end(), [&](const PlaneFit& fit) {
            return cell.crossed_by(fit.plane);
        });
        if (crossed) return cell;
        return cell.with_neighbours(rule_.grid.pitch);
    }

    /// The limit of Dykstra's alternating projections from x onto `cell` and onto an affine set
    /// (a plane, line or point: `project` gives its point nearest a point), at most
    /// kProjectionRounds rounds, as a point of the set: its point nearest x within the cell
    /// where the set meets the cell, else near its point nearest the cell.
    template <class Project>
    static Vec3 nearest_to_cell(const Vec3& x, const Project& project, const Cell& cell) {
        constexpr int kProjectionRounds = 64;
        Vec3 p = Vec3::Zero(), q = Vec3::Zero();
        Vec3 y = x;
        for (int round = 0; round < kProjectionRounds; ++round) {
            const Vec3 z = cell.clamp(y + p);
            const Vec3 p_next = y + p - z;
            const Vec3 next = project(z + q);
            const Vec3 q_next = z + q - next;
            // A round that leaves its terms as they were, to the bit, leaves them so in every
            // round after: the rounds left would give the same y.
            if (same_bits(p_next, p) && same_bits(q_next, q) && same_bits(next, y)) break;
            p = p_next, q = q_next, y = next;
        }
        return y;
    }

    static bool same_bits(const Vec3& a, const Vec3& b) {
        return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0;
    }

    /// The axis of the grid edge x lies on: its one coordinate off the grid lines; -1 if x is not
    /// on a grid edge.
    int grid_edge_axis(const Vec3& x) const {
        int axis = -1;
        for (int a = 0; a < 3; ++a) {
            const double u = (x[a] - rule_.grid.origin[a]) / rule_.grid.pitch;
            if (std::abs(u - std::round(u)) > 1e-4) {
                if (axis >= 0) return -1;
                axis = a;
            }
        }
        return axis;
    }

    /// Whether y is a place the mesher could have meant for input place x: within x's cell
    /// (near), within x's grid edge (midpoint: the move runs along it). Cells are closed, a
    /// thousandth of a pitch wider.
    bool within_reach(const Vec3& x, const Vec3& y) const {
        const double slack = 1e-3;
        for (int a = 0; a < 3; ++a) {
            const double cell = std::floor((x[a] - rule_.grid.origin[a]) / rule_.grid.pitch);
            const double u = (y[a] - rule_.grid.origin[a]) / rule_.grid.pitch - cell;
            if (u < -slack || u > 1.0 + slack) return false;
        }
        return true;
    }

    /// Near, on a curved side (its vertices scatter about their plane): the point over v of a
    /// second-order surface fitted to them, where that fits them at least twice as closely as
    /// the plane and the point lies in v's cell. A plane fitted to three rings of a cylinder of
    /// radius r leaves it by about (3 h)^2 / 2 r at the band.
    std::optional<Vec3> point_on_curved(Index v, const Side& own, Scratch& scratch) const {
        if (rule_.placement != VertexPlacement::Near || own.patch == kNoIndex ||
            own.fit.rms_distance <= on_plane_tolerance())
            return std::nullopt;
        collect_side_points(own.patch, scratch, scratch.fit_reached);
        const std::optional<HeightFit> fit =
            fit_height_quadric(scratch.points, own.fit.plane, current_.mesh.positions[v]);
        if (!fit || !(fit->rms_distance < 0.5 * own.fit.rms_distance) ||
            !within_reach(input_[v], fit->point))
            return std::nullopt;
        return fit->point;
    }

    /// Near: where v's own side is its flat face's plane (flat_faces()) and that plane misses v's
    /// input cell, the point of it nearest v within the cells around (as junction_reach()). A
    /// cell-mean vertex in a cell its face does not cross was put there by a distance the mesher
    /// got wrong by more than a cell: OpenVDB's beside a concave edge (on stepped_block turned at
    /// 100 cells, a band vertex 0.74 of a pitch in front of its face, and the points placed from
    /// the plane through it 0.9 of a pitch off the edge). None elsewhere, and where the point
    /// found is off the plane.
    std::optional<Vec3> point_on_face_beyond_cell(Index v, const Side& own) const {
        if (rule_.placement != VertexPlacement::Near || !is_face_plane(own.patch, own.fit.plane))
            return std::nullopt;
        return nearest_beyond_cell(current_.mesh.positions[v], flat_face_[own.patch]->plane,
                                   input_[v]);
    }

    /// Where `face` misses the grid cell of input place `from`, its point nearest x within the
    /// cells around (point_on_face_beyond_cell()); none where it crosses the cell, or misses
    /// those too.
    std::optional<Vec3> nearest_beyond_cell(const Vec3& x, const Plane& face,
                                            const Vec3& from) const {
        const Cell cell = cell_of(from);
        if (cell.crossed_by(face)) return std::nullopt;
        return nearest_within(x, face, cell.with_neighbours(rule_.grid.pitch));
    }

    /// v's place on its own patch's plane (sides[0]), if within reach of its input place (or
    /// beyond it, point_on_face_beyond_cell()) and bounding the solid next to every other side.
    /// Only its own: the feature normals the edge points are then placed with are those of v's own
    /// patch (eq. 5.1), so a band vertex moved onto another side's plane, though nearer, would meet
    /// them off its plane (on the CAD corpus: Edge F-score 0.530 -> 0.680 on hex_prism aligned,
    /// docs/results.md).
    std::optional<Vec3> point_on_own_side(Index v, std::span<const Side> sides,
                                          Scratch& scratch) const {
        const double tolerance = on_plane_tolerance();
        const Side& own = sides[0];
        std::optional<Vec3> y = point_on_curved(v, own, scratch);
        if (!y) y = point_on(v, own);
        if (y && !within_reach(input_[v], *y)) y.reset();
        if (!y) y = point_on_face_beyond_cell(v, own);
        if (!y) return std::nullopt;
        const bool valid = std::all_of(sides.begin() + 1, sides.end(), [&](const Side& b) {
            return bounds_solid(*y, own, b, tolerance);
        });
        return valid ? y : std::nullopt;
    }

    /// A band vertex with no point on its own side: the nearest point within its reach on
    /// another side's surface (near: its second-order surface where curved, point_on_curved();
    /// its plane where that is flat within the junction scatter; midpoint: where its grid edge
    /// meets the side's plane) that bounds the solid next to every other side, its own among
    /// them; and that side's patch, which the moved mesh's segmentation gives the vertex
    /// (patches_after_moves(); midpoint: the moved mesh is segmented anew). A midpoint vertex
    /// segmentation gave one face may sit on a grid edge that crosses the other: the mesher put
    /// it there because the edge crosses the boundary, wherever that is. OpenVDB puts the vertex of
    /// a cell a convex edge crosses behind both faces, nearer the other face than its own where the
    /// edge runs off the grid axes; its own plane's foot then lies past the edge, and where
    /// keep_one_sided_junctions() also withdrew its junction it stayed off the surface, a crease
    /// each side of it (hex_prism turned at 100 cells: 21 of the top face's band vertices 0.2 to
    /// 0.4 pitches behind it). Left in its own patch on the other face, its edge points were
    /// placed with its own face's feature normal and the faces to its own patch's vertices were
    /// not cut (docs/method.md). A curved side's plane put a vertex of mech's floor 0.1 mm above
    /// it, and two split pieces beside it turned over.
    FacePoint point_on_other_side(Index v, std::span<const Side> sides, Scratch& scratch) const {
        const Vec3& x = current_.mesh.positions[v];
        FacePoint nearest;
        for (std::size_t i = 1; i < sides.size(); ++i) {
            std::optional<Vec3> y = point_on_curved(v, sides[i], scratch);
            if (!y &&
                (rule_.placement == VertexPlacement::Midpoint ||
                 sides[i].fit.rms_distance <= options_.max_junction_scatter * rule_.grid.pitch))
                y = point_on(v, sides[i]);
            if (!y || !within_reach(input_[v], *y)) continue;
            const bool valid = std::all_of(sides.begin(), sides.end(), [&](const Side& b) {
                return &b == &sides[i] || bounds_solid(*y, sides[i], b, on_plane_tolerance());
            });
            if (valid) nearest.offer(x, *y, sides[i].patch);
        }
        return nearest;
    }

    const InputSurface& current_;
    const std::vector<Vec3>& input_;
    const std::vector<Index>& vertex_patch_;
    MoveRule rule_;
    VertexMoveOptions options_;
    double max_scatter_;
    Neighbours neighbours_;
    std::vector<std::uint8_t> in_band_;  ///< per vertex: a corner of an edge or corner triangle
    /// Midpoint, patch scope: per patch id, whole_patch_planes(); empty otherwise.
    std::vector<std::optional<PlaneFit>> patch_plane_;
    /// Near, patch scope: per patch id, flat_faces(); empty otherwise.
    std::vector<std::optional<PlaneFit>> flat_face_;
    /// Near, patch scope: the cells that hold an input vertex in a band or between patches
    /// (band_places()); none otherwise.
    std::optional<OccupiedCells> occupied_;
};

void validate(const Grid& grid, const VertexMoveOptions& options) {
    if (!(grid.pitch > 0.0) || !std::isfinite(grid.pitch))
        throw InvalidInput("vertex moves: the grid pitch must be positive");
    if (options.fit_rings < 1 || options.fit_rings > 8 || options.other_side_fit_rings < 1 ||
        options.other_side_fit_rings > 8 || options.min_fit_points < 3 ||
        !(options.max_scatter_near >= 0.0) || !(options.max_scatter_midpoint >= 0.0) ||
        !(options.max_junction_scatter >= 0.0) ||
        !(options.junction_angle_deg >= 0.0 && options.junction_angle_deg < 180.0))
        throw InvalidInput(
            "vertex moves: fit rings and other side fit rings in [1, 8], at least 3 fit points, "
            "scatter limits not negative, junction angle in [0, 180)");
}

/// Sets moved, moved_count and largest_move from the positions against the input's.
void recount(const std::vector<Vec3>& input, VertexMoves& moves) {
    moves.moved.assign(input.size(), 0);
    moves.moved_count = 0;
    moves.largest_move = 0.0;
    for (std::size_t v = 0; v < input.size(); ++v) {
        if (moves.position[v] == input[v]) continue;
        moves.moved[v] = 1;
        ++moves.moved_count;
        moves.largest_move = std::max(moves.largest_move, (moves.position[v] - input[v]).norm());
    }
}

/// Whether every face around v lies on one side once v is on a junction: its two other
/// corners of one patch, or one of them on a junction too. A face with its other corners on
/// two sides would stand across the edge, and the split point on its crossing edge would cut
/// it into pieces turned some 90 degrees from it and from v's own side's normal, which the
/// guard refuses: the face is left a chamfer facet, and its edges false crease.
bool one_sided_around(const Mesh& mesh, const Connectivity& connectivity,
                      const std::vector<Index>& vertex_patch,
                      const std::vector<std::uint8_t>& on_junction, Index v) {
    for (Index f : connectivity.faces_around(v)) {
        const Triangle& t = mesh.triangles[f];
        const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
        const Index a = t[(k + 1) % 3], b = t[(k + 2) % 3];
        if (on_junction[a] || on_junction[b]) continue;
        if (vertex_patch[a] == kNoIndex || vertex_patch[a] != vertex_patch[b]) return false;
    }
    return true;
}

/// Withdraws the junction of the vertices that `may_take` marks (they are also marked in
/// `on_junction`, with the vertices between patches that go onto theirs) until every vertex
/// still marked is one_sided_around(): the largest such set, whatever the order (a vertex
/// withdrawn only takes away from its neighbours' one-sidedness), so the same on any thread
/// count. Off the grid axes a band winds, and its faces meet the edge at every angle: there a
/// patch vertex moved onto the junction often leaves a face across the edge, and the rule
/// without this test lost more than it gained (surface-nets Edge F-score, stepped_block
/// rotated 0.813 -> 0.767). Bound: each vertex is withdrawn at most once, each withdrawal
/// queues its ring.
void keep_one_sided_junctions(const Mesh& mesh, const Connectivity& connectivity,
                              const std::vector<Index>& vertex_patch,
                              std::vector<std::uint8_t>& may_take,
                              std::vector<std::uint8_t>& on_junction) {
    std::vector<Index> queue;
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
        if (may_take[v]) queue.push_back(v);
    }
    while (!queue.empty()) {
        const Index v = queue.back();
        queue.pop_back();
        if (!may_take[v] || one_sided_around(mesh, connectivity, vertex_patch, on_junction, v))
            continue;
        may_take[v] = on_junction[v] = 0;
        for_each_ring_vertex(mesh, connectivity, v, [&](Index j) {
            if (may_take[j]) queue.push_back(j);
        });
    }
}

}  // namespace

VertexMoves plan_vertex_moves(const InputSurface& current, const std::vector<Vec3>& input,
                              const std::vector<Index>& vertex_patch,
                              const BandClassification& bands, const MoveRule& rule,
                              const VertexMoveOptions& options) {
    const Mesh& mesh = current.mesh;
    VertexMoves moves{mesh.positions, std::vector<std::uint8_t>(mesh.vertex_count(), 0), 0, 0.0};
    if (input.size() != mesh.vertex_count())
        throw InvalidInput("vertex moves: one input position per vertex is needed");
    if (rule.placement != VertexPlacement::Exact) {
        validate(rule.grid, options);
        const MovePlanner planner(current, input, vertex_patch, bands, rule, options);
        std::vector<std::uint8_t> on_junction(mesh.vertex_count(), 0);
        std::vector<std::uint8_t> may_take(mesh.vertex_count(), 0);
        // Per thread, the vertices with a junction point and the point: a few percent of the
        // vertices, where an array of every vertex's was 24 bytes a vertex of fresh memory.
        using JunctionPoints = std::vector<std::pair<Index, Vec3>>;
        tbb::enumerable_thread_specific<JunctionPoints> junctions;
        tbb::enumerable_thread_specific<Scratch> scratches;
        tbb::enumerable_thread_specific<std::vector<std::pair<Index, Index>>> other_patches;
        tbb::parallel_for(
            tbb::blocked_range<Index>(0, static_cast<Index>(mesh.vertex_count()), 2048),
            [&](const auto& range) {
                Scratch& scratch = scratches.local();
                JunctionPoints& found = junctions.local();
                for (Index v = range.begin(); v != range.end(); ++v) {
                    const Target t = planner.target(v, scratch);
                    if (t.point) moves.position[v] = *t.point;
                    if (t.point && t.other_patch != kNoIndex)
                        other_patches.local().emplace_back(v, t.other_patch);
                    on_junction[v] = t.between_patches && t.point.has_value();
                    if (!t.junction) continue;
                    found.emplace_back(v, *t.junction);
                    may_take[v] = on_junction[v] = 1;
                }
            });
        keep_one_sided_junctions(mesh, current.connectivity, vertex_patch, may_take, on_junction);
        for (const JunctionPoints& found : junctions) {
            for (const auto& [v, point] : found) {
                if (may_take[v]) moves.position[v] = point;
            }
        }
        for (const auto& found : other_patches) {
            for (const auto& [v, patch] : found) {
                if (!may_take[v]) moves.onto_other_patch.emplace_back(v, patch);
            }
        }
        std::sort(moves.onto_other_patch.begin(), moves.onto_other_patch.end());
    }
    recount(input, moves);
    return moves;
}

std::vector<Index> patches_after_moves(std::vector<Index> vertex_patch, const VertexMoves& moves) {
    for (const auto& [v, patch] : moves.onto_other_patch) {
        if (moves.moved[v]) vertex_patch[v] = patch;
    }
    return vertex_patch;
}

Mesh moved_mesh(const Mesh& mesh, const VertexMoves& moves) {
    Mesh moved;
    moved.positions = moves.position;
    moved.triangles = mesh.triangles;
    return moved;
}

namespace {

/// Takes back the moves of the corners of `faces` (input face indices) and recounts.
void undo_moves_of(const Mesh& mesh, const std::vector<Index>& faces, VertexMoves& moves) {
    for (Index f : faces) {
        for (Index v : mesh.triangles[f]) {
            moves.moved[v] = 0;
            moves.position[v] = mesh.positions[v];
        }
    }
    recount(mesh.positions, moves);
}

}  // namespace

VertexMoves recounted(const std::vector<Vec3>& input, VertexMoves moves) {
    recount(input, moves);
    return moves;
}

VertexMoves without_turned_over_faces(const Mesh& mesh, const Connectivity& connectivity,
                                      VertexMoves moves) {
    // Bound: every pass that does not end the loop takes back at least one move.
    while (moves.moved_count > 0) {
        std::vector<Index> turned;
        for (Index f : faces_with_moved_corner(mesh, connectivity, moves.moved)) {
            const Triangle& t = mesh.triangles[f];
            const auto& x = mesh.positions;
            const auto& y = moves.position;
            const Vec3 before = triangle_normal(x[t[0]], x[t[1]], x[t[2]]);
            if (!before.isZero(0.0) &&
                before.dot(triangle_normal(y[t[0]], y[t[1]], y[t[2]])) <= 0.0)
                turned.push_back(f);
        }
        if (turned.empty()) break;
        undo_moves_of(mesh, turned, moves);
    }
    return moves;
}

}  // namespace resharp
