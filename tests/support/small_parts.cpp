#include "support/small_parts.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "resharp/sim/csg.h"
#include "resharp/sim/tridexel.h"

namespace resharp::test {
namespace {

using sim::CsgNode;
using sim::CsgOp;

constexpr double kDeg = std::numbers::pi / 180.0;

CsgNode primitive(sim::Shape shape, const Vec3& at = Vec3::Zero(),
                  const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity()) {
    CsgNode node;
    node.shape = std::move(shape);
    node.placement.translation = at;
    node.placement.rotation = rotation;
    return node;
}

CsgNode box(const Vec3& min, const Vec3& max) { return primitive(sim::BoxShape{min, max}); }

CsgNode operation(CsgOp op, std::vector<CsgNode> operands) {
    CsgNode node;
    node.op = op;
    node.operands = std::move(operands);
    return node;
}

CsgNode pocketed_block() {
    return operation(CsgOp::Difference,
                     {box(Vec3(0, 0, 0), Vec3(14, 11, 6)), box(Vec3(3, 3, 2.8), Vec3(8, 8, 7)),
                      primitive(sim::ConeShape{8.0, 1.9, 1.9}, Vec3(11, 5.5, -1))});
}

CsgNode bossed_plate() {
    CsgNode solid =
        operation(CsgOp::Union, {box(Vec3(0, 0, 0), Vec3(14, 12, 3)),
                                 primitive(sim::ConeShape{3.2, 3.1, 3.1}, Vec3(8.5, 6.5, 2)),
                                 primitive(sim::ConeShape{1.4, 3.1, 1.9}, Vec3(8.5, 6.5, 5.2))});
    return operation(CsgOp::Difference, {solid, primitive(sim::SphereShape{2.2}, Vec3(3, 3, 4.1))});
}

CsgNode tilted_wedge() {
    const Eigen::Matrix3d slant = Eigen::AngleAxisd(35 * kDeg, Vec3::UnitY()).toRotationMatrix();
    CsgNode wedge =
        operation(CsgOp::Intersection, {box(Vec3(0, 0, 0), Vec3(12, 9, 7)),
                                        primitive(sim::HalfSpaceShape{}, Vec3(8, 0, 7), slant)});
    wedge.placement.rotation =
        (Eigen::AngleAxisd(20 * kDeg, Vec3::UnitZ()) * Eigen::AngleAxisd(12 * kDeg, Vec3::UnitX()))
            .toRotationMatrix();
    return wedge;
}

CsgNode description(SmallPart part) {
    switch (part) {
        case SmallPart::PocketedBlock:
            return pocketed_block();
        case SmallPart::BossedPlate:
            return bossed_plate();
        case SmallPart::TiltedWedge:
            return tilted_wedge();
    }
    return pocketed_block();
}

}  // namespace

std::string_view to_string(SmallPart part) {
    switch (part) {
        case SmallPart::PocketedBlock:
            return "pocketed block";
        case SmallPart::BossedPlate:
            return "bossed plate";
        case SmallPart::TiltedWedge:
            return "tilted wedge";
    }
    return "unknown";
}

sim::CsgSolid small_part_solid(SmallPart part) { return sim::CsgSolid(description(part)); }

sim::GridSpec small_part_grid(SmallPart part, double pitch) {
    return sim::phased_grid(small_part_solid(part).bounds(), pitch, 0.37);
}

Mesh small_part(SmallPart part, double pitch, sim::Mesher mesher) {
    const sim::DexelGrid grid =
        sim::sample_solid(small_part_grid(part, pitch), small_part_solid(part));
    return sim::mesh_dexels(grid, {.mesher = mesher}).mesh;
}

double distance_along_lines(const sim::CsgSolid& solid, const Vec3& p) {
    const std::array<Vec3, 7> directions{Vec3::UnitX(),
                                         Vec3::UnitY(),
                                         Vec3::UnitZ(),
                                         Vec3(1, 1, 1) / std::sqrt(3.0),
                                         Vec3(1, 1, -1) / std::sqrt(3.0),
                                         Vec3(1, -1, 1) / std::sqrt(3.0),
                                         Vec3(-1, 1, 1) / std::sqrt(3.0)};
    double nearest = std::numeric_limits<double>::infinity();
    std::vector<sim::Interval> intervals;
    for (const Vec3& direction : directions) {
        intervals.clear();
        solid.intersect_line(p, direction, intervals);
        for (const sim::Interval& i : intervals)
            nearest = std::min({nearest, std::abs(i.enter.t), std::abs(i.exit.t)});
    }
    return nearest;
}

}  // namespace resharp::test
