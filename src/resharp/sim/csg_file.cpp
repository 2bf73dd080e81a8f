#include "resharp/sim/csg_file.h"

#include <numbers>
#include <set>

#include "resharp/core/errors.h"
#include "resharp/sim/detail/json_fields.h"

namespace resharp::sim {
namespace {

using detail::json;
using detail::JsonFields;

const std::set<std::string> kShapes{"box", "cylinder", "cone", "sphere", "torus", "halfspace"};
const std::set<std::string> kOperations{"union", "difference", "intersection"};

/// A frame at `origin` whose z axis points along `axis` (non-zero).
Placement frame_along(const Vec3& origin, const Vec3& axis) {
    return {Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), axis).toRotationMatrix(), origin};
}

class CsgReader {
public:
    explicit CsgReader(const std::string& source) : fields_(source) {}

    CsgNode read(const json& root) const {
        fields_.expect_keys(root, "", {"solid", "description"});
        if (root.contains("description") && !root["description"].is_string()) {
            fields_.bad("description", "must be text");
        }
        CsgNode solid = node(fields_.member(root, "", "solid"), "solid", 1);
        try {
            const CsgSolid check(solid);
        } catch (const InvalidInput& e) {
            fields_.bad("solid", e.what());
        }
        return solid;
    }

private:
    CsgNode node(const json& j, const std::string& where, int depth) const {
        if (depth > kMaxCsgDepth) {
            fields_.bad(where, "nested deeper than " + std::to_string(kMaxCsgDepth));
        }
        std::set<std::string> allowed{"rotate", "translate"};
        allowed.insert(kShapes.begin(), kShapes.end());
        allowed.insert(kOperations.begin(), kOperations.end());
        fields_.expect_keys(j, where, allowed);
        std::string kind;
        for (const auto& item : j.items()) {
            if (item.key() == "rotate" || item.key() == "translate") continue;
            if (!kind.empty()) fields_.bad(where, "has both " + kind + " and " + item.key());
            kind = item.key();
        }
        if (kind.empty()) fields_.bad(where, "needs a shape or an operation");
        const std::string place = JsonFields::place(where, kind);
        CsgNode n = kShapes.count(kind) ? shape(kind, j[kind], place)
                                        : operation(kind, j[kind], place, depth);
        n.placement = placement(j, where) * n.placement;
        return n;
    }

    CsgNode operation(const std::string& kind, const json& list, const std::string& place,
                      int depth) const {
        if (!list.is_array() || list.empty()) fields_.bad(place, "must be a non-empty array");
        CsgNode n;
        n.op = kind == "union"          ? CsgOp::Union
               : kind == "intersection" ? CsgOp::Intersection
                                        : CsgOp::Difference;
        for (std::size_t i = 0; i < list.size(); ++i) {
            n.operands.push_back(node(list[i], place + "[" + std::to_string(i) + "]", depth + 1));
        }
        return n;
    }

    double get(const json& object, const std::string& where, const char* key) const {
        return fields_.number(fields_.member(object, where, key), JsonFields::place(where, key));
    }
    Vec3 get_point(const json& object, const std::string& where, const char* key) const {
        return fields_.point(fields_.member(object, where, key), JsonFields::place(where, key));
    }
    Vec3 get_direction(const json& object, const std::string& where, const char* key) const {
        const Vec3 v = get_point(object, where, key);
        if (!(v.norm() > 0.0)) fields_.bad(JsonFields::place(where, key), "must not be zero");
        return v.normalized();
    }

    /// A shape and the frame that puts it where the file says.
    CsgNode shape(const std::string& kind, const json& j, const std::string& where) const {
        CsgNode n;
        if (kind == "box") {
            fields_.expect_keys(j, where, {"min", "max"});
            n.shape = BoxShape{get_point(j, where, "min"), get_point(j, where, "max")};
        } else if (kind == "cylinder" || kind == "cone") {
            const bool cylinder = kind == "cylinder";
            fields_.expect_keys(
                j, where,
                cylinder ? std::set<std::string>{"from", "to", "radius"}
                         : std::set<std::string>{"from", "to", "radius_from", "radius_to"});
            const Vec3 from = get_point(j, where, "from"), to = get_point(j, where, "to");
            if (!((to - from).norm() > 0.0)) fields_.bad(where, "from and to coincide");
            const double r0 = get(j, where, cylinder ? "radius" : "radius_from");
            const double r1 = cylinder ? r0 : get(j, where, "radius_to");
            n.shape = ConeShape{(to - from).norm(), r0, r1};
            n.placement = frame_along(from, to - from);
        } else if (kind == "sphere") {
            fields_.expect_keys(j, where, {"center", "radius"});
            n.shape = SphereShape{get(j, where, "radius")};
            n.placement.translation = get_point(j, where, "center");
        } else if (kind == "torus") {
            fields_.expect_keys(j, where, {"center", "axis", "major", "minor"});
            n.shape = TorusShape{get(j, where, "major"), get(j, where, "minor")};
            n.placement =
                frame_along(get_point(j, where, "center"), get_direction(j, where, "axis"));
        } else {
            fields_.expect_keys(j, where, {"point", "normal"});
            n.shape = HalfSpaceShape{};
            n.placement =
                frame_along(get_point(j, where, "point"), get_direction(j, where, "normal"));
        }
        try {
            check_shape(n.shape);
        } catch (const InvalidInput& e) {
            fields_.bad(where, e.what());
        }
        return n;
    }

    /// The node's own "rotate" and "translate" (identity where absent).
    Placement placement(const json& j, const std::string& where) const {
        Placement p;
        if (j.contains("rotate")) {
            const std::string place = JsonFields::place(where, "rotate");
            fields_.expect_keys(j["rotate"], place, {"axis", "degrees"});
            const double degrees = get(j["rotate"], place, "degrees");
            p.rotation = Eigen::AngleAxisd(degrees * std::numbers::pi / 180.0,
                                           get_direction(j["rotate"], place, "axis"))
                             .toRotationMatrix();
        }
        if (j.contains("translate")) {
            p.translation = fields_.point(j["translate"], JsonFields::place(where, "translate"));
        }
        return p;
    }

    JsonFields fields_;
};

}  // namespace

CsgNode parse_csg(const std::string& text, const std::string& source) {
    return CsgReader(source).read(detail::parse_json(text, source));
}

CsgNode read_csg(const std::string& path) { return parse_csg(detail::read_text_file(path), path); }

}  // namespace resharp::sim
