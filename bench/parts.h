#pragma once
// The benchmark parts of examples/<part>/ (docs/design.md §4), simulated once per process so that
// benchmarks time only what they measure. Run from the repository root, or set
// RESHARP_EXAMPLES=<folder>.

#include <string>

#include "resharp/sim/job.h"
#include "resharp/sim/marching_cubes.h"
#include "resharp/sim/simulate.h"

namespace resharp::bench {

struct Part {
    sim::Job job;
    sim::ToolPath path;
    sim::SimulationOptions options;
};

/// The parsed job and program of examples/<name>/, cached.
const Part& part(const std::string& name);

/// The part simulated and meshed at its job's pitch, with its oracle, cached.
const sim::OracleMesh& part_mesh(const std::string& name);

}  // namespace resharp::bench
