#pragma once
/// The volume a tool sweeps along one motion, intersected exactly with grid rays.
///
/// What is exact and what is sampled:
/// - horizontal lines and horizontal arcs (G2/G3 in XY at constant z): exact for every tool;
///   a z-ray meets the tool where the path comes nearest, an x- or y-ray at height z meets the
///   tool's disk at that height swept along the path (a stadium or an annular sector);
/// - plunges (vertical lines): exact for every tool;
/// - ramps (lines moving in both XY and Z): exact for flat end (including the surface the
///   bottom rim sweeps), ball end (a capsule around the centre path plus the shank) and conical
///   mills (cone_ramp.h);
///   bull-nose is the union of copies of the tool every `bullnose_step` along the ramp: the
///   smooth underside is off by about step² / (8 rc), the sharp rim at the flute top (which
///   should stay above the stock) by up to a step;
/// - helical arcs are not motions: the simulator cuts them into ramps (simulate.h).
/// Crossings carry the exact outward normal of the swept volume (the tool's normal at the point
/// that generates it) and the id tool_surface_id(move, part).

#include <cstddef>

#include "resharp/sim/tool.h"
#include "resharp/sim/tridexel.h"

namespace resharp::sim {

/// One tool motion: the tool tip moves along a straight line or a horizontal circular arc.
struct ToolMotion {
    enum class Kind { Line, Arc };
    Kind kind = Kind::Line;
    Vec3 start = Vec3::Zero();         ///< tip position at the start, mm
    Vec3 end = Vec3::Zero();           ///< tip position at the end, mm
    Eigen::Vector2d center{0.0, 0.0};  ///< Arc: centre (x, y), mm
    double radius = 0.0;               ///< Arc: radius, mm
    double start_angle = 0.0;          ///< Arc: angle of `start` about the centre, rad
    double sweep = 0.0;  ///< Arc: signed angle swept, rad, positive counter-clockwise (G3)
};

/// The point of the motion's path in plan (XY) nearest `p`: on the segment between the ends'
/// XY positions, or on the arc.
Eigen::Vector2d nearest_on_path(const ToolMotion& motion, const Eigen::Vector2d& p);

struct SweepOptions {
    double bullnose_step = 0.05;  ///< spacing of the tool copies sampling a bull-nose ramp, mm
};

/// The swept volume of `tool` along `motion`; its surfaces get ids tool_surface_id(move, part).
class SweptVolume final : public Solid {
public:
    /// \throws InvalidInput if an arc changes height or has no radius, or bullnose_step <= 0.
    SweptVolume(const Tool& tool, const ToolMotion& motion, std::size_t move,
                const SweepOptions& options = {});

    Box3 bounds() const override { return bounds_; }
    void intersect(const Ray& ray, std::vector<Interval>& out) const override;

    /// How the volume is intersected, which decides the shape of each part's surface.
    enum class Method {
        Horizontal,  ///< a horizontal line or arc: the tool at the start's height along the path
        Plunge,      ///< Z only: the tool at the lower end, its top at the upper end
        FlatRamp,    ///< flat end, XY and Z together
        BallRamp,    ///< ball end, XY and Z together
        ConeRamp,    ///< V-bit, XY and Z together (cone_ramp.h)
        SampledRamp  ///< bull-nose, XY and Z together: copies every bullnose_step (not exact)
    };
    Method method() const { return method_; }
    const Tool& tool() const { return tool_; }
    const ToolMotion& motion() const { return motion_; }
    std::size_t move() const { return move_; }

private:
    void intersect_vertical(const Ray& ray, std::vector<Interval>& out) const;
    void intersect_horizontal(const Ray& ray, std::vector<Interval>& out) const;
    void intersect_static_copies(const Ray& ray, std::vector<Interval>& out) const;
    Crossing crossing(const Vec3& p, const Eigen::Vector2d& nearest, const ProfilePoint& profile,
                      double t) const;

    Tool tool_;
    ToolMotion motion_;
    std::size_t move_;
    SweepOptions options_;
    Method method_ = Method::Horizontal;
    Box3 bounds_;
};

}  // namespace resharp::sim
