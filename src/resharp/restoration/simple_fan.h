#pragma once
/// The simple-fan certificate of the harm check's crossing test: whether the output faces around
/// one vertex form a disc that, seen along one axis, turns once around the vertex. Then no two
/// of them that share only that vertex can cross, and the pairwise test can skip them.

#include <array>
#include <cstddef>
#include <vector>

#include "resharp/core/types.h"

namespace resharp {

/// Fans of more faces than this are left to the pairwise test (grid meshes have 4 to 12).
inline constexpr std::size_t kMaxFan = 16;

/// One face around a vertex (the apex): the vertices after and before the apex in the face's
/// counter-clockwise order, and its unit normal (zero for a degenerate face).
struct Wedge {
    Index next = kNoIndex, prev = kNoIndex;
    const Vec3* normal = nullptr;
};

/// The faces around a vertex, at most kMaxFan; `overflow` when there were more. The normals
/// are referred to, not copied: they must outlive the fan.
struct Fan {
    std::array<Wedge, kMaxFan> wedges;
    std::size_t size = 0;
    bool overflow = false;

    /// Adds triangle t, which holds `apex`, with its unit normal.
    void add(const Triangle& t, Index apex, const Vec3& normal) {
        if (size == kMaxFan) {
            overflow = true;
            return;
        }
        const int k = t[0] == apex ? 0 : t[1] == apex ? 1 : 2;
        wedges[size++] = {t[(k + 1) % 3], t[(k + 2) % 3], &normal};
    }
};

/// Whether the faces around `apex` form one simple fan: a closed disc that, seen along the sum
/// of their normals (the axis), turns once around the apex with every face turning forwards.
/// Then the faces, seen along the axis, lie in angular sectors around the apex that overlap
/// nowhere, so two of them that share only the apex meet nowhere else.
///
/// Why the checks prove it. Every face faces the axis (cosine above kFrontCosine), so seen
/// along it each face turns forwards (counter-clockwise) from its `next` side to its `prev`
/// side, by less than half a turn. Every `prev` is exactly one face's `next`, and no face
/// follows two, so following them is a permutation: the faces chain into closed cycles, each
/// turning a whole number of times (at least once) around the apex. Counting
/// the faces that cross one line from the apex (from its right side to its left) counts those
/// turns; one crossing leaves one cycle turning once. The sides are
/// computed once per edge, so the count is consistent, and edges nearer the line than
/// kOffLineRatio of their length are refused, so rounding cannot misplace one.
///
/// Takes the positions the fan's vertex ids index and the apex. False (not proven) for fans of
/// fewer than three faces, with more than kMaxFan, open, non-manifold or folded ones.
bool is_simple_fan(const std::vector<Vec3>& positions, Index apex, const Fan& fan);

}  // namespace resharp
