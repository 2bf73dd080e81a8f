#pragma once
/// The tri-dexel model (docs/design.md §4): three families of grid rays, along x, y and z; each ray
/// keeps the sorted solid intervals where it lies inside the workpiece, and every interval end
/// remembers the exact parameter, the exact outward normal and the id of the surface there.
///
/// Ray families and indices. Family a runs along axis a; with b = (a + 1) % 3 and c = (a + 2) % 3
/// the ray through nodes (i_b, i_c) has index i_b + n_b * i_c and parameter t = the coordinate
/// along axis a (absolute, in mm). So z-rays are indexed i + nx * j, x-rays j + ny * k, y-rays
/// k + nz * i.
///
/// Boundaries exactly on a ray or a node (a pocket floor at a grid height, a wall on a grid
/// plane) are decided by one symbolic perturbation shared by every routine here and by the mesher:
/// boundary_is_inside().

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "resharp/core/types.h"
#include "resharp/sim/small_vector.h"

namespace resharp::sim {

using Box3 = Eigen::AlignedBox3d;

/// Where a ray meets a surface.
struct Crossing {
    double t = 0.0;              ///< coordinate along the ray's axis (mm)
    Vec3 normal = Vec3::Zero();  ///< exact unit normal there, pointing out of the solid
    std::int32_t surface = -1;   ///< id of the surface (docs/oracle.md)
};

/// A stretch of a ray inside a solid, enter.t < exit.t.
struct Interval {
    Crossing enter;
    Crossing exit;
};

/// A grid line: point(t) = origin + t * e_axis, with origin[axis] = 0.
struct Ray {
    int axis = 2;
    Vec3 origin = Vec3::Zero();

    Vec3 point(double t) const {
        Vec3 p = origin;
        p[axis] = t;
        return p;
    }
};

/// The symbolic perturbation every intersection routine and the mesher share: a point exactly on
/// a boundary counts as inside when its outward normal points against δ = (ε, ε², ε³), i.e. when
/// the first non-zero component of the normal is negative. A grid node then gets the same state
/// from all three rays through it even when a face passes exactly through it.
inline bool boundary_is_inside(const Vec3& n) {
    if (n.x() != 0.0) return n.x() < 0.0;
    if (n.y() != 0.0) return n.y() < 0.0;
    return n.z() < 0.0;
}

/// Half-length, relative to the radius, of the chord a ray gets where it only touches a round
/// surface at a point that counts as inside by boundary_is_inside(). The perturbed ray would cut
/// a chord of length ~sqrt(ε) around the touching point, holding any node there; this keeps such
/// a node in agreement with the other rays through it. The chord's ends lie within
/// (kTouchingChord² / 2) * radius of the surface.
inline constexpr double kTouchingChord = 1e-9;

/// True when crossing c lies before the node at parameter node_t on a ray along `axis`, under the
/// perturbation of boundary_is_inside(): strictly before, or at the node and ordered before it.
inline bool crossing_precedes(const Crossing& c, double node_t, int axis) {
    if (c.t != node_t) return c.t < node_t;
    return boundary_is_inside(c.normal) == (c.normal[axis] < 0.0);
}

/// A solid known through exact ray intersection.
class Solid {
public:
    virtual ~Solid() = default;
    /// A box holding the solid; rays that miss it are not asked.
    virtual Box3 bounds() const = 0;
    /// Appends to `out` the sorted, disjoint intervals where the ray lies inside the solid, with
    /// this solid's outward normals. Intervals of zero length are left out.
    virtual void intersect(const Ray& ray, std::vector<Interval>& out) const = 0;
};

/// Node positions: node (i, j, k) sits at origin + (i, j, k) * pitch.
struct GridSpec {
    Vec3 origin = Vec3::Zero();          ///< position of node (0, 0, 0), mm
    double pitch = 0.5;                  ///< node spacing h, mm
    std::array<int, 3> counts{0, 0, 0};  ///< nodes along x, y, z

    /// Coordinate of node i along `axis`; the one formula every caller uses, so node positions
    /// compare exactly.
    double node(int axis, int i) const { return origin[axis] + i * pitch; }
    /// Number of rays in family `axis`.
    std::size_t ray_count(int axis) const {
        return static_cast<std::size_t>(counts[(axis + 1) % 3]) * counts[(axis + 2) % 3];
    }
    /// Ray `index` of family `axis`.
    Ray ray(int axis, std::size_t index) const;
};

/// The grid with nodes at anchor + k * pitch (k integer) that encloses `box` with one node
/// strictly outside it on every side, so a mesh of anything inside the box is closed.
/// \throws InvalidInput if pitch is not positive or the box is empty or not finite.
GridSpec grid_enclosing(const Box3& box, double pitch, const Vec3& anchor = Vec3::Zero());

/// The simulator's grid over `box`: pitch h = `pitch`, nodes at box.min + (k + phase) * h on
/// every axis (k integer), enclosing the box as grid_enclosing() does. A phase off 0 keeps faces
/// at round coordinates off the grid planes.
/// \throws InvalidInput as grid_enclosing(), or if the grid would exceed 2^31 nodes.
GridSpec phased_grid(const Box3& box, double pitch, double phase);

/// The pitch that puts `cells` cells along the longest side of `box`.
/// \throws InvalidInput unless cells is positive and finite and the box is not empty.
double pitch_for_cells(const Box3& box, double cells);

/// The solid intervals of one ray.
using RayIntervals = SmallVector<Interval, 2>;

/// A tri-dexel model: the grid and, per family, per ray, its solid intervals.
struct DexelGrid {
    GridSpec spec;
    std::array<std::vector<RayIntervals>, 3> rays;  ///< [axis][ray index]
};

/// Samples `solid` on every ray of the grid.
DexelGrid sample_solid(const GridSpec& spec, const Solid& solid);

/// Removes `volume` from every ray it crosses. Where a removed stretch cuts a solid interval the
/// new end takes the volume's surface id and its normal reversed (it now bounds the remaining
/// material). Ends exactly tied with an existing end keep the existing one.
void subtract(DexelGrid& grid, const Solid& volume);

/// Removes each volume in turn, in order, as subtract() would one by one, with the same result
/// bit for bit; rays are visited in parallel tiles, each tile only by the volumes whose bounds
/// reach it. `on_progress(done, total)` (optional) is called from one thread as tiles finish.
void subtract_in_order(DexelGrid& grid, std::span<const Solid* const> volumes,
                       const std::function<void(std::size_t, std::size_t)>& on_progress = {});

/// Removes the sorted, disjoint `removed` intervals (outward normals of the removed volume) from
/// one ray's intervals. `scratch` is a reusable buffer.
void subtract_intervals(RayIntervals& solid, std::span<const Interval> removed,
                        std::vector<Interval>& scratch);

}  // namespace resharp::sim
