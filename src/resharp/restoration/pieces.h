#pragma once
/// How a face with points is cut into pieces (paper §5.2, after Attene et al.'s EdgeSharpener),
/// shared by the guard, which judges pieces before any mesh is built, and the split, which
/// emits them. One rule in one place, so that what the guard accepted is what the split makes.

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "resharp/mesh/geometric_order.h"
#include "resharp/mesh/mesh.h"
#include "resharp/restoration/sharp_points.h"

namespace resharp {

/// Vertex ids while a mesh is split: below `original_count` an input vertex, from it on new
/// point `id - original_count`.
class PieceVertices {
public:
    PieceVertices(const Mesh& mesh, std::span<const Vec3> points)
        : mesh_(mesh), points_(points), original_count_(static_cast<Index>(mesh.vertex_count())) {}

    bool is_original(Index id) const { return id < original_count_; }
    Index of_point(Index point) const { return original_count_ + point; }
    Index point_of(Index id) const { return id - original_count_; }
    const Vec3& position(Index id) const {
        return is_original(id) ? mesh_.positions[id] : points_[id - original_count_];
    }

private:
    const Mesh& mesh_;
    std::span<const Vec3> points_;
    Index original_count_;
};

namespace detail {

/// A face's boundary after insertion: its corners with the edge points between them.
struct FacePolygon {
    std::array<Index, 6> ids{};
    int size = 0;
    void push(Index id) { ids[static_cast<std::size_t>(size++)] = id; }
    Index at(int i) const { return ids[static_cast<std::size_t>((i + size) % size)]; }
};

/// Shape qualities closer than this (relative) are a tie: far above the rounding of points solved
/// about their edge (1e-11 of its length), far below any difference of shape that matters.
inline constexpr double kQualityTie = 1e-6;

/// Shape quality of a triangle, 1 for equilateral and 0 for degenerate: 4 sqrt(3) area over
/// the sum of squared edge lengths. Ranks triangles like their smallest angle, without
/// trigonometry. Negative where the triangle turns against `facing` (the normal of the face
/// it is cut from), so that a split with a piece turned over ranks below any split without.
inline double shape_quality(const PieceVertices& ids, Index a, Index b, Index c,
                            const Vec3& facing) {
    const Vec3 &pa = ids.position(a), &pb = ids.position(b), &pc = ids.position(c);
    const double edges =
        (pb - pa).squaredNorm() + (pc - pb).squaredNorm() + (pa - pc).squaredNorm();
    if (edges == 0.0) return 0.0;
    const Vec3 n = (pb - pa).cross(pc - pa);
    const double quality = 2.0 * std::sqrt(3.0) * n.norm() / edges;
    return n.dot(facing) > 0.0 ? quality : -quality;
}

/// Whether the quad `rest` is split along its diagonal 0-2 rather than 1-3, given the worse
/// quality of each split: the better one, and on a tie the diagonal through the quad's first
/// corner in geometric order, which the face's numbering does not change.
inline bool diagonal_02_is_better(const PieceVertices& ids, const FacePolygon& rest,
                                  double quality_02, double quality_13) {
    const double tie = kQualityTie * std::max(std::abs(quality_02), std::abs(quality_13));
    if (std::abs(quality_02 - quality_13) > tie) return quality_02 > quality_13;
    int first = 0;
    for (int i = 1; i < 4; ++i) {
        if (lexicographically_less(ids.position(rest.at(i)), ids.position(rest.at(first))))
            first = i;
    }
    return first % 2 == 0;
}

}  // namespace detail

/// Calls emit(a, b, c) for each piece of face f (ids as PieceVertices numbers them),
/// counter-clockwise like the face; at most six pieces. With a corner point: a fan around it
/// (Fig. 7b). Otherwise: an ear at each corner whose two edges were split (it lies on one
/// feature, cut off by the new sharp edge; none where both hold one point), then the rest as one
/// triangle or a quad split along the diagonal that gives the better-shaped worse triangle
/// (ties: diagonal_02_is_better()), never along an original edge. A face without points is its
/// own one piece.
template <class Emit>
void for_each_piece(const Mesh& mesh, const PointSlots& slots, const PieceVertices& ids, Index f,
                    Emit&& emit) {
    detail::FacePolygon polygon;
    for (Index k = 0; k < 3; ++k) {
        polygon.push(mesh.triangles[f][k]);
        if (slots.edge_point(3 * f + k) != kNoIndex) {
            polygon.push(ids.of_point(slots.edge_point(3 * f + k)));
        }
    }
    if (slots.corner_point(f) != kNoIndex) {
        // An edge snapped onto the corner point (the guard's repair) leaves its two pieces empty.
        const Index centre = ids.of_point(slots.corner_point(f));
        for (int i = 0; i < polygon.size; ++i) {
            if (polygon.at(i) != centre && polygon.at(i + 1) != centre) {
                emit(polygon.at(i), polygon.at(i + 1), centre);
            }
        }
        return;
    }
    detail::FacePolygon rest;
    for (int i = 0; i < polygon.size; ++i) {
        const Index id = polygon.at(i);
        if (ids.is_original(id) && !ids.is_original(polygon.at(i - 1)) &&
            !ids.is_original(polygon.at(i + 1))) {
            // Both edges of the corner on one point (the guard's merge): the ear is a segment,
            // and the corner is cut off by the faces across those edges alone.
            if (polygon.at(i - 1) != polygon.at(i + 1))
                emit(polygon.at(i - 1), id, polygon.at(i + 1));
        } else if (rest.size == 0 || id != rest.at(rest.size - 1)) {
            rest.push(id);
        }
    }
    if (rest.size > 3 && rest.at(rest.size - 1) == rest.at(0)) --rest.size;  // (a merge)
    if (rest.size == 3) {
        emit(rest.at(0), rest.at(1), rest.at(2));
        return;
    }
    using detail::shape_quality;
    const bool may_use_02 = !(ids.is_original(rest.at(0)) && ids.is_original(rest.at(2)));
    const bool may_use_13 = !(ids.is_original(rest.at(1)) && ids.is_original(rest.at(3)));
    // A quad whose corner lies past the line of the sharp edge (beside a corner of mixed
    // convexity, where the edge ends) turns one piece over with one diagonal only.
    const auto& t = mesh.triangles[f];
    const Vec3 facing = (mesh.positions[t[1]] - mesh.positions[t[0]])
                            .cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
    const double quality_02 =
        std::min(shape_quality(ids, rest.at(0), rest.at(1), rest.at(2), facing),
                 shape_quality(ids, rest.at(0), rest.at(2), rest.at(3), facing));
    const double quality_13 =
        std::min(shape_quality(ids, rest.at(1), rest.at(2), rest.at(3), facing),
                 shape_quality(ids, rest.at(1), rest.at(3), rest.at(0), facing));
    // Within kQualityTie the diagonals are alike: a symmetric quad (two points mirrored about
    // its diagonal, as on a boss) ties exactly, and neither the last bits of the points, which
    // differ with where the part lies, nor the corner the face starts at may choose.
    if (may_use_02 &&
        (!may_use_13 || detail::diagonal_02_is_better(ids, rest, quality_02, quality_13))) {
        emit(rest.at(0), rest.at(1), rest.at(2));
        emit(rest.at(0), rest.at(2), rest.at(3));
    } else {
        emit(rest.at(1), rest.at(2), rest.at(3));
        emit(rest.at(1), rest.at(3), rest.at(0));
    }
}

}  // namespace resharp
