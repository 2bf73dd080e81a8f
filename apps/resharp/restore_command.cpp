#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "batch.h"
#include "commands.h"
#include "report_json.h"
#include "restore_file.h"

namespace resharp::cli {
namespace {

struct RestoreArguments {
    std::vector<std::string> inputs;
    RestoreTargets targets;  ///< input unset; folders in a batch
    BatchSettings batch;
    bool ascii = false;
    bool paper = false;
    RestoreOptions options;
};

/// One flag per field of RestoreOptions; the defaults shown by --help are the struct's own.
void bind_options(CLI::App& command, RestoreOptions& o) {
    const std::map<std::string, CurvatureFeature> features{
        {"magnitude", CurvatureFeature::Magnitude}, {"signed", CurvatureFeature::Signed}};
    command
        .add_option("--curvature-feature", o.edges.feature,
                    "what k-means clusters: 'signed' (k1, k2) as the paper, or 'magnitude' "
                    "(|k|min, |k|max), which keeps concave and convex edges together")
        ->transform(CLI::CheckedTransformer(features, CLI::ignore_case))
        ->option_text("{magnitude,signed}=magnitude");
    const std::map<std::string, NormalEstimate> estimates{
        {"fit", NormalEstimate::LinearFit}, {"angle-weighted", NormalEstimate::AngleWeighted}};
    command
        .add_option("--normals", o.normals.estimate,
                    "feature normals at band vertices: 'angle-weighted' is eq. 5.1 as the "
                    "paper; 'fit' extrapolates the feature's face normals to the vertex, "
                    "exact on planes and better on curved features")
        ->transform(CLI::CheckedTransformer(estimates, CLI::ignore_case))
        ->option_text("{fit,angle-weighted}=fit");
    command
        .add_option("--max-fit-correction", o.normals.max_fit_correction_deg,
                    "a fitted normal further than this (degrees) from eq. 5.1's is not used")
        ->capture_default_str();
    command
        .add_option("--max-fit-residual", o.normals.max_fit_residual_deg,
                    "faces whose normal is further than this (degrees) from the first fit, such "
                    "as faces beyond a scallop cusp, are left out of the second; 180 keeps all")
        ->capture_default_str();
    command
        .add_option("--kmeans-tolerance", o.edges.kmeans_tolerance,
                    "eps_K (paper eq. 3.2): k-means stops when centres move less (1/length)")
        ->capture_default_str();
    command
        .add_option("--max-kmeans-iterations", o.edges.max_kmeans_iterations,
                    "safety bound on k-means iterations")
        ->capture_default_str();
    command
        .add_option("--bridge-walk", o.edges.max_bridge_walk,
                    "P (paper 3.3): vertices a walk may visit to bridge a broken edge")
        ->capture_default_str();
    command
        .add_option("--flat-spread", o.edges.flat_normal_spread_deg,
                    "edge vertices whose one-ring normals spread less (degrees) are flat")
        ->capture_default_str();
    command
        .add_option("--region-angle", o.features.max_normal_angle_deg,
                    "eps_theta (paper 4): neighbouring faces closer than this (degrees) grow "
                    "into one patch")
        ->capture_default_str();
    command
        .add_option("--tiny-patch", o.features.tiny_patch_faces,
                    "patches with fewer faces are tiny and absorbed (paper 4)")
        ->capture_default_str();
    command
        .add_option("--band-interior-fraction", o.features.band_interior_fraction,
                    "patches with fewer interior vertices than this share are chamfer bands")
        ->capture_default_str();
    command
        .add_option("--merge-angle", o.features.merge_angle_deg,
                    "touching patches whose normals differ less (degrees) along their border "
                    "are merged")
        ->capture_default_str();
    command
        .add_option("--curved-region-faces", o.features.curved_region_faces,
                    "a region this large only grows into faces near its seed's normal, so "
                    "growth cannot creep around a scallop cusp; 0 grows without limit (paper)")
        ->capture_default_str();
    command.add_flag("!--merge-over-sharp-borders", o.features.keep_sharp_borders_apart,
                     "plain greedy merging (paper): may join patches through smooth borders even "
                     "where they meet at a sharp border elsewhere");
    command
        .add_option("--unconfirmed-border-angle", o.bands.unconfirmed_border_angle_deg,
                    "a patch border without edge vertices is a sharp edge when the patches' "
                    "normals differ more (degrees); 180 is the paper's rule")
        ->capture_default_str();
    command
        .add_option("--smooth-border-angle", o.bands.smooth_border_angle_deg,
                    "a patch border whose patches' normals differ less (degrees) is never a "
                    "sharp edge, even with edge vertices; 0 is the paper's rule")
        ->capture_default_str();
    command
        .add_option("--spike-angle", o.points.spike_angle_deg,
                    "corner points are refused when normals around the corner differ more "
                    "(degrees, paper 5.3)")
        ->capture_default_str();
    command
        .add_option("--thin-angle", o.guard.thin_material_angle_deg,
                    "the guard: pieces joining vertices whose normals differ more (degrees) "
                    "stand across thin material and must clear both surfaces by a wider margin")
        ->capture_default_str();
    command
        .add_option("--fold-angle", o.harm.fold_angle_deg,
                    "the harm check: adjacent output faces whose normals differ more (degrees) "
                    "than their input faces' did are folded, and their points undone")
        ->capture_default_str();
    command.add_flag("!--no-crossing-check", o.harm.check_crossings,
                     "skip the harm check's test of every new piece against the faces near it "
                     "(faster; a self-intersection is then no longer ruled out)");
    command
        .add_option("--harm-rounds", o.max_harm_rounds,
                    "rounds of guard, split and harm check at most; past them the mesh comes "
                    "back unchanged")
        ->capture_default_str();
    command.add_flag("!--keep-duplicate-faces", o.repair.remove_duplicate_faces,
                     "keep exact duplicate faces (same vertices, same orientation) instead of "
                     "removing all but the first copy");
    command
        .add_option("--threads", o.threads,
                    "worker threads, 0 for all cores; the output "
                    "does not depend on it")
        ->capture_default_str();
}

void run_restore(const RestoreArguments& args, const CLI::App& command) {
    const RestoreOptions options = args.paper ? paper_variant(args.options) : args.options;
    const io::Encoding encoding = args.ascii ? io::Encoding::Ascii : io::Encoding::Binary;
    if (is_batch(args.inputs, args.targets.output)) {
        run_batch(args.inputs, args.targets, args.batch, options, encoding, command);
        return;
    }
    check_single_file(command);
    RestoreTargets targets = args.targets;
    targets.input = args.inputs.front();
    const RestoreReport report = restore_file(targets, options, encoding);
    if (!args.batch.quiet) std::cerr << summarize(report, targets.input, targets.output);
}

}  // namespace

void add_restore_command(CLI::App& app) {
    auto args = std::make_shared<RestoreArguments>();
    CLI::App* command = app.add_subcommand(
        "restore",
        "Restore sharp edges and corners of a mesh made by grid-based machining "
        "simulation. Formats from the extension: .stl (binary or ASCII), .obj, .ply, "
        ".off.");
    command->footer(std::string(kBatchHelp) + "\n\n" + app.get_footer());
    command->add_option("input", args->inputs, "mesh to restore; several, or folders: a batch")
        ->required();
    command->add_option("-o,--output", args->targets.output, "restored mesh; a folder in a batch")
        ->required();
    command->add_option("--report", args->targets.report,
                        "write every count and stage time as JSON (a folder in a batch)");
    command->add_option("--segments", args->targets.segments,
                        "write the input as PLY with vertex colours (red: edge vertices) and face "
                        "colours (one per feature patch; yellow: edge triangles; magenta: corner "
                        "triangles); a folder in a batch");
#ifdef RESHARP_HAS_VIEWER
    command->add_option("--html", args->targets.html,
                        "write the viewer page: input and restored mesh side by side (a folder "
                        "in a batch)");
#endif
    command->add_flag("--ascii", args->ascii, "write STL and PLY as text instead of binary");
    command->add_flag("-q,--quiet", args->batch.quiet,
                      "print no summary (a batch still prints each failure)");
    add_batch_options(*command, args->batch);
    bind_options(*command, args->options);
    CLI::Option* paper = command->add_flag(
        "--paper", args->paper,
        "the paper's choice wherever resharp makes another (docs/method.md): signed k-means, "
        "unlimited region growing, plain merging, borders confirmed by edge vertices only, eq. "
        "5.1 normals");
    for (const char* choice :
         {"--curvature-feature", "--normals", "--curved-region-faces", "--merge-over-sharp-borders",
          "--unconfirmed-border-angle", "--smooth-border-angle"}) {
        paper->excludes(command->get_option(choice));
    }
    command->callback([args, command] { run_restore(*args, *command); });
}

}  // namespace resharp::cli
