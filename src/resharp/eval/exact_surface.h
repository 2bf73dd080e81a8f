#pragma once
/// The exact surfaces of a milled part as implicit functions: each stock face and each part of a
/// tool on one motion (docs/oracle.md lists their ids), in the closed forms the simulator
/// intersects rays with (sim/sweep.h). Each form is unbounded: a tool part's surface goes on
/// past the part's edges, so where two of them meet says nothing yet about whether both bound
/// the solid there (MachinedSolid answers that).

#include <cstdint>
#include <optional>

#include "resharp/core/types.h"
#include "resharp/sim/sweep.h"
#include "resharp/surfaces/junction.h"

namespace resharp::eval {

/// One exact surface. Values are signed distances (positive outside the tool, or outside the
/// stock for a stock face) for every form but Rim, whose value is a distance in plan.
/// d(p) below is the distance in plan (XY) from p to the motion's path (sim::nearest_on_path).
struct ImplicitSurface {
    enum class Form {
        Plane,     ///< normal · p - offset
        Wall,      ///< d(p) - radius: a tool's side (cylinder, stadium, band along an arc)
        Toroidal,  ///< sqrt((d(p) - inset)² + (p_z - height)²) - radius: a ball or torus corner
                   ///< on a horizontal motion or a plunge
        Capsule,   ///< |p - nearest point of [motion.start, motion.end]| - radius: the ball of a
                   ///< ball end ramping (the ends are the ball centre's, not the tip's)
        Rim,       ///< |p_xy - c_xy(p_z)| - radius, c(z) the point of the line through the
                   ///< motion's ends at height z - height: the slanted cylinder a rim sweeps
        Cone,      ///< min over the tip positions c of the motion of cos β (|p_xy - c_xy| -
                   ///< inset) - sin β (p_z - c_z): a conical mill's cone swept along a line, an
                   ///< arc or a ramp (flanks and end cones; the union's distance outside it)
    };
    Form form = Form::Plane;
    Vec3 normal = Vec3::UnitZ();  ///< Plane: unit normal
    double offset = 0.0;          ///< Plane: normal · p on the plane, mm
    sim::ToolMotion motion;       ///< the path of every other form
    double radius = 0.0;          ///< mm
    double inset = 0.0;       ///< Toroidal: d(p) of the corner circle's centre; Cone: tip radius
    double height = 0.0;      ///< Toroidal: z of that centre; Rim: rim height above the tip
    double half_angle = 0.0;  ///< Cone: β, half the included tip angle, rad

    /// The value and gradient at p. The gradient is zero where the form has none (on a Wall's
    /// path, at a Capsule's axis).
    SurfaceValue evaluate(const Vec3& p) const;
};

/// Face `face` (sim::BoxFace: -x, +x, -y, +y, -z, +z) of the stock box, outward normal.
ImplicitSurface stock_face(const sim::Box3& stock, int face);

/// The surface `part` of `volume`'s tool sweeps, or nothing if that volume has no such part
/// (a flat end's corner, a rim off a ramp) or is not exact (SweptVolume::Method::SampledRamp).
std::optional<ImplicitSurface> tool_part_surface(const sim::SweptVolume& volume,
                                                 sim::ToolPart part);

}  // namespace resharp::eval
