#pragma once
/// The part a job mills, rebuilt the way resharp::sim mills it (stock box minus every swept
/// volume, in program order) for questions about single points: which exact surface an id
/// names near a point, and where the solid's boundary crosses a line through a point.

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "resharp/eval/exact_surface.h"
#include "resharp/mesh/uniform_grid.h"
#include "resharp/sim/gcode.h"
#include "resharp/sim/simulate.h"

namespace resharp::eval {

class MachinedSolid {
public:
    /// The solid `stock` minus what `path`'s moves sweep with `tools`, as sim::simulate mills it
    /// with `options` (its pitch sizes an internal index only).
    /// \throws InvalidInput as sim::swept_volumes.
    MachinedSolid(const sim::Box3& stock, const std::map<int, sim::Tool>& tools,
                  const sim::ToolPath& path, const sim::SimulationOptions& options = {});

    /// What an id names near a point.
    enum class SurfaceKind {
        Exact,    ///< a stock face or an exact tool part: `surface` is set
        Sampled,  ///< a tool part of a bull-nose ramp, which the simulator samples
        Unknown,  ///< no stock face, and no move of the program sweeps that part
    };
    struct SurfaceNear {
        SurfaceKind kind = SurfaceKind::Unknown;
        std::optional<ImplicitSurface> surface;
        /// mm: |value| / |gradient| of `surface` at the point, a first-order distance from it.
        double distance = 0.0;
    };

    /// The exact surface `id` near `p`: of the swept volumes with that id (a helical arc has one
    /// per ramp), the one whose surface passes nearest p, to first order.
    SurfaceNear surface_near(std::int32_t id, const Vec3& p) const;

    /// The solid's boundary crossings (exact normals, surface ids, parameter t = the coordinate
    /// along `axis`) on the line through p along `axis`, within `reach` of p (mm), in order.
    std::vector<sim::Crossing> crossings_near(const Vec3& p, int axis, double reach) const;

private:
    sim::Box3 stock_;
    std::vector<sim::SweptVolume> volumes_;
    /// Per move: the range [first, last) of its volumes (volumes come in move order).
    std::map<std::size_t, std::pair<std::size_t, std::size_t>> volumes_of_move_;
    detail::UniformGrid index_;  ///< volumes by their bounds
};

}  // namespace resharp::eval
