#pragma once
/// The job file of `resharp simulate`: stock, tool table, grid pitch and the G-code program.
///
/// JSON, every key checked (an unknown key is an error, so a typo never goes unnoticed):
/// ```json
/// {
///   "stock":   {"min": [0, 0, 0], "max": [120, 90, 40]},   // box, mm
///   "pitch":   0.5,                                        // grid pitch h, mm (optional)
///   "program": "mech.nc",                                  // relative to the job file
///   "start":   [60, 45, 90],                               // tip before the first move (optional,
///                                                          //   default 50 mm above the stock
///                                                          centre)
///   "mesher":  "mc",                                       // mc, bisect, midpoint, surface-nets
///                                                          //   (optional, default mc)
///   "seam_duplicates": 0,                                  // K (optional, MeshingOptions)
///   "tools": [
///     {"number": 1, "type": "flat", "diameter": 10, "flute_length": 30},
///     {"number": 2, "type": "ball", "diameter": 6, "flute_length": 20},
///     {"number": 3, "type": "bullnose", "diameter": 8, "corner_radius": 1, "flute_length": 20},
///     {"number": 4, "type": "vbit", "diameter": 12, "tip_angle": 90, "tip_diameter": 0.5,
///      "flute_length": 20}                               // tip angle: included, degrees;
///                                                        //   tip diameter optional, default 0
///   ]
/// }
/// ```

#include <map>
#include <string>

#include "resharp/sim/marching_cubes.h"
#include "resharp/sim/tool.h"
#include "resharp/sim/tridexel.h"

namespace resharp::sim {

struct Job {
    Box3 stock;                          ///< the raw block, mm
    std::map<int, Tool> tools;           ///< by tool number (T word)
    double pitch = 0.5;                  ///< grid pitch h, mm
    std::string program;                 ///< G-code path, already resolved against the job's folder
    Vec3 start_position = Vec3::Zero();  ///< tool tip before the first move, mm
    MeshingOptions meshing;              ///< "mesher" and "seam_duplicates"; the rest default
};

/// Parses a job; `source` names it in errors and `folder` resolves the program path.
/// \throws ParseError(source, line, reason) for malformed JSON; InvalidInput naming the source
/// and the key for a missing, unknown, mistyped or out-of-range value.
Job parse_job(const std::string& json, const std::string& source, const std::string& folder);

/// Reads a job file. \throws ReadError if unreadable; otherwise as parse_job().
Job read_job(const std::string& path);

}  // namespace resharp::sim
