#pragma once
/// The restore report as JSON (`resharp restore --report`: resharp/pipeline/report_json.h),
/// and the one-paragraph summary.

#include <string>

#include "resharp/pipeline/report_json.h"

namespace resharp::cli {

/// The summary printed on stderr after a restore.
std::string summarize(const RestoreReport& report, const std::string& input,
                      const std::string& output);

}  // namespace resharp::cli
