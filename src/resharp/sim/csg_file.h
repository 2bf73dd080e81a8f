#pragma once
/// The CSG solid file of `resharp simulate --solid` and `resharp evaluate --solid` (csg.h).
///
/// JSON, comments allowed, every key checked (an unknown key is an error). The top level holds
/// the tree under "solid" and an optional "description" (text, ignored). A node is an object
/// with exactly one shape or operation key, and optionally "rotate" and "translate", which
/// place it (rotation first) in its parent's frame:
/// ```json
/// {
///   "description": "a plate with a hole, turned 20 degrees about a slanted axis",
///   "solid": {
///     "difference": [
///       {"box": {"min": [0, 0, 0], "max": [80, 50, 10]}},
///       {"cylinder": {"from": [40, 25, -1], "to": [40, 25, 11], "radius": 8}}
///     ],
///     "rotate": {"axis": [1, 2, 3], "degrees": 20},
///     "translate": [0, 0, 5]
///   }
/// }
/// ```
/// Shapes (lengths in mm):
/// - "box": {"min": [x, y, z], "max": [x, y, z]}
/// - "cylinder": {"from": p, "to": q, "radius": r}: axis from p to q, caps at both ends
/// - "cone": {"from": p, "to": q, "radius_from": r0, "radius_to": r1}: a frustum (one radius
///   may be 0: a cone)
/// - "sphere": {"center": c, "radius": r}
/// - "torus": {"center": c, "axis": a, "major": R, "minor": r}, R > r > 0
/// - "halfspace": {"point": p, "normal": n}: the material lies on the side n points away from
/// Operations: "union", "intersection", "difference": a non-empty array of nodes (a difference
/// is its first node minus all the others). "rotate": {"axis": a, "degrees": d} about the
/// origin of the parent's frame; "translate": [x, y, z].

#include <string>

#include "resharp/sim/csg.h"

namespace resharp::sim {

/// Parses a solid file; `source` names it in errors.
/// \throws ParseError(source, line) for malformed JSON; InvalidInput reading "SOURCE: PLACE:
/// REASON" (PLACE such as solid.difference[1].cylinder.radius) for a missing, unknown,
/// mistyped or out-of-range value, nesting deeper than kMaxCsgDepth, or an empty or unbounded
/// solid.
CsgNode parse_csg(const std::string& json, const std::string& source);

/// Reads a solid file. \throws ReadError if unreadable; otherwise as parse_csg().
CsgNode read_csg(const std::string& path);

}  // namespace resharp::sim
