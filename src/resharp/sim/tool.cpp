#include "resharp/sim/tool.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "resharp/core/errors.h"

namespace resharp::sim {

Tool Tool::make(ToolShape shape, double diameter, double corner_radius, double flute_length) {
    const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
    if (!positive(diameter)) throw InvalidInput("tool diameter must be positive");
    if (!positive(flute_length)) throw InvalidInput("tool flute length must be positive");
    Tool t;
    t.shape = shape;
    t.radius = diameter / 2;
    t.flute_length = flute_length;
    switch (shape) {
        case ToolShape::FlatEnd:
            t.corner_radius = 0.0;
            break;
        case ToolShape::BallEnd:
            t.corner_radius = t.radius;
            break;
        case ToolShape::BullNose:
            if (!positive(corner_radius) || corner_radius >= t.radius) {
                throw InvalidInput(
                    "bull-nose corner radius must lie strictly between 0 and "
                    "half the diameter");
            }
            t.corner_radius = corner_radius;
            break;
        case ToolShape::Cone:
            throw InvalidInput("a conical tool is made by Tool::make_cone");
    }
    if (t.flute_length < t.corner_radius) {
        throw InvalidInput("tool flute length is shorter than its corner radius");
    }
    return t;
}

Tool Tool::make_cone(double diameter, double tip_angle_deg, double tip_diameter,
                     double flute_length) {
    if (!(tip_angle_deg > 0.0 && tip_angle_deg < 180.0)) {
        throw InvalidInput("tip angle must lie strictly between 0 and 180 degrees");
    }
    if (!std::isfinite(diameter) || !(diameter > 0.0)) {
        throw InvalidInput("tool diameter must be positive");
    }
    if (!std::isfinite(flute_length) || !(flute_length > 0.0)) {
        throw InvalidInput("tool flute length must be positive");
    }
    if (!std::isfinite(tip_diameter) || !(tip_diameter >= 0.0 && tip_diameter < diameter)) {
        throw InvalidInput("tip diameter must lie in [0, diameter)");
    }
    Tool t;
    t.shape = ToolShape::Cone;
    t.radius = diameter / 2;
    t.flute_length = flute_length;
    t.half_angle = tip_angle_deg / 2 * std::numbers::pi / 180;
    t.tip_radius = tip_diameter / 2;
    if (t.flute_length < t.cone_height()) {
        throw InvalidInput("tool flute length is shorter than its cone");
    }
    return t;
}

double Tool::cone_height() const {
    return shape == ToolShape::Cone ? (radius - tip_radius) / std::tan(half_angle) : 0.0;
}

namespace {

/// The cone's outward profile normal (cos β, -sin β) at r = value.
ProfilePoint on_cone(const Tool& tool, double value) {
    return {value, std::cos(tool.half_angle), -std::sin(tool.half_angle), ToolPart::Cone};
}

}  // namespace

ProfilePoint bottom_at(const Tool& tool, double r) {
    if (tool.shape == ToolShape::Cone) {
        if (r <= tool.tip_radius) return {0.0, 0.0, -1.0, ToolPart::Bottom};
        return on_cone(tool, (r - tool.tip_radius) / std::tan(tool.half_angle));
    }
    const double core = tool.radius - tool.corner_radius;
    if (r <= core) return {0.0, 0.0, -1.0, ToolPart::Bottom};
    const double rc = tool.corner_radius;
    const double across = std::min(r - core, rc);
    const double up = std::sqrt(std::max(rc * rc - across * across, 0.0));
    return {rc - up, across / rc, -up / rc, ToolPart::Corner};
}

ProfilePoint radius_at(const Tool& tool, double z) {
    if (tool.shape == ToolShape::Cone) {
        if (z >= tool.cone_height()) return {tool.radius, 1.0, 0.0, ToolPart::Side};
        return on_cone(tool, tool.tip_radius + z * std::tan(tool.half_angle));
    }
    const double rc = tool.corner_radius;
    if (z >= rc) return {tool.radius, 1.0, 0.0, ToolPart::Side};
    const double below = rc - z;  // > 0
    const double out = std::sqrt(std::max(rc * rc - below * below, 0.0));
    return {tool.radius - rc + out, out / rc, -below / rc, ToolPart::Corner};
}

const char* to_string(ToolShape shape) {
    switch (shape) {
        case ToolShape::FlatEnd:
            return "flat";
        case ToolShape::BallEnd:
            return "ball";
        case ToolShape::BullNose:
            return "bullnose";
        case ToolShape::Cone:
            return "vbit";
    }
    return "?";
}

}  // namespace resharp::sim
