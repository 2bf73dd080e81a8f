#include "resharp/restoration/split.h"

#include <array>

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

double smallest_angle(const SplitVertices& ids, Index a, Index b, Index c) {
    const Vec3 &pa = ids.position(a), &pb = ids.position(b), &pc = ids.position(c);
    auto angle = [](const Vec3& apex, const Vec3& u, const Vec3& w) {
        const Vec3 x = u - apex, y = w - apex;
        return std::atan2(x.cross(y).norm(), x.dot(y));
    };
    return std::min({angle(pa, pb, pc), angle(pb, pc, pa), angle(pc, pa, pb)});
}

/// Emits the pieces of face f, counter-clockwise like the face. With a corner point: a fan
/// around it (Fig. 7b). Otherwise: an ear at each corner whose two edges were split (it lies on
/// one feature, cut off by the new sharp edge), then the rest as one triangle or a quad split
/// along the diagonal with the larger smallest angle — never along an original edge.
template <class Emit>
void emit_pieces(const Mesh& mesh, const SharpPoints& p, const SplitVertices& ids, Index f,
                 Emit&& emit) {
    const FacePolygon polygon = boundary_of(mesh, p, ids, f);
    if (p.corner_point[f] != kNoIndex) {
        const Index centre = ids.of_point(p.corner_point[f]);
        for (int i = 0; i < polygon.size; ++i) emit(polygon.at(i), polygon.at(i + 1), centre);
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
    const double quality_02 = std::min(smallest_angle(ids, rest.at(0), rest.at(1), rest.at(2)),
                                       smallest_angle(ids, rest.at(0), rest.at(2), rest.at(3)));
    const double quality_13 = std::min(smallest_angle(ids, rest.at(1), rest.at(2), rest.at(3)),
                                       smallest_angle(ids, rest.at(1), rest.at(3), rest.at(0)));
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

bool pieces_are_sound(const Mesh& mesh, const std::vector<Vec3>& face_normals,
                      const std::vector<Vec3>& feature_normals, const SharpPoints& p,
                      const SplitVertices& ids, Index f) {
    const Triangle& t = mesh.triangles[f];
    double scale = 0.0;
    for (int k = 0; k < 3; ++k) {
        scale = std::max(scale, (mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]]).squaredNorm());
    }
    bool sound = true;
    emit_pieces(mesh, p, ids, f, [&](Index a, Index b, Index c) {
        const Vec3 n = (ids.position(b) - ids.position(a)).cross(ids.position(c) - ids.position(a));
        if (n.norm() <= kCollapsedAreaRatio * scale || n.dot(face_normals[f]) <= 0.0) sound = false;
        for (Index v : {a, b, c}) {
            if (ids.is_original(v) && n.dot(feature_normals[v]) < 0.0) sound = false;
        }
    });
    return sound;
}

std::size_t drop_points_of(const Connectivity& c, SharpPoints& p, Index f) {
    std::size_t dropped = 0;
    for (Index k = 0; k < 3; ++k) {
        const Index h = 3 * f + k;
        if (p.edge_point[h] == kNoIndex) continue;
        p.edge_point[h] = kNoIndex;
        if (c.twin[h] != kNoIndex) p.edge_point[c.twin[h]] = kNoIndex;
        ++dropped;
    }
    if (p.corner_point[f] != kNoIndex) {
        p.corner_point[f] = kNoIndex;
        ++dropped;
    }
    return dropped;
}

/// Drops points until every face with points splits soundly. Only drops, so it ends.
std::size_t drop_unsound_points(const Mesh& mesh, const Connectivity& c,
                                const std::vector<Vec3>& face_normals,
                                const std::vector<Vec3>& feature_normals, SharpPoints& p,
                                const SplitVertices& ids) {
    std::vector<Index> candidates;
    for (Index f = 0; f < mesh.face_count(); ++f) {
        if (has_points(p, f)) candidates.push_back(f);
    }
    std::size_t dropped = 0;
    bool changed = true;
    while (changed) {
        changed = false;
        for (Index f : candidates) {
            if (has_points(p, f) &&
                !pieces_are_sound(mesh, face_normals, feature_normals, p, ids, f)) {
                dropped += drop_points_of(c, p, f);
                changed = true;
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
                          const std::vector<Vec3>& feature_normals, SharpPoints& points,
                          SplitReport& report, std::vector<Index>& source_face) {
    const SplitVertices ids(mesh, points);
    report.refused_by_quality =
        drop_unsound_points(mesh, connectivity, face_normals, feature_normals, points, ids);

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
