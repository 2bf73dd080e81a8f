#include "resharp/near/concave_bevels.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "resharp/core/parallel.h"
#include "resharp/near/tangent_plane.h"
#include "resharp/surfaces/plane_fit.h"

namespace resharp {
namespace {

/// How far from the edge (in pitches) a bevel's vertices may lie: OpenVDB's lie on a plane
/// across the corner, its outer rows about 1.4 pitches from the edge (one cell along the face,
/// one out), and a strip wider than two pitches is a face the part may have.
constexpr double kBevelReach = 2.0;
/// The share of a bevel's vertices that may fail that: where it ends at a side of the part, its
/// last vertices lie in the corner with that side, beside or behind the edge's faces.
constexpr double kBevelEndShare = 0.1;
/// A strip two or three rows wide has at most about four vertices per pitch of its length, and
/// its length is up to sqrt(2) times its bounding box's diagonal where it turns a corner (mech's
/// floor bevel along two walls of a pocket, one patch round its rounded corner: 452 vertices on
/// a diagonal of 109 pitches): at most this many per pitch of that diagonal.
constexpr double kStripRows = 6.0;
/// A side that is not flat as a whole (a pocket's walls, one patch around its rounded corners)
/// is fitted by its vertices within this many pitches of the strip's long axis: the rows beside
/// the bevel, past the band, where the wall runs straight along it.
constexpr double kLocalSideReach = 5.0;
/// The plane most of a side's vertices lie on holds them to this share of the scatter allowed a
/// flat fit: a face's vertices off the bands lie on it to rounding, and the full scatter would
/// let the test of two lines (ten times this apart) take three rows of a face for two.
constexpr double kOnSidePlane = 0.1;
/// How many rings around a bevel's vertex a curved side's nearest vertex off the bands is sought
/// in: a bevel two or three rows wide has the faces' rows beside it within three.
constexpr int kCurvedSideRings = 4;

/// Per patch id, whether it could be a strip a few rows wide: no more vertices than kStripRows
/// per pitch of its bounding box's diagonal (a face of side L has about (L / h)^2), and enough
/// for a plane. Cheap (a pass over the vertices), and true of far fewer patches than the fits it
/// spares: on mech by surface nets the fits of every patch cost restore() 3.6 % of its
/// instructions.
std::vector<std::uint8_t> strips(const InputSurface& current, const FeatureSegmentation& features,
                                 double h, std::size_t min_points) {
    const std::size_t patches = features.patch_count;
    std::vector<std::size_t> count(patches, 0);
    std::vector<Vec3> low(patches, Vec3::Constant(std::numeric_limits<double>::infinity()));
    std::vector<Vec3> high(patches, -low[0]);
    for (Index v = 0; v < current.mesh.vertex_count(); ++v) {
        const Index p = features.vertex_patch[v];
        if (p >= patches) continue;  // kNoIndex too
        ++count[p];
        low[p] = low[p].cwiseMin(current.mesh.positions[v]);
        high[p] = high[p].cwiseMax(current.mesh.positions[v]);
    }
    std::vector<std::uint8_t> strip(patches, 0);
    for (std::size_t p = 0; p < patches; ++p) {
        strip[p] = count[p] >= min_points && static_cast<double>(count[p]) <=
                                                 kStripRows * ((high[p] - low[p]).norm() / h + 1.0);
    }
    return strip;
}

/// The vertices of the patches flagged in `wanted` (all, and those off the bands: `in_band`
/// 0), by patch id; empty for the others. Bound: a pass over the vertices.
struct PatchMembers {
    std::vector<std::vector<Index>> all, off_band;
};

PatchMembers patch_members(const Mesh& mesh, const FeatureSegmentation& features,
                           const std::vector<std::uint8_t>& in_band,
                           const std::vector<std::uint8_t>& wanted) {
    PatchMembers m;
    m.all.resize(features.patch_count);
    m.off_band.resize(features.patch_count);
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
        const Index p = features.vertex_patch[v];
        if (p >= features.patch_count || !wanted[p]) continue;
        m.all[p].push_back(v);
        if (!in_band[v]) m.off_band[p].push_back(v);
    }
    return m;
}

/// Per patch id, the other patches that share a face with it, ascending. Bound: one pass over
/// the faces.
std::vector<std::vector<Index>> neighbouring_patches(const Mesh& mesh,
                                                     const FeatureSegmentation& features) {
    std::vector<std::vector<Index>> around(features.patch_count);
    for (const auto& t : mesh.triangles) {
        for (int a = 0; a < 3; ++a) {
            const Index p = features.vertex_patch[t[a]];
            const Index q = features.vertex_patch[t[(a + 1) % 3]];
            if (p == q || p == kNoIndex || q == kNoIndex) continue;
            if (p >= features.patch_count || q >= features.patch_count) continue;
            around[p].push_back(q);
        }
    }
    for (std::vector<Index>& list : around) {
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
    }
    return around;
}

/// The patches next to p and next to those, but p, ascending: the faces a bevel lies across.
/// Where the bevel is a few cells wide its cross-section may bend, and segmentation cut it in
/// two along its length (on a small L-block at pitch 0.5 mm, facets at 58 and 20 degrees to the
/// floor), each piece next to one of the faces only.
std::vector<Index> within_two_steps(const std::vector<std::vector<Index>>& around, Index p) {
    std::vector<Index> reached = around[p];
    for (Index q : around[p]) reached.insert(reached.end(), around[q].begin(), around[q].end());
    std::sort(reached.begin(), reached.end());
    reached.erase(std::unique(reached.begin(), reached.end()), reached.end());
    reached.erase(std::remove(reached.begin(), reached.end(), p), reached.end());
    return reached;
}

/// The places of the vertices listed, and the sum of their normals (the side a plane of them
/// faces).
struct PlacedPoints {
    std::vector<Vec3> points;
    Vec3 facing = Vec3::Zero();
};

PlacedPoints placed(const InputSurface& current, const std::vector<Index>& vertices) {
    PlacedPoints placed;
    placed.points.reserve(vertices.size());
    for (Index v : vertices) {
        placed.points.push_back(current.mesh.positions[v]);
        placed.facing += current.normals.vertex[v];
    }
    return placed;
}

/// The plane of the vertices listed, where they lie on it within `scatter` (mm); facing their
/// normals' side. None with fewer than `min_points`.
std::optional<PlaneFit> flat_plane(const InputSurface& current, const std::vector<Index>& vertices,
                                   std::size_t min_points, double scatter) {
    if (vertices.size() < min_points) return std::nullopt;
    const PlacedPoints p = placed(current, vertices);
    std::optional<PlaneFit> fit = fit_plane(p.points, p.facing);
    if (!fit || fit->rms_distance > scatter) return std::nullopt;
    return fit;
}

/// What a plane of most of a patch's vertices is taken for (plane_of_most()).
enum class MostOf {
    /// A bevel: the plane its vertices scatter about within the flat fit's scatter once the
    /// farthest are left out (its ends, where it bends round a pocket's rounded corners; its
    /// cross-section, where OpenVDB bends it by a few degrees between its rows). Two rows of a
    /// bevel are a plane.
    Bevel,
    /// A face beside a bevel (a pocket's walls, straight along it but curved round the corners):
    /// the plane most of its vertices lie on to kOnSidePlane of that scatter, not two lines
    /// (fit_plane_of_most()).
    Face,
};

/// flat_plane() of the vertices listed, or where they scatter more, the plane most of them lie
/// on, taken as `kind` says.
std::optional<PlaneFit> plane_of_most(const InputSurface& current,
                                      const std::vector<Index>& vertices, std::size_t min_points,
                                      double scatter, MostOf kind) {
    if (vertices.size() < min_points) return std::nullopt;
    const PlacedPoints p = placed(current, vertices);
    const std::optional<PlaneFit> all = fit_plane(p.points, p.facing);
    if (!all || all->rms_distance <= scatter) return all;
    std::vector<Vec3> kept;
    return kind == MostOf::Bevel
               ? fit_plane_trimmed(p.points, p.facing, *all, scatter, min_points, kept)
               : fit_plane_of_most(p.points, p.facing, *all, kOnSidePlane * scatter, min_points,
                                   kept);
}

/// The long axis of a strip where it lies on its plane: the line through the centroid of its
/// vertices within `tolerance` of `plane` along their largest spread, and how far along it they
/// reach. A bevel's ends, where it bends round a pocket's rounded corners, are left out, and with
/// them the curved walls there.
struct StripAxis {
    Vec3 centre = Vec3::Zero();
    Vec3 direction = Vec3::UnitX();
    double from = 0.0, to = 0.0;

    /// Whether x lies within `reach` of the axis, between the strip's ends.
    bool near(const Vec3& x, double reach) const {
        const Vec3 off = x - centre;
        const double along = off.dot(direction);
        return along >= from && along <= to && (off - along * direction).norm() <= reach;
    }
};

/// `tolerance`: at least the rms distance of the vertices from `plane`.
StripAxis strip_axis(const Mesh& mesh, const std::vector<Index>& vertices, const Plane& plane,
                     double tolerance) {
    std::vector<Vec3> on_plane;
    for (Index v : vertices) {
        if (std::abs(plane.signed_distance(mesh.positions[v])) <= tolerance)
            on_plane.push_back(mesh.positions[v]);
    }
    // Not empty: `plane` is fitted to the vertices, so some lie within their rms of it.
    StripAxis axis;
    for (const Vec3& x : on_plane) axis.centre += x;
    axis.centre /= static_cast<double>(on_plane.size());
    Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
    for (const Vec3& x : on_plane) spread += (x - axis.centre) * (x - axis.centre).transpose();
    axis.direction = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(spread).eigenvectors().col(2);
    axis.from = std::numeric_limits<double>::infinity();
    axis.to = -axis.from;
    for (const Vec3& x : on_plane) {
        const double along = (x - axis.centre).dot(axis.direction);
        axis.from = std::min(axis.from, along);
        axis.to = std::max(axis.to, along);
    }
    return axis;
}

/// The plane of the vertices listed within `reach` of the strip's axis: the plane most of them
/// lie on, as a face's (plane_of_most(), MostOf::Face).
std::optional<PlaneFit> flat_plane_near(const InputSurface& current,
                                        const std::vector<Index>& vertices, const StripAxis& axis,
                                        double reach, std::size_t min_points, double scatter) {
    std::vector<Index> near;
    std::copy_if(vertices.begin(), vertices.end(), std::back_inserter(near),
                 [&](Index v) { return axis.near(current.mesh.positions[v], reach); });
    return plane_of_most(current, near, min_points, scatter, MostOf::Face);
}

/// A corner whose faces meet at an acute angle holds a bevel farther from its edge, where the
/// corner is as wide as a right angle's at the reach: by the ratio of the half-angles' sines,
/// at most this (a corner opening at 41 degrees or less).
constexpr double kMaxAcuteReachScale = 2.0;

/// The two faces of a concave edge: their planes, and the edge's line.
struct ConcaveCorner {
    PlaneFit a, b;
    Vec3 on_line = Vec3::Zero();  ///< the point of the line nearest the origin
    Vec3 direction = Vec3::UnitX();
    /// How much farther than at a right angle a bevel lies from the edge (kMaxAcuteReachScale):
    /// OpenVDB's across the corners of hex_prism's triangular pocket, which open at 60 degrees,
    /// has its outer rows 2.3 pitches from the edge at 100 cells.
    double reach_scale = 1.0;

    /// Whether x lies in front of both planes (in the corner's empty side, to `tolerance`) and
    /// within `reach` of the line (scaled by reach_scale).
    bool holds(const Vec3& x, double tolerance, double reach) const {
        if (a.plane.signed_distance(x) < -tolerance || b.plane.signed_distance(x) < -tolerance)
            return false;
        const Vec3 off = x - on_line;
        return (off - off.dot(direction) * direction).norm() <= reach_scale * reach;
    }

    /// Whether the corners of face t all lie in the corner (holds()), not all on one of its
    /// planes (within `tolerance`): a row of faces between a bevel and a face, not the face's own.
    bool holds_face(const Mesh& mesh, const std::array<Index, 3>& t, double tolerance,
                    double reach) const {
        const auto all = [&](auto&& test) {
            return std::all_of(t.begin(), t.end(),
                               [&](Index v) { return test(mesh.positions[v]); });
        };
        const auto on = [&](const Plane& plane) {
            return [&](const Vec3& x) { return std::abs(plane.signed_distance(x)) <= tolerance; };
        };
        return all([&](const Vec3& x) { return holds(x, tolerance, reach); }) &&
               !all(on(a.plane)) && !all(on(b.plane));
    }
};

/// The corner of two patches of planes a and b where they meet at a concave edge: their normals
/// part by more than the junction angle, a's vertices lie in front of b's plane and b's in front
/// of a's; none otherwise.
std::optional<ConcaveCorner> concave_corner(const PlaneFit& a, const PlaneFit& b,
                                            double min_angle_cosine) {
    const Vec3& na = a.plane.normal;
    const Vec3& nb = b.plane.normal;
    if (na.dot(nb) >= min_angle_cosine) return std::nullopt;
    if (b.plane.signed_distance(a.centroid) < 0.0 || a.plane.signed_distance(b.centroid) < 0.0)
        return std::nullopt;
    ConcaveCorner corner{a, b};
    corner.direction = na.cross(nb).normalized();
    // The corner opens at pi minus the normals' angle; the sine of half that is the cosine of
    // half the normals' angle.
    const double half_opening_sine = std::sqrt(0.5 * (1.0 + na.dot(nb)));
    corner.reach_scale = std::clamp(std::sqrt(0.5) / half_opening_sine, 1.0, kMaxAcuteReachScale);
    // The point of the line nearest the origin: on both planes and normal to the line.
    Eigen::Matrix3d rows;
    rows << na.transpose(), nb.transpose(), corner.direction.transpose();
    corner.on_line = rows.partialPivLu().solve(Vec3(a.plane.offset, b.plane.offset, 0.0));
    return corner;
}

/// Whether all but kBevelEndShare of the vertices lie in front of both of the corner's planes
/// (in its empty side) and within `reach` of its line.
bool mostly_in_corner(const InputSurface& current, const std::vector<Index>& vertices,
                      const ConcaveCorner& corner, double tolerance, double reach) {
    const auto in_corner = std::count_if(vertices.begin(), vertices.end(), [&](Index v) {
        return corner.holds(current.mesh.positions[v], tolerance, reach);
    });
    return static_cast<double>(in_corner) >=
           (1.0 - kBevelEndShare) * static_cast<double>(vertices.size());
}

/// The patch with the most faces around v (the first met of those tied), none if no face
/// around it has one. `counts`: scratch, reused from vertex to vertex.
Index most_faces_around(const Connectivity& connectivity, const std::vector<Index>& face_patch,
                        Index v, std::vector<std::pair<Index, int>>& counts) {
    count_ring_patches(connectivity, face_patch, v, counts);
    Index best = kNoIndex;
    int most = 0;
    for (const auto& [p, n] : counts) {
        if (n > most) best = p, most = n;
    }
    return best;
}

/// A bevel found: the faces it holds (a whole strip's, or a piece's) and the corner it lies
/// across, where that is one of two planes (none along a curved face).
struct Bevel {
    std::vector<Index> faces;
    std::optional<ConcaveCorner> corner;
};

/// The faces to dissolve with the bevels: their own, and those reached from them across edges
/// that lie in the bevel's corner off its faces (ConcaveCorner::holds_face()), whatever their
/// patch. OpenVDB's bevel across mech's pocket floor edges (y = 14, z = 19 at pitch 0.5 mm) runs
/// floor, a row at 16 degrees, the bevel's two rows at 45, a row at 74, wall: the row at 74
/// degrees grew into the patch of the next wall round the pocket's corner, and left there it gave
/// the bevel's vertices three patches around them, one with no plane nearby: they stayed where
/// they were, with no crease left along the edge. Bound: each face once.
std::vector<std::uint8_t> faces_in_bevel_corners(const InputSurface& current,
                                                 const std::vector<Index>& face_patch,
                                                 const std::vector<Bevel>& bevels, double tolerance,
                                                 double reach) {
    const Mesh& mesh = current.mesh;
    std::vector<std::uint8_t> taken(mesh.face_count(), 0);
    std::vector<std::pair<Index, const ConcaveCorner*>> open;
    for (const Bevel& bevel : bevels) {
        for (Index f : bevel.faces) {
            taken[f] = 1;
            if (bevel.corner) open.emplace_back(f, &*bevel.corner);
        }
    }
    while (!open.empty()) {
        const auto [f, corner] = open.back();
        open.pop_back();
        for (Index k = 0; k < 3; ++k) {
            const Index twin = current.connectivity.twin[3 * f + k];
            if (twin == kNoIndex) continue;
            const Index g = face_of(twin);
            if (taken[g] || face_patch[g] == kNoIndex) continue;
            if (corner->holds_face(mesh, mesh.triangles[g], tolerance, reach)) {
                taken[g] = 1;
                open.emplace_back(g, corner);
            }
        }
    }
    return taken;
}

/// Judges strips, or pieces of them, as bevels: the sides of a strip are the patches within two
/// steps of it, each with its plane as a whole, or where it has none (a pocket's walls round its
/// rounded corners), the plane of its vertices along the strip (flat_plane_near()); a bevel faces
/// the same way as both of two sides that meet at a concave edge, and all but kBevelEndShare of
/// its vertices lie in their corner within kBevelReach pitches.
class BevelJudge {
public:
    /// `strip`: per patch id, the patches to judge (strips()).
    BevelJudge(const InputSurface& current, const FeatureSegmentation& features,
               const std::vector<std::uint8_t>& in_band, const std::vector<std::uint8_t>& strip,
               const VertexMoveOptions& options, double h)
        : current_(current),
          vertex_patch_(features.vertex_patch),
          in_band_(in_band),
          h_(h),
          scatter_(options.max_scatter_near * h),
          min_points_(static_cast<std::size_t>(options.min_fit_points)),
          min_angle_cosine_(std::cos(options.junction_angle_deg * std::numbers::pi / 180.0)),
          sides_(features.patch_count),
          reached_in_(current.mesh.vertex_count(), 0) {
        const std::vector<std::vector<Index>> around = neighbouring_patches(current.mesh, features);
        std::vector<std::uint8_t> wanted(features.patch_count, 0);
        for (std::size_t p = 0; p < features.patch_count; ++p) {
            if (!strip[p]) continue;
            sides_[p] = within_two_steps(around, static_cast<Index>(p));
            for (Index q : sides_[p]) wanted[q] = 1;
        }
        members_ = patch_members(current.mesh, features, in_band, wanted);
        side_plane_.resize(features.patch_count);
        for_each_index(features.patch_count, 1, [&](std::size_t p) {
            if (wanted[p])
                side_plane_[p] = flat_plane(current, members_.off_band[p], min_points_, scatter_);
        });
    }

    /// The corner that the strip of patch p, or a piece of it (its `vertices`, on `plane`), lies
    /// across as a bevel; none if it is no bevel. Bound: a plane fit for each side with none as
    /// a whole, and a test per pair of sides.
    std::optional<ConcaveCorner> corner_across(Index p, const std::vector<Index>& vertices,
                                               const PlaneFit& plane) const {
        const std::vector<Index>& next = sides_[p];
        const StripAxis axis = strip_axis(current_.mesh, vertices, plane.plane, scatter_);
        std::vector<std::optional<PlaneFit>> side(next.size());
        for (std::size_t i = 0; i < next.size(); ++i) {
            side[i] = side_plane_[next[i]]
                          ? side_plane_[next[i]]
                          : flat_plane_near(current_, members_.off_band[next[i]], axis,
                                            kLocalSideReach * h_, min_points_, scatter_);
        }
        const Vec3& own = plane.plane.normal;
        for (std::size_t i = 0; i < next.size(); ++i) {
            for (std::size_t j = i + 1; j < next.size(); ++j) {
                if (!side[i] || !side[j]) continue;
                // The bevel faces the same way as both faces: it lies across their corner.
                if (own.dot(side[i]->plane.normal) <= 0.0 || own.dot(side[j]->plane.normal) <= 0.0)
                    continue;
                const std::optional<ConcaveCorner> corner =
                    concave_corner(*side[i], *side[j], min_angle_cosine_);
                if (corner &&
                    mostly_in_corner(current_, vertices, *corner, scatter_, kBevelReach * h_))
                    return corner;
            }
        }
        return std::nullopt;
    }

    /// Whether the strip of patch p lies across the concave edge of a flat side and a curved one
    /// (a side with no plane as a whole, read near each vertex by curved_side_plane()): all but
    /// kBevelEndShare of its vertices face the way of both, lie in front of both and within
    /// kBevelReach pitches of where they meet, as ConcaveCorner::holds() tests against two
    /// planes. A dual mesher bevels such an edge as it does one of two planes: OpenVDB's across
    /// spool's hub where it meets a flange (h = 0.4 mm) puts three vertices on a cone at 45
    /// degrees 0.3 to 0.5 mm from the circle, which segmentation took for a face of its own.
    /// Bound: per pair of a flat and a curved side, per vertex a walk of kCurvedSideRings rings.
    /// One strip at a time (curved_side_plane()).
    bool across_curved_corner(Index p, const std::vector<Index>& vertices) const {
        const double allowed = kBevelEndShare * static_cast<double>(vertices.size());
        // The flat sides that most of the vertices face and lie in front of: a test of each
        // vertex against a plane, where the curved side's asks for a walk round it.
        std::vector<Index> flats;
        for (Index flat : sides_[p]) {
            if (!side_plane_[flat]) continue;
            const auto facing = std::count_if(vertices.begin(), vertices.end(), [&](Index v) {
                return faces_flat_side(v, *side_plane_[flat]);
            });
            if (static_cast<double>(vertices.size() - facing) <= allowed) flats.push_back(flat);
        }
        if (flats.empty()) return false;
        std::vector<CurvedSideNear> near(vertices.size());
        for (Index curved : sides_[p]) {
            if (side_plane_[curved] || members_.off_band[curved].size() < min_points_) continue;
            std::fill(near.begin(), near.end(), CurvedSideNear{});
            for (Index flat : flats) {
                std::size_t missed = 0;
                for (std::size_t i = 0; i < vertices.size(); ++i) {
                    missed += !in_curved_corner(vertices[i], *side_plane_[flat], curved, near[i]);
                    if (static_cast<double>(missed) > allowed) break;
                }
                if (static_cast<double>(missed) <= allowed) return true;
            }
        }
        return false;
    }

    /// The plane of a strip's or a piece's vertices as a bevel's (MostOf::Bevel).
    std::optional<PlaneFit> bevel_plane(const std::vector<Index>& vertices) const {
        return plane_of_most(current_, vertices, min_points_, scatter_, MostOf::Bevel);
    }

private:
    /// Whether v faces the way of the flat side and lies in front of it (to the scatter).
    bool faces_flat_side(Index v, const PlaneFit& flat) const {
        return current_.normals.vertex[v].dot(flat.plane.normal) > 0.0 &&
               flat.plane.signed_distance(current_.mesh.positions[v]) >= -scatter_;
    }

    /// A curved side's tangent plane near a vertex (curved_side_plane()), sought once.
    struct CurvedSideNear {
        bool sought = false;
        std::optional<PlaneFit> tangent;
    };

    /// Whether v faces the way of the flat side and of the curved side's tangent plane near it
    /// (`near`: sought here where it was not), and the two meet at a concave edge whose corner
    /// holds v (ConcaveCorner::holds()). The flat side's centroid is taken at v's foot on it: a
    /// flange ringing a hub has its centroid on the axis, behind the hub.
    bool in_curved_corner(Index v, const PlaneFit& flat, Index curved, CurvedSideNear& near) const {
        if (!faces_flat_side(v, flat)) return false;
        const Vec3& x = current_.mesh.positions[v];
        const Vec3& normal = current_.normals.vertex[v];
        if (!near.sought) near = {true, curved_side_plane(v, curved)};
        if (!near.tangent || normal.dot(near.tangent->plane.normal) <= 0.0) return false;
        const PlaneFit flat_here{flat.plane, flat.plane.projection(x), flat.rms_distance};
        const std::optional<ConcaveCorner> corner =
            concave_corner(flat_here, *near.tangent, min_angle_cosine_);
        return corner && corner->holds(x, scatter_, kBevelReach * h_);
    }

    /// The tangent plane of patch `curved` at its vertex off the bands nearest v (by rings, then
    /// by distance) within kCurvedSideRings rings: its vertex normal there (a cylinder of 20
    /// pitches' radius leaves that plane by d^2 / 2r, a fortieth of a pitch a pitch away, about a
    /// bevel's width). None where it has none there.
    /// Bound: the vertices within those rings. Not for two threads at once: it marks what it
    /// reaches in the judge.
    std::optional<PlaneFit> curved_side_plane(Index v, Index curved) const {
        // Each walk marks what it reached with a number of its own, so no mark is cleared.
        if (++walk_ == 0) std::fill(reached_in_.begin(), reached_in_.end(), walk_++);
        std::vector<Index>& reached = reached_;
        reached.assign(1, v);
        reached_in_[v] = walk_;
        std::size_t ring_begin = 0;
        for (int ring = 0; ring < kCurvedSideRings; ++ring) {
            const std::size_t ring_end = reached.size();
            for (std::size_t i = ring_begin; i < ring_end; ++i) {
                for_each_ring_vertex(current_.mesh, current_.connectivity, reached[i],
                                     [&](Index j) {
                                         if (reached_in_[j] == walk_) return;
                                         reached_in_[j] = walk_;
                                         reached.push_back(j);
                                     });
            }
            const std::optional<PlaneFit> tangent = tangent_plane_at_nearest(
                current_, vertex_patch_, in_band_, std::span(reached).subspan(ring_end),
                current_.mesh.positions[v], curved);
            if (tangent) return tangent;
            ring_begin = ring_end;
        }
        return std::nullopt;
    }

    const InputSurface& current_;
    const std::vector<Index>& vertex_patch_;
    const std::vector<std::uint8_t>& in_band_;
    double h_, scatter_;
    std::size_t min_points_;
    double min_angle_cosine_;
    std::vector<std::vector<Index>> sides_;
    PatchMembers members_;
    std::vector<std::optional<PlaneFit>> side_plane_;
    /// curved_side_plane()'s walks: per vertex (#V) the number of the walk that last reached it,
    /// the current walk's number, and what it reached.
    mutable std::vector<std::uint32_t> reached_in_;
    mutable std::uint32_t walk_ = 0;
    mutable std::vector<Index> reached_;
};

/// Normals within this angle (degrees) of a piece's first face keep to the piece: a bevel's rows
/// part by a few degrees, the legs of a bevel that turns a pocket's corner by 90.
constexpr double kPieceAngleDeg = 20.0;

/// The faces of `patch` (`faces`, ascending) in pieces: from its lowest face not yet in a piece,
/// the faces reached across its edges within the patch whose normals lie within kPieceAngleDeg of
/// that face's. A strip that turns a corner (mech's floor bevel along the walls x = 32 and y = 52
/// round the pocket's rounded corner, one patch) lies on no plane; each of its legs does. Bound:
/// each face of the patch once, found among them by bisection.
std::vector<std::vector<Index>> pieces_of(const InputSurface& current,
                                          const std::vector<Index>& face_patch,
                                          const std::vector<Index>& faces, Index patch) {
    const double min_cosine = std::cos(kPieceAngleDeg * std::numbers::pi / 180.0);
    std::vector<std::uint8_t> placed(faces.size(), 0);  // per entry of `faces`
    const auto entry = [&](Index f) {
        return static_cast<std::size_t>(std::lower_bound(faces.begin(), faces.end(), f) -
                                        faces.begin());
    };
    std::vector<std::vector<Index>> pieces;
    for (std::size_t s = 0; s < faces.size(); ++s) {
        if (placed[s]) continue;
        const Vec3& normal = current.normals.face[faces[s]];
        std::vector<Index> piece{faces[s]};
        placed[s] = 1;
        for (std::size_t i = 0; i < piece.size(); ++i) {
            for (Index k = 0; k < 3; ++k) {
                const Index twin = current.connectivity.twin[3 * piece[i] + k];
                if (twin == kNoIndex) continue;
                const Index g = face_of(twin);
                if (face_patch[g] != patch || current.normals.face[g].dot(normal) < min_cosine)
                    continue;
                const std::size_t e = entry(g);
                if (placed[e]) continue;
                placed[e] = 1;
                piece.push_back(g);
            }
        }
        pieces.push_back(std::move(piece));
    }
    return pieces;
}

/// The corners of the faces listed, each once, ascending.
std::vector<Index> corners_of(const Mesh& mesh, const std::vector<Index>& faces) {
    std::vector<Index> corners;
    for (Index f : faces)
        corners.insert(corners.end(), mesh.triangles[f].begin(), mesh.triangles[f].end());
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    return corners;
}

/// Takes the faces flagged in `taken` out of their patches in `features`, and gives a new patch
/// (the one with the most faces around it, none if no face around it has one) to each vertex of
/// a bevel's patch (`bevel`, per patch id) and each vertex that lost a face of its patch and has
/// none left around it; the others keep theirs (a vertex whose faces all lie in bands has the
/// patch whose plane it lies on, refine_border_labels()). In place: every patch is judged
/// before, and a vertex's new patch reads the faces' alone.
void dissolve(const InputSurface& current, const std::vector<std::uint8_t>& taken,
              const std::vector<std::uint8_t>& bevel, FeatureSegmentation& features) {
    // Per vertex, whether a face taken had its patch: flags, not a copy of the faces' patches.
    std::vector<std::uint8_t> lost(current.mesh.vertex_count(), 0);
    for (Index f = 0; f < current.mesh.face_count(); ++f) {
        if (!taken[f]) continue;
        for (Index v : current.mesh.triangles[f])
            lost[v] |=
                static_cast<std::uint8_t>(features.vertex_patch[v] == features.face_patch[f]);
        features.face_patch[f] = kNoIndex;
    }
    std::vector<std::pair<Index, int>> counts;
    for (Index v = 0; v < current.mesh.vertex_count(); ++v) {
        const Index p = features.vertex_patch[v];
        if (p == kNoIndex || p >= bevel.size() || !(lost[v] || bevel[p])) continue;
        const auto ring = current.connectivity.faces_around(v);
        const bool kept = std::any_of(ring.begin(), ring.end(),
                                      [&](Index f) { return features.face_patch[f] == p; });
        if (!kept)
            features.vertex_patch[v] =
                most_faces_around(current.connectivity, features.face_patch, v, counts);
    }
}

/// Of `faces` (ascending), those in none of bevels[from, ...).
std::vector<Index> faces_outside(const std::vector<Index>& faces, const std::vector<Bevel>& bevels,
                                 std::size_t from) {
    std::vector<Index> inside;
    for (std::size_t b = from; b < bevels.size(); ++b)
        inside.insert(inside.end(), bevels[b].faces.begin(), bevels[b].faces.end());
    std::sort(inside.begin(), inside.end());
    std::vector<Index> outside;
    std::set_difference(faces.begin(), faces.end(), inside.begin(), inside.end(),
                        std::back_inserter(outside));
    return outside;
}

/// The pieces (pieces_of()) of a strip that is no bevel as a whole that are bevels, into
/// `bevels`. Bound: per piece, a plane fit and BevelJudge::corner_across().
void add_bevel_pieces(const InputSurface& current, const std::vector<Index>& face_patch,
                      const BevelJudge& judge, Index patch, const std::vector<Index>& faces,
                      std::vector<Bevel>& bevels) {
    for (std::vector<Index>& piece : pieces_of(current, face_patch, faces, patch)) {
        const std::vector<Index> vertices = corners_of(current.mesh, piece);
        const std::optional<PlaneFit> plane = judge.bevel_plane(vertices);
        if (!plane) continue;
        const std::optional<ConcaveCorner> corner = judge.corner_across(patch, vertices, *plane);
        if (corner) bevels.push_back({std::move(piece), *corner});
    }
}

}  // namespace

BevelDissolution without_concave_bevels(const InputSurface& current, FeatureSegmentation features,
                                        const BandClassification& bands, const Grid& grid,
                                        const VertexMoveOptions& options) {
    const double h = grid.pitch;
    const double scatter = options.max_scatter_near * h;
    const auto min_points = static_cast<std::size_t>(options.min_fit_points);
    const std::size_t patches = features.patch_count;
    const std::vector<std::uint8_t> strip = strips(current, features, h, min_points);
    if (std::find(strip.begin(), strip.end(), 1) == strip.end()) return {std::move(features), 0};
    const std::vector<std::uint8_t> in_band = band_vertices(current.mesh, bands);
    const PatchMembers strips_members = patch_members(current.mesh, features, in_band, strip);
    const BevelJudge judge(current, features, in_band, strip, options, h);
    // A strip's plane as a bevel: of all its vertices (those off the bands run along its middle,
    // on one line, and a bevel's ends, where it meets the next one's at a corner, part from its
    // plane by a few hundredths of a pitch, or bend round a pocket's rounded corner).
    std::vector<std::optional<ConcaveCorner>> across(patches);
    for_each_index(patches, 1, [&](std::size_t p) {
        if (!strip[p]) return;
        const std::vector<Index>& vertices = strips_members.all[p];
        const std::optional<PlaneFit> plane = judge.bevel_plane(vertices);
        if (plane) across[p] = judge.corner_across(static_cast<Index>(p), vertices, *plane);
    });
    std::vector<std::vector<Index>> faces_of(patches);
    for (Index f = 0; f < current.mesh.face_count(); ++f) {
        const Index p = features.face_patch[f];
        if (p != kNoIndex && p < patches && strip[p]) faces_of[p].push_back(f);
    }
    std::vector<Bevel> bevels;
    std::vector<std::uint8_t> bevel(patches, 0);
    for (std::size_t p = 0; p < patches; ++p) {
        if (across[p]) {
            bevel[p] = 1;
            bevels.push_back({std::move(faces_of[p]), across[p]});
        } else if (strip[p]) {
            const std::size_t found = bevels.size();
            add_bevel_pieces(current, features.face_patch, judge, static_cast<Index>(p),
                             faces_of[p], bevels);
            if (!judge.across_curved_corner(static_cast<Index>(p), strips_members.all[p])) continue;
            bevel[p] = 1;
            std::vector<Index> rest = faces_outside(faces_of[p], bevels, found);
            if (!rest.empty()) bevels.push_back({std::move(rest), std::nullopt});
        }
    }
    BevelDissolution r{std::move(features), 0};
    r.bevels = bevels.size();
    if (r.bevels == 0) return r;
    dissolve(
        current,
        faces_in_bevel_corners(current, r.features.face_patch, bevels, scatter, kBevelReach * h),
        bevel, r.features);
    return r;
}

}  // namespace resharp
