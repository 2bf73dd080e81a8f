#include "resharp/eval/validity.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_set>

#include "resharp/core/errors.h"
#include "resharp/eval/restoration_rate.h"
#include "resharp/eval/self_intersections.h"
#include "resharp/mesh/diagnostics.h"
#include "resharp/mesh/geometry.h"
#include "resharp/mesh/uniform_grid.h"

namespace resharp::eval {
namespace {

/// Turned more than 90 degrees means a dot product of unit normals below minus this: a face in
/// one plane of a right-angled edge is not turned against the other plane, whatever the rounding.
constexpr double kRightAngleMargin = 1e-6;

double smallest_angle_deg(const Mesh& mesh) {
    double smallest = 180.0;
    for (const Triangle& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) {
            const Vec3& p = mesh.positions[t[k]];
            const Vec3 a = mesh.positions[t[(k + 1) % 3]] - p,
                       b = mesh.positions[t[(k + 2) % 3]] - p;
            const double area2 = a.cross(b).norm();
            if (area2 == 0.0) break;  // degenerate: counted apart
            smallest = std::min(smallest, std::atan2(area2, a.dot(b)) * 180.0 / std::numbers::pi);
        }
    }
    return smallest;
}

/// A face's vertex set as one key, for finding output faces that are input faces.
struct FaceKey {
    std::size_t operator()(const Triangle& t) const {
        return (std::size_t{t[0]} * 73856093u) ^ (std::size_t{t[1]} * 19349663u) ^
               (std::size_t{t[2]} * 83492791u);
    }
};

/// The grid cell for point searches near the mesh: its mean edge length.
double mean_edge_length(const Mesh& mesh) {
    double sum = 0.0;
    for (const Triangle& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) {
            sum += (mesh.positions[t[k]] - mesh.positions[t[(k + 1) % 3]]).norm();
        }
    }
    return sum > 0.0 ? sum / (3.0 * double(mesh.face_count())) : 1.0;
}

Triangle sorted(Triangle t) {
    std::sort(t.begin(), t.end());
    return t;
}

/// Whether unit normal n turns more than 90 degrees against normal_of(i) for every item i of
/// `grid` no farther from q than the nearest one plus `tie`; false for an empty grid.
template <class Distance, class Normal>
bool turned_against_every_nearest(const detail::UniformGrid& grid, const Vec3& q, const Vec3& n,
                                  double tie, Distance&& distance, Normal&& normal_of) {
    const auto [nearest, d] = grid.nearest(q, distance);
    if (nearest == kNoIndex) return false;
    const double reach = d + tie;
    bool turned = true;
    grid.for_each_near(q, reach, [&](Index i) {  // Bound: the items filed in the cells within reach
        if (turned && distance(i) <= reach && n.dot(normal_of(i)) >= -kRightAngleMargin) {
            turned = false;
        }
    });
    return turned;
}

}  // namespace

MeshValidity check_validity(const Mesh& mesh) {
    const MeshDiagnostics d = diagnose(mesh, build_connectivity(mesh));
    MeshValidity v;
    v.vertices = mesh.vertex_count();
    v.triangles = mesh.face_count();
    v.boundary_edges = d.boundary_edges;
    v.nonmanifold_edges = d.nonmanifold_edges;
    v.inconsistent_edges = d.inconsistent_edges;
    v.degenerate_faces = d.degenerate_faces;
    v.self_intersections = self_intersecting_pairs(mesh).size();
    v.min_angle_deg = smallest_angle_deg(mesh);
    return v;
}

std::size_t count_flipped_faces(const Mesh& input, const Mesh& output, const Oracle& oracle,
                                const SurfaceSamples& exact, FlipScope scope) {
    const std::vector<std::uint8_t> flipped = flipped_faces(input, output, oracle, exact, scope);
    return static_cast<std::size_t>(std::count(flipped.begin(), flipped.end(), 1));
}

std::vector<std::uint8_t> flipped_faces(const Mesh& input, const Mesh& output, const Oracle& oracle,
                                        const SurfaceSamples& exact, FlipScope scope) {
    check_output_extends_input(input, output);
    if (oracle.normals.size() != input.vertex_count()) {
        throw InvalidInput("the oracle does not have one normal per input vertex");
    }
    std::unordered_set<Triangle, FaceKey> input_faces;
    if (scope == FlipScope::ChangedFaces) {
        for (const Triangle& t : input.triangles) input_faces.insert(sorted(t));
    }
    const detail::UniformGrid exact_grid(
        exact.size(), [&](std::size_t i) { return detail::Box3(exact.points[i], exact.points[i]); },
        mean_edge_length(input));
    const Index first_new = static_cast<Index>(input.vertex_count());
    // An off-surface vertex carries the normal of the exact point nearest it, which beside an
    // edge can be the other face's: a face lying on one face of a 90 degree edge would meet it
    // at a dot product of 0 (docs/robustness.md). A face with a vertex farther than
    // kOffSurface mean edge lengths from its surface point (a midpoint or surface-nets vertex,
    // not a bisection one, h/512 off) is judged where it lies, against the samples about as
    // near its centroid as the nearest (within its vertices' largest offset).
    constexpr double kOffSurface = 0.01;
    const double off_distance = kOffSurface * mean_edge_length(input);
    const auto offset = [&](Index v) {
        return oracle.surface_points.empty()
                   ? 0.0
                   : (input.positions[v] - oracle.surface_points[v]).norm();
    };
    std::vector<std::uint8_t> flipped(output.face_count(), 0);
    for (Index f = 0; f < output.face_count(); ++f) {
        const Triangle& t = output.triangles[f];
        if (scope == FlipScope::ChangedFaces && input_faces.count(sorted(t))) continue;
        const Vec3 &a = output.positions[t[0]], &b = output.positions[t[1]],
                   &c = output.positions[t[2]];
        const Vec3 n = (b - a).cross(c - a);
        if (n.squaredNorm() == 0.0) continue;
        bool is_flipped = false, has_input_vertex = false;
        double face_offset = 0.0;  // the farthest its mesher put one of its vertices off
        for (Index v : t) {
            if (v >= first_new) continue;
            has_input_vertex = true;
            face_offset = std::max(face_offset, offset(v));
            is_flipped = is_flipped || n.dot(oracle.normals[v]) <= 0.0;
        }
        if ((!has_input_vertex || face_offset > off_distance || is_flipped) && exact.size() > 0) {
            // A face whose mesher put its vertices up to face_offset off the surface may lie
            // that much nearer one face of an edge than the other, and the surface point
            // nearest it lie up to the samples' spacing from the nearest sample: it is turned
            // only if it turns against every sample within both of the nearest. So too a face
            // the vertex test finds turned: a vertex on an edge (a grid line crossing it) has
            // the normal of one of its two surfaces, and a face on the other one meets that
            // normal at the edge's angle, 90 degrees or more (CAD parts at 100 cells: every
            // split piece so counted lay on the other surface).
            const Vec3 q = (a + b + c) / 3.0;
            is_flipped = turned_against_every_nearest(
                exact_grid, q, n.normalized(), face_offset + exact.spacing,
                [&](Index i) { return (exact.points[i] - q).norm(); },
                [&](Index i) { return exact.normals[i]; });
        }
        flipped[f] = is_flipped;
    }
    return flipped;
}

std::vector<std::uint8_t> turned_against_input(const Mesh& input, const Mesh& output) {
    if (output.vertex_count() < input.vertex_count()) {
        throw InvalidInput(
            "the output has fewer vertices than the input: output vertex i must be "
            "input vertex i, moved or not");
    }
    std::unordered_set<Triangle, FaceKey> input_faces;
    for (const Triangle& t : input.triangles) input_faces.insert(sorted(t));
    const std::vector<Vec3> input_normals = face_normals(input);  // zero where degenerate
    const detail::UniformGrid grid = detail::face_grid(input, mean_edge_length(input));
    // Distances within rounding of each other tie, relative to the part, so that a scaled or
    // moved part ties the same faces (as tests/support/harm_criteria.h, which checks this).
    Eigen::AlignedBox3d box;
    for (const Vec3& p : input.positions) box.extend(p);
    const double tie = 1e-10 * box.diagonal().norm();
    const auto moved = [&](Index v) {
        return v >= input.vertex_count() || output.positions[v] != input.positions[v];
    };
    std::vector<std::uint8_t> turned(output.face_count(), 0);
    for (Index f = 0; f < output.face_count(); ++f) {  // Bound: the output's faces
        const Triangle& t = output.triangles[f];
        if (input_faces.count(sorted(t)) && !moved(t[0]) && !moved(t[1]) && !moved(t[2])) continue;
        const Vec3 &a = output.positions[t[0]], &b = output.positions[t[1]],
                   &c = output.positions[t[2]];
        const Vec3 n = triangle_normal(a, b, c);
        const auto turned_at = [&](const Vec3& q) {
            const auto distance = [&](Index g) {
                const Triangle& s = input.triangles[g];
                return std::sqrt(squared_distance_to_triangle(
                    q, input.positions[s[0]], input.positions[s[1]], input.positions[s[2]]));
            };
            return turned_against_every_nearest(grid, q, n, tie, distance,
                                                [&](Index g) { return input_normals[g]; });
        };
        turned[f] = n.isZero(0.0) || turned_at((a + b + c) / 3.0) || turned_at(a) || turned_at(b) ||
                    turned_at(c);
    }
    return turned;
}

}  // namespace resharp::eval
