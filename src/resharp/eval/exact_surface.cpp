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

/// The tip position along a line motion that minimises the cone's value at p: g(s) = cos β
/// |w - s e| + sin β dz s (w = p_xy - start_xy, e and dz the motion in plan and in z) is convex,
/// so its stationary point, clamped to [0, 1], is the minimum. With τ = s |e| - w·e/|e| and q the
/// distance of w from the line of e, g' = 0 where τ / sqrt(τ² + q²) = k = -tan β dz / |e|.
double cone_tip_parameter(const ImplicitSurface& s, const Vec3& p) {
    const Vec3 delta = s.motion.end - s.motion.start;
    const Eigen::Vector2d e = delta.head<2>(), w = p.head<2>() - s.motion.start.head<2>();
    const double a = e.norm();
    if (a == 0.0) return delta.z() > 0.0 ? 0.0 : 1.0;  // a plunge: the lower end
    const double k = -std::tan(s.half_angle) * delta.z() / a;
    if (k >= 1.0) return 1.0;  // descending faster than the flank: the end is lowest
    if (k <= -1.0) return 0.0;
    const double along = w.dot(e) / a;
    const double across = std::sqrt(std::max(w.squaredNorm() - along * along, 0.0));
    const double tau = k * across / std::sqrt(1.0 - k * k);
    return std::clamp((along + tau) / a, 0.0, 1.0);
}

SurfaceValue cone(const ImplicitSurface& s, const Vec3& p) {
    Vec3 tip = s.motion.start;
    Vec2 away;
    if (s.motion.kind == sim::ToolMotion::Kind::Arc) {  // horizontal: the nearest point in plan
        away = p.head<2>() - sim::nearest_on_path(s.motion, p.head<2>());
    } else {
        tip += cone_tip_parameter(s, p) * (s.motion.end - s.motion.start);
        away = p.head<2>() - tip.head<2>();
    }
    const double c = std::cos(s.half_angle), sn = std::sin(s.half_angle);
    const double d = away.norm();
    const Vec2 g = d > 0.0 ? Vec2(away / d) : Vec2::Zero();
    // The gradient at fixed s: s minimises, so its own change adds nothing (envelope theorem).
    return {c * (d - s.inset) - sn * (p.z() - tip.z()), Vec3(c * g.x(), c * g.y(), -sn)};
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

/// A ball end's or bull-nose's corner: a capsule around the ball centre's path on a ramp, a
/// sphere or torus swept along a horizontal path or plunged to `low`.
std::optional<ImplicitSurface> corner(const sim::SweptVolume& volume, double low) {
    const sim::Tool& tool = volume.tool();
    if (tool.corner_radius == 0.0 || tool.shape == sim::ToolShape::Cone ||
        volume.method() == Method::FlatRamp) {
        return std::nullopt;
    }
    if (volume.method() == Method::BallRamp) {
        sim::ToolMotion centre = volume.motion();
        centre.start.z() += tool.radius;
        centre.end.z() += tool.radius;
        return around(Form::Capsule, centre, tool.radius);
    }
    ImplicitSurface s = around(Form::Toroidal, volume.motion(), tool.corner_radius);
    s.inset = tool.radius - tool.corner_radius;
    s.height = low + tool.corner_radius;
    return s;
}

/// The slanted cylinder a rim sweeps on a ramp: the bottom rim where the side (or the cone)
/// starts (a flat end's tip, a ball's equator, a conical mill's flat tip), the rim between a
/// cone and its cylinder, the top rim.
ImplicitSurface swept_rim(const sim::SweptVolume& volume, ToolPart part) {
    const sim::Tool& tool = volume.tool();
    const bool is_cone = tool.shape == sim::ToolShape::Cone;
    ImplicitSurface s = around(Form::Rim, volume.motion(), tool.radius);
    if (part == ToolPart::TopRim) {
        s.height = tool.flute_length;
    } else if (part == ToolPart::ConeRim) {
        s.height = tool.cone_height();
    } else if (is_cone) {
        s.radius = tool.tip_radius;
    } else {
        s.height = volume.method() == Method::BallRamp ? tool.radius : 0.0;
    }
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
        case Form::Cone:
            return cone(*this, p);
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
    if (method == Method::SampledRamp) return std::nullopt;
    const double low = std::min(motion.start.z(), motion.end.z());
    const double high = std::max(motion.start.z(), motion.end.z());
    const bool ramp =
        method == Method::FlatRamp || method == Method::BallRamp || method == Method::ConeRamp;
    const bool is_cone = tool.shape == sim::ToolShape::Cone;
    switch (part) {
        case ToolPart::Bottom:
            // The lowest copy's disk; a ball end ramping has none (its ball is the Corner).
            if (method == Method::BallRamp) return std::nullopt;
            return plane(-Vec3::UnitZ(), -low);
        case ToolPart::Corner:
            return corner(volume, low);
        case ToolPart::Side:
            return around(Form::Wall, motion, tool.radius);
        case ToolPart::Top:
            return plane(Vec3::UnitZ(), high + tool.flute_length);
        case ToolPart::BottomRim:
        case ToolPart::TopRim:
        case ToolPart::ConeRim:
            if (!ramp || (part == ToolPart::ConeRim && !is_cone)) return std::nullopt;
            return swept_rim(volume, part);
        case ToolPart::Cone: {
            if (!is_cone) return std::nullopt;
            ImplicitSurface s = around(Form::Cone, motion, 0.0);
            s.inset = tool.tip_radius;
            s.half_angle = tool.half_angle;
            return s;
        }
    }
    return std::nullopt;
}

}  // namespace resharp::eval
