#include "resharp/pipeline/options.h"

namespace resharp {

RestoreOptions paper_variant(RestoreOptions options) {
    options.edges.feature = CurvatureFeature::Signed;
    options.features.curved_region_faces = 0;
    options.features.keep_sharp_borders_apart = false;
    options.bands.unconfirmed_border_angle_deg = 180.0;
    options.bands.smooth_border_angle_deg = 0.0;
    options.bands.smooth_continuation_angle_deg = 0.0;
    options.normals.estimate = NormalEstimate::AngleWeighted;
    return options;
}

}  // namespace resharp
