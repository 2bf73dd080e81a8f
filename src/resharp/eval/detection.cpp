#include "resharp/eval/detection.h"

#include <cmath>
#include <numbers>

#include "resharp/core/errors.h"
#include "resharp/mesh/connectivity.h"

namespace resharp::eval {
namespace {

DetectionScore score(std::span<const BandRole> detected, std::span<const BandRole> truth,
                     auto&& counts) {
    DetectionScore s;
    for (std::size_t f = 0; f < truth.size(); ++f) {
        const bool d = counts(detected[f]), t = counts(truth[f]);
        s.detected += d;
        s.actual += t;
        s.matched += d && t;
    }
    if (s.detected > 0) s.precision = double(s.matched) / double(s.detected);
    if (s.actual > 0) s.recall = double(s.matched) / double(s.actual);
    return s;
}

}  // namespace

std::vector<BandRole> true_band_roles(const Mesh& mesh, const Oracle& oracle,
                                      const IdealPointOptions& options) {
    check_oracle(oracle, mesh);
    const double min_cosine = std::cos(options.sharp_angle_deg * std::numbers::pi / 180.0);
    auto sharp = [&](Index u, Index v) { return is_sharp_junction(oracle, u, v, min_cosine); };
    std::vector<BandRole> role(mesh.face_count(), BandRole::None);
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
        const Triangle& t = mesh.triangles[f];
        const int crossings = sharp(t[0], t[1]) + sharp(t[1], t[2]) + sharp(t[2], t[0]);
        if (crossings == 3) {
            role[f] = BandRole::Corner;
        } else if (crossings > 0) {
            role[f] = BandRole::Edge;
        }
    }
    return role;
}

DetectionScores score_detection(std::span<const BandRole> detected,
                                std::span<const BandRole> truth) {
    if (detected.size() != truth.size()) {
        throw InvalidInput("detected and true face roles differ in length");
    }
    return {score(detected, truth, [](BandRole r) { return r != BandRole::None; }),
            score(detected, truth, [](BandRole r) { return r == BandRole::Corner; })};
}

}  // namespace resharp::eval
