#include "resharp/segmentation/edge_segmentation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "resharp/core/disjoint_sets.h"
#include "resharp/core/errors.h"
#include "resharp/mesh/geometric_order.h"
#include "resharp/segmentation/kmeans.h"

namespace resharp {
namespace {

void validate(const EdgeSegmentationOptions& o) {
    if (!(o.kmeans_tolerance > 0.0)) throw InvalidInput("kmeans tolerance must be positive");
    if (o.max_kmeans_iterations < 1) throw InvalidInput("k-means needs at least one iteration");
    if (o.max_bridge_walk < 0) throw InvalidInput("bridge walk length must not be negative");
    if (!(o.flat_normal_spread_deg >= 0.0 && o.flat_normal_spread_deg <= 180.0)) {
        throw InvalidInput("flat normal spread must lie in [0, 180] degrees");
    }
}

/// Initial centres (§3.2): the flat centre is the componentwise median of (k1, k2), since most
/// of a machined part is smooth; the edge centre is the mean of the 10% of points farthest
/// from it. Starting the edge centre at a single extreme point would let one sliver capture it.
std::array<Eigen::Vector2d, 2> initial_centres(std::vector<Eigen::Vector2d> points) {
    const auto middle = points.begin() + static_cast<std::ptrdiff_t>(points.size() / 2);
    std::nth_element(points.begin(), middle, points.end(),
                     [](const auto& a, const auto& b) { return a.x() < b.x(); });
    const double k1 = middle->x();
    std::nth_element(points.begin(), middle, points.end(),
                     [](const auto& a, const auto& b) { return a.y() < b.y(); });
    const Eigen::Vector2d flat(k1, middle->y());

    const std::size_t far_count = std::max<std::size_t>(1, points.size() / 10);
    const auto far_end = points.begin() + static_cast<std::ptrdiff_t>(far_count);
    std::nth_element(points.begin(), far_end - 1, points.end(), [&](const auto& a, const auto& b) {
        return (a - flat).squaredNorm() > (b - flat).squaredNorm();
    });
    Eigen::Vector2d edge = Eigen::Vector2d::Zero();
    for (auto it = points.begin(); it != far_end; ++it) edge += *it;
    return {flat, edge / static_cast<double>(far_count)};
}

/// Clusters (k1, k2); the cluster whose centre lies farther from zero curvature is "edge".
std::vector<std::uint8_t> cluster_edge_vertices(const PrincipalCurvatures& k,
                                                const EdgeSegmentationOptions& o, int& iterations) {
    std::vector<Eigen::Vector2d> points(k.k1.size());
    for (std::size_t v = 0; v < points.size(); ++v) {
        const double a = std::abs(k.k1[v]), b = std::abs(k.k2[v]);
        points[v] = o.feature == CurvatureFeature::Signed
                        ? Eigen::Vector2d(k.k1[v], k.k2[v])
                        : Eigen::Vector2d(std::min(a, b), std::max(a, b));
    }
    std::vector<std::uint8_t> is_edge(points.size(), 0);
    if (points.empty()) return is_edge;
    const TwoMeansResult r =
        two_means(points, initial_centres(points), o.kmeans_tolerance, o.max_kmeans_iterations);
    iterations = r.iterations;
    if ((r.centres[0] - r.centres[1]).norm() < o.kmeans_tolerance) return is_edge;  // all alike
    const std::uint8_t edge_cluster = r.centres[1].norm() > r.centres[0].norm() ? 1 : 0;
    for (std::size_t v = 0; v < points.size(); ++v) is_edge[v] = r.cluster[v] == edge_cluster;
    return is_edge;
}

std::size_t remove_isolated(const Mesh& mesh, const Connectivity& c,
                            std::vector<std::uint8_t>& is_edge) {
    std::vector<Index> isolated;
    for (Index v = 0; v < is_edge.size(); ++v) {
        if (!is_edge[v]) continue;
        bool has_edge_neighbour = false;
        for_each_ring_vertex(mesh, c, v, [&](Index j) { has_edge_neighbour |= is_edge[j] != 0; });
        if (!has_edge_neighbour) isolated.push_back(v);
    }
    for (Index v : isolated) is_edge[v] = 0;
    return isolated.size();
}

/// Labels the connected pieces of the edge-vertex graph (kNoIndex for non-edge vertices).
std::vector<Index> label_edge_pieces(const Mesh& mesh, const Connectivity& c,
                                     const std::vector<std::uint8_t>& is_edge) {
    std::vector<Index> piece(is_edge.size(), kNoIndex);
    std::vector<Index> stack;
    Index next = 0;
    for (Index seed = 0; seed < is_edge.size(); ++seed) {
        if (!is_edge[seed] || piece[seed] != kNoIndex) continue;
        piece[seed] = next;
        stack.push_back(seed);
        while (!stack.empty()) {  // bound: a vertex is pushed once, when it gets its piece
            const Index v = stack.back();
            stack.pop_back();
            for_each_ring_vertex(mesh, c, v, [&](Index j) {
                if (is_edge[j] && piece[j] == kNoIndex) {
                    piece[j] = next;
                    stack.push_back(j);
                }
            });
        }
        ++next;
    }
    return piece;
}

/// An end of a broken edge: an edge vertex with at most one distinct edge neighbour.
bool is_edge_end(const Mesh& mesh, const Connectivity& c, const std::vector<std::uint8_t>& is_edge,
                 Index v) {
    Index first = kNoIndex;
    bool second = false;
    for_each_ring_vertex(mesh, c, v, [&](Index j) {
        if (!is_edge[j]) return;
        if (first == kNoIndex)
            first = j;
        else if (j != first)
            second = true;
    });
    return !second;
}

/// A breadth-first walk from an end of a broken edge through non-edge vertices to another
/// piece of edge. Each vertex's new neighbours join the queue in geometric order
/// (geometric_order.h), and of the pieces' vertices one ring reaches, the first in that order
/// is taken, so the walk and its path do not depend on the mesh's numbering.
class BridgeWalk {
public:
    explicit BridgeWalk(std::size_t vertex_count) : parent_(vertex_count, kNoIndex) {}

    /// The vertex of another piece reached from `end` through at most `max_walk` non-edge
    /// vertices, or kNoIndex; path() then leads back from it.
    template <class PieceOf>
    Index walk(const Mesh& mesh, const Connectivity& c, const std::vector<std::uint8_t>& is_edge,
               Index end, int max_walk, PieceOf&& piece_of) {
        clear();
        queue_.assign(1, end);
        parent_[end] = end;
        touched_.assign(1, end);
        const Index own = piece_of(end);
        int walked = 0;
        // Bound: at most P (max_walk) vertices walked from the end, each visiting its ring.
        for (std::size_t head = 0; head < queue_.size() && walked <= max_walk; ++head) {
            const Index v = queue_[head];
            if (v != end) ++walked;
            Index reached = kNoIndex;
            fresh_.clear();
            for_each_ring_vertex(mesh, c, v, [&](Index j) {
                if (parent_[j] != kNoIndex) return;
                if (!is_edge[j]) {
                    parent_[j] = v;
                    touched_.push_back(j);
                    fresh_.push_back(j);
                } else if (piece_of(j) != own &&
                           (reached == kNoIndex || vertex_before(mesh, j, reached))) {
                    reached = j;
                }
            });
            if (reached != kNoIndex) {
                parent_[reached] = v;
                touched_.push_back(reached);
                return reached;
            }
            sort_vertices(mesh, fresh_);
            queue_.insert(queue_.end(), fresh_.begin(), fresh_.end());
        }
        return kNoIndex;
    }

    Index parent(Index v) const { return parent_[v]; }

private:
    void clear() {
        for (Index v : touched_) parent_[v] = kNoIndex;
        touched_.clear();
    }

    std::vector<Index> parent_;
    std::vector<Index> touched_, queue_, fresh_;
};

/// §3.3: from each end of a broken edge, a breadth-first walk through at most `max_walk`
/// non-edge vertices; when it reaches another piece of edge, the path becomes edge. Ends are
/// taken in geometric order. Bridging only adds edge vertices, and a path vertex has two edge
/// neighbours, so the ends are those found at the start that are still ends when their turn
/// comes. Ends go in sweep order (geometric_order.h).
std::size_t bridge_broken_edges(const Mesh& mesh, const Connectivity& c, int max_walk,
                                std::vector<std::uint8_t>& is_edge) {
    std::vector<Index> first_piece = label_edge_pieces(mesh, c, is_edge);
    DisjointSets pieces(is_edge.size());
    auto piece_of = [&](Index v) { return pieces.find(first_piece[v]); };
    std::vector<Index> ends;
    for (Index v = 0; v < is_edge.size(); ++v) {
        if (is_edge[v] && is_edge_end(mesh, c, is_edge, v)) ends.push_back(v);
    }
    std::sort(ends.begin(), ends.end(),
              [&](Index a, Index b) { return vertex_swept_before(mesh, a, b); });
    BridgeWalk walk(is_edge.size());
    std::size_t added = 0;
    for (Index end : ends) {  // Bound: the ends found at the start
        if (!is_edge_end(mesh, c, is_edge, end)) continue;
        const Index reached = walk.walk(mesh, c, is_edge, end, max_walk, piece_of);
        if (reached == kNoIndex) continue;
        pieces.unite(piece_of(reached), piece_of(end));
        for (Index v = walk.parent(reached); v != end; v = walk.parent(v)) {
            is_edge[v] = 1;
            first_piece[v] = first_piece[end];
            ++added;
        }
    }
    return added;
}

/// True when every two non-degenerate face normals around v are closer than the angle whose
/// cosine is given (compared as cosines: no trigonometry per pair).
bool has_flat_ring(const Connectivity& c, const std::vector<Vec3>& face_normals, Index v,
                   double min_cosine) {
    const auto ring = c.faces_around(v);
    for (std::size_t a = 0; a < ring.size(); ++a) {
        const Vec3& na = face_normals[ring[a]];
        if (na.isZero(0.0)) continue;
        for (std::size_t b = a + 1; b < ring.size(); ++b) {
            const Vec3& nb = face_normals[ring[b]];
            if (!nb.isZero(0.0) && na.dot(nb) <= min_cosine) return false;
        }
    }
    return true;
}

std::size_t remove_flat(const Connectivity& c, const std::vector<Vec3>& face_normals,
                        double spread_deg, std::vector<std::uint8_t>& is_edge) {
    const double min_cosine = std::cos(spread_deg * std::numbers::pi / 180.0);
    std::size_t removed = 0;
    for (Index v = 0; v < is_edge.size(); ++v) {
        if (is_edge[v] && has_flat_ring(c, face_normals, v, min_cosine)) {
            is_edge[v] = 0;
            ++removed;
        }
    }
    return removed;
}

}  // namespace

std::size_t EdgeSegmentation::edge_vertex_count() const {
    return static_cast<std::size_t>(std::count(is_edge.begin(), is_edge.end(), 1));
}

EdgeSegmentation segment_edges(const Mesh& mesh, const Connectivity& connectivity,
                               const PrincipalCurvatures& curvatures,
                               const std::vector<Vec3>& face_normals,
                               const EdgeSegmentationOptions& options) {
    validate(options);
    EdgeSegmentation s;
    s.is_edge = cluster_edge_vertices(curvatures, options, s.kmeans_iterations);
    s.clustered_edge_vertices = s.edge_vertex_count();
    s.isolated_removed = remove_isolated(mesh, connectivity, s.is_edge);
    s.bridge_vertices_added =
        bridge_broken_edges(mesh, connectivity, options.max_bridge_walk, s.is_edge);
    s.flat_removed =
        remove_flat(connectivity, face_normals, options.flat_normal_spread_deg, s.is_edge);
    return s;
}

}  // namespace resharp
