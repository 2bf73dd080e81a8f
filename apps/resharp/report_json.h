#pragma once
/// The restore report as JSON (`resharp restore --report`), and the one-paragraph summary.

#include <nlohmann/json.hpp>
#include <string>

#include "resharp/pipeline/report.h"

namespace resharp::cli {

/// Every counter of the report under stable keys; times in seconds.
nlohmann::json report_to_json(const RestoreReport& report);

/// The summary printed on stderr after a restore.
std::string summarize(const RestoreReport& report, const std::string& input,
                      const std::string& output);

}  // namespace resharp::cli
