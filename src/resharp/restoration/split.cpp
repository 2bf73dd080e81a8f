#include "resharp/restoration/split.h"

#include <array>
#include <cmath>
#include <numbers>

#include "resharp/mesh/geometry.h"

namespace resharp {
namespace {

/// Vertex ids of the split: below `original_count` an input vertex, above it new point
/// `id - original_count`.
class SplitVertices {
public:
    SplitVertices(const Mesh& mesh, const SharpPoints& points)
        : mesh_(mesh), points_(points), original_count_(static_cast<Index>(mesh.vertex_count())) {}

    bool is_original(Index id) const { return id < original_count_; }
    Index of_point(Index point) const { return original_count_ + point; }
    const Vec3& position(Index id) const {
        return is_original(id) ? mesh_.positions[id] : points_.points[id - original_count_];
    }

private:
    const Mesh& mesh_;
    const SharpPoints& points_;
    Index original_count_;
};

/// A face's boundary after insertion: its corners with the edge points between them.
struct FacePolygon {
    std::array<Index, 6> ids{};
    int size = 0;
    void push(Index id) { ids[static_cast<std::size_t>(size++)] = id; }
    Index at(int i) const { return ids[static_cast<std::size_t>((i + size) % size)]; }
};

bool has_points(const SharpPoints& p, Index f) {
    return p.corner_point[f] != kNoIndex || p.edge_point[3 * f] != kNoIndex ||
           p.edge_point[3 * f + 1] != kNoIndex || p.edge_point[3 * f + 2] != kNoIndex;
}

FacePolygon boundary_of(const Mesh& mesh, const SharpPoints& p, const SplitVertices& ids,
                        Index f) {
    FacePolygon polygon;
    for (Index k = 0; k < 3; ++k) {
        polygon.push(mesh.triangles[f][k]);
        if (p.edge_point[3 * f + k] != kNoIndex) polygon.push(ids.of_point(p.edge_point[3 * f + k]));
    }
    return polygon;
}

/// Shape quality of a triangle, 1 for equilateral and 0 for degenerate: 4 sqrt(3) area over
/// the sum of squared edge lengths. Ranks triangles like their smallest angle, without
/// trigonometry.
double shape_quality(const SplitVertices& ids, Index a, Index b, Index c) {
    const Vec3 &pa = ids.position(a), &pb = ids.position(b), &pc = ids.position(c);
    const double edges = (pb - pa).squaredNorm() + (pc - pb).squaredNorm() + (pa - pc).squaredNorm();
    if (edges == 0.0) return 0.0;
    return 2.0 * std::sqrt(3.0) * (pb - pa).cross(pc - pa).norm() / edges;
}

/// Emits the pieces of face f, counter-clockwise like the face. With a corner point: a fan
/// around it (Fig. 7b). Otherwise: an ear at each corner whose two edges were split (it lies on
/// one feature, cut off by the new sharp edge), then the rest as one triangle or a quad split
/// along the diagonal that gives the better-shaped worse triangle, never along an original edge.
template <class Emit>
void emit_pieces(const Mesh& mesh, const SharpPoints& p, const SplitVertices& ids, Index f,
                 Emit&& emit) {
    const FacePolygon polygon = boundary_of(mesh, p, ids, f);
    if (p.corner_point[f] != kNoIndex) {
        // An edge split at the corner point itself (see repair_face) leaves its two pieces empty.
        const Index centre = ids.of_point(p.corner_point[f]);
        for (int i = 0; i < polygon.size; ++i) {
            if (polygon.at(i) != centre && polygon.at(i + 1) != centre) {
                emit(polygon.at(i), polygon.at(i + 1), centre);
            }
        }
        return;
    }
    FacePolygon rest;
    for (int i = 0; i < polygon.size; ++i) {
        const Index id = polygon.at(i);
        if (ids.is_original(id) && !ids.is_original(polygon.at(i - 1)) &&
            !ids.is_original(polygon.at(i + 1))) {
            emit(polygon.at(i - 1), id, polygon.at(i + 1));
        } else {
            rest.push(id);
        }
    }
    if (rest.size == 3) {
        emit(rest.at(0), rest.at(1), rest.at(2));
        return;
    }
    const bool may_use_02 = !(ids.is_original(rest.at(0)) && ids.is_original(rest.at(2)));
    const bool may_use_13 = !(ids.is_original(rest.at(1)) && ids.is_original(rest.at(3)));
    const double quality_02 = std::min(shape_quality(ids, rest.at(0), rest.at(1), rest.at(2)),
                                       shape_quality(ids, rest.at(0), rest.at(2), rest.at(3)));
    const double quality_13 = std::min(shape_quality(ids, rest.at(1), rest.at(2), rest.at(3)),
                                       shape_quality(ids, rest.at(1), rest.at(3), rest.at(0)));
    if (may_use_02 && (!may_use_13 || quality_02 >= quality_13)) {
        emit(rest.at(0), rest.at(1), rest.at(2));
        emit(rest.at(0), rest.at(2), rest.at(3));
    } else {
        emit(rest.at(1), rest.at(2), rest.at(3));
        emit(rest.at(1), rest.at(3), rest.at(0));
    }
}

/// Relative area below which a piece counts as collapsed: far below any real triangle of a
/// grid mesh, far above rounding noise.
constexpr double kCollapsedAreaRatio = 1e-12;

/// The normal a piece at an input vertex must agree with: the vertex's feature normal, or its
/// plain vertex normal where it has none (a vertex whose faces all lie in bands). The plain
/// normal of such a vertex leans towards the band by up to half the edge's angle, so a piece
/// must face within 60 degrees of it.
/// A feature normal is trusted to within its fit correction: on a curved feature the estimate
/// is that much off, and a piece standing almost on edge to it may lean past the true surface,
/// so the piece must face within 90 degrees less that correction. On planes it is zero.
struct ReferenceNormals {
    const FeatureNormals& feature;
    const std::vector<Vec3>& vertex;
    /// The reference normal at v, and the smallest cosine a piece's normal may make with it.
    std::pair<const Vec3&, double> at(Index v) const {
        if (feature.normal[v].isZero(0.0)) return {vertex[v], 0.5};
        const double margin = std::min<double>(feature.fit_correction_deg[v], 30.0);
        return {feature.normal[v], std::sin(margin * std::numbers::pi / 180.0)};
    }
};

/// A piece is sound when it has area and turns the way of the surface it lies on: the reference
/// normal of each of its input vertices, or, for a piece of new points only, the face it was
/// cut from. (The
/// face's own normal is no guide where a feature normal is known: along a chamfer that does not
/// follow the grid, a band face can lean almost onto one feature, 90 degrees or more from
/// pieces that rightly lie on the other.)
bool pieces_are_sound(const Mesh& mesh, const std::vector<Vec3>& face_normals,
                      const ReferenceNormals& reference, const SharpPoints& p,
                      const SplitVertices& ids, Index f) {
    const Triangle& t = mesh.triangles[f];
    double scale = 0.0;
    for (int k = 0; k < 3; ++k) {
        scale = std::max(scale, (mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]]).squaredNorm());
    }
    bool sound = true;
    emit_pieces(mesh, p, ids, f, [&](Index a, Index b, Index c) {
        const Vec3 n = (ids.position(b) - ids.position(a)).cross(ids.position(c) - ids.position(a));
        if (n.norm() <= kCollapsedAreaRatio * scale) sound = false;
        bool has_reference = false;
        for (Index v : {a, b, c}) {
            if (!ids.is_original(v)) continue;
            const auto [normal, min_cosine] = reference.at(v);
            if (normal.isZero(0.0)) continue;
            has_reference = true;
            if (n.dot(normal) <= min_cosine * n.norm()) sound = false;
        }
        if (!has_reference && n.dot(face_normals[f]) <= 0.0) sound = false;
    });
    return sound;
}

/// The slots of face f that may hold a point: its three half-edges and its corner.
struct PointSlots {
    std::array<Index*, 4> slot{};
    std::array<Index*, 4> twin_slot{};  ///< the same edge point seen from the other face
};

PointSlots slots_of(const Connectivity& c, SharpPoints& p, Index f) {
    PointSlots s;
    for (Index k = 0; k < 3; ++k) {
        const Index h = 3 * f + k;
        s.slot[k] = &p.edge_point[h];
        s.twin_slot[k] = c.twin[h] != kNoIndex ? &p.edge_point[c.twin[h]] : nullptr;
    }
    s.slot[3] = &p.corner_point[f];
    return s;
}

void clear_slot(const PointSlots& s, int i) {
    *s.slot[i] = kNoIndex;
    if (s.twin_slot[i] != nullptr) *s.twin_slot[i] = kNoIndex;
}

/// Tries `replacement` in slot i of face f; keeps it (on both faces of the edge) if the face
/// then splits soundly.
bool try_slot(const Mesh& mesh, const std::vector<Vec3>& face_normals,
              const ReferenceNormals& reference, SharpPoints& p, const SplitVertices& ids,
              Index f, const PointSlots& s, int i, Index replacement) {
    const Index kept = *s.slot[i];
    *s.slot[i] = replacement;
    const bool sound = pieces_are_sound(mesh, face_normals, reference, p, ids, f);
    *s.slot[i] = kept;
    if (!sound) return false;
    *s.slot[i] = replacement;
    if (s.twin_slot[i] != nullptr) *s.twin_slot[i] = replacement;
    return true;
}

/// Makes face f split soundly by changing as little as possible, in this order:
/// - drop a single point (the first that is enough, in slot order): two close points out of
///   order along the sharp edge make a flipped sliver, and the one kept still restores the edge;
/// - in a corner triangle, split one edge at the corner point instead of its own point: where a
///   sharp edge ends at a corner, eq. 5.2 can put the point beyond the corner on the edge's
///   extension, and the corner is where that edge really stops;
/// - drop every point of the face.
/// Returns the number of points dropped.
std::size_t repair_face(const Mesh& mesh, const Connectivity& c,
                        const std::vector<Vec3>& face_normals,
                        const ReferenceNormals& reference, SharpPoints& p,
                        const SplitVertices& ids, Index f) {
    const PointSlots s = slots_of(c, p, f);
    for (int i = 0; i < 4; ++i) {
        if (*s.slot[i] != kNoIndex &&
            try_slot(mesh, face_normals, reference, p, ids, f, s, i, kNoIndex)) {
            return 1;
        }
    }
    const Index corner = p.corner_point[f];
    const bool has_snapped_edge = *s.slot[0] == corner || *s.slot[1] == corner || *s.slot[2] == corner;
    for (int i = 0; i < 3 && corner != kNoIndex && !has_snapped_edge; ++i) {
        if (*s.slot[i] != kNoIndex &&
            try_slot(mesh, face_normals, reference, p, ids, f, s, i, corner)) {
            return 1;
        }
    }
    std::size_t dropped = 0;
    for (int i = 0; i < 4; ++i) {
        if (*s.slot[i] == kNoIndex) continue;
        clear_slot(s, i);
        ++dropped;
    }
    return dropped;
}

/// Repairs faces until every face with points splits soundly. A worklist holds the faces to
/// check: first all faces with points, then, after a repair, the faces across its edges, whose
/// split changed too. Repairs only drop points or move an edge's point onto a corner point
/// once, so it ends.
std::size_t drop_unsound_points(const Mesh& mesh, const Connectivity& c,
                                const std::vector<Vec3>& face_normals,
                                const ReferenceNormals& reference, SharpPoints& p,
                                const SplitVertices& ids) {
    std::vector<Index> work;
    std::vector<std::uint8_t> queued(mesh.face_count(), 0);
    for (Index f = 0; f < mesh.face_count(); ++f) {
        if (has_points(p, f)) {
            work.push_back(f);
            queued[f] = 1;
        }
    }
    std::size_t dropped = 0;
    for (std::size_t next = 0; next < work.size(); ++next) {
        const Index f = work[next];
        queued[f] = 0;
        if (!has_points(p, f) || pieces_are_sound(mesh, face_normals, reference, p, ids, f)) {
            continue;
        }
        dropped += repair_face(mesh, c, face_normals, reference, p, ids, f);
        for (Index k = 0; k < 3; ++k) {
            const Index twin = c.twin[3 * f + k];
            if (twin != kNoIndex && !queued[face_of(twin)]) {
                queued[face_of(twin)] = 1;
                work.push_back(face_of(twin));
            }
        }
    }
    return dropped;
}

/// Output index of each surviving point, in points order.
std::vector<Index> number_surviving_points(const SharpPoints& p, Index first) {
    std::vector<std::uint8_t> used(p.points.size(), 0);
    for (Index id : p.edge_point) if (id != kNoIndex) used[id] = 1;
    for (Index id : p.corner_point) if (id != kNoIndex) used[id] = 1;
    std::vector<Index> number(p.points.size(), kNoIndex);
    for (std::size_t i = 0; i < used.size(); ++i) {
        if (used[i]) number[i] = first++;
    }
    return number;
}

}  // namespace

Mesh split_band_triangles(const Mesh& mesh, const Connectivity& connectivity,
                          const std::vector<Vec3>& face_normals,
                          const FeatureNormals& feature_normals,
                          const std::vector<Vec3>& vertex_normals, SharpPoints& points,
                          SplitReport& report, std::vector<Index>& source_face) {
    const SplitVertices ids(mesh, points);
    const ReferenceNormals reference{feature_normals, vertex_normals};
    report.refused_by_quality =
        drop_unsound_points(mesh, connectivity, face_normals, reference, points, ids);

    const Index original_count = static_cast<Index>(mesh.vertex_count());
    const std::vector<Index> number = number_surviving_points(points, original_count);
    Mesh out;
    out.positions = mesh.positions;
    for (std::size_t i = 0; i < number.size(); ++i) {
        if (number[i] != kNoIndex) out.positions.push_back(points.points[i]);
    }
    report.new_vertices = out.positions.size() - mesh.vertex_count();

    auto output_id = [&](Index id) { return ids.is_original(id) ? id : number[id - original_count]; };
    out.triangles.reserve(mesh.face_count() + 4 * report.new_vertices);
    source_face.clear();
    source_face.reserve(out.triangles.capacity());
    for (Index f = 0; f < mesh.face_count(); ++f) {
        if (!has_points(points, f)) {
            out.triangles.push_back(mesh.triangles[f]);
            source_face.push_back(f);
            continue;
        }
        ++report.split_faces;
        emit_pieces(mesh, points, ids, f, [&](Index a, Index b, Index c) {
            out.triangles.push_back({output_id(a), output_id(b), output_id(c)});
            source_face.push_back(f);
        });
    }
    report.output_faces = out.triangles.size();
    return out;
}

}  // namespace resharp
