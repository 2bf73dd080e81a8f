#include "support/harm_criteria.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

#include "resharp/eval/self_intersections.h"
#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/diagnostics.h"
#include "resharp/mesh/geometry.h"

namespace resharp::test {
namespace {

/// The input's faces as bounding spheres sorted by the x of their centres, so that a search
/// for the faces nearest a point walks out from it along x and stops where no face left can be
/// nearer: brute force, pruned by a bound anyone can check by hand.
class NearestFaces {
public:
    explicit NearestFaces(const Mesh& input)
        : input_(input), normal_(face_normals(input)), order_(input.face_count()) {
        const std::size_t n = input.face_count();
        centre_.resize(n);
        radius_.resize(n);
        Eigen::AlignedBox3d box;
        for (std::size_t g = 0; g < n; ++g) {
            const Triangle& t = input.triangles[g];
            centre_[g] =
                (input.positions[t[0]] + input.positions[t[1]] + input.positions[t[2]]) / 3;
            for (Index v : t) {
                radius_[g] = std::max(radius_[g], (input.positions[v] - centre_[g]).norm());
                box.extend(input.positions[v]);
            }
            max_radius_ = std::max(max_radius_, radius_[g]);
        }
        std::iota(order_.begin(), order_.end(), Index{0});
        std::sort(order_.begin(), order_.end(),
                  [&](Index a, Index b) { return centre_[a].x() < centre_[b].x(); });
        sorted_x_.reserve(n);
        for (Index g : order_) sorted_x_.push_back(centre_[g].x());
        // Distances this close count as equal: a vertex lies on every face around it, at a
        // distance rounding may make slightly above 0, and a point nearest an input edge or
        // vertex is equally near the faces holding it, at any distance. Relative to the part, so
        // that a scaled, moved or renumbered part ties the same faces. (Until issue 12 the tie
        // was on squared distances, which ties faces only near a distance of 0: elsewhere
        // rounding chose, differently in each face order.)
        tie_ = 1e-10 * box.diagonal().norm();
    }

    /// Squared distances a and b, a nearer than b by more than the tie.
    bool nearer(double a, double b) const { return std::sqrt(a) + tie_ < std::sqrt(b); }

    /// The squared distance within which a face may be among the nearest, nearest being the
    /// least found so far: 1 % beyond it, and the tie.
    double bound(double nearest) const {
        const double d = std::sqrt(1.01 * nearest) + tie_;
        return d * d;
    }

    /// Whether some input face among those nearest q has a normal within 90 degrees of n.
    bool nearest_agree(const Vec3& q, const Vec3& n) const {
        double nearest = std::numeric_limits<double>::infinity();
        bool agrees = false;
        auto consider = [&](Index g) {
            const double reach = std::max(0.0, (q - centre_[g]).norm() - radius_[g]);
            if (reach * reach > bound(nearest)) return;  // cannot be among the nearest
            const Triangle& t = input_.triangles[g];
            const double d = squared_distance_to_triangle(
                q, input_.positions[t[0]], input_.positions[t[1]], input_.positions[t[2]]);
            if (nearer(d, nearest)) agrees = false;
            if (!nearer(nearest, d)) agrees = agrees || normal_[g].dot(n) >= -1e-6;
            nearest = std::min(nearest, d);
        };
        // A face whose centre is farther than max_radius_ + sqrt(bound) along x is farther than
        // sqrt(bound) from q, so each walk ends there (at the latest at the end of the list).
        auto beyond = [&](double x) {
            const double gap = std::abs(x - q.x()) - max_radius_;
            return gap > 0.0 && gap * gap > bound(nearest);
        };
        const auto start = std::lower_bound(sorted_x_.begin(), sorted_x_.end(), q.x());
        const std::size_t middle = static_cast<std::size_t>(start - sorted_x_.begin());
        for (std::size_t k = middle; k < order_.size() && !beyond(sorted_x_[k]); ++k) {
            consider(order_[k]);
        }
        for (std::size_t k = middle; k-- > 0 && !beyond(sorted_x_[k]);) consider(order_[k]);
        return agrees;
    }

private:
    const Mesh& input_;
    std::vector<Vec3> normal_;
    std::vector<Vec3> centre_;
    std::vector<double> radius_;
    double max_radius_ = 0.0;
    std::vector<Index> order_;      // faces by the x of their centres
    std::vector<double> sorted_x_;  // those x, in that order
    double tie_ = 0.0;
};

std::size_t added(std::size_t before, std::size_t after) {
    return after > before ? after - before : 0;
}

/// The face turned to start at its smallest vertex: equal for exact duplicates.
Triangle canonical(Triangle t) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
}

/// The input faces some output face comes from (in input order); counts in `lost` the other
/// faces that are not a copy of an earlier input face.
Mesh kept_faces(const Mesh& input, std::span<const Index> source_face, std::size_t& lost) {
    const std::size_t n = input.face_count();
    std::vector<std::uint8_t> is_source(n, 0);
    for (Index s : source_face) is_source[s] = 1;
    std::vector<Triangle> shape(n);
    for (std::size_t f = 0; f < n; ++f) shape[f] = canonical(input.triangles[f]);
    std::vector<Index> order(n);
    std::iota(order.begin(), order.end(), Index{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](Index a, Index b) { return shape[a] < shape[b]; });
    std::vector<std::uint8_t> is_copy(n, 0);
    for (std::size_t k = 1; k < n; ++k) is_copy[order[k]] = shape[order[k]] == shape[order[k - 1]];
    Mesh kept{input.positions, {}};
    for (std::size_t f = 0; f < n; ++f) {
        if (is_source[f]) {
            kept.triangles.push_back(input.triangles[f]);
        } else {
            lost += !is_copy[f];
        }
    }
    return kept;
}

}  // namespace

std::size_t turned_against_nearest(const Mesh& input, const Mesh& output,
                                   std::span<const Index> source_face) {
    const NearestFaces nearest(input);
    std::size_t turned = 0;
    for (std::size_t o = 0; o < output.face_count(); ++o) {
        const Triangle& t = output.triangles[o];
        const auto& x = output.positions;
        const bool corners_in_place = std::all_of(t.begin(), t.end(), [&](Index v) {
            return v < input.vertex_count() && x[v] == input.positions[v];
        });
        if (t == input.triangles[source_face[o]] && corners_in_place) continue;
        const Vec3 n = triangle_normal(x[t[0]], x[t[1]], x[t[2]]);
        bool is_turned =
            n.isZero(0.0) || !nearest.nearest_agree((x[t[0]] + x[t[1]] + x[t[2]]) / 3.0, n);
        for (Index v : t) is_turned = is_turned || !nearest.nearest_agree(x[v], n);
        turned += is_turned;
    }
    return turned;
}

std::size_t new_self_intersections(const Mesh& input, const Mesh& output,
                                   std::span<const Index> source_face) {
    const std::vector<std::pair<Index, Index>> before = eval::self_intersecting_pairs(input);
    std::size_t added_pairs = 0;
    for (const auto& [f, g] : eval::self_intersecting_pairs(output)) {
        const std::pair<Index, Index> source = std::minmax(source_face[f], source_face[g]);
        added_pairs += !std::binary_search(before.begin(), before.end(), source);
    }
    return added_pairs;
}

HarmCriteria criteria_for(const RestoreReport& report) {
    return {.allowed_move = 2.0 * std::sqrt(3.0) * report.grid_pitch};
}

HarmFound find_harm(const Mesh& input, const Mesh& output, std::span<const Index> source_face,
                    const HarmCriteria& criteria) {
    HarmFound h;
    if (output.vertex_count() < input.vertex_count()) {
        h.moved_input_vertices = input.vertex_count() - output.vertex_count();
    }
    for (std::size_t v = 0; v < std::min(input.vertex_count(), output.vertex_count()); ++v) {
        const double move = (output.positions[v] - input.positions[v]).norm();
        h.moved_input_vertices +=
            output.positions[v] != input.positions[v] && !(move <= criteria.allowed_move);
    }
    h.bad_source_faces = source_face.size() == output.face_count() ? 0 : 1;
    for (Index s : source_face) h.bad_source_faces += s >= input.face_count();
    if (h.bad_source_faces > 0) return h;  // the rest reads the source faces
    const Mesh kept = kept_faces(input, source_face, h.lost_faces);
    const MeshDiagnostics before = diagnose(kept, build_connectivity(kept));
    const MeshDiagnostics after = diagnose(output, build_connectivity(output));
    h.added_boundary_edges = added(before.boundary_edges, after.boundary_edges);
    h.added_nonmanifold_edges = added(before.nonmanifold_edges, after.nonmanifold_edges);
    h.added_inconsistent_edges = added(before.inconsistent_edges, after.inconsistent_edges);
    h.turned_faces = turned_against_nearest(input, output, source_face);
    if (criteria.self_intersections) {
        h.new_self_intersections = new_self_intersections(input, output, source_face);
    }
    return h;
}

}  // namespace resharp::test
