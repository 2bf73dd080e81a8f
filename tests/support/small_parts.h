#pragma once
/// Small machined parts described by constructive solid geometry (sim/csg.h), sampled on a
/// tri-dexel grid and meshed by the simulator: seeds for property tests and the restore()
/// fuzzer. No GoogleTest here, so that the fuzzer builds them too.

#include <array>
#include <string_view>

#include "resharp/mesh/mesh.h"
#include "resharp/sim/csg.h"
#include "resharp/sim/marching_cubes.h"
#include "resharp/sim/tridexel.h"

namespace resharp::test {

enum class SmallPart {
    /// The block [0, 14] x [0, 11] x [0, 6] mm with a square pocket 3.2 mm deep and a through
    /// hole: convex and concave edges, corners, a cylinder.
    PocketedBlock,
    /// A 3 mm plate under a round boss with a conical chamfer, a ball-end dimple in the plate:
    /// slanted and curved faces.
    BossedPlate,
    /// A block cut by a slanted plane, the whole turned about two axes: no edge along the grid.
    TiltedWedge,
};
inline constexpr std::array<SmallPart, 3> kSmallParts{
    SmallPart::PocketedBlock, SmallPart::BossedPlate, SmallPart::TiltedWedge};

std::string_view to_string(SmallPart part);

/// The part sampled at `pitch` (mm; grid phase 0.37, so that its faces at round coordinates are
/// off the grid planes) and meshed by `mesher`: closed, manifold, outward oriented. At the default
/// pitch 0.5 they have 5,920, 4,644 and 5,112 triangles; the count grows as 1 / pitch^2.
Mesh small_part(SmallPart part, double pitch = 0.5,
                sim::Mesher mesher = sim::Mesher::MarchingCubes);

/// The part's exact solid, and the grid small_part() samples it on at `pitch`.
sim::CsgSolid small_part_solid(SmallPart part);
sim::GridSpec small_part_grid(SmallPart part, double pitch = 0.5);

/// The distance from p to the solid's surface along the nearest of seven lines through p: the
/// three axes (exact where that surface is a plane across the axis) and the four body diagonals
/// (so that a point on an edge or corner of faces along the axes, which the axis lines only
/// graze, is at 0). Infinite if no line meets the solid.
double distance_along_lines(const sim::CsgSolid& solid, const Vec3& p);

}  // namespace resharp::test
