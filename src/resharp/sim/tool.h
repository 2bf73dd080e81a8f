#pragma once
/// Mills: flat end, ball end and bull-nose (torus corner) as one profile family, and conical
/// mills (V-bits and chamfer mills).
///
/// The profile is given in (r, z'): r the distance from the tool axis, z' the height above the
/// tip. An end mill of radius R and corner radius rc has a flat bottom out to r = R - rc, a
/// quarter circle of radius rc (the torus, or the ball when rc = R) up to z' = rc, then a
/// cylinder of radius R up to the flute length H. Flat end: rc = 0; ball end: rc = R. A conical
/// mill of half tip angle β has a flat tip out to r = rt (0 for a sharp V), a cone
/// r = rt + z' tan β up to z' = (R - rt) / tan β, then the cylinder. Above H nothing cuts.

#include <cstdint>
#include <string>

#include "resharp/core/types.h"

namespace resharp::sim {

enum class ToolShape { FlatEnd, BallEnd, BullNose, Cone };

/// The parts of a tool's surface, as they appear in surface ids (docs/oracle.md).
enum class ToolPart : std::int32_t {
    Bottom = 0,     ///< the flat bottom disk (r <= R - rc)
    Corner = 1,     ///< the torus (bull-nose) or the ball
    Side = 2,       ///< the cylinder r = R
    Top = 3,        ///< the disk at z' = H (where the cut stops)
    BottomRim = 4,  ///< surface swept by the bottom rim (flat end, cone's flat tip) on a ramp
    TopRim = 5,     ///< surface swept by the top rim on a ramp
    Cone = 6,       ///< the cone of a conical mill
    ConeRim = 7,    ///< surface swept by the rim between the cone and the cylinder on a ramp
};

/// Surface ids: stock face k (0..5) is k; part p of the tool on move m is (m + 1) * 8 + p.
inline constexpr std::int32_t kSurfacesPerMove = 8;
inline std::int32_t tool_surface_id(std::size_t move, ToolPart part) {
    return static_cast<std::int32_t>((move + 1) * kSurfacesPerMove) +
           static_cast<std::int32_t>(part);
}

struct Tool {
    ToolShape shape = ToolShape::FlatEnd;
    double radius = 5.0;         ///< R, half the diameter, mm
    double corner_radius = 0.0;  ///< rc, mm: 0 for flat end, R for ball end, in (0, R) bull-nose
    double flute_length = 30.0;  ///< H, cutting length above the tip, mm (>= rc, >= cone height)
    double half_angle = 0.0;     ///< β, cone: half the included tip angle, rad, in (0, π/2)
    double tip_radius = 0.0;     ///< rt, cone: radius of the flat tip, mm, in [0, R)

    /// An end mill from the numbers of a tool table (not a cone).
    /// \throws InvalidInput if a size is not positive and finite, the corner radius is not
    /// within (0, R) for a bull-nose, the flute is shorter than the corner, or shape is Cone.
    static Tool make(ToolShape shape, double diameter, double corner_radius, double flute_length);

    /// A conical mill: included tip angle in degrees, flat tip diameter (0 for a sharp V).
    /// \throws InvalidInput if the angle is not within (0, 180), a size is not finite, the
    /// diameter or flute length is not positive, the tip diameter not within [0, diameter), or
    /// the flute is shorter than the cone.
    static Tool make_cone(double diameter, double tip_angle_deg, double tip_diameter,
                          double flute_length);

    /// Cone: height z' where the cone meets the cylinder, (R - rt) / tan β; 0 for end mills.
    double cone_height() const;
};

/// A point of the tool profile: its height or radius, and the outward profile normal.
struct ProfilePoint {
    double value = 0.0;                      ///< z' for bottom_at(), r for radius_at()
    double normal_r = 0.0, normal_z = -1.0;  ///< unit outward normal in the (r, z') plane
    ToolPart part = ToolPart::Bottom;
};

/// Height z' of the tool's underside at distance r <= R from the axis.
ProfilePoint bottom_at(const Tool& tool, double r);

/// Radius of the tool at height z' in [0, H) above the tip; radius 0 where nothing is there.
ProfilePoint radius_at(const Tool& tool, double z);

/// "flat", "ball", "bullnose" or "vbit".
const char* to_string(ToolShape shape);

}  // namespace resharp::sim
