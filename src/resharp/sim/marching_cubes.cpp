#include "resharp/sim/marching_cubes.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <limits>
#include <string>
#include <utility>

#include "resharp/core/errors.h"

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

/// The number of crossings of `ray` (along `axis`) before the point at t, under the
/// perturbation rule; odd when t is inside the material. Binary search: rays can hold many.
std::size_t crossings_before(const RayIntervals& ray, double t, int axis) {
    std::size_t lo = 0, hi = 2 * ray.size();
    while (lo < hi) {
        const std::size_t mid = (lo + hi) / 2;
        if (crossing_precedes(crossing(ray, mid), t, axis)) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    return lo;
}

/// Bisection on the ray's inside/outside state (Mesher::Bisection): [lo, hi] starts as the cell
/// edge [t0, t1] and keeps the lower node's state at lo; the result is the last middle.
double bisect(const RayIntervals& ray, int axis, double t0, double t1, bool lower_inside,
              int steps) {
    double lo = t0, hi = t1;
    for (int step = 0; step < steps; ++step) {
        const double mid = 0.5 * (lo + hi);
        const bool inside = crossings_before(ray, mid, axis) % 2 == 1;
        (inside == lower_inside ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

/// The exact crossing nearest a point, found among candidates.
struct NearestCrossing {
    double squared_distance = std::numeric_limits<double>::infinity();
    Vec3 point = Vec3::Zero();
    Crossing crossing;
    bool found() const { return squared_distance < std::numeric_limits<double>::infinity(); }
};

/// Of the four cells around a cell edge along d, the one at offset (-bit_b, -bit_c) from the
/// edge's lower node sits at position slot(bit_b, bit_c) counter-clockwise about +e_d.
int slot_around_edge(int bit_b, int bit_c) { return bit_c == 0 ? bit_b : 3 - bit_b; }

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
        if (options_.mesher == Mesher::SurfaceNets) {
            build_dual();
        } else {
            build_triangles();
        }
        out_.stats.multiple_crossings = multiple_crossings_;
        out_.stats.clamped_vertices = clamped_vertices_;
        return std::move(out_);
    }

private:
    /// The loops of one cell: its corner states, the vertex on each crossed edge and, per
    /// crossed edge, the next one along the loop (kNoEdge elsewhere).
    struct CellLoops {
        std::array<bool, 8> in{};
        std::array<Index, 12> vertex{};
        std::array<int, 12> next{};
    };

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
            out_.surface_points.resize(base);
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
            const Vec3 exact = ray.point(chosen.t);
            switch (options_.mesher) {
                case Mesher::MarchingCubes:
                case Mesher::SurfaceNets:
                    set_vertex(v, exact, {0.0, exact, chosen});
                    break;
                case Mesher::Bisection:
                    place_off_surface(v,
                                      ray.point(bisect(intervals, a, t0, t1, lower_inside,
                                                       options_.bisection_steps)),
                                      a, ray_node(a, r, k), {0.0, exact, chosen});
                    break;
                case Mesher::Midpoint:
                    place_off_surface(v, ray.point(0.5 * (t0 + t1)), a, ray_node(a, r, k),
                                      {0.0, exact, chosen});
                    break;
            }
        }
    }

    /// Grid coordinates of node k on ray r of family a.
    std::array<int, 3> ray_node(int a, std::size_t r, int k) const {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        const auto nb = static_cast<std::size_t>(spec_.counts[b]);
        std::array<int, 3> node{};
        node[a] = k;
        node[b] = static_cast<int>(r % nb);
        node[c] = static_cast<int>(r / nb);
        return node;
    }

    void set_vertex(Index v, const Vec3& position, const NearestCrossing& surface) {
        out_.mesh.positions[v] = position;
        out_.surface_points[v] = surface.point;
        out_.normals[v] = surface.crossing.normal;
        out_.surface_ids[v] = surface.crossing.surface;
    }

    /// A vertex at p on the cell edge along a from `node`: its oracle is the foot of p on the
    /// tangent plane of the nearest crossing on the edges of the four cells around the edge.
    void place_off_surface(Index v, const Vec3& p, int a, const std::array<int, 3>& node,
                           const NearestCrossing& own) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        NearestCrossing best;
        for (int q = 0; q < 4; ++q) {
            std::array<int, 3> cell = node;
            cell[b] -= q & 1;
            cell[c] -= q >> 1;
            nearest_on_cell(p, cell, best);
        }
        set_vertex(v, p, foot(p, best.found() ? best : own));
    }

    /// Updates `best` with the crossings on the twelve edges of the cell whose lowest node is
    /// `cell` (edges outside the grid have none).
    void nearest_on_cell(const Vec3& p, const std::array<int, 3>& cell,
                         NearestCrossing& best) const {
        for (int a = 0; a < 3; ++a) {
            const int b = (a + 1) % 3, c = (a + 2) % 3;
            for (int q = 0; q < 4; ++q) {
                std::array<int, 3> node = cell;
                node[b] += q & 1;
                node[c] += q >> 1;
                nearest_on_edge(p, a, node, best);
            }
        }
    }

    void nearest_on_edge(const Vec3& p, int a, const std::array<int, 3>& node,
                         NearestCrossing& best) const {
        for (int d = 0; d < 3; ++d) {
            if (node[d] < 0 || node[d] + (d == a ? 1 : 0) >= spec_.counts[d]) return;
        }
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        const std::size_t r = node[b] + static_cast<std::size_t>(spec_.counts[b]) * node[c];
        const RayIntervals& ray = grid_.rays[a][r];
        const double t0 = spec_.node(a, node[a]), t1 = spec_.node(a, node[a] + 1);
        Vec3 at;
        for (int d = 0; d < 3; ++d) at[d] = spec_.node(d, node[d]);
        for (std::size_t k = crossings_before(ray, t0, a); k < 2 * ray.size(); ++k) {
            const Crossing& x = crossing(ray, k);
            if (x.t > t1) break;
            at[a] = x.t;
            const double d2 = (at - p).squaredNorm();
            if (d2 < best.squared_distance) best = {d2, at, x};
        }
    }

    /// The foot of p on the tangent plane of the crossing: exact on a plane, within
    /// |foot - crossing|² / (2 ρ) of a surface of curvature radius ρ (docs/oracle.md).
    static NearestCrossing foot(const Vec3& p, const NearestCrossing& nearest) {
        NearestCrossing s = nearest;
        const Vec3& n = nearest.crossing.normal;
        s.point = p - (p - nearest.point).dot(n) * n;
        return s;
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

    /// Calls visit(i, j, k, loops) for every cell the surface crosses: slabs (fixed k) in
    /// parallel, cells in order within a slab, so visit() may append to per-slab lists. Gives
    /// the number of cell faces with four crossings.
    template <class Visit>
    std::size_t for_each_crossed_cell(Visit&& visit) const {
        const int slabs = std::max(spec_.counts[2] - 1, 0);
        std::atomic<std::size_t> ambiguous{0};
        tbb::parallel_for(0, slabs, [&](int k) {
            std::size_t slab_ambiguous = 0;
            CellLoops loops;
            for (int j = 0; j + 1 < spec_.counts[1]; ++j) {
                for (int i = 0; i + 1 < spec_.counts[0]; ++i) {
                    if (cell_loops(i, j, k, loops, slab_ambiguous)) visit(i, j, k, loops);
                }
            }
            ambiguous += slab_ambiguous;
        });
        return ambiguous;
    }

    void build_triangles() {
        std::vector<std::vector<Triangle>> per_slab(std::max(spec_.counts[2] - 1, 0));
        std::vector<LoopTriangulator> triangulators(per_slab.size());
        out_.stats.ambiguous_faces =
            for_each_crossed_cell([&](int, int, int k, const CellLoops& loops) {
                emit_loops(loops, triangulators[k], per_slab[k]);
            });
        for (const auto& slab : per_slab) {
            out_.mesh.triangles.insert(out_.mesh.triangles.end(), slab.begin(), slab.end());
        }
    }

    /// The corner states, edge vertices and loop links of cell (i, j, k); false when the
    /// surface does not cross it.
    bool cell_loops(int i, int j, int k, CellLoops& loops, std::size_t& ambiguous) const {
        int inside_count = 0;
        for (int c = 0; c < 8; ++c) {
            loops.in[c] = inside_[node_index(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1))];
            inside_count += loops.in[c];
        }
        if (inside_count == 0 || inside_count == 8) return false;
        for (int e = 0; e < 12; ++e) {
            const int lower = edge_lower_corner(e);
            const int upper = lower | (1 << (e / 4));
            if (loops.in[lower] != loops.in[upper]) {
                loops.vertex[e] = vertex_on_edge(e / 4, i + (lower & 1), j + ((lower >> 1) & 1),
                                                 k + ((lower >> 2) & 1));
            }
        }
        loops.next = link_face_segments(loops.in, loops.vertex, ambiguous);
        return true;
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

    /// Calls visit(edges, n) for each loop of next[], its n edges in walk order. The walk turns
    /// counter-clockwise around the inside corners seen from outside the cell, i.e. its
    /// right-hand normal points into the material.
    template <class Visit>
    static void for_each_loop(const std::array<int, 12>& next, Visit&& visit) {
        std::array<bool, 12> visited{};
        for (int start = 0; start < 12; ++start) {
            if (next[start] == kNoEdge || visited[start]) continue;
            std::array<int, LoopTriangulator::kMaxLoop> edges{};
            int n = 0;
            for (int e = start; !visited[e]; e = next[e]) {
                visited[e] = true;
                edges[n++] = e;
            }
            visit(edges, n);
        }
    }

    /// Triangulates each loop, reversed so that the triangles face out of the material.
    void emit_loops(const CellLoops& loops, LoopTriangulator& triangulator,
                    std::vector<Triangle>& triangles) const {
        for_each_loop(loops.next, [&](const auto& edges, int n) {
            std::array<Index, LoopTriangulator::kMaxLoop> loop{};
            for (int q = 0; q < n; ++q) loop[q] = loops.vertex[edges[n - 1 - q]];
            triangulator.triangulate(out_.mesh.positions, loop, n,
                                     [&](const Triangle& t) { triangles.push_back(t); });
        });
    }

    /// Surface nets: the dual of the loops. One vertex per loop at the mean of its crossings,
    /// then one quad per crossed cell edge through the vertices of the loops of its four cells.
    void build_dual() {
        struct Slab {
            std::vector<Vec3> points;
            std::vector<NearestCrossing> surfaces;
            std::vector<std::pair<std::size_t, Index>> links;  // (4 edge vertex + slot, loop)
        };
        std::vector<Slab> slabs(std::max(spec_.counts[2] - 1, 0));
        out_.stats.ambiguous_faces = for_each_crossed_cell([&](int i, int j, int k,
                                                               const CellLoops& loops) {
            Slab& slab = slabs[k];
            for_each_loop(loops.next, [&](const auto& edges, int n) {
                Vec3 mean = Vec3::Zero();
                for (int q = 0; q < n; ++q) {
                    const int e = edges[q];
                    mean += out_.mesh.positions[loops.vertex[e]];
                    const std::size_t slot = slot_around_edge(e % 2, (e / 2) % 2);
                    slab.links.emplace_back(4 * std::size_t{loops.vertex[e]} + slot,
                                            static_cast<Index>(slab.points.size()));
                }
                mean /= static_cast<double>(n);
                NearestCrossing best;
                nearest_on_cell(mean, {i, j, k}, best);
                if (!best.found()) {  // cannot happen: the loop's own crossings are candidates
                    const Index v = loops.vertex[edges[0]];
                    best = {
                        0.0, out_.surface_points[v], {0.0, out_.normals[v], out_.surface_ids[v]}};
                }
                slab.points.push_back(mean);
                slab.surfaces.push_back(foot(mean, best));
            });
        });
        std::vector<Index> dual(4 * out_.mesh.vertex_count(), kNoIndex);
        OracleMesh net;
        for (const Slab& slab : slabs) {
            const auto base = static_cast<Index>(net.mesh.positions.size());
            for (const auto& [link, loop] : slab.links) dual[link] = base + loop;
            for (std::size_t q = 0; q < slab.points.size(); ++q) {
                net.mesh.positions.push_back(slab.points[q]);
                net.surface_points.push_back(slab.surfaces[q].point);
                net.normals.push_back(slab.surfaces[q].crossing.normal);
                net.surface_ids.push_back(slab.surfaces[q].crossing.surface);
            }
        }
        emit_quads(dual, net.mesh);
        net.stats = out_.stats;
        out_ = std::move(net);
    }

    /// One quad per crossed cell edge, counter-clockwise seen from the outside node, split
    /// along its shorter diagonal; edges with a cell outside the grid get none.
    void emit_quads(const std::vector<Index>& dual, Mesh& net) const {
        for (int a = 0; a < 3; ++a) {
            const std::size_t stride = strides_[a];
            for (std::size_t r = 0; r < spec_.ray_count(a); ++r) {
                const std::size_t first = ray_first_node(a, r);
                for (Index slot = ray_offsets_[a][r]; slot < ray_offsets_[a][r + 1]; ++slot) {
                    const std::size_t v = family_base_[a] + slot;
                    std::array<Index, 4> q{dual[4 * v], dual[4 * v + 1], dual[4 * v + 2],
                                           dual[4 * v + 3]};
                    if (std::find(q.begin(), q.end(), kNoIndex) != q.end()) continue;
                    if (!inside_[first + stride * ray_edges_[a][slot]]) std::swap(q[1], q[3]);
                    const auto& p = net.positions;
                    if ((p[q[0]] - p[q[2]]).squaredNorm() <= (p[q[1]] - p[q[3]]).squaredNorm()) {
                        net.triangles.push_back({q[0], q[1], q[2]});
                        net.triangles.push_back({q[0], q[2], q[3]});
                    } else {
                        net.triangles.push_back({q[1], q[2], q[3]});
                        net.triangles.push_back({q[1], q[3], q[0]});
                    }
                }
            }
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

/// Appends a second copy of every triangle that touches or crosses one of `seams` grid planes
/// x = const spread evenly over the grid. Gives the number appended.
std::size_t duplicate_seams(Mesh& mesh, const GridSpec& spec, int seams) {
    std::vector<double> planes;
    for (int p = 0; p < seams; ++p) {
        planes.push_back(spec.node(0, (p + 1) * (spec.counts[0] - 1) / (seams + 1)));
    }
    const std::size_t count = mesh.triangles.size();
    for (std::size_t f = 0; f < count; ++f) {
        const Triangle t = mesh.triangles[f];
        double lo = mesh.positions[t[0]].x(), hi = lo;
        for (const Index v : t) {
            lo = std::min(lo, mesh.positions[v].x());
            hi = std::max(hi, mesh.positions[v].x());
        }
        const auto plane = std::lower_bound(planes.begin(), planes.end(), lo);
        if (plane != planes.end() && *plane <= hi) mesh.triangles.push_back(t);
    }
    return mesh.triangles.size() - count;
}

}  // namespace

const char* to_string(Mesher mesher) {
    switch (mesher) {
        case Mesher::MarchingCubes:
            return "mc";
        case Mesher::Bisection:
            return "bisect";
        case Mesher::Midpoint:
            return "midpoint";
        case Mesher::SurfaceNets:
            return "surface-nets";
    }
    return "?";
}

std::optional<Mesher> mesher_from_string(std::string_view name) {
    for (const Mesher m :
         {Mesher::MarchingCubes, Mesher::Bisection, Mesher::Midpoint, Mesher::SurfaceNets}) {
        if (name == to_string(m)) return m;
    }
    return std::nullopt;
}

OracleMesh mesh_dexels(const DexelGrid& grid, const MeshingOptions& options) {
    if (options.bisection_steps < 1 || options.bisection_steps > 52) {
        throw InvalidInput("bisection steps must lie in 1..52");
    }
    const int planes = std::max(grid.spec.counts[0] - 2, 0);
    if (options.seam_duplicates < 0 || options.seam_duplicates > planes) {
        throw InvalidInput("seam duplicates must lie in 0.." + std::to_string(planes) +
                           " on this grid (its interior node planes along x)");
    }
    OracleMesh out = DexelMesher(grid, options).run();
    out.stats.duplicated_triangles = duplicate_seams(out.mesh, grid.spec, options.seam_duplicates);
    return out;
}

}  // namespace resharp::sim
