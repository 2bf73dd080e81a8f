#include "resharp/sim/marching_cubes.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <limits>

namespace resharp::sim {
namespace {

// Cell corners are numbered c = dx + 2 dy + 4 dz. Cell edge e runs along axis d = e / 4 from
// the corner whose bits (d + 1) % 3 and (d + 2) % 3 are e % 2 and (e / 2) % 2.
constexpr int kNoEdge = -1;

int edge_lower_corner(int e) {
    const int d = e / 4;
    return ((e % 2) << ((d + 1) % 3)) | (((e / 2) % 2) << ((d + 2) % 3));
}

/// The six faces of a cell, each with its corners in counter-clockwise order seen from outside
/// the cell and the cell edge between corner k and corner k + 1.
struct FaceTable {
    std::array<std::array<int, 4>, 6> corners{};
    std::array<std::array<int, 4>, 6> edges{};
};

FaceTable make_face_table() {
    FaceTable table;
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        for (int side = 0; side < 2; ++side) {
            const int f = 2 * a + side;
            // (b, c) = (0,0), (1,0), (1,1), (0,1) turns counter-clockwise about +e_a.
            std::array<std::array<int, 2>, 4> bc{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
            if (side == 0) std::reverse(bc.begin() + 1, bc.end());
            for (int k = 0; k < 4; ++k) {
                table.corners[f][k] = (side << a) | (bc[k][0] << b) | (bc[k][1] << c);
            }
            for (int k = 0; k < 4; ++k) {
                const int p = table.corners[f][k], q = table.corners[f][(k + 1) % 4];
                const int d = (p ^ q) == 1 ? 0 : (p ^ q) == 2 ? 1 : 2;
                const int lower = p & q;
                table.edges[f][k] =
                    4 * d + ((lower >> ((d + 1) % 3)) & 1) + 2 * ((lower >> ((d + 2) % 3)) & 1);
            }
        }
    }
    return table;
}

const FaceTable& face_table() {
    static const FaceTable table = make_face_table();
    return table;
}

/// Crossing k of a ray: the interval ends in order.
const Crossing& crossing(const RayIntervals& ray, std::size_t k) {
    return k % 2 == 0 ? ray[k / 2].enter : ray[k / 2].exit;
}

/// Largest-minimum-quality triangulation of a polygon of up to 12 vertices (a cell's loop).
class LoopTriangulator {
public:
    static constexpr int kMaxLoop = 12;

    template <class Emit>
    void triangulate(const std::vector<Vec3>& positions, const std::array<Index, kMaxLoop>& loop,
                     int n, Emit&& emit) {
        if (n == 3) {
            emit(Triangle{loop[0], loop[1], loop[2]});
            return;
        }
        for (int span = 2; span < n; ++span) {
            for (int i = 0; i + span < n; ++i) {
                const int j = i + span;
                best_[i][j] = -1.0;
                for (int m = i + 1; m < j; ++m) {
                    double q = quality(positions[loop[i]], positions[loop[m]], positions[loop[j]]);
                    if (m - i >= 2) q = std::min(q, best_[i][m]);
                    if (j - m >= 2) q = std::min(q, best_[m][j]);
                    if (q > best_[i][j]) best_[i][j] = q, split_[i][j] = m;
                }
            }
        }
        emit_range(loop, 0, n - 1, emit);
    }

private:
    /// Area over the sum of squared sides: 0 for a degenerate triangle, largest for equilateral.
    static double quality(const Vec3& a, const Vec3& b, const Vec3& c) {
        const double sides = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
        return sides > 0.0 ? (b - a).cross(c - a).norm() / sides : 0.0;
    }

    template <class Emit>
    void emit_range(const std::array<Index, kMaxLoop>& loop, int i, int j, Emit&& emit) {
        if (j - i < 2) return;
        const int m = split_[i][j];
        emit(Triangle{loop[i], loop[m], loop[j]});
        emit_range(loop, i, m, emit);
        emit_range(loop, m, j, emit);
    }

    double best_[kMaxLoop][kMaxLoop]{};
    int split_[kMaxLoop][kMaxLoop]{};
};

class DexelMesher {
public:
    DexelMesher(const DexelGrid& grid, const MeshingOptions& options)
        : grid_(grid), spec_(grid.spec), options_(options) {
        strides_ = {1, static_cast<std::size_t>(spec_.counts[0]),
                    static_cast<std::size_t>(spec_.counts[0]) * spec_.counts[1]};
    }

    OracleMesh run() {
        classify_nodes();
        place_vertices();
        build_triangles();
        out_.stats.multiple_crossings = multiple_crossings_;
        out_.stats.clamped_vertices = clamped_vertices_;
        return std::move(out_);
    }

private:
    std::size_t node_index(int i, int j, int k) const {
        return i + strides_[1] * j + strides_[2] * k;
    }

    /// First node and stride of ray `r` of family a.
    std::size_t ray_first_node(int a, std::size_t r) const {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        const std::size_t nb = spec_.counts[b];
        return strides_[b] * (r % nb) + strides_[c] * (r / nb);
    }

    /// A node's state comes from its z-ray only: inside when an interval holds it under the
    /// perturbation rule.
    void classify_nodes() {
        const int nx = spec_.counts[0], ny = spec_.counts[1], nz = spec_.counts[2];
        inside_.assign(static_cast<std::size_t>(nx) * ny * nz, 0);
        tbb::parallel_for(0, ny, [&](int j) {
            for (int i = 0; i < nx; ++i) {
                const RayIntervals& ray = grid_.rays[2][i + static_cast<std::size_t>(nx) * j];
                std::size_t p = 0;
                for (int k = 0; k < nz && p < ray.size(); ++k) {
                    const double t = spec_.node(2, k);
                    while (p < ray.size() && crossing_precedes(ray[p].exit, t, 2)) ++p;
                    if (p < ray.size() && crossing_precedes(ray[p].enter, t, 2)) {
                        inside_[node_index(i, j, k)] = 1;
                    }
                }
            }
        });
    }

    /// One vertex per cell edge whose nodes differ, stored per ray in CSR: the edge indices along
    /// the ray (sorted) and, at the same position, the vertex.
    void place_vertices() {
        std::size_t base = 0;
        for (int a = 0; a < 3; ++a) {
            const std::size_t rays = spec_.ray_count(a);
            const int n = spec_.counts[a];
            const std::size_t stride = strides_[a];
            std::vector<Index>& offsets = ray_offsets_[a];
            offsets.assign(rays + 1, 0);
            tbb::parallel_for(std::size_t{0}, rays, [&](std::size_t r) {
                const std::size_t first = ray_first_node(a, r);
                Index count = 0;
                for (int k = 0; k + 1 < n; ++k) {
                    count += inside_[first + stride * k] != inside_[first + stride * (k + 1)];
                }
                offsets[r + 1] = count;
            });
            for (std::size_t r = 0; r < rays; ++r) offsets[r + 1] += offsets[r];
            family_base_[a] = static_cast<Index>(base);
            base += offsets.back();
            ray_edges_[a].resize(offsets.back());
            out_.mesh.positions.resize(base);
            out_.normals.resize(base);
            out_.surface_ids.resize(base);
            tbb::parallel_for(std::size_t{0}, rays, [&](std::size_t r) { place_on_ray(a, r); });
        }
    }

    void place_on_ray(int a, std::size_t r) {
        const std::size_t first = ray_first_node(a, r);
        const std::size_t stride = strides_[a];
        const RayIntervals& intervals = grid_.rays[a][r];
        const Ray ray = spec_.ray(a, r);
        const std::size_t crossings = 2 * intervals.size();
        Index slot = ray_offsets_[a][r];
        std::size_t e = 0;  // first crossing not before node k
        for (int k = 0; k + 1 < spec_.counts[a]; ++k) {
            const bool lower_inside = inside_[first + stride * k];
            if (lower_inside == static_cast<bool>(inside_[first + stride * (k + 1)])) continue;
            const double t0 = spec_.node(a, k), t1 = spec_.node(a, k + 1);
            while (e < crossings && crossing_precedes(crossing(intervals, e), t0, a)) ++e;
            std::size_t f = e;
            while (f < crossings && crossing_precedes(crossing(intervals, f), t1, a)) ++f;
            Crossing chosen;
            if (f > e) {
                // Keep the end that bounds the material around the inside node.
                chosen = crossing(intervals, lower_inside ? e : f - 1);
                if (f - e > 1) ++multiple_crossings_;
            } else {
                chosen = nearest_crossing(intervals, e, t0, t1);
                ++clamped_vertices_;
            }
            const Index v = family_base_[a] + slot;
            ray_edges_[a][slot++] = static_cast<Index>(k);
            out_.mesh.positions[v] = ray.point(chosen.t);
            out_.normals[v] = chosen.normal;
            out_.surface_ids[v] = chosen.surface;
        }
    }

    /// The state of a node disagrees with its ray: no end lies on the edge [t0, t1]. Take the
    /// closest end (crossing e - 1 before the edge or e after it), moved onto the edge.
    static Crossing nearest_crossing(const RayIntervals& intervals, std::size_t e, double t0,
                                     double t1) {
        const std::size_t crossings = 2 * intervals.size();
        if (crossings == 0) return Crossing{0.5 * (t0 + t1), Vec3::Zero(), -1};
        const bool has_before = e > 0, has_after = e < crossings;
        const bool use_after = !has_before || (has_after && crossing(intervals, e).t - t1 <
                                                                t0 - crossing(intervals, e - 1).t);
        Crossing c = crossing(intervals, use_after ? e : e - 1);
        c.t = std::clamp(c.t, t0, t1);
        return c;
    }

    Index vertex_on_edge(int d, int i, int j, int k) const {
        const std::array<int, 3> node{i, j, k};
        const int b = (d + 1) % 3, c = (d + 2) % 3;
        const std::size_t r = node[b] + static_cast<std::size_t>(spec_.counts[b]) * node[c];
        const auto& edges = ray_edges_[d];
        const auto begin = edges.begin() + ray_offsets_[d][r];
        const auto end = edges.begin() + ray_offsets_[d][r + 1];
        const auto it = std::lower_bound(begin, end, static_cast<Index>(node[d]));
        return family_base_[d] + static_cast<Index>(it - edges.begin());
    }

    void build_triangles() {
        const int slabs = spec_.counts[2] - 1;
        std::vector<std::vector<Triangle>> per_slab(std::max(slabs, 0));
        std::atomic<std::size_t> ambiguous{0};
        tbb::parallel_for(0, std::max(slabs, 0), [&](int k) {
            LoopTriangulator triangulator;
            std::size_t slab_ambiguous = 0;
            for (int j = 0; j + 1 < spec_.counts[1]; ++j) {
                for (int i = 0; i + 1 < spec_.counts[0]; ++i) {
                    mesh_cell(i, j, k, triangulator, per_slab[k], slab_ambiguous);
                }
            }
            ambiguous += slab_ambiguous;
        });
        for (const auto& slab : per_slab) {
            out_.mesh.triangles.insert(out_.mesh.triangles.end(), slab.begin(), slab.end());
        }
        out_.stats.ambiguous_faces = ambiguous;
    }

    void mesh_cell(int i, int j, int k, LoopTriangulator& triangulator,
                   std::vector<Triangle>& triangles, std::size_t& ambiguous) const {
        std::array<bool, 8> in{};
        int inside_count = 0;
        for (int c = 0; c < 8; ++c) {
            in[c] = inside_[node_index(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1))];
            inside_count += in[c];
        }
        if (inside_count == 0 || inside_count == 8) return;

        std::array<Index, 12> vertex{};
        for (int e = 0; e < 12; ++e) {
            const int lower = edge_lower_corner(e);
            const int upper = lower | (1 << (e / 4));
            if (in[lower] != in[upper]) {
                vertex[e] = vertex_on_edge(e / 4, i + (lower & 1), j + ((lower >> 1) & 1),
                                           k + ((lower >> 2) & 1));
            }
        }
        const std::array<int, 12> next = link_face_segments(in, vertex, ambiguous);
        emit_loops(next, vertex, triangulator, triangles);
    }

    /// On each face, joins each crossing where the boundary walk (counter-clockwise from outside)
    /// leaves an inside corner to the crossing where it re-enters one: next[tail] = head.
    std::array<int, 12> link_face_segments(const std::array<bool, 8>& in,
                                           const std::array<Index, 12>& vertex,
                                           std::size_t& ambiguous) const {
        const FaceTable& table = face_table();
        std::array<int, 12> next;
        next.fill(kNoEdge);
        for (int f = 0; f < 6; ++f) {
            const auto& corner = table.corners[f];
            const auto& edge = table.edges[f];
            std::array<bool, 4> crossed{};
            int crossings = 0;
            for (int q = 0; q < 4; ++q) {
                crossed[q] = in[corner[q]] != in[corner[(q + 1) % 4]];
                crossings += crossed[q];
            }
            if (crossings == 2) {
                int tail = -1, head = -1;
                for (int q = 0; q < 4; ++q) {
                    if (!crossed[q]) continue;
                    (in[corner[q]] ? tail : head) = q;
                }
                next[edge[tail]] = edge[head];
            } else if (crossings == 4) {
                ++ambiguous;
                const bool connect = connects_inside(in, corner, edge, vertex);
                for (int q = 0; q < 4; ++q) {
                    if (in[corner[q]]) next[edge[q]] = edge[(q + (connect ? 1 : 3)) % 4];
                }
            }
        }
        return next;
    }

    /// The rule for a face with four crossings, from that face's data alone so that the cells on
    /// both sides agree: the sums below are the same numbers whichever way round they are walked.
    bool connects_inside(const std::array<bool, 8>& in, const std::array<int, 4>& corner,
                         const std::array<int, 4>& edge,
                         const std::array<Index, 12>& vertex) const {
        if (options_.ambiguous_faces == AmbiguousFaceRule::SeparateInside) return false;
        const auto& p = out_.mesh.positions;
        double around_outside = 0.0, around_inside = 0.0;
        for (int q = 0; q < 4; ++q) {
            const double length = (p[vertex[edge[q]]] - p[vertex[edge[(q + 1) % 4]]]).norm();
            // Crossings q and q + 1 flank corner q + 1.
            (in[corner[(q + 1) % 4]] ? around_inside : around_outside) += length;
        }
        return around_outside < around_inside;
    }

    /// Follows next[] around each loop and triangulates it. The walk turns counter-clockwise
    /// around the inside corners seen from outside the cell, i.e. its right-hand normal points
    /// into the material: emit the loop reversed.
    void emit_loops(const std::array<int, 12>& next, const std::array<Index, 12>& vertex,
                    LoopTriangulator& triangulator, std::vector<Triangle>& triangles) const {
        std::array<bool, 12> visited{};
        for (int start = 0; start < 12; ++start) {
            if (next[start] == kNoEdge || visited[start]) continue;
            std::array<Index, LoopTriangulator::kMaxLoop> loop{};
            int n = 0;
            for (int e = start; !visited[e]; e = next[e]) {
                visited[e] = true;
                loop[n++] = vertex[e];
            }
            std::reverse(loop.begin(), loop.begin() + n);
            triangulator.triangulate(out_.mesh.positions, loop, n,
                                     [&](const Triangle& t) { triangles.push_back(t); });
        }
    }

    const DexelGrid& grid_;
    const GridSpec& spec_;
    MeshingOptions options_;
    std::array<std::size_t, 3> strides_{};
    std::vector<std::uint8_t> inside_;               // per node
    std::array<std::vector<Index>, 3> ray_offsets_;  // per family: CSR over rays
    std::array<std::vector<Index>, 3> ray_edges_;    // per family: edge index along the ray
    std::array<Index, 3> family_base_{};             // first vertex of each family
    std::atomic<std::size_t> multiple_crossings_{0};
    std::atomic<std::size_t> clamped_vertices_{0};
    OracleMesh out_;
};

}  // namespace

OracleMesh mesh_dexels(const DexelGrid& grid, const MeshingOptions& options) {
    return DexelMesher(grid, options).run();
}

}  // namespace resharp::sim
