#include "resharp/restoration/band_classification.h"

namespace resharp {

BandClassification classify_bands(const Mesh& mesh, const Connectivity& connectivity,
                                  const std::vector<Vec3>& face_normals,
                                  const std::vector<std::uint8_t>& is_edge_vertex,
                                  const std::vector<Index>& vertex_patch) {
    BandClassification b;
    const std::size_t nh = connectivity.twin.size();
    b.is_crossing.assign(nh, 0);
    for (Index h = 0; h < nh; ++h) {
        const Index twin = connectivity.twin[h];
        if (twin == kNoIndex || face_normals[face_of(h)].isZero(0.0) ||
            face_normals[face_of(twin)].isZero(0.0)) {
            continue;
        }
        const Index u = tail_vertex(mesh, h);
        const Index v = head_vertex(mesh, h);
        const bool different_features = vertex_patch[u] != kNoIndex &&
                                        vertex_patch[v] != kNoIndex &&
                                        vertex_patch[u] != vertex_patch[v];
        // The edge-based labels confirm the border: region growing alone also splits smooth
        // surfaces, whose border vertices have low curvature.
        if (different_features && (is_edge_vertex[u] || is_edge_vertex[v])) {
            b.is_crossing[h] = 1;
            b.crossing_edges += h < twin;
        }
    }
    b.face_role.assign(mesh.face_count(), BandRole::None);
    for (Index f = 0; f < mesh.face_count(); ++f) {
        const int crossing = b.is_crossing[3 * f] + b.is_crossing[3 * f + 1] + b.is_crossing[3 * f + 2];
        if (crossing == 3) {
            b.face_role[f] = BandRole::Corner;
            ++b.corner_triangles;
        } else if (crossing > 0) {
            b.face_role[f] = BandRole::Edge;
            ++b.edge_triangles;
        }
    }
    return b;
}

}  // namespace resharp
