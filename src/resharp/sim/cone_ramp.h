#pragma once
/// A conical mill swept along a ramp (a line moving in both XY and Z), cut exactly by a grid ray.
///
/// Relative to its tip, a point (u, w) (u the horizontal offset from the axis, w the height) is
/// inside the tool when 0 <= w <= H, |u| <= rt + w tan β and |u| <= R: a convex solid. Swept with
/// its tip along a + s d, s in [0, 1], the ray o + t e_k is inside where some s puts it inside the
/// tool: a convex region of the (t, s) plane bounded by four lines (w = 0, w = H, s = 0, s = 1)
/// and two conics (the cone and the cylinder; the cone's two tangent planes along the motion are
/// where its conic is tangent to a line t = const). The extreme t of that region lie where two
/// bounds meet or where a conic is tangent to a line t = const, each a root of a quadratic along
/// a line, so entry and exit are exact to rounding. At each the normal is the tool's own, or on a
/// rim (the flat tip's, the cone-cylinder rim, the top) the member of the rim's normal cone
/// orthogonal to the motion (the envelope normal).

#include <cstddef>
#include <optional>

#include "resharp/sim/tool.h"
#include "resharp/sim/tridexel.h"

namespace resharp::sim {

/// Where `ray` is inside the conical `tool` swept with its tip from `start` to `end`, with the
/// exact outward normals and ids tool_surface_id(move, part); nothing if it misses. The ramp must
/// move in both XY and Z (horizontal lines and plunges are exact through the tool profile).
std::optional<Interval> cut_cone_ramp(const Tool& tool, const Vec3& start, const Vec3& end,
                                      const Ray& ray, std::size_t move);

}  // namespace resharp::sim
