#include "resharp/pipeline/options.h"

#include <algorithm>
#include <cmath>

#include "resharp/core/errors.h"

namespace resharp {

RestoreOptions paper_variant(RestoreOptions options) {
    options.edges.feature = CurvatureFeature::Signed;
    options.features.curved_region_faces = 0;
    options.features.keep_sharp_borders_apart = false;
    options.bands.unconfirmed_border_angle_deg = 180.0;
    options.bands.smooth_border_angle_deg = 0.0;
    options.bands.smooth_continuation_angle_deg = 0.0;
    options.normals.estimate = NormalEstimate::AngleWeighted;
    options.points.placement = PointPlacement::TangentPlanes;
    return options;
}

void set_grid(VertexOptions& vertices, std::span<const double> numbers) {
    const bool finite =
        std::all_of(numbers.begin(), numbers.end(), [](double x) { return std::isfinite(x); });
    if ((numbers.size() != 1 && numbers.size() != 4) || !finite || !(numbers[0] > 0.0))
        throw InvalidInput(
            "grid: expected a pitch, or a pitch and a grid point (x, y, z), all "
            "finite, the pitch positive");
    vertices.grid.pitch = numbers[0];
    vertices.grid_origin_given = numbers.size() == 4;
    vertices.grid.origin =
        vertices.grid_origin_given ? Vec3(numbers[1], numbers[2], numbers[3]) : Vec3::Zero();
}

}  // namespace resharp
