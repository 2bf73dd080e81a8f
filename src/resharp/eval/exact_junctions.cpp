#include "resharp/eval/exact_junctions.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "resharp/core/errors.h"

namespace resharp::eval {
namespace {

/// Newton steps that put a probe back onto its surface (quadratic convergence from 0.05 h).
constexpr int kProbeProjectionSteps = 8;

/// One ideal point's outcome.
struct Outcome {
    JunctionStatus status = JunctionStatus::Unsolved;
    Vec3 position = Vec3::Zero();
};

/// What the solid's boundary is beside a junction, on one surface's side.
struct Probe {
    enum class Result {
        Bounds,     ///< the surface itself
        Continues,  ///< another surface, smoothly continuing it (the next move of a pass)
        Fails,      ///< neither: the surface does not bound the solid there
    };
    Result result = Result::Fails;
    std::int32_t surface = -1;  ///< Continues: the id of the continuing surface
    Vec3 at = Vec3::Zero();     ///< Continues: a point on it
};

class JunctionFinder {
public:
    JunctionFinder(const Mesh& mesh, const Oracle& oracle, const MachinedSolid& solid,
                   const ExactJunctionOptions& options)
        : mesh_(mesh),
          oracle_(oracle),
          solid_(solid),
          options_(options),
          same_normal_cosine_(cosine_of(options.probe_normal_angle_deg)),
          smooth_cosine_(cosine_of(options.smooth_angle_deg)) {}

    Outcome find(const IdealPoint& p) const {
        Surfaces surfaces;
        if (const std::optional<Outcome> stop = vertex_surfaces(p, surfaces)) return *stop;
        // Each round either settles or hands a side over to the surface that continues it
        // there, so at most max_continuations + 1 solves.
        for (int round = 0; round <= options_.max_continuations; ++round) {
            const std::optional<Vec3> x =
                p.kind == IdealKind::Edge ? edge(p, surfaces) : corner(p, surfaces);
            if (!x) return {};
            if (const std::optional<Outcome> done = check_sides(p, *x, surfaces)) return *done;
        }
        return {JunctionStatus::NotBounding};
    }

private:
    using Surfaces = std::array<ImplicitSurface, 3>;

    static std::size_t side_count(const IdealPoint& p) { return p.kind == IdealKind::Edge ? 2 : 3; }

    /// The surfaces of p's vertices into `surfaces`, or the outcome if they end the search.
    std::optional<Outcome> vertex_surfaces(const IdealPoint& p, Surfaces& surfaces) const {
        for (std::size_t k = 0; k < side_count(p); ++k) {
            const Index w = p.vertices[k];
            const MachinedSolid::SurfaceNear s =
                solid_.surface_near(oracle_.surfaces[w], mesh_.positions[w]);
            if (s.kind == MachinedSolid::SurfaceKind::Unknown) {
                throw InvalidInput("vertex " + std::to_string(w) + " lies on surface " +
                                   std::to_string(oracle_.surfaces[w]) +
                                   ", which the job does not make (oracle and job differ)");
            }
            if (s.kind == MachinedSolid::SurfaceKind::Sampled) {
                return Outcome{JunctionStatus::SampledSurface};
            }
            if (!(s.distance <= options_.on_surface_tolerance * h())) return Outcome{};
            surfaces[k] = *s.surface;
        }
        return std::nullopt;
    }

    /// Probes every side of the junction x: the outcome once decided, or nothing after handing
    /// a side over to the surface that continues it (then `surfaces` holds that one).
    std::optional<Outcome> check_sides(const IdealPoint& p, const Vec3& x,
                                       Surfaces& surfaces) const {
        // Along an edge's junction curve the probes move across it only.
        const Vec3 tangent = p.kind == IdealKind::Edge
                                 ? surfaces[0]
                                       .evaluate(x)
                                       .gradient.cross(surfaces[1].evaluate(x).gradient)
                                       .normalized()
                                 : Vec3::Zero();
        bool settled = true;
        for (std::size_t k = 0; k < side_count(p); ++k) {
            const Probe probe = probe_side(surfaces[k], x, mesh_.positions[p.vertices[k]], tangent);
            if (probe.result == Probe::Result::Fails)
                return Outcome{JunctionStatus::NotBounding, x};
            if (probe.result == Probe::Result::Bounds) continue;
            const MachinedSolid::SurfaceNear next = solid_.surface_near(probe.surface, probe.at);
            if (next.kind == MachinedSolid::SurfaceKind::Sampled) {
                return Outcome{JunctionStatus::SampledSurface, x};
            }
            if (!next.surface) return Outcome{JunctionStatus::NotBounding, x};
            surfaces[k] = *next.surface;
            settled = false;
        }
        if (settled) return Outcome{JunctionStatus::Exact, x};
        return std::nullopt;
    }

    double h() const { return options_.solver.pitch; }

    /// The junction nearest the edge's midpoint, searched from the eq. 5.2 point, then from the
    /// midpoint itself (where eq. 5.2 starts it on another branch).
    std::optional<Vec3> edge(const IdealPoint& p, const Surfaces& surfaces) const {
        const Vec3 midpoint =
            0.5 * (mesh_.positions[p.vertices[0]] + mesh_.positions[p.vertices[1]]);
        for (const Vec3& start : {p.position, midpoint}) {
            const std::optional<Vec3> x =
                edge_junction(surfaces[0], surfaces[1], midpoint, start, options_.solver);
            if (x && (*x - midpoint).norm() <= options_.max_distance * h()) return x;
        }
        return std::nullopt;
    }

    std::optional<Vec3> corner(const IdealPoint& p, const Surfaces& surfaces) const {
        const Vec3 centroid = (mesh_.positions[p.vertices[0]] + mesh_.positions[p.vertices[1]] +
                               mesh_.positions[p.vertices[2]]) /
                              3.0;
        for (const Vec3& start : {p.position, centroid}) {
            const std::optional<Vec3> x =
                corner_junction(surfaces[0], surfaces[1], surfaces[2], start, options_.solver);
            if (x && (*x - centroid).norm() <= options_.max_distance * h()) return x;
        }
        return std::nullopt;
    }

    /// What bounds the solid next to the junction x on the side of `vertex` (which lies on
    /// `surface`): probe_distance from x towards the vertex along the surface, square to
    /// `tangent` (unit, or zero for a corner), the boundary crossing nearest the probe on the
    /// axis line most nearly normal to the surface.
    Probe probe_side(const ImplicitSurface& surface, const Vec3& x, const Vec3& vertex,
                     const Vec3& tangent) const {
        const double reach = options_.probe_distance * h();
        const Vec3 n = surface.evaluate(x).gradient.normalized();
        Vec3 away = vertex - x;
        away -= away.dot(n) * n + away.dot(tangent) * tangent;
        // The vertex itself lies on the surface and on the solid's boundary.
        if (away.norm() <= reach) return {Probe::Result::Bounds};
        Vec3 q = x + reach * away.normalized();
        SurfaceValue f = surface.evaluate(q);
        for (int k = 0; k < kProbeProjectionSteps && f.gradient.squaredNorm() > 0.0; ++k) {
            q -= (f.value / f.gradient.squaredNorm()) * f.gradient;
            f = surface.evaluate(q);
        }
        const double g = f.gradient.norm();
        if (!(g > 0.0)) return {};
        int axis = 0;
        f.gradient.cwiseAbs().maxCoeff(&axis);
        const std::vector<sim::Crossing> crossings = solid_.crossings_near(q, axis, 4.0 * reach);
        const auto nearest =
            std::min_element(crossings.begin(), crossings.end(),
                             [&](const sim::Crossing& a, const sim::Crossing& b) {
                                 return std::abs(a.t - q[axis]) < std::abs(b.t - q[axis]);
                             });
        if (nearest == crossings.end()) return {};
        const double cosine = std::abs(nearest->normal.dot(f.gradient) / g);
        if (std::abs(nearest->t - q[axis]) <= options_.probe_tolerance * h() &&
            cosine >= same_normal_cosine_) {
            return {Probe::Result::Bounds};
        }
        if (cosine < smooth_cosine_) return {};
        Vec3 at = q;
        at[axis] = nearest->t;
        return {Probe::Result::Continues, nearest->surface, at};
    }

    static double cosine_of(double degrees) { return std::cos(degrees * std::numbers::pi / 180.0); }

    const Mesh& mesh_;
    const Oracle& oracle_;
    const MachinedSolid& solid_;
    const ExactJunctionOptions& options_;
    double same_normal_cosine_, smooth_cosine_;
};

}  // namespace

std::string_view junction_status_name(JunctionStatus status) {
    switch (status) {
        case JunctionStatus::Exact:
            return "exact";
        case JunctionStatus::SampledSurface:
            return "sampled_surface";
        case JunctionStatus::NotBounding:
            return "not_bounding";
        case JunctionStatus::Unsolved:
            return "unsolved";
    }
    return "unknown";
}

ExactIdealPoints find_exact_ideal_points(const Mesh& mesh, const Oracle& oracle,
                                         std::span<const IdealPoint> first_order,
                                         const MachinedSolid& solid,
                                         const ExactJunctionOptions& options) {
    check_oracle(oracle, mesh);
    const JunctionFinder finder(mesh, oracle, solid, options);
    std::vector<Outcome> outcomes(first_order.size());
    tbb::parallel_for(std::size_t{0}, first_order.size(), [&](std::size_t i) {
        if (!first_order[i].on_boundary) outcomes[i] = finder.find(first_order[i]);
    });
    const Connectivity c = build_connectivity(mesh);
    ExactIdealPoints result;
    for (std::size_t i = 0; i < first_order.size(); ++i) {
        const IdealPoint& p = first_order[i];
        if (p.on_boundary) continue;
        const bool is_edge = p.kind == IdealKind::Edge;
        ++(is_edge ? result.edges : result.corners)[static_cast<std::size_t>(outcomes[i].status)];
        if (outcomes[i].status != JunctionStatus::Exact) continue;
        IdealPoint exact = p;
        exact.position = outcomes[i].position;
        exact.beyond_chord = is_edge && is_beyond_chord(mesh, c, oracle, p, exact.position);
        result.points.push_back(exact);
    }
    return result;
}

}  // namespace resharp::eval
