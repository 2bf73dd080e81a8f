#include "resharp/mesh/duplicate_faces.h"

#include <algorithm>
#include <array>

namespace resharp {
namespace {

/// A face's vertices rotated so that the smallest comes first: two faces are exact duplicates
/// when their keys are equal, and opposite when one's key equals the other's reversed key.
using FaceKey = std::array<Index, 3>;

FaceKey key_of(const Triangle& t) {
    const int first = t[0] < t[1] ? (t[0] < t[2] ? 0 : 2) : (t[1] < t[2] ? 1 : 2);
    return {t[first], t[(first + 1) % 3], t[(first + 2) % 3]};
}

FaceKey reversed(const FaceKey& k) { return {k[0], k[2], k[1]}; }

bool has_repeated_vertex(const Triangle& t) { return t[0] == t[1] || t[1] == t[2] || t[0] == t[2]; }

/// The kinds of edge on which duplicates lie: more than two faces, or two the same way.
bool is_defective(EdgeKind kind) {
    return kind == EdgeKind::NonManifold || kind == EdgeKind::Inconsistent;
}

/// Whether face f's three half-edges all have their twin in one later face: on manifold
/// edges, the only way two faces can be opposite (counted once, from the earlier face).
bool starts_manifold_opposite_pair(const Connectivity& c, Index f) {
    const Index t0 = c.twin[3 * f];
    if (t0 == kNoIndex || face_of(t0) <= f) return false;  // most faces stop here
    const Index g = face_of(t0), t1 = c.twin[3 * f + 1], t2 = c.twin[3 * f + 2];
    return t1 != kNoIndex && t2 != kNoIndex && face_of(t1) == g && face_of(t2) == g;
}

}  // namespace

DuplicateFaces find_duplicate_faces(const Mesh& mesh, const Connectivity& connectivity) {
    DuplicateFaces out;
    std::vector<std::pair<FaceKey, Index>> candidates;
    for (Index f = 0; f < mesh.face_count(); ++f) {  // a clean mesh costs only this and the scan
        out.opposite_pairs += starts_manifold_opposite_pair(connectivity, f);
    }
    Index last = kNoIndex;  // the last face taken: a face's half-edges come one after another
    for_each_halfedge_without_twin(connectivity, [&](Index h) {
        const Index f = face_of(h);
        const Triangle& t = mesh.triangles[f];
        if (f == last || !is_defective(connectivity.edge_kind[h]) || has_repeated_vertex(t)) return;
        candidates.emplace_back(key_of(t), f);
        last = f;
    });
    if (candidates.empty()) return out;
    std::sort(candidates.begin(), candidates.end());
    std::vector<std::uint8_t> is_removed(mesh.face_count(), 0);
    for (std::size_t i = 1; i < candidates.size(); ++i) {
        if (candidates[i].first == candidates[i - 1].first) {
            is_removed[candidates[i].second] = 1;  // sorted by face within equal keys
            ++out.removed;
        }
    }
    // Opposite pairs among the candidates, once per distinct key met both ways.
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        const FaceKey& key = candidates[i].first;
        if ((i > 0 && candidates[i - 1].first == key) || reversed(key) < key) continue;
        out.opposite_pairs += std::binary_search(
            candidates.begin(), candidates.end(), std::pair{reversed(key), Index{0}},
            [](const auto& a, const auto& b) { return a.first < b.first; });
    }
    if (out.removed == 0) return out;
    out.kept.reserve(mesh.face_count() - out.removed);
    for (Index f = 0; f < mesh.face_count(); ++f) {
        if (!is_removed[f]) out.kept.push_back(f);
    }
    return out;
}

Mesh keep_faces(const Mesh& mesh, const std::vector<Index>& kept) {
    Mesh out;
    out.positions = mesh.positions;
    out.triangles.reserve(kept.size());
    for (Index f : kept) out.triangles.push_back(mesh.triangles[f]);
    return out;
}

DroppedFaces drop_faces(Mesh& mesh, const std::vector<Index>& kept) {
    DroppedFaces dropped;
    std::size_t next = 0;  // in `kept`
    for (Index f = 0; f < mesh.face_count(); ++f) {
        if (next < kept.size() && kept[next] == f) {
            mesh.triangles[next++] = mesh.triangles[f];  // next <= f: not read again
        } else {
            dropped.index.push_back(f);
            dropped.triangle.push_back(mesh.triangles[f]);
        }
    }
    mesh.triangles.resize(next);
    return dropped;
}

void put_back_faces(Mesh& mesh, const DroppedFaces& dropped) {
    const std::size_t kept = mesh.face_count();
    mesh.triangles.resize(kept + dropped.index.size());
    // From the back, so that every kept face moves to a place no face still to move holds.
    std::size_t from = kept, back = dropped.index.size();
    for (std::size_t to = mesh.triangles.size(); to-- > 0;) {
        if (back > 0 && dropped.index[back - 1] == to) {
            mesh.triangles[to] = dropped.triangle[--back];
        } else {
            mesh.triangles[to] = mesh.triangles[--from];
        }
    }
}

}  // namespace resharp
