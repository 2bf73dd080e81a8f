#include "resharp/restoration/split.h"

#include <algorithm>

#include "resharp/core/assert.h"
#include "resharp/core/parallel.h"
#include "resharp/restoration/pieces.h"

namespace resharp {
namespace {

/// Faces per block of the parallel passes: large enough that a block's bookkeeping is nothing
/// beside its copying.
constexpr std::size_t kBlock = 16384;

/// The faces with a point, ascending, found block by block in parallel (a scan of every face's
/// slots, most of the split's reading), and per point (#P) its output vertex if a slot uses it,
/// kNoIndex otherwise, numbered from `first` in point order. Every point a slot holds is held
/// by a slot of a face with points, so those faces' slots are all there is to read.
struct UsedPoints {
    std::vector<Index> faces;
    std::vector<Index> number;
};

UsedPoints used_points(std::size_t face_count, std::size_t point_count, const PointSlots& slots,
                       Index first) {
    const std::size_t blocks = (face_count + kBlock - 1) / kBlock;
    std::vector<std::vector<Index>> in_block(blocks);
    for_each_index(blocks, 1, [&](std::size_t b) {
        for (std::size_t f = b * kBlock; f < std::min(face_count, (b + 1) * kBlock); ++f) {
            if (slots.has_points(static_cast<Index>(f)))
                in_block[b].push_back(static_cast<Index>(f));
        }
    });
    UsedPoints used{{}, std::vector<Index>(point_count, kNoIndex)};
    for (const std::vector<Index>& faces : in_block) {
        used.faces.insert(used.faces.end(), faces.begin(), faces.end());
    }
    for (Index f : used.faces) slots.for_each_point(f, [&](Index p) { used.number[p] = 0; });
    for (Index& n : used.number) {
        if (n != kNoIndex) n = first++;
    }
    return used;
}

/// Where the output of each face with points (`split`, ascending) starts: the output faces
/// before its first piece; then, last, how many output faces there are. The faces between two
/// of them follow one for one.
std::vector<Index> first_outputs(const Mesh& mesh, const PointSlots& slots,
                                 const PieceVertices& ids, const std::vector<Index>& split) {
    std::vector<Index> pieces(split.size(), 0);
    for_each_index(split.size(), 256, [&](std::size_t i) {
        for_each_piece(mesh, slots, ids, split[i], [&](Index, Index, Index) { ++pieces[i]; });
    });
    std::vector<Index> first(split.size() + 1);
    Index extra = 0;  // output faces beyond one per input face, before split[i]'s
    for (std::size_t i = 0; i < split.size(); ++i) {
        first[i] = split[i] + extra;
        extra += pieces[i] - 1;
    }
    first.back() = static_cast<Index>(mesh.face_count()) + extra;
    return first;
}

}  // namespace

SplitMesh split_faces(const Mesh& mesh, std::span<const Vec3> points, const PointSlots& slots) {
    const PieceVertices ids(mesh, points);
    const Index original_count = static_cast<Index>(mesh.vertex_count());
    UsedPoints used = used_points(mesh.face_count(), points.size(), slots, original_count);
    const std::vector<Index>& number = used.number;
    const std::vector<Index>& split = used.faces;
    SplitMesh out;
    for (std::size_t i = 0; i < number.size(); ++i) {
        if (number[i] != kNoIndex) out.point_of_new_vertex.push_back(static_cast<Index>(i));
    }
    // Sized first and filled in parallel blocks: the copies are most of the split's time, and
    // the pieces of each block go where first_outputs() says, so the output is the same bits
    // whatever the threads.
    out.mesh.positions.resize(mesh.vertex_count() + out.point_of_new_vertex.size());
    for_each_index((mesh.vertex_count() + kBlock - 1) / kBlock, 1, [&](std::size_t b) {
        const std::size_t end = std::min(mesh.vertex_count(), (b + 1) * kBlock);
        std::copy(mesh.positions.begin() + b * kBlock, mesh.positions.begin() + end,
                  out.mesh.positions.begin() + b * kBlock);
    });
    for (std::size_t i = 0; i < out.point_of_new_vertex.size(); ++i) {
        out.mesh.positions[original_count + i] = points[out.point_of_new_vertex[i]];
    }
    const std::vector<Index> first = first_outputs(mesh, slots, ids, split);
    const std::size_t face_count = mesh.face_count();
    const std::size_t output_count = first.back();
    out.mesh.triangles.resize(output_count);
    out.source_face.resize(output_count);
    auto output_id = [&](Index id) { return ids.is_original(id) ? id : number[ids.point_of(id)]; };
    for_each_index((face_count + kBlock - 1) / kBlock, 1, [&](std::size_t block) {
        const Index begin = static_cast<Index>(block * kBlock);
        const Index end = static_cast<Index>(std::min(face_count, (block + 1) * kBlock));
        // The first face with points at or after `begin` (or the end), and where the block's
        // output starts: before that face's, by the faces between.
        std::size_t i = std::lower_bound(split.begin(), split.end(), begin) - split.begin();
        const Index next = i < split.size() ? split[i] : static_cast<Index>(face_count);
        Index o = first[i] - (next - begin);
        for (Index f = begin; f < end; ++f) {
            if (i < split.size() && split[i] == f) {
                for_each_piece(mesh, slots, ids, f, [&](Index a, Index b, Index c) {
                    out.mesh.triangles[o] = {output_id(a), output_id(b), output_id(c)};
                    out.source_face[o++] = f;
                });
                ++i;
                continue;
            }
            out.mesh.triangles[o] = mesh.triangles[f];
            out.source_face[o++] = f;
        }
    });
    out.split_faces = split.size();
    // Every piece of a face with points holds a point, so no such face comes out as itself.
    out.altered_faces = std::move(used.faces);
    return out;
}

}  // namespace resharp
