#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <span>
#include <sstream>
#include <string>

#include "commands.h"
#include "grid_choice.h"
#include "resharp/core/errors.h"
#include "resharp/core/stage_timer.h"
#include "resharp/io/mesh_io.h"
#include "resharp/sim/csg_file.h"
#include "resharp/sim/job.h"
#include "resharp/sim/marching_cubes.h"
#include "resharp/sim/simulate.h"

namespace resharp::cli {
namespace {

struct SimulateArguments {
    std::string job;
    std::string solid;  // a CSG solid file instead of a job
    std::string output;
    std::string oracle;
    GridChoice grid;           // neither given: the job's pitch, or 100 cells for a solid
    std::string mesher;        // empty: the job's
    int seam_duplicates = -1;  // -1: the job's
    bool ascii = false;
    bool quiet = false;
    sim::SimulationOptions options;
};

/// A progress bar on stderr that appears only once a run has taken a second, so short runs
/// stay silent, and redraws at most ten times a second.
class ProgressBar {
public:
    explicit ProgressBar(bool enabled) : enabled_(enabled) {}
    ~ProgressBar() { finish(); }

    void update(double fraction) {
        if (!enabled_) return;
        const auto now = std::chrono::steady_clock::now();
        if (now - start_ < std::chrono::seconds(1) ||
            now - last_draw_ < std::chrono::milliseconds(100)) {
            return;
        }
        last_draw_ = now;
        constexpr int kWidth = 40;
        const int filled = static_cast<int>(fraction * kWidth + 0.5);
        std::fprintf(stderr, "\rsimulating [%s%s] %3d%%", std::string(filled, '#').c_str(),
                     std::string(kWidth - filled, ' ').c_str(), static_cast<int>(fraction * 100));
        std::fflush(stderr);
        shown_ = true;
    }

    void finish() {
        if (shown_) std::fprintf(stderr, "\r%60s\r", "");
        shown_ = false;
    }

private:
    bool enabled_;
    bool shown_ = false;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point last_draw_{};
};

double seconds(std::chrono::nanoseconds t) { return std::chrono::duration<double>(t).count(); }

/// The grid meshed with the meshing options of the file (`from_file`: a job's, or the defaults
/// for a solid), the command line's where given. A seam count the grid cannot hold is reported
/// against the job key or the flag that set it.
sim::OracleMesh mesh(const sim::DexelGrid& grid, const sim::MeshingOptions& from_file,
                     const SimulateArguments& args) {
    sim::MeshingOptions options = from_file;
    if (!args.mesher.empty()) options.mesher = *sim::mesher_from_string(args.mesher);
    if (args.seam_duplicates >= 0) options.seam_duplicates = args.seam_duplicates;
    try {
        return sim::mesh_dexels(grid, options);
    } catch (const InvalidInput& e) {
        throw InvalidInput((args.seam_duplicates >= 0 ? std::string("--seam-duplicates")
                                                      : args.job + ": seam_duplicates") +
                           ": " + e.what());
    }
}

/// What was meshed, with what it took.
struct Meshed {
    sim::OracleMesh mesh;
    sim::GridSpec grid;
    std::string summary;  // the start of the report's first line
    std::chrono::nanoseconds sampling{}, meshing{};
};

Meshed mill_job(const SimulateArguments& args) {
    const sim::Job job = sim::read_job(args.job);
    sim::SimulationOptions options = args.options;
    options.pitch = resolve_pitch(args.grid, job.stock, job.pitch);
    const sim::ToolPath path = sim::read_gcode(job.program, {.start_position = job.start_position});
    const StageTimer simulation_timer;
    sim::Simulation simulation;
    {
        ProgressBar bar(!args.quiet);
        simulation = sim::simulate(job.stock, job.tools, path, options,
                                   [&](double fraction) { bar.update(fraction); });
    }
    Meshed m;
    m.sampling = simulation_timer.elapsed();
    const StageTimer meshing_timer;
    m.mesh = mesh(simulation.grid, job.meshing, args);
    m.meshing = meshing_timer.elapsed();
    m.grid = simulation.grid.spec;
    std::ostringstream s;
    s << job.program << ": " << simulation.stats.moves << " moves ("
      << simulation.stats.cutting_moves << " cutting, " << simulation.stats.swept_volumes
      << " swept volumes)";
    m.summary = s.str();
    return m;
}

Meshed sample_solid_file(const SimulateArguments& args) {
    const sim::CsgSolid solid(sim::read_csg(args.solid));
    const double pitch = resolve_pitch(args.grid, solid.bounds(), 0.0);
    const StageTimer sampling_timer;
    const sim::DexelGrid grid =
        sim::sample_solid(sim::phased_grid(solid.bounds(), pitch, args.options.grid_phase), solid);
    Meshed m;
    m.sampling = sampling_timer.elapsed();
    const StageTimer meshing_timer;
    m.mesh = mesh(grid, sim::MeshingOptions{}, args);
    m.meshing = meshing_timer.elapsed();
    m.grid = grid.spec;
    m.summary =
        args.solid + ": CSG solid, " + std::to_string(solid.surfaces().size()) + " surfaces";
    return m;
}

void run_simulate(const SimulateArguments& args) {
    const Meshed m = args.solid.empty() ? mill_job(args) : sample_solid_file(args);
    const sim::OracleMesh& meshed = m.mesh;
    const std::string& source = args.solid.empty() ? args.job : args.solid;
    const std::string output =
        args.output.empty() ? std::filesystem::path(source).replace_extension(".stl").string()
                            : args.output;
    const io::WriteOptions encoding{.encoding =
                                        args.ascii ? io::Encoding::Ascii : io::Encoding::Binary};
    io::write_mesh(output, meshed.mesh, encoding);
    if (!args.oracle.empty()) {
        // Vertices on the surface (mc) are their own surface points: no sx, sy, sz.
        const bool on_surface = meshed.surface_points == meshed.mesh.positions;
        io::write_mesh(args.oracle, meshed.mesh, encoding,
                       {.vertex_normals = meshed.normals,
                        .vertex_surfaces = meshed.surface_ids,
                        .vertex_surface_points = on_surface ? std::span<const Vec3>()
                                                            : std::span(meshed.surface_points)});
    }
    if (args.quiet) return;
    const auto& counts = m.grid.counts;
    std::ostringstream s;
    s << m.summary << ", grid " << counts[0] << " x " << counts[1] << " x " << counts[2]
      << " at h = " << m.grid.pitch << " mm\n"
      << "  " << (args.solid.empty() ? "simulation " : "sampling ") << seconds(m.sampling)
      << " s, meshing " << seconds(m.meshing) << " s\n"
      << "  " << meshed.mesh.face_count() << " triangles, " << meshed.mesh.vertex_count()
      << " vertices";
    if (meshed.stats.duplicated_triangles > 0) {
        s << " (" << meshed.stats.duplicated_triangles << " duplicated on seams)";
    }
    s << " -> " << output;
    if (!args.oracle.empty()) s << ", oracle -> " << args.oracle;
    s << "\n";
    if (meshed.stats.clamped_vertices > 0) {
        s << "  note: " << meshed.stats.clamped_vertices
          << " vertices were taken from the nearest ray crossing off their cell edge\n";
    }
    std::cerr << s.str();
}

}  // namespace

void add_simulate_command(CLI::App& app) {
    auto args = std::make_shared<SimulateArguments>();
    CLI::App* command = app.add_subcommand(
        "simulate",
        "Mill a box stock along a G-code program on a tri-dexel grid, or sample a CSG solid "
        "(--solid) on it, and mesh the result (marching cubes by default, every vertex exactly "
        "on the surface). The job file (JSON) gives the stock, the tool table, the pitch and the "
        "program; the solid file is described in src/resharp/sim/csg_file.h; see "
        "docs/oracle.md for the oracle file.");
    CLI::Option* job = command->add_option("job", args->job, "job file (JSON)");
    CLI::Option* solid =
        command->add_option("--solid", args->solid, "a CSG solid file (JSON) instead of a job");
    job->excludes(solid);
    command->add_option("-o,--output", args->output,
                        "mesh to write (.stl, .obj, .ply, .off); default: the job's or solid's "
                        "path with .stl");
    command
        ->add_option("--oracle", args->oracle,
                     "also write the mesh as PLY with each vertex's exact normal (nx ny nz) "
                     "and surface id (surface)")
        ->check([](const std::string& path) {
            return std::filesystem::path(path).extension() == ".ply" ? std::string()
                                                                     : "the oracle is a .ply file";
        });
    add_grid_options(*command, args->grid, "the job's pitch; 100 cells for a solid");
    command
        ->add_option("--grid-phase", args->options.grid_phase,
                     "grid nodes at the stock's (or solid's box's) min + (k + phase) * h")
        ->capture_default_str();
    command
        ->add_option("--helix-tolerance", args->options.helix_tolerance,
                     "largest distance (mm) of the ramps replacing a helical arc")
        ->capture_default_str();
    command
        ->add_option("--bullnose-step", args->options.sweep.bullnose_step,
                     "spacing (mm) of the tool copies that sample a bull-nose ramp")
        ->capture_default_str();
    command
        ->add_option("--mesher", args->mesher,
                     "how vertices are placed: mc (exact ray crossings), bisect (8 bisection "
                     "steps), midpoint (cell edge midpoints), surface-nets (one per cell at the "
                     "mean of its crossings); default: the job's, else mc")
        ->check(CLI::IsMember({"mc", "bisect", "midpoint", "surface-nets"}));
    command
        ->add_option("--seam-duplicates", args->seam_duplicates,
                     "write the triangles on K grid planes x = const twice, as parallel "
                     "meshing jobs do on their seams; default: the job's, else 0")
        ->check(CLI::NonNegativeNumber);
    command->add_flag("--ascii", args->ascii, "write STL and PLY as text instead of binary");
    command->add_flag("-q,--quiet", args->quiet, "no progress bar and no summary");
    command->callback([args] {
        if (args->job.empty() && args->solid.empty()) {
            throw CLI::RequiredError("a job file or --solid");
        }
        run_simulate(*args);
    });
}

}  // namespace resharp::cli
