#pragma once
/// Reusable checks of the output invariants of restore() (docs/design.md §3). Each records gtest
/// failures with the offending element, so one call covers a whole mesh.

#include <vector>

#include "resharp/mesh/mesh.h"
#include "resharp/pipeline/restore.h"

namespace resharp::test {

/// Every input vertex is in the output at the same index with the same coordinates, bit for bit.
void expect_input_vertices_preserved(const Mesh& input, const Mesh& output);

/// No boundary, non-manifold or inconsistently oriented edge, no non-manifold vertex, no
/// degenerate face.
void expect_closed_manifold(const Mesh& mesh);

/// No face cut by the restoration is turned against the surface it lies on: its normal has a
/// positive dot product with the exact normal of each of its input vertices, and a face made
/// only of new vertices turns the way of the input face it was cut from (`source_face`, as
/// RestoreResult::source_face gives it). Faces passed through unchanged are not judged: grid
/// meshers leave a few sliver faces in chamfer bands that already lean against a vertex normal.
void expect_no_flipped_triangles(const Mesh& input, const Mesh& output,
                                 const std::vector<Vec3>& exact_normals,
                                 const std::vector<Index>& source_face);

/// The output has no self-intersection the input did not have (CGAL, exact predicates).
void expect_no_new_self_intersections(const Mesh& input, const Mesh& output);

/// What must hold of any restoration of `input` into `r` with `options`: the harm loop within its
/// bound and nothing find_harm() (support/harm_criteria.h) finds, each criterion its own failure;
/// input vertices stay in place, or within the diagonal of two cells of the grid r's report names.
void expect_no_harm(const Mesh& input, const RestoreResult& r, const RestoreOptions& options);

/// Distance from p to the segment a-b.
double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b);

}  // namespace resharp::test
