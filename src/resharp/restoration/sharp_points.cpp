#include "resharp/restoration/sharp_points.h"

#include <algorithm>
#include <cstdint>

#include "resharp/core/assert.h"
#include "resharp/core/errors.h"
#include "resharp/core/parallel.h"
#include "resharp/mesh/geometric_order.h"
#include "resharp/mesh/geometry.h"
#include "resharp/surfaces/junction.h"
#include "resharp/surfaces/local_quadric.h"

namespace resharp {
namespace {

/// Below this |sin| between two unit normals the planes are treated as parallel: the edge point
/// would move by more than about 1e6 edge lengths per unit of normal error.
constexpr double kParallelSine = 1e-6;

/// Eq. 5.4's product, relative to |D|^2, below which its sign is rounding: D is a difference
/// of positions, whose relative error grows with the part's distance from the origin (about
/// 2e-12 for vertices half a millimetre apart 1e4 mm from it: on the tilted wedge of
/// property_test.cpp 1e-12 let one point's test go the other way there).
constexpr double kFlipMargin = 1e-9;

/// The point x with n_i . x = d_i for three unit normals, by Cramer's rule in vector form:
/// x = (d_1 (n_2 x n_3) + d_2 (n_3 x n_1) + d_3 (n_1 x n_2)) / (n_1 . (n_2 x n_3)). The
/// determinant is the volume the unit normals span: a scale-free conditioning test.
std::optional<Vec3> solve_planes(const Vec3& n1, const Vec3& n2, const Vec3& n3, double d1,
                                 double d2, double d3) {
    const Vec3 n23 = n2.cross(n3);
    const double det = n1.dot(n23);
    if (std::abs(det) < kParallelSine) return std::nullopt;
    return Vec3((d1 * n23 + d2 * n3.cross(n1) + d3 * n1.cross(n2)) / det);
}

}  // namespace

std::optional<Vec3> edge_point(const Vec3& a, const Vec3& n_a, const Vec3& b, const Vec3& n_b) {
    const Vec3 direction = n_a.cross(n_b);
    const double sine = direction.norm();
    if (sine < kParallelSine) return std::nullopt;
    const Vec3 d = direction / sine;
    // Solved about the edge's midpoint: the right-hand sides are then a fraction of an edge
    // length wherever the part lies, and the point moves with the part to its last bits.
    const Vec3 middle = 0.5 * (a + b);
    const std::optional<Vec3> x =
        solve_planes(n_a, n_b, d, n_a.dot(a - middle), n_b.dot(b - middle), 0.0);
    if (!x) return std::nullopt;
    return Vec3(middle + *x);
}

bool passes_flip_test(const Vec3& a, const Vec3& n_a, const Vec3& b, const Vec3& n_b) {
    const Vec3 cross = n_a.cross(n_b);
    const double sine = cross.norm();
    if (sine < kParallelSine) return false;
    const Vec3 n2 = cross / sine;                   // eq. 5.5: N_2, the edge direction
    const Vec3 d = (b - a) - (b - a).dot(n2) * n2;  // D: a-b seen in the section normal to N_2
    const Vec3 n20 = n2.cross(n_a);                 // trace of plane a in that section
    const Vec3 n21 = n2.cross(n_b);                 // trace of plane b
    // Eq. 5.4 in units of |D|^2 (the product of the sines of D's angles to the two traces): a
    // product within rounding of zero (D along a trace, the point at a or b) is refused
    // whatever the part's scale or placement, instead of going the way its last bits do.
    const double sides = n20.cross(d).dot(n2) * n21.cross(d).dot(n2);
    return sides < -kFlipMargin * d.squaredNorm();
}

std::optional<Vec3> corner_point(const Vec3& a, const Vec3& n_a, const Vec3& b, const Vec3& n_b,
                                 const Vec3& c, const Vec3& n_c) {
    const Vec3 centre = (a + b + c) / 3.0;  // as edge_point(): offsets of a triangle's size
    const std::optional<Vec3> x =
        solve_planes(n_a, n_b, n_c, n_a.dot(a - centre), n_b.dot(b - centre), n_c.dot(c - centre));
    if (!x) return std::nullopt;
    return Vec3(centre + *x);
}

namespace {

/// The new points' surfaces: tangent planes or second-order surfaces at band vertices.
///
/// Every solve works in coordinates relative to the crossing edge's midpoint (the corner
/// triangle's centroid) and converges to a tolerance relative to the edge's length, so that
/// the same part anywhere and at any scale takes the same steps and stops at the same one:
/// at 1e4 mm from the origin a coordinate's last bit is 2e-12 mm, which an absolute solve
/// carries into every value and gradient, and a convergence test can tip on it.
class SideSurfaces {
public:
    SideSurfaces(const Mesh& mesh, const FeatureNormals& features, PointPlacement placement)
        : mesh_(mesh), features_(features), placement_(placement) {}

    bool second_order() const { return placement_ == PointPlacement::SecondOrder; }

    /// Where the surfaces of u's and v's features meet nearest the edge's midpoint, starting
    /// from `start` (the tangent planes' point); `start` itself for tangent planes, for two
    /// planar sides, or where the surfaces do not meet within an edge length of it (counted).
    Vec3 edge_point(Index u, Index v, const Vec3& start, std::size_t& fallbacks) const {
        if (!second_order() || (flat(u) && flat(v))) return start;
        const Vec3& a = mesh_.positions[u];
        const Vec3& b = mesh_.positions[v];
        const Vec3 middle = 0.5 * (a + b);
        const double length = (b - a).norm();
        const std::optional<Vec3> x = edge_junction(surface(u, middle), surface(v, middle),
                                                    Vec3::Zero(), start - middle, solver(length));
        return accepted(x, middle, start, length, fallbacks);
    }

    /// Where the surfaces of the corner triangle t's three vertices meet nearest `start`.
    Vec3 corner_point(const Triangle& t, const Vec3& start, std::size_t& fallbacks) const {
        if (!second_order() || (flat(t[0]) && flat(t[1]) && flat(t[2]))) return start;
        const Vec3 &a = mesh_.positions[t[0]], &b = mesh_.positions[t[1]],
                   &c = mesh_.positions[t[2]];
        const Vec3 centre = (a + b + c) / 3.0;
        const double length = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
        const std::optional<Vec3> x =
            corner_junction(surface(t[0], centre), surface(t[1], centre), surface(t[2], centre),
                            start - centre, solver(length));
        return accepted(x, centre, start, length, fallbacks);
    }

private:
    /// True unless v's normal is its feature's fitted field (the fit was trusted to place the
    /// normal, so its slope shapes the surface too); fields kept only to tell smooth from sharp
    /// (drop_smooth_crossings) and planes, whose field is zero, give the tangent plane.
    bool flat(Index v) const {
        const NormalField& field = features_.field(v);
        return field.n0 != features_.normal(v) || field.gradient.isZero(0.0);
    }

    /// v's surface with `origin` as the origin of coordinates.
    LocalQuadric surface(Index v, const Vec3& origin) const {
        const Eigen::Matrix3d slope =
            flat(v) ? Eigen::Matrix3d::Zero() : features_.field(v).gradient;
        return quadric_from_normal_slope(Vec3(mesh_.positions[v] - origin), features_.normal(v),
                                         slope);
    }

    /// Lengths in units of the band's edges: converged to 1e-9 of them; a step at most half one.
    static JunctionSolverOptions solver(double length) {
        return {.pitch = length, .max_iterations = 20, .tolerance = 1e-9, .max_step = 0.5};
    }

    /// origin + x, the second-order point found at x about `origin`, unless the surfaces did
    /// not meet within `length` of `start`: curvatures fitted on a few faces can put a far
    /// meeting that is no edge.
    static Vec3 accepted(const std::optional<Vec3>& x, const Vec3& origin, const Vec3& start,
                         double length, std::size_t& fallbacks) {
        if (x && (*x - (start - origin)).norm() <= length) return Vec3(origin + *x);
        ++fallbacks;
        return start;
    }

    const Mesh& mesh_;
    const FeatureNormals& features_;
    PointPlacement placement_;
};

/// Barycentric coordinates below this (relative: a fraction of the face) count as outside. A
/// point this near the face's border would cut a sliver off it (the fan around the point)
/// standing almost on edge, whose normal the point's own error turns: on impeller two such
/// pieces, their point 1.6 % of the face from its edge, faced away from the exact surface. At
/// 0.03 none does on the four benchmark parts, at the cost of 0.22 points of cavity's rate (0.05:
/// 0.45), docs/results.md.
constexpr double kInsideMargin = 0.03;

/// True when p, projected along the normal of face f, falls inside f, off its border.
bool face_holds(const Mesh& mesh, Index f, const Vec3& p) {
    const Triangle& t = mesh.triangles[f];
    // Differences only: the test reads the same wherever the part lies.
    const Vec3 a = mesh.positions[t[0]] - p, b = mesh.positions[t[1]] - p,
               c = mesh.positions[t[2]] - p;
    const Vec3 n = (b - a).cross(c - a);
    const double area = n.squaredNorm();
    if (area == 0.0) return false;
    // Each coordinate is the area of the sub-triangle opposite a corner over the face's.
    const double margin = kInsideMargin * area;
    return b.cross(c).dot(n) > margin && c.cross(a).dot(n) > margin && a.cross(b).dot(n) > margin;
}

/// Whether face f may take a point inside it: not a corner triangle (whose slot its corner
/// point takes) and no other edge's point inside it already.
bool may_take_point(const BandClassification& bands, const SharpPoints& out, Index f) {
    return bands.face_role[f] != BandRole::Corner && out.slots.corner_point(f) == kNoIndex;
}

/// The face that holds the point x of crossing edge h, beyond the edge's chord, and may take it:
/// a face of the edge, else an edge triangle around one of its ends (where the junction lies
/// past an end almost on it, as at a scallop cusp; faces off the bands would take phantom points
/// on coarse smooth surfaces, docs/method.md). kNoIndex if none. Looks at the two faces and the
/// two ends' rings, each face once at most per ring.
Index holding_face(const Mesh& mesh, const Connectivity& c, const BandClassification& bands,
                   const SharpPoints& out, Index h, const Vec3& x) {
    for (Index g : {h, c.twin[h]}) {
        const Index f = face_of(g);
        if (may_take_point(bands, out, f) && face_holds(mesh, f, x)) return f;
    }
    for (Index end : {tail_vertex(mesh, h), head_vertex(mesh, h)}) {
        for (Index f : c.faces_around(end)) {
            if (f == face_of(h) || f == face_of(c.twin[h])) continue;
            if (bands.face_role[f] != BandRole::None && may_take_point(bands, out, f) &&
                face_holds(mesh, f, x))
                return f;
        }
    }
    return kNoIndex;
}

/// A point of a crossing edge beyond its chord, waiting for a face to hold it.
struct PointBeyondChord {
    Index halfedge;
    Vec3 x;
};

/// What became of the crossing edge of one half-edge (edge_placement()).
enum class EdgeFate : std::uint8_t {
    None,           ///< not a crossing edge, or its twin places it
    MissingNormal,  ///< an end has no feature normal
    Refused,        ///< by the flip test (eq. 5.4)
    Spike,          ///< by the spike test (SharpPointOptions::edge_spike_angle_deg)
    OnEdge,         ///< a point on the edge
    Beyond,         ///< second order: a point beyond the chord, for a face to hold
};

struct EdgePlacement {
    EdgeFate fate = EdgeFate::None;
    std::size_t fallbacks = 0;  ///< second-order solves that fell back to the tangent planes
    Vec3 x = Vec3::Zero();
};

/// The point of the crossing edge of half-edge h, if h runs from its end first in sweep order
/// (so each edge is placed once, in the same direction whatever the corners' order), both
/// ends have feature normals no more than `spike_angle_deg` apart (the spike test): on the edge
/// where eq. 5.4 holds; with second-order placement, where it fails, beyond the chord. Reads
/// nothing another edge's placement writes.
EdgePlacement edge_placement(const Mesh& mesh, const Connectivity& c,
                             const BandClassification& bands, const FeatureNormals& normals,
                             const SideSurfaces& sides, double spike_angle_deg, Index h) {
    EdgePlacement out;
    if (!bands.is_crossing[h] || c.twin[h] == kNoIndex) return out;
    const Index u = tail_vertex(mesh, h);
    const Index v = head_vertex(mesh, h);
    if (!vertex_swept_before(mesh, u, v)) return out;  // the twin places it
    const Vec3& a = mesh.positions[u];
    const Vec3& b = mesh.positions[v];
    if (normals.normal(u).isZero(0.0) || normals.normal(v).isZero(0.0)) {
        out.fate = EdgeFate::MissingNormal;
        return out;
    }
    // At 180 (exact meshes) no angle exceeds it, and none is measured.
    if (spike_angle_deg < 180.0 &&
        angle_deg(normals.normal(u), normals.normal(v)) > spike_angle_deg) {
        out.fate = EdgeFate::Spike;
        return out;
    }
    const std::optional<Vec3> m = edge_point(a, normals.normal(u), b, normals.normal(v));
    const bool on_edge = m && passes_flip_test(a, normals.normal(u), b, normals.normal(v));
    if (!m || (!on_edge && !sides.second_order())) {
        out.fate = EdgeFate::Refused;
        return out;
    }
    out.x = sides.edge_point(u, v, *m, out.fallbacks);
    out.fate = on_edge ? EdgeFate::OnEdge : EdgeFate::Beyond;
    return out;
}

/// Takes edge_placement()'s result for half-edge h into `out` (counts, and the point on the
/// edge numbered next) or, for a point beyond the chord, into `beyond`.
void take_edge_placement(const Connectivity& c, Index h, const EdgePlacement& placed,
                         SharpPoints& out, std::vector<PointBeyondChord>& beyond) {
    out.first_order_fallbacks += placed.fallbacks;
    switch (placed.fate) {
        case EdgeFate::None:
            return;
        case EdgeFate::MissingNormal:
            ++out.missing_normal;
            return;
        case EdgeFate::Refused:
            ++out.refused_by_flip_test;
            return;
        case EdgeFate::Spike:
            ++out.refused_by_spike_test;
            return;
        case EdgeFate::Beyond:
            beyond.push_back({h, placed.x});
            return;
        case EdgeFate::OnEdge:
            out.slots.set_edge_point(h, static_cast<Index>(out.points.size()));
            out.slots.set_edge_point(c.twin[h], static_cast<Index>(out.points.size()));
            out.points.push_back(placed.x);
            ++out.edge_points;
            return;
    }
}

/// Puts each point beyond its chord inside a face that holds it (holding_face()), in sweep order
/// of their edges: two such points may want one face, and the first takes it, so the order must
/// not be the mesh's.
void place_points_beyond_chords(const Mesh& mesh, const Connectivity& c,
                                const BandClassification& bands,
                                std::vector<PointBeyondChord> beyond, SharpPoints& out) {
    std::sort(
        beyond.begin(), beyond.end(), [&](const PointBeyondChord& p, const PointBeyondChord& q) {
            const Index pu = tail_vertex(mesh, p.halfedge), qu = tail_vertex(mesh, q.halfedge);
            if (pu != qu) return vertex_swept_before(mesh, pu, qu);
            return vertex_swept_before(mesh, head_vertex(mesh, p.halfedge),
                                       head_vertex(mesh, q.halfedge));
        });
    for (const PointBeyondChord& p : beyond) {
        const Index f = holding_face(mesh, c, bands, out, p.halfedge, p.x);
        if (f == kNoIndex) {
            ++out.refused_by_flip_test;
            continue;
        }
        out.slots.set_corner_point(f, static_cast<Index>(out.points.size()));
        out.points.push_back(p.x);
        ++out.face_points;
        ++out.edge_points;
    }
}

/// §5.2: the points of every crossing edge; only faces with a crossing edge are looked at. Points
/// on their edges first, in face order, then those inside faces.
void place_edge_points(const Mesh& mesh, const Connectivity& c, const BandClassification& bands,
                       const FeatureNormals& normals, const SideSurfaces& sides,
                       double spike_angle_deg, SharpPoints& out) {
    std::vector<Index> halfedges;  // of the faces with a crossing edge (few), in face order
    for (Index f = 0; f < bands.face_role.size(); ++f) {
        if (bands.face_role[f] == BandRole::None) continue;
        for (Index h = 3 * f; h < 3 * f + 3; ++h) halfedges.push_back(h);
    }
    // The edges are solved in parallel, then numbered in face order on one thread.
    std::vector<EdgePlacement> placed(halfedges.size());
    for_each_index(halfedges.size(), 64, [&](std::size_t i) {
        placed[i] = edge_placement(mesh, c, bands, normals, sides, spike_angle_deg, halfedges[i]);
    });
    std::vector<PointBeyondChord> beyond;
    for (std::size_t i = 0; i < halfedges.size(); ++i)
        take_edge_placement(c, halfedges[i], placed[i], out, beyond);
    place_points_beyond_chords(mesh, c, bands, std::move(beyond), out);
}

/// §5.3: the normals around a corner triangle are its vertices' feature normals and the normals
/// of the three faces across its edges; nearly opposite ones mean a spike.
bool is_spike(const Connectivity& c, const std::vector<Vec3>& face_normals,
              const std::array<Vec3, 3>& vertex_normals, Index f, double spike_angle_deg) {
    std::vector<Vec3> around(vertex_normals.begin(), vertex_normals.end());
    for (Index k = 0; k < 3; ++k) {
        const Index twin = c.twin[3 * f + k];
        if (twin != kNoIndex && !face_normals[face_of(twin)].isZero(0.0)) {
            around.push_back(face_normals[face_of(twin)]);
        }
    }
    for (std::size_t i = 0; i < around.size(); ++i) {
        for (std::size_t j = i + 1; j < around.size(); ++j) {
            if (angle_deg(around[i], around[j]) > spike_angle_deg) return true;
        }
    }
    return false;
}

/// True when p, projected along the normal of face f, lies beyond its edge k: on the far side of
/// the edge's line from the face's third corner.
bool lies_beyond_edge(const Mesh& mesh, Index f, Index k, const Vec3& p) {
    const Triangle& t = mesh.triangles[f];
    // Differences only, as face_holds().
    const Vec3 a = mesh.positions[t[k]] - p, b = mesh.positions[t[(k + 1) % 3]] - p,
               c = mesh.positions[t[(k + 2) % 3]] - p;
    return a.cross(b).dot((b - a).cross(c - a)) < 0.0;
}

/// Puts corner point `id` of corner triangle f also on each crossing edge of f that has no point
/// (eq. 5.4 refused it, no face holding it) and that the corner point lies beyond. Without it the
/// fan around the corner point (Fig. 7b) folds over that edge and the guard drops every point
/// of the face: on a mesh turned off the grid axes a corner point often lies just past an edge
/// whose own point lay past its chord (a vertex of the edge almost on the junction). On the edge
/// the fan's two pieces at it are empty (as for an edge the guard snaps onto the corner point)
/// and the face across splits at the corner point instead.
void put_on_edges_it_lies_beyond(const Mesh& mesh, const Connectivity& c,
                                 const BandClassification& bands, Index f, Index id,
                                 SharpPoints& out) {
    const Vec3& corner = out.points[id];
    for (Index k = 0; k < 3; ++k) {
        const Index h = 3 * f + k;
        if (!bands.is_crossing[h] || c.twin[h] == kNoIndex) continue;
        if (out.slots.edge_point(h) != kNoIndex || !lies_beyond_edge(mesh, f, k, corner)) continue;
        out.slots.set_edge_point(h, id);
        out.slots.set_edge_point(c.twin[h], id);
    }
}

void place_corner_points(const Mesh& mesh, const Connectivity& c,
                         const std::vector<Vec3>& face_normals, const BandClassification& bands,
                         const FeatureNormals& normals, const SideSurfaces& sides,
                         double spike_angle_deg, SharpPoints& out) {
    for (Index f = 0; f < mesh.face_count(); ++f) {
        if (bands.face_role[f] != BandRole::Corner) continue;
        const Triangle& t = mesh.triangles[f];
        const std::array<Vec3, 3> n{normals.normal(t[0]), normals.normal(t[1]),
                                    normals.normal(t[2])};
        if (n[0].isZero(0.0) || n[1].isZero(0.0) || n[2].isZero(0.0)) {
            ++out.missing_normal;
            continue;
        }
        const std::optional<Vec3> m = corner_point(mesh.positions[t[0]], n[0], mesh.positions[t[1]],
                                                   n[1], mesh.positions[t[2]], n[2]);
        if (!m || is_spike(c, face_normals, n, f, spike_angle_deg)) {
            ++out.refused_by_spike_test;
            continue;
        }
        const Index id = static_cast<Index>(out.points.size());
        out.slots.set_corner_point(f, id);
        out.points.push_back(sides.corner_point(t, *m, out.first_order_fallbacks));
        ++out.corner_points;
        put_on_edges_it_lies_beyond(mesh, c, bands, f, id, out);
    }
}

}  // namespace

namespace {

/// Invariant of the placement: edge points only on crossing edges, the same point on both
/// half-edges; every slot names an existing point.
[[maybe_unused]] bool slots_follow_bands(const Connectivity& c, const BandClassification& bands,
                                         const SharpPoints& p) {
    for (Index h = 0; h < 3 * p.slots.face_count(); ++h) {
        const Index id = p.slots.edge_point(h);
        if (id == kNoIndex) continue;
        if (!bands.is_crossing[h] || c.twin[h] == kNoIndex || p.slots.edge_point(c.twin[h]) != id ||
            id >= p.points.size()) {
            return false;
        }
    }
    for (Index f = 0; f < p.slots.face_count(); ++f) {
        const Index id = p.slots.corner_point(f);
        if (id != kNoIndex && id >= p.points.size()) return false;
    }
    return true;
}

}  // namespace

SharpPoints place_sharp_points(const Mesh& mesh, const Connectivity& connectivity,
                               const std::vector<Vec3>& face_normals,
                               const BandClassification& bands,
                               const FeatureNormals& feature_normals,
                               const SharpPointOptions& options) {
    if (!(options.spike_angle_deg > 0.0 && options.spike_angle_deg <= 180.0)) {
        throw InvalidInput("spike angle must lie in (0, 180] degrees");
    }
    if (!(options.edge_spike_angle_deg > 0.0 && options.edge_spike_angle_deg <= 180.0)) {
        throw InvalidInput("edge spike angle must lie in (0, 180] degrees");
    }
    SharpPoints out;
    out.slots = PointSlots(mesh.face_count());
    const SideSurfaces sides(mesh, feature_normals, options.placement);
    place_edge_points(mesh, connectivity, bands, feature_normals, sides,
                      options.edge_spike_angle_deg, out);
    place_corner_points(mesh, connectivity, face_normals, bands, feature_normals, sides,
                        options.spike_angle_deg, out);
    RESHARP_EXPENSIVE_ASSERT(slots_follow_bands(connectivity, bands, out));
    return out;
}

}  // namespace resharp
