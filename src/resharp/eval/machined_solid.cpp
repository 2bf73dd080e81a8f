#include "resharp/eval/machined_solid.h"

#include <algorithm>
#include <limits>

#include "resharp/sim/solids.h"

namespace resharp::eval {
namespace {

/// Cells of the volume index, in grid pitches: volumes are tools' sizes and longer, so finer
/// cells would file each of them many times over.
constexpr double kIndexCell = 16.0;

double first_order_distance(const SurfaceValue& v) {
    const double g = v.gradient.norm();
    return g > 0.0 ? std::abs(v.value) / g : std::numeric_limits<double>::infinity();
}

}  // namespace

MachinedSolid::MachinedSolid(const sim::Box3& stock, const std::map<int, sim::Tool>& tools,
                             const sim::ToolPath& path, const sim::SimulationOptions& options)
    : stock_(stock),
      volumes_(sim::swept_volumes(stock, tools, path, options)),
      index_(
          volumes_.size(), [&](std::size_t i) { return volumes_[i].bounds(); },
          kIndexCell * options.pitch) {
    for (std::size_t i = 0; i < volumes_.size(); ++i) {
        auto [it, fresh] = volumes_of_move_.try_emplace(volumes_[i].move(), i, i + 1);
        if (!fresh) it->second.second = i + 1;
    }
}

MachinedSolid::SurfaceNear MachinedSolid::surface_near(std::int32_t id, const Vec3& p) const {
    SurfaceNear best;
    if (id >= 0 && id < 6) {
        best.surface = stock_face(stock_, id);
        best.kind = SurfaceKind::Exact;
        best.distance = first_order_distance(best.surface->evaluate(p));
        return best;
    }
    if (id < sim::kSurfacesPerMove) return best;
    const auto move = static_cast<std::size_t>(id / sim::kSurfacesPerMove - 1);
    const auto part = static_cast<sim::ToolPart>(id % sim::kSurfacesPerMove);
    const auto volumes = volumes_of_move_.find(move);
    if (volumes == volumes_of_move_.end()) return best;
    best.distance = std::numeric_limits<double>::infinity();
    for (std::size_t i = volumes->second.first; i < volumes->second.second; ++i) {
        if (volumes_[i].method() == sim::SweptVolume::Method::SampledRamp) {
            best.kind = SurfaceKind::Sampled;
            best.surface.reset();
            return best;
        }
        const std::optional<ImplicitSurface> s = tool_part_surface(volumes_[i], part);
        if (!s) continue;
        const double d = first_order_distance(s->evaluate(p));
        if (!best.surface || d < best.distance) {
            best = {SurfaceKind::Exact, s, d};
        }
    }
    return best;
}

std::vector<sim::Crossing> MachinedSolid::crossings_near(const Vec3& p, int axis,
                                                         double reach) const {
    sim::Ray ray;
    ray.axis = axis;
    ray.origin = p;
    ray.origin[axis] = 0.0;
    const Vec3 along = reach * Vec3::Unit(axis);
    const sim::Box3 window(p - along, p + along);

    std::vector<sim::Interval> pieces;
    sim::axis_box(stock_, 0).intersect(ray, pieces);
    sim::RayIntervals solid;
    solid.assign(pieces.data(), pieces.data() + pieces.size());
    // Volumes that miss the window change no crossing inside it; the others are removed in
    // program order, as the simulator removes them, so ties resolve as they did there.
    std::vector<Index> near;
    index_.for_each_near(p, reach, [&](Index i) {
        if (volumes_[i].bounds().intersects(window)) near.push_back(i);
    });
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    std::vector<sim::Interval> scratch;
    for (Index i : near) {
        pieces.clear();
        volumes_[i].intersect(ray, pieces);
        if (!pieces.empty()) sim::subtract_intervals(solid, pieces, scratch);
    }

    std::vector<sim::Crossing> crossings;
    for (const sim::Interval& in : solid) {
        for (const sim::Crossing& c : {in.enter, in.exit}) {
            if (std::abs(c.t - p[axis]) <= reach) crossings.push_back(c);
        }
    }
    return crossings;
}

}  // namespace resharp::eval
