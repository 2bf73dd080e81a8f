#include "resharp/restoration/split.h"

#include <algorithm>

#include "resharp/core/assert.h"
#include "resharp/restoration/pieces.h"

namespace resharp {
namespace {

/// Per point (#P): its output vertex if a slot uses it, kNoIndex otherwise; numbered from
/// `first` in point order.
std::vector<Index> number_used_points(std::size_t point_count, const PointSlots& slots,
                                      Index first) {
    std::vector<Index> number(point_count, kNoIndex);
    for (Index id : slots.edge_point) {
        if (id != kNoIndex) number[id] = 0;
    }
    for (Index id : slots.corner_point) {
        if (id != kNoIndex) number[id] = 0;
    }
    for (Index& n : number) {
        if (n != kNoIndex) n = first++;
    }
    return number;
}

}  // namespace

SplitMesh split_faces(const Mesh& mesh, std::span<const Vec3> points, const PointSlots& slots) {
    const PieceVertices ids(mesh, points);
    const Index original_count = static_cast<Index>(mesh.vertex_count());
    const std::vector<Index> number = number_used_points(points.size(), slots, original_count);
    const std::size_t used = static_cast<std::size_t>(
        std::count_if(number.begin(), number.end(), [](Index n) { return n != kNoIndex; }));
    SplitMesh out;
    out.mesh.positions.reserve(mesh.vertex_count() + used);  // exact: no doubling on growth
    out.mesh.positions = mesh.positions;
    out.point_of_new_vertex.reserve(used);
    for (std::size_t i = 0; i < number.size(); ++i) {
        if (number[i] == kNoIndex) continue;
        out.mesh.positions.push_back(points[i]);
        out.point_of_new_vertex.push_back(static_cast<Index>(i));
    }
    auto output_id = [&](Index id) { return ids.is_original(id) ? id : number[ids.point_of(id)]; };
    const std::size_t new_vertices = out.point_of_new_vertex.size();
    out.mesh.triangles.reserve(mesh.face_count() + 4 * new_vertices);
    out.source_face.reserve(out.mesh.triangles.capacity());
    for (Index f = 0; f < mesh.face_count(); ++f) {
        if (!slots.has_points(f)) {
            out.mesh.triangles.push_back(mesh.triangles[f]);
            out.source_face.push_back(f);
            continue;
        }
        ++out.split_faces;
        for_each_piece(mesh, slots, ids, f, [&](Index a, Index b, Index c) {
            out.mesh.triangles.push_back({output_id(a), output_id(b), output_id(c)});
            out.source_face.push_back(f);
        });
    }
    return out;
}

}  // namespace resharp
