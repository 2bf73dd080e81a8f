#pragma once
/// The do-no-harm criteria (docs/method.md, "Do no harm") checked apart from the library's own
/// harm check, by other means: a brute-force search for the input faces nearest a point, edge
/// counts from diagnose() before and after, and CGAL's exact self-intersection test. No
/// GoogleTest here, so that the restore() fuzzer uses the same checks as the tests.

#include <cstddef>
#include <span>

#include "resharp/mesh/mesh.h"
#include "resharp/pipeline/report.h"

namespace resharp::test {

/// What a restoration made worse than its input; all zero when it did no harm.
struct HarmFound {
    /// Input vertices not kept bit for bit at their index (or, with HarmCriteria::allowed_move,
    /// moved farther).
    std::size_t moved_input_vertices = 0;
    std::size_t bad_source_faces = 0;  ///< output faces whose source face is out of range
    /// Input faces no output face comes from that are not a later copy of an exact duplicate
    /// (same vertices, same orientation) of an earlier input face: faces lost.
    std::size_t lost_faces = 0;
    std::size_t turned_faces = 0;  ///< see turned_against_nearest()
    std::size_t added_boundary_edges = 0;
    std::size_t added_nonmanifold_edges = 0;
    std::size_t added_inconsistent_edges = 0;
    std::size_t new_self_intersections = 0;  ///< see new_self_intersections(); 0 when not run

    bool any() const {
        return moved_input_vertices + bad_source_faces + lost_faces + turned_faces +
                   added_boundary_edges + added_nonmanifold_edges + added_inconsistent_edges +
                   new_self_intersections >
               0;
    }
};

/// Takes the input, the output and its source faces (#F out, as RestoreResult::source_face);
/// gives the output faces that replace an input face (differ from their source, or have a corner
/// moved off its input place) and turn more
/// than 90 degrees against every input face nearest their centroid or one of their vertices,
/// searched by brute force over the whole input (ties within rounding count as nearest). A face
/// of zero area counts as turned. Expects valid source faces.
std::size_t turned_against_nearest(const Mesh& input, const Mesh& output,
                                   std::span<const Index> source_face);

/// Takes the same; gives the pairs of output faces that intersect (CGAL, exact predicates) where
/// their source faces did not: pieces of one input face, or of two that did not intersect.
std::size_t new_self_intersections(const Mesh& input, const Mesh& output,
                                   std::span<const Index> source_face);

/// Which criteria find_harm() checks beyond the cheap ones.
struct HarmCriteria {
    /// Run the CGAL self-intersection test on input and output (it costs the most: about as much
    /// as restore() itself on a clean mesh).
    bool self_intersections = true;
    /// How far (mm) input vertices may move: near-surface restoration moves them within their
    /// grid cells. 0: not at all.
    double allowed_move = 0.0;
};

/// The criteria for a restoration that reported `report`: input vertices may move within the
/// diagonal of two cells of the grid it names (near-surface restoration: its own cell, or the
/// cells around it where the surface does not cross its own), not at all without one.
HarmCriteria criteria_for(const RestoreReport& report);

/// Every criterion on the input, the output and its source faces (#F out). Edges are counted
/// against the input less the exact duplicates restore() removes (MeshRepairOptions): removing
/// the third face of an edge may leave two that disagree on orientation, a defect the input
/// had under another name.
HarmFound find_harm(const Mesh& input, const Mesh& output, std::span<const Index> source_face,
                    const HarmCriteria& criteria = {});

}  // namespace resharp::test
