#include "resharp/restoration/split.h"

#include <algorithm>
#include <numeric>

#include "resharp/core/assert.h"
#include "resharp/restoration/pieces.h"

namespace resharp {
namespace {

/// The faces with a point, ascending, and per point (#P) its output vertex if a slot uses it,
/// kNoIndex otherwise, numbered from `first` in point order. Every point a slot holds is held
/// by a slot of a face with points, so those faces' slots are all there is to read.
struct UsedPoints {
    std::vector<Index> faces;
    std::vector<Index> number;
};

UsedPoints used_points(std::size_t face_count, std::size_t point_count, const PointSlots& slots,
                       Index first) {
    UsedPoints used{{}, std::vector<Index>(point_count, kNoIndex)};
    for (Index f = 0; f < face_count; ++f) {
        if (!slots.has_points(f)) continue;
        used.faces.push_back(f);
        slots.for_each_point(f, [&](Index p) { used.number[p] = 0; });
    }
    for (Index& n : used.number) {
        if (n != kNoIndex) n = first++;
    }
    return used;
}

/// Appends input faces begin .. end - 1 unchanged, each its own source.
void append_unchanged(const Mesh& mesh, Index begin, Index end, SplitMesh& out) {
    out.mesh.triangles.insert(out.mesh.triangles.end(), mesh.triangles.begin() + begin,
                              mesh.triangles.begin() + end);
    const std::size_t at = out.source_face.size();
    out.source_face.resize(at + (end - begin));
    std::iota(out.source_face.begin() + static_cast<std::ptrdiff_t>(at), out.source_face.end(),
              begin);
}

}  // namespace

SplitMesh split_faces(const Mesh& mesh, std::span<const Vec3> points, const PointSlots& slots) {
    const PieceVertices ids(mesh, points);
    const Index original_count = static_cast<Index>(mesh.vertex_count());
    UsedPoints used = used_points(mesh.face_count(), points.size(), slots, original_count);
    const std::vector<Index>& number = used.number;
    const std::size_t used_count = static_cast<std::size_t>(
        std::count_if(number.begin(), number.end(), [](Index n) { return n != kNoIndex; }));
    SplitMesh out;
    out.mesh.positions.reserve(mesh.vertex_count() + used_count);  // exact: no doubling on growth
    out.mesh.positions = mesh.positions;
    out.point_of_new_vertex.reserve(used_count);
    for (std::size_t i = 0; i < number.size(); ++i) {
        if (number[i] == kNoIndex) continue;
        out.mesh.positions.push_back(points[i]);
        out.point_of_new_vertex.push_back(static_cast<Index>(i));
    }
    auto output_id = [&](Index id) { return ids.is_original(id) ? id : number[ids.point_of(id)]; };
    const std::size_t new_vertices = out.point_of_new_vertex.size();
    out.mesh.triangles.reserve(mesh.face_count() + 4 * new_vertices);
    out.source_face.reserve(out.mesh.triangles.capacity());
    // The faces between two split ones go over as whole runs.
    Index next = 0;
    for (Index f : used.faces) {
        append_unchanged(mesh, next, f, out);
        ++out.split_faces;
        for_each_piece(mesh, slots, ids, f, [&](Index a, Index b, Index c) {
            out.mesh.triangles.push_back({output_id(a), output_id(b), output_id(c)});
            out.source_face.push_back(f);
        });
        next = f + 1;
    }
    append_unchanged(mesh, next, static_cast<Index>(mesh.face_count()), out);
    // Every piece of a face with points holds a point, so no such face comes out as itself.
    out.altered_faces = std::move(used.faces);
    return out;
}

}  // namespace resharp
