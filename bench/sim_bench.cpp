// Simulation and meshing time of the four benchmark parts (examples/<part>/job.json) at their
// job's pitch (0.5 mm). Run from the repository root, or pass RESHARP_EXAMPLES=<folder>:
//   build/bench/resharp_sim_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only
// Each part is parsed once per process (fixture); simulation and meshing are timed apart.

#include <benchmark/benchmark.h>

#include <string>

#include "parts.h"

namespace {

using namespace resharp::sim;
using resharp::bench::Part;
using resharp::bench::part;

void BM_Simulate(benchmark::State& state, const std::string& name) {
    const Part& p = part(name);
    for (auto _ : state) {
        Simulation s = simulate(p.job.stock, p.job.tools, p.path, p.options);
        benchmark::DoNotOptimize(s.grid.rays[2].data());
    }
    state.counters["moves"] = static_cast<double>(p.path.moves.size());
}

void BM_Mesh(benchmark::State& state, const std::string& name) {
    const Part& p = part(name);
    const Simulation s = simulate(p.job.stock, p.job.tools, p.path, p.options);
    std::size_t triangles = 0;
    for (auto _ : state) {
        const OracleMesh m = mesh_dexels(s.grid);
        triangles = m.mesh.face_count();
        benchmark::DoNotOptimize(m.mesh.triangles.data());
    }
    state.counters["triangles"] = static_cast<double>(triangles);
}

}  // namespace

#define RESHARP_SIM_PART(name)                                                               \
    BENCHMARK_CAPTURE(BM_Simulate, name, std::string(#name))->Unit(benchmark::kMillisecond); \
    BENCHMARK_CAPTURE(BM_Mesh, name, std::string(#name))->Unit(benchmark::kMillisecond)

RESHARP_SIM_PART(mech);
RESHARP_SIM_PART(frogface);
RESHARP_SIM_PART(cavity);
RESHARP_SIM_PART(impeller);

BENCHMARK_MAIN();
