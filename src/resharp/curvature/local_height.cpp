#include "resharp/curvature/local_height.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace resharp {

double median_edge_length(const Mesh& mesh) {
    if (mesh.triangles.empty()) return 0.0;
    // A sample of at most ~64k edges is plenty for a median and keeps this O(F) at worst.
    const std::size_t stride = std::max<std::size_t>(1, mesh.face_count() / 65536);
    // Squared lengths: sqrt is monotonic, so the root of their median is the median length,
    // and one root is taken instead of one per edge.
    std::vector<double> squared_lengths;
    squared_lengths.reserve(3 * (mesh.face_count() / stride + 1));
    for (std::size_t f = 0; f < mesh.face_count(); f += stride) {
        const Triangle& t = mesh.triangles[f];
        for (int k = 0; k < 3; ++k) {
            squared_lengths.push_back(
                (mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]]).squaredNorm());
        }
    }
    const auto middle =
        squared_lengths.begin() + static_cast<std::ptrdiff_t>(squared_lengths.size() / 2);
    std::nth_element(squared_lengths.begin(), middle, squared_lengths.end());
    return std::sqrt(*middle);
}

PrincipalCurvatures estimate_principal_curvatures(const Mesh& mesh,
                                                  const Connectivity& connectivity,
                                                  const std::vector<Vec3>& vertex_normals) {
    const std::size_t nv = mesh.vertex_count();
    PrincipalCurvatures result;  // unwritten: the loop below writes every vertex's pair
    result.k1.resize(nv);
    result.k2.resize(nv);
    const double typical_length = median_edge_length(mesh);
    const double limit = typical_length > 0.0 ? 2.0 / typical_length : 0.0;

    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 4096), [&](const auto& range) {
        for (std::size_t v = range.begin(); v != range.end(); ++v) {
            const Vec3& n = vertex_normals[v];
            const Vec3& x = mesh.positions[v];
            double lo = std::numeric_limits<double>::infinity();
            double hi = -lo;
            // One sample per face, towards the vertex after v: around a closed fan that visits
            // every neighbour once (a boundary vertex misses one neighbour).
            for (Index f : connectivity.faces_around(static_cast<Index>(v))) {
                const Triangle& t = mesh.triangles[f];
                const Index j = t[0] == v ? t[1] : t[1] == v ? t[2] : t[0];
                const Vec3 d = mesh.positions[j] - x;
                const double length2 = d.squaredNorm();
                if (length2 == 0.0) continue;
                const double kappa = std::clamp(-2.0 * d.dot(n) / length2, -limit, limit);
                lo = std::min(lo, kappa);
                hi = std::max(hi, kappa);
            }
            const bool sampled = lo <= hi && !n.isZero(0.0);
            result.k1[v] = sampled ? lo : 0.0;
            result.k2[v] = sampled ? hi : 0.0;
        }
    });
    return result;
}

}  // namespace resharp
