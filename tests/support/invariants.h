#pragma once
/// Reusable checks of the output invariants of restore() (design.md §3). Each records gtest
/// failures with the offending element, so one call covers a whole mesh.

#include <vector>

#include "resharp/mesh/mesh.h"

namespace resharp::test {

/// Every input vertex is in the output at the same index with the same coordinates, bit for bit.
void expect_input_vertices_preserved(const Mesh& input, const Mesh& output);

/// No boundary, non-manifold or inconsistently oriented edge, no non-manifold vertex, no
/// degenerate face.
void expect_closed_manifold(const Mesh& mesh);

/// Every output face turns the same way as the input face it came from (positive dot product of
/// the normals). `source_face` maps output faces to input faces (RestoreResult::source_face).
void expect_no_flipped_triangles(const Mesh& input, const Mesh& output,
                                 const std::vector<Index>& source_face);

/// The output has no self-intersection the input did not have (CGAL, exact predicates).
void expect_no_new_self_intersections(const Mesh& input, const Mesh& output);

/// Distance from p to the segment a-b.
double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b);

}  // namespace resharp::test
