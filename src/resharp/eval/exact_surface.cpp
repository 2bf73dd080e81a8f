#include "resharp/eval/exact_surface.h"

#include <algorithm>
#include <cmath>

namespace resharp::eval {
namespace {

using Vec2 = Eigen::Vector2d;
using Form = ImplicitSurface::Form;
using Method = sim::SweptVolume::Method;
using sim::ToolPart;

/// The distance in plan from p to the motion's path, and its gradient (zero on the path).
SurfaceValue plan_distance(const sim::ToolMotion& motion, const Vec3& p) {
    const Vec2 away = p.head<2>() - sim::nearest_on_path(motion, p.head<2>());
    const double d = away.norm();
    if (d == 0.0) return {0.0, Vec3::Zero()};
    return {d, Vec3(away.x() / d, away.y() / d, 0.0)};
}

SurfaceValue capsule(const ImplicitSurface& s, const Vec3& p) {
    const Vec3 axis = s.motion.end - s.motion.start;
    const double length_squared = axis.squaredNorm();
    const double t = length_squared > 0.0
                         ? std::clamp((p - s.motion.start).dot(axis) / length_squared, 0.0, 1.0)
                         : 0.0;
    const Vec3 away = p - (s.motion.start + t * axis);
    const double d = away.norm();
    return {d - s.radius, d > 0.0 ? Vec3(away / d) : Vec3::Zero()};
}

SurfaceValue rim(const ImplicitSurface& s, const Vec3& p) {
    const Vec3 delta = s.motion.end - s.motion.start;
    const double along = (p.z() - s.motion.start.z() - s.height) / delta.z();
    const Vec2 away = p.head<2>() - (s.motion.start.head<2>() + along * delta.head<2>());
    const double d = away.norm();
    if (d == 0.0) return {-s.radius, Vec3::Zero()};
    const Vec2 g = away / d;
    // Moving p up by dz moves the circle's centre by dz * delta_xy / delta_z.
    return {d - s.radius, Vec3(g.x(), g.y(), -g.dot(delta.head<2>()) / delta.z())};
}

ImplicitSurface plane(const Vec3& normal, double offset) {
    ImplicitSurface s;
    s.form = Form::Plane;
    s.normal = normal;
    s.offset = offset;
    return s;
}

ImplicitSurface around(Form form, const sim::ToolMotion& motion, double radius) {
    ImplicitSurface s;
    s.form = form;
    s.motion = motion;
    s.radius = radius;
    return s;
}

}  // namespace

SurfaceValue ImplicitSurface::evaluate(const Vec3& p) const {
    switch (form) {
        case Form::Plane:
            return {normal.dot(p) - offset, normal};
        case Form::Wall: {
            const SurfaceValue d = plan_distance(motion, p);
            return {d.value - radius, d.gradient};
        }
        case Form::Toroidal: {
            const SurfaceValue d = plan_distance(motion, p);
            const double across = d.value - inset, up = p.z() - height;
            const double r = std::hypot(across, up);
            if (r == 0.0) return {-radius, Vec3::Zero()};
            return {r - radius, (across * d.gradient + up * Vec3::UnitZ()) / r};
        }
        case Form::Capsule:
            return capsule(*this, p);
        case Form::Rim:
            return rim(*this, p);
    }
    return {};
}

ImplicitSurface stock_face(const sim::Box3& stock, int face) {
    const int axis = face / 2;
    const bool upper = face % 2 == 1;
    const Vec3 n = (upper ? 1.0 : -1.0) * Vec3::Unit(axis);
    return plane(n, n.dot(upper ? stock.max() : stock.min()));
}

std::optional<ImplicitSurface> tool_part_surface(const sim::SweptVolume& volume, ToolPart part) {
    const sim::Tool& tool = volume.tool();
    const sim::ToolMotion& motion = volume.motion();
    const Method method = volume.method();
    // Sampled bull-nose ramps are not exact; V-bit surfaces are not modelled here yet: both
    // junctions are counted apart, not in the rate.
    if (method == Method::SampledRamp || method == Method::ConeRamp) return std::nullopt;
    const double low = std::min(motion.start.z(), motion.end.z());
    const double high = std::max(motion.start.z(), motion.end.z());
    const bool ramp = method == Method::FlatRamp || method == Method::BallRamp;
    switch (part) {
        case ToolPart::Bottom:
            // The lowest copy's disk; a ball end ramping has none (its ball is the Corner).
            if (method == Method::BallRamp) return std::nullopt;
            return plane(-Vec3::UnitZ(), -low);
        case ToolPart::Corner: {
            if (tool.corner_radius == 0.0 || method == Method::FlatRamp) return std::nullopt;
            if (method == Method::BallRamp) {
                sim::ToolMotion centre = motion;
                centre.start.z() += tool.radius;
                centre.end.z() += tool.radius;
                return around(Form::Capsule, centre, tool.radius);
            }
            ImplicitSurface s = around(Form::Toroidal, motion, tool.corner_radius);
            s.inset = tool.radius - tool.corner_radius;
            s.height = low + tool.corner_radius;
            return s;
        }
        case ToolPart::Side:
            return around(Form::Wall, motion, tool.radius);
        case ToolPart::Top:
            return plane(Vec3::UnitZ(), high + tool.flute_length);
        case ToolPart::Cone:
        case ToolPart::ConeRim:
            return std::nullopt;  // V-bit surfaces: not modelled here yet (see above)
        case ToolPart::BottomRim:
        case ToolPart::TopRim: {
            if (!ramp) return std::nullopt;
            ImplicitSurface s = around(Form::Rim, motion, tool.radius);
            // The bottom rim is where the side starts: the tip of a flat end, the ball's equator.
            const double bottom = method == Method::BallRamp ? tool.radius : 0.0;
            s.height = part == ToolPart::TopRim ? tool.flute_length : bottom;
            return s;
        }
    }
    return std::nullopt;
}

}  // namespace resharp::eval
