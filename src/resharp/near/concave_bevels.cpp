#include "resharp/near/concave_bevels.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "resharp/core/parallel.h"
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
/// A strip two or three rows wide has at most about this many vertices per pitch of its length.
constexpr double kStripRows = 4.0;

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

/// The plane of the vertices listed, where they lie on it within `scatter` (mm); facing their
/// normals' side. None with fewer than `min_points`.
std::optional<PlaneFit> flat_plane(const InputSurface& current, const std::vector<Index>& vertices,
                                   std::size_t min_points, double scatter) {
    if (vertices.size() < min_points) return std::nullopt;
    std::vector<Vec3> points;
    points.reserve(vertices.size());
    Vec3 facing = Vec3::Zero();
    for (Index v : vertices) {
        points.push_back(current.mesh.positions[v]);
        facing += current.normals.vertex[v];
    }
    std::optional<PlaneFit> fit = fit_plane(points, facing);
    if (!fit || fit->rms_distance > scatter) return std::nullopt;
    return fit;
}

/// Whether patch `bevel` (its plane `own`) lies across the concave edge between two patches of
/// planes a and b: each two normals part by more than the junction angle but the bevel's faces
/// the same way as both (it lies across their corner), a's vertices in front of b's plane and b's
/// in front of a's (the edge is concave), and all but kBevelEndShare of the bevel's vertices in
/// front of both planes (in the corner's empty side) and within `reach` of their line.
bool lies_across(const InputSurface& current, const std::vector<Index>& bevel, const Plane& own,
                 const PlaneFit& a, const PlaneFit& b, double min_angle_cosine, double tolerance,
                 double reach) {
    const Vec3& na = a.plane.normal;
    const Vec3& nb = b.plane.normal;
    if (na.dot(nb) >= min_angle_cosine || own.normal.dot(na) <= 0.0 || own.normal.dot(nb) <= 0.0)
        return false;
    if (b.plane.signed_distance(a.centroid) < 0.0 || a.plane.signed_distance(b.centroid) < 0.0)
        return false;
    const Vec3 direction = na.cross(nb).normalized();
    // The point of the line nearest the origin: on both planes and normal to the line.
    Eigen::Matrix3d rows;
    rows << na.transpose(), nb.transpose(), direction.transpose();
    const Vec3 on_line = rows.partialPivLu().solve(Vec3(a.plane.offset, b.plane.offset, 0.0));
    const auto across = std::count_if(bevel.begin(), bevel.end(), [&](Index v) {
        const Vec3& x = current.mesh.positions[v];
        if (a.plane.signed_distance(x) < -tolerance || b.plane.signed_distance(x) < -tolerance)
            return false;
        const Vec3 off = x - on_line;
        return (off - off.dot(direction) * direction).norm() <= reach;
    });
    return static_cast<double>(across) >=
           (1.0 - kBevelEndShare) * static_cast<double>(bevel.size());
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

}  // namespace

BevelDissolution without_concave_bevels(const InputSurface& current, FeatureSegmentation features,
                                        const BandClassification& bands, const Grid& grid,
                                        const VertexMoveOptions& options) {
    const double h = grid.pitch;
    const double scatter = options.max_scatter_near * h;
    const auto min_points = static_cast<std::size_t>(options.min_fit_points);
    const double min_angle_cosine = std::cos(options.junction_angle_deg * std::numbers::pi / 180.0);
    const std::size_t patches = features.patch_count;
    const std::vector<std::uint8_t> strip = strips(current, features, h, min_points);
    if (std::find(strip.begin(), strip.end(), 1) == strip.end()) return {std::move(features), 0};
    // A strip's plane as a bevel: all its vertices (those off the bands run along its middle,
    // on one line, and a bevel's ends, where it meets the next one's at a corner, part from its
    // plane by a few hundredths of a pitch).
    const std::vector<std::uint8_t> in_band = band_vertices(current.mesh, bands);
    const PatchMembers strips_members = patch_members(current.mesh, features, in_band, strip);
    std::vector<std::optional<PlaneFit>> whole(patches);
    for_each_index(patches, 1, [&](std::size_t p) {
        if (strip[p]) whole[p] = flat_plane(current, strips_members.all[p], min_points, scatter);
    });
    const std::vector<std::vector<Index>> around = neighbouring_patches(current.mesh, features);
    // The faces a flat strip may lie across, each with its plane as a side (its vertices off
    // the bands, which lie on its face).
    std::vector<std::vector<Index>> sides(patches);
    std::vector<std::uint8_t> wanted(patches, 0);
    for (std::size_t p = 0; p < patches; ++p) {
        if (!whole[p]) continue;
        sides[p] = within_two_steps(around, static_cast<Index>(p));
        for (Index q : sides[p]) wanted[q] = 1;
    }
    const PatchMembers members = patch_members(current.mesh, features, in_band, wanted);
    std::vector<std::optional<PlaneFit>> side(patches);
    for_each_index(patches, 1, [&](std::size_t p) {
        if (wanted[p]) side[p] = flat_plane(current, members.off_band[p], min_points, scatter);
    });
    std::vector<std::uint8_t> dissolved(patches, 0);
    for_each_index(patches, 1, [&](std::size_t p) {
        if (!whole[p]) return;
        const std::vector<Index>& next = sides[p];
        for (std::size_t i = 0; i < next.size() && !dissolved[p]; ++i) {
            for (std::size_t j = i + 1; j < next.size() && !dissolved[p]; ++j) {
                if (!side[next[i]] || !side[next[j]]) continue;
                dissolved[p] =
                    lies_across(current, strips_members.all[p], whole[p]->plane, *side[next[i]],
                                *side[next[j]], min_angle_cosine, scatter, kBevelReach * h);
            }
        }
    });
    BevelDissolution r{std::move(features), 0};
    r.bevels = static_cast<std::size_t>(std::count(dissolved.begin(), dissolved.end(), 1));
    if (r.bevels == 0) return r;
    // In place: every patch is judged above, and a vertex's new patch reads the faces' alone.
    FeatureSegmentation& out = r.features;
    for (Index& p : out.face_patch) {
        if (p != kNoIndex && p < patches && dissolved[p]) p = kNoIndex;
    }
    std::vector<std::pair<Index, int>> counts;
    for (Index v = 0; v < current.mesh.vertex_count(); ++v) {
        const Index p = out.vertex_patch[v];
        if (p != kNoIndex && p < patches && dissolved[p])
            out.vertex_patch[v] =
                most_faces_around(current.connectivity, out.face_patch, v, counts);
    }
    return r;
}

}  // namespace resharp
