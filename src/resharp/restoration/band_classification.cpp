#include "resharp/restoration/band_classification.h"

#include <cmath>
#include <numbers>
#include <utility>

#include "resharp/restoration/feature_normals.h"
#include "resharp/segmentation/feature_segmentation.h"

namespace resharp {
namespace {

/// The role of face f given its half-edges' crossing flags.
BandRole role_of(const std::vector<std::uint8_t>& is_crossing, Index f) {
    const int crossing = is_crossing[3 * f] + is_crossing[3 * f + 1] + is_crossing[3 * f + 2];
    return crossing == 3 ? BandRole::Corner : crossing > 0 ? BandRole::Edge : BandRole::None;
}

/// Counts a face of `role` in b's totals (`add`) or takes it out of them.
void count_role(BandRole role, bool add, BandClassification& b) {
    if (role == BandRole::None) return;
    std::size_t& count = role == BandRole::Corner ? b.corner_triangles : b.edge_triangles;
    count = add ? count + 1 : count - 1;
}

/// Sets (`crossing`) or clears edge h (and its twin) in b, with the roles and counts of its two
/// faces: only those change.
void set_crossing(Index h, Index twin, bool crossing, BandClassification& b) {
    b.is_crossing[h] = b.is_crossing[twin] = crossing ? 1 : 0;
    b.crossing_edges = crossing ? b.crossing_edges + 1 : b.crossing_edges - 1;
    for (Index f : {face_of(h), face_of(twin)}) {
        const BandRole role = role_of(b.is_crossing, f);
        if (role == b.face_role[f]) continue;  // (the second face, if both are one)
        count_role(b.face_role[f], false, b);
        count_role(role, true, b);
        b.face_role[f] = role;
    }
}

}  // namespace

BandClassification classify_bands(const Mesh& mesh, const Connectivity& connectivity,
                                  const std::vector<Vec3>& face_normals,
                                  const std::vector<std::uint8_t>& is_edge_vertex,
                                  const std::vector<Index>& face_patch,
                                  const std::vector<Index>& vertex_patch,
                                  const ClassificationOptions& options) {
    const double max_cosine =
        std::cos(options.unconfirmed_border_angle_deg * std::numbers::pi / 180.0);
    const double smooth_cosine =
        std::cos(options.smooth_border_angle_deg * std::numbers::pi / 180.0);
    // Edge vertices confirm a border unless the two patches' normals there are closer than the
    // smooth angle; without an edge vertex the normals must differ by the unconfirmed angle.
    auto border_is_sharp = [&](Index u, Index v) {
        const bool edge_vertex = is_edge_vertex[u] || is_edge_vertex[v];
        const Vec3 nu =
            patch_mean_normal(mesh, connectivity, face_normals, face_patch, u, vertex_patch[u]);
        const Vec3 nv =
            patch_mean_normal(mesh, connectivity, face_normals, face_patch, v, vertex_patch[v]);
        if (nu.isZero(0.0) || nv.isZero(0.0)) return edge_vertex;
        return edge_vertex ? nu.dot(nv) <= smooth_cosine : nu.dot(nv) < max_cosine;
    };
    BandClassification b;
    b.is_crossing.assign(connectivity.twin.size(), 0);
    b.face_role.assign(mesh.face_count(), BandRole::None);
    for (Index f = 0; f < mesh.face_count(); ++f) {
        const Triangle& t = mesh.triangles[f];
        // A face whose vertices share one label has no edge between features: most faces.
        const Index label = vertex_patch[t[0]];
        if (vertex_patch[t[1]] == label && vertex_patch[t[2]] == label) continue;
        for (Index k = 0; k < 3; ++k) {
            const Index h = 3 * f + k;
            const Index twin = connectivity.twin[h];
            if (twin == kNoIndex || twin < h) continue;  // each edge once, from its lower half
            const Index u = t[k], v = t[(k + 1) % 3];
            const bool different_features = vertex_patch[u] != kNoIndex &&
                                            vertex_patch[v] != kNoIndex &&
                                            vertex_patch[u] != vertex_patch[v];
            // The edge-based labels confirm the border: region growing alone also splits smooth
            // surfaces, whose border vertices have low curvature. Degenerate faces stay as they
            // are. Labels are checked first: they rule out almost every edge, and cheaply.
            const bool confirmed = different_features && border_is_sharp(u, v);
            if (confirmed && !face_normals[f].isZero(0.0) &&
                !face_normals[face_of(twin)].isZero(0.0)) {
                set_crossing(h, twin, true, b);
            }
        }
    }
    return b;
}

BandClassification drop_smooth_crossings(const Mesh& mesh, const Connectivity& connectivity,
                                         const BandClassification& bands,
                                         const FeatureNormals& normals,
                                         const ClassificationOptions& options) {
    if (options.smooth_continuation_angle_deg <= 0.0) return bands;
    const double min_cosine =
        std::cos(options.smooth_continuation_angle_deg * std::numbers::pi / 180.0);
    // The normal of v's side carried to x: a sharp edge's two sides keep their angle up to
    // the edge, one smooth surface's meet there.
    auto carried = [&](Index v, const Vec3& x) -> Vec3 {
        const NormalField& field = normals.continuation_field(v);
        if (field.n0.isZero(0.0)) return normals.normal(v);
        return field.n0 + field.gradient * (x - mesh.positions[v]);
    };
    // Only edges go, so only the faces of the edges that go change role.
    BandClassification out = bands;
    for (Index f = 0; f < mesh.face_count(); ++f) {
        if (bands.face_role[f] == BandRole::None) continue;  // no crossing edge: most faces
        const Triangle& t = mesh.triangles[f];
        for (Index k = 0; k < 3; ++k) {
            const Index h = 3 * f + k;
            if (!out.is_crossing[h]) continue;
            const Index twin = connectivity.twin[h];
            if (twin < h) continue;  // each crossing edge once
            const Index u = t[k], v = t[(k + 1) % 3];
            if (normals.normal(u).isZero(0.0) || normals.normal(v).isZero(0.0)) continue;
            const Vec3 middle = 0.5 * (mesh.positions[u] + mesh.positions[v]);
            const Vec3 nu = carried(u, middle), nv = carried(v, middle);
            if (nu.dot(nv) > min_cosine * nu.norm() * nv.norm()) set_crossing(h, twin, false, out);
        }
    }
    return out;
}

BandClassification classify_faces(std::vector<std::uint8_t> is_crossing) {
    BandClassification b;
    b.is_crossing = std::move(is_crossing);
    const std::size_t faces = b.is_crossing.size() / 3;
    b.face_role.assign(faces, BandRole::None);
    std::size_t crossing_halves = 0;
    for (Index f = 0; f < faces; ++f) {
        crossing_halves +=
            b.is_crossing[3 * f] + b.is_crossing[3 * f + 1] + b.is_crossing[3 * f + 2];
        b.face_role[f] = role_of(b.is_crossing, f);
        count_role(b.face_role[f], true, b);
    }
    b.crossing_edges = crossing_halves / 2;
    return b;
}

std::vector<std::uint8_t> band_vertices(const Mesh& mesh, const BandClassification& bands) {
    std::vector<std::uint8_t> in_band(mesh.vertex_count(), 0);
    for (Index f = 0; f < mesh.face_count(); ++f) {
        if (bands.face_role[f] == BandRole::None) continue;
        for (Index v : mesh.triangles[f]) in_band[v] = 1;
    }
    return in_band;
}

}  // namespace resharp
