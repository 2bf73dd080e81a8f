#pragma once
/// A curved face read near a point as its tangent plane at its nearest vertex: what the bevel
/// step (near/concave_bevels.h) and the moves (near/vertex_moves.h) take a curved face for beside
/// a concave edge, where a fit over its vertices nearby would take in the rows a dual mesher
/// displaces along the edge.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "resharp/restoration/input_surface.h"
#include "resharp/surfaces/plane_fit.h"

namespace resharp {

/// Takes the mesh as it stands, each vertex's patch (#V) and band flag (#V), the vertices to
/// look among and a point x; gives the tangent plane of patch `patch` at the one of
/// `candidates` of that patch and off the bands nearest x (its vertex normal through it, its
/// centroid there); none where no candidate is one. Bound: a pass over the candidates.
std::optional<PlaneFit> tangent_plane_at_nearest(const InputSurface& surface,
                                                 const std::vector<Index>& vertex_patch,
                                                 const std::vector<std::uint8_t>& in_band,
                                                 std::span<const Index> candidates, const Vec3& x,
                                                 Index patch);

}  // namespace resharp
