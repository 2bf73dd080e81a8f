#include "resharp/sim/tool.h"

#include <algorithm>
#include <cmath>

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
    }
    if (t.flute_length < t.corner_radius) {
        throw InvalidInput("tool flute length is shorter than its corner radius");
    }
    return t;
}

ProfilePoint bottom_at(const Tool& tool, double r) {
    const double core = tool.radius - tool.corner_radius;
    if (r <= core) return {0.0, 0.0, -1.0, ToolPart::Bottom};
    const double rc = tool.corner_radius;
    const double across = std::min(r - core, rc);
    const double up = std::sqrt(std::max(rc * rc - across * across, 0.0));
    return {rc - up, across / rc, -up / rc, ToolPart::Corner};
}

ProfilePoint radius_at(const Tool& tool, double z) {
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
    }
    return "?";
}

}  // namespace resharp::sim
