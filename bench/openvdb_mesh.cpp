// resharp_openvdb_mesh: meshes a closed mesh the way a user of OpenVDB would, volumeToMesh at
// adaptivity 0 over the mesh's narrow-band level set (extras/openvdb_mesher.h), so that
// bench/mesher_results.py can score resharp on the third-party mesher users have (issue 14).
//
//   resharp_openvdb_mesh FINE.ply -o OUT.ply --pitch H [--origin X,Y,Z]
//   resharp_openvdb_mesh FINE.ply -o OUT.ply --job JOB.json | --solid SOLID.json [--cells N]
//                        [--input-oracle FINE_ORACLE.ply --oracle OUT_ORACLE.ply]
//
// --job and --solid put OpenVDB's voxel centres on the nodes of the grid `resharp simulate`
// samples that job or solid on (same pitch, same phase), so its rows compare cell for cell with
// the simulator's meshers' rows. --oracle writes the oracle `resharp evaluate` needs
// (docs/oracle.md) for the dual mesh, whose vertices are no simulator's.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "openvdb_mesher.h"
#include "resharp/core/errors.h"
#include "resharp/eval/evaluation_files.h"
#include "resharp/io/mesh_io.h"
#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/diagnostics.h"
#include "resharp/mesh/uniform_grid.h"
#include "resharp/sim/csg_file.h"
#include "resharp/sim/job.h"
#include "resharp/sim/simulate.h"

namespace resharp {
namespace {

struct Arguments {
    std::string input, output, input_oracle, oracle, job, solid;
    double pitch = 0.0;          // mm; 0: from --job or --solid
    double cells = 100.0;        // as `resharp simulate --solid` without --pitch or --cells
    std::vector<double> origin;  // a voxel centre; empty: from --job or --solid, else 0, 0, 0
};

/// Voxel size and the position of one voxel centre.
struct VoxelGrid {
    double pitch = 0.0;
    Vec3 origin = Vec3::Zero();
};

/// The grid `resharp simulate` samples the job or solid on: nodes at box.min + (k + phase) h
/// (sim::phased_grid), with the simulator's default phase, which keeps faces at round
/// coordinates off the voxel centres as it keeps them off the simulator's grid planes.
VoxelGrid simulation_grid(const Arguments& args) {
    const double phase = sim::SimulationOptions{}.grid_phase;
    if (!args.job.empty()) {
        const sim::Job job = sim::read_job(args.job);
        const double h = args.pitch > 0.0 ? args.pitch : job.pitch;
        return {h, job.stock.min().array() + phase * h};
    }
    const sim::CsgSolid solid(sim::read_csg(args.solid));
    const double h =
        args.pitch > 0.0 ? args.pitch : sim::pitch_for_cells(solid.bounds(), args.cells);
    return {h, solid.bounds().min().array() + phase * h};
}

VoxelGrid voxel_grid(const Arguments& args) {
    if (!args.job.empty() || !args.solid.empty()) return simulation_grid(args);
    VoxelGrid grid{args.pitch, Vec3::Zero()};
    if (!args.origin.empty()) grid.origin = Vec3(args.origin[0], args.origin[1], args.origin[2]);
    return grid;
}

/// The input, welded. \throws InvalidInput naming the file unless it is closed and manifold:
/// meshToLevelSet tells inside from outside by the surface, and a hole lets the outside in.
Mesh read_closed_mesh(const std::string& path) {
    Mesh mesh = weld(io::read_mesh(path));
    if (mesh.face_count() == 0) throw InvalidInput(path + ": no triangles");
    const MeshDiagnostics d = diagnose(mesh, build_connectivity(mesh));
    if (d.boundary_edges > 0 || d.nonmanifold_edges > 0) {
        throw InvalidInput(path + ": not a closed manifold mesh (" +
                           std::to_string(d.boundary_edges) + " boundary, " +
                           std::to_string(d.nonmanifold_edges) +
                           " non-manifold edges); OpenVDB's level set needs a closed surface");
    }
    return mesh;
}

/// The oracle of `dual` (docs/oracle.md, "Surface points of off-surface vertices") from the
/// oracle of the fine mesh it was made from: for each dual vertex p, x is the fine mesh's surface
/// point nearest p (its vertex itself for an exact-crossing mesh), s = p - ((p - x).n) n the foot
/// on the tangent plane at x, and n and the surface id those of x. The simulator takes x among
/// the exact crossings of p's own cell; here they are the fine grid's crossings, which lie a fine
/// pitch apart, so x is nearer p's true nearest point than the simulator's choice would be.
eval::Oracle dual_oracle(const Mesh& fine, const eval::Oracle& oracle, const Mesh& dual,
                         double pitch) {
    const auto surface_point = [&](std::size_t v) {
        return oracle.surface_points.empty() ? fine.positions[v] : oracle.surface_points[v];
    };
    const detail::UniformGrid grid(
        fine.vertex_count(),
        [&](std::size_t v) { return detail::Box3(surface_point(v), surface_point(v)); }, pitch);
    eval::Oracle out;
    for (const Vec3& p : dual.positions) {
        const Index x =
            grid.nearest(p, [&](Index i) { return (surface_point(i) - p).norm(); }).first;
        const Vec3& n = oracle.normals[x];
        out.normals.push_back(n);
        out.surfaces.push_back(oracle.surfaces[x]);
        out.surface_points.push_back(p - (p - surface_point(x)).dot(n) * n);
    }
    return out;
}

void run(const Arguments& args) {
    const VoxelGrid grid = voxel_grid(args);
    const Mesh fine = read_closed_mesh(args.input);
    const Mesh dual = extras::openvdb_dual_mesh(fine, grid.pitch, grid.origin);
    if (dual.face_count() == 0) {
        throw InvalidInput(args.input + ": OpenVDB made no surface at pitch " +
                           std::to_string(grid.pitch) + " mm");
    }
    io::write_mesh(args.output, dual);
    if (args.oracle.empty()) return;
    const eval::Oracle o =
        dual_oracle(fine, eval::read_oracle(args.input_oracle, fine), dual, grid.pitch);
    io::write_mesh(args.oracle, dual, {},
                   {.vertex_normals = o.normals,
                    .vertex_surfaces = o.surfaces,
                    .vertex_surface_points = o.surface_points});
}

}  // namespace
}  // namespace resharp

int main(int argc, char** argv) {
    using namespace resharp;
    Arguments args;
    CLI::App app{
        "Mesh a closed mesh by OpenVDB's volumeToMesh (adaptivity 0) on voxels of a given "
        "pitch, as a third-party mesher would (bench/mesher_results.py --meshers openvdb)"};
    app.add_option("input", args.input, "a closed mesh (.stl, .obj, .ply, .off)")->required();
    app.add_option("-o,--output", args.output, "the dual mesh to write")->required();
    CLI::Option* pitch =
        app.add_option("--pitch", args.pitch, "voxel size in mm (with --job: instead of its pitch)")
            ->check(CLI::PositiveNumber);
    CLI::Option* origin = app.add_option("--origin", args.origin, "a voxel centre, X,Y,Z in mm")
                              ->delimiter(',')
                              ->expected(3);
    CLI::Option* job =
        app.add_option("--job", args.job, "voxel centres on the nodes of the job's simulation grid")
            ->excludes(origin);
    CLI::Option* solid = app.add_option("--solid", args.solid,
                                        "voxel centres on the nodes of the grid `resharp simulate "
                                        "--solid` samples this CSG solid on")
                             ->excludes(origin)
                             ->excludes(job);
    app.add_option("--cells", args.cells, "with --solid: cells along its longest side")
        ->check(CLI::PositiveNumber)
        ->needs(solid)
        ->excludes(pitch);
    CLI::Option* input_oracle = app.add_option(
        "--input-oracle", args.input_oracle, "the input's oracle PLY (resharp simulate --oracle)");
    app.add_option("--oracle", args.oracle,
                   "also write the dual mesh's oracle PLY, from the input's (docs/oracle.md)")
        ->needs(input_oracle);
    try {
        app.parse(argc, argv);
        if (args.pitch <= 0.0 && args.job.empty() && args.solid.empty()) {
            throw CLI::RequiredError("--pitch, --job or --solid");
        }
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    try {
        run(args);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "resharp_openvdb_mesh: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
