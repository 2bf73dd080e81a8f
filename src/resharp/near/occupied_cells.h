#pragma once
/// The grid cells that hold a vertex of a mesh: which cells its mesher put a vertex in. A dual
/// mesher (surface nets, OpenVDB's volumeToMesh) puts one in every cell the surface crosses where
/// its samples tell; a crossed cell with none is one where they did not, and the vertex nearest it
/// stands for it (near/vertex_moves.h).

#include <cstdint>
#include <vector>

#include "resharp/mesh/geometry.h"
#include "resharp/near/vertex_placement.h"

namespace resharp {

class OccupiedCells {
public:
    /// Takes the vertices' places and the grid they were placed on (pitch > 0). Bound: a sort of
    /// the vertices' cells.
    OccupiedCells(const std::vector<Vec3>& positions, const Grid& grid);

    /// Whether the cell that holds x (its lower faces included) holds a vertex. Bound: a
    /// bisection of the cells.
    bool holds_vertex(const Vec3& x) const;

private:
    /// A 64-bit hash of the cell's three indices: sorting them is three times as fast as
    /// sorting the indices (mech by OpenVDB: 170 000 vertices). Two cells may share one (about
    /// one pair in 2^64 / n^2); a cell so taken for occupied only keeps a vertex from it.
    std::uint64_t key_of(const Vec3& x) const;
    static std::uint64_t mix(std::uint64_t z);

    Grid grid_;
    std::vector<std::uint64_t> cells_;  ///< ascending, each once
};

}  // namespace resharp
