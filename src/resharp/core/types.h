#pragma once
/// Basic value types shared by every stage.

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <array>
#include <cstdint>
#include <limits>

namespace resharp {

using Vec3 = Eigen::Vector3d;

/// Index of a vertex, face or half-edge. 32 bits: meshes up to 4G elements, half the memory of
/// size_t in the adjacency tables that dominate our footprint.
using Index = std::uint32_t;

/// Marks "no such element" (a boundary half-edge has no twin, an unlabelled vertex no patch).
inline constexpr Index kNoIndex = std::numeric_limits<Index>::max();

/// Three vertex indices, counter-clockwise seen from outside.
using Triangle = std::array<Index, 3>;

}  // namespace resharp
