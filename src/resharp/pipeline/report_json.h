#pragma once
/// The restore report as JSON, under the stable keys of `resharp restore --report` and of the
/// Python module's `report` dict. A separate target (resharp::report_json) so that the library
/// itself needs no JSON.

#include <nlohmann/json.hpp>

#include "resharp/pipeline/report.h"

namespace resharp {

/// Every counter of the report under stable keys, grouped by stage; times in seconds.
nlohmann::json report_to_json(const RestoreReport& report);

}  // namespace resharp
