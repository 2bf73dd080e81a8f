// `resharp evaluate`: scores a restored mesh against the simulator's oracle and the exact
// surface (docs/design.md §5, docs/results.md): ideal points on the exact junction of the job's
// surfaces, and the first-order (eq. 5.2) ones beside them. A thin layer over resharp::eval.

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>

#include "commands.h"
#include "grid_choice.h"
#include "resharp/core/errors.h"
#include "resharp/core/stage_timer.h"
#include "resharp/eval/cad_metrics.h"
#include "resharp/eval/crease_losses.h"
#include "resharp/eval/detection.h"
#include "resharp/eval/evaluation_files.h"
#include "resharp/eval/exact_creases.h"
#include "resharp/eval/exact_junctions.h"
#include "resharp/eval/ideal_points.h"
#include "resharp/eval/miss_causes.h"
#include "resharp/eval/oracle_restoration.h"
#include "resharp/eval/restoration_rate.h"
#include "resharp/eval/surface_distance.h"
#include "resharp/eval/validity.h"
#include "resharp/io/atomic_file.h"
#include "resharp/io/mesh_io.h"
#include "resharp/pipeline/restore.h"
#include "resharp/sim/csg_file.h"
#include "resharp/sim/gcode.h"
#include "resharp/sim/job.h"
#include "resharp/sim/simulate.h"

namespace resharp::cli {
namespace {

using nlohmann::json;

struct EvaluateArguments {
    std::string input, oracle, job, solid, output, segments, json;
    GridChoice grid;             // the pitch the input was made with (a job's own by default)
    bool restore = false;        // run restore() here instead of reading --output
    bool exact_normals = false;  // with --restore: the oracle's normals replace eq. 5.1
    bool oracle_bands = false;   // with --restore: the split alone, on the oracle's bands
    CurvatureFeature feature = CurvatureFeature::Magnitude;
    bool paper = false;          // with --restore: paper_variant() of the options
    double sample_pitch = 0.25;  // exact samples: ray grid pitch in h
    double grid_phase = sim::SimulationOptions{}.grid_phase;
    eval::IdealPointOptions ideal;
    eval::ExactJunctionOptions junctions;
    eval::RestorationOptions restoration;
    eval::SurfaceMetricsOptions surface;
    eval::CadMetricsOptions cad;
    bool quiet = false;
};

json to_json(const eval::EdgeMetrics& e) {
    return {{"exact_edge_samples", e.exact_edge_samples},
            {"mesh_edge_samples", e.mesh_edge_samples},
            {"ecd", e.ecd},
            {"ef1", e.ef1}};
}

json to_json(const eval::SurfaceMetrics& m) {
    return {{"exact_samples", m.exact_samples},
            {"mesh_samples", m.mesh_samples},
            {"chamfer_l1", m.chamfer_l1},
            {"chamfer_l2", m.chamfer_l2},
            {"hausdorff", m.hausdorff},
            {"hausdorff_p99", m.hausdorff_p99},
            {"normal_consistency", m.normal_consistency},
            {"f1", m.f1},
            {"edges_ndc", to_json(m.edges_ndc)},
            {"edges_dihedral", to_json(m.edges_dihedral)}};
}

json to_json(const eval::MeshValidity& v) {
    return {{"vertices", v.vertices},
            {"triangles", v.triangles},
            {"boundary_edges", v.boundary_edges},
            {"nonmanifold_edges", v.nonmanifold_edges},
            {"inconsistent_edges", v.inconsistent_edges},
            {"degenerate_faces", v.degenerate_faces},
            {"self_intersections", v.self_intersections},
            {"min_angle_deg", v.min_angle_deg}};
}

json to_json(const eval::DetectionScore& d) {
    return {{"detected", d.detected},
            {"actual", d.actual},
            {"matched", d.matched},
            {"precision", d.precision},
            {"recall", d.recall}};
}

json to_json(const eval::MissCauses& c) {
    json edges, corners;
    for (std::size_t k = 0; k < eval::kMissCauseCount; ++k) {
        const std::string name(eval::miss_cause_name(static_cast<eval::MissCause>(k)));
        edges[name] = c.edges[k];
        corners[name] = c.corners[k];
    }
    return {{"edges", edges}, {"corners", corners}};
}

json to_json(const eval::RestorationScore& s) {
    return {{"edges", s.ideal_edges},
            {"corners", s.ideal_corners},
            {"restored_edges", s.restored_edges},
            {"restored_corners", s.restored_corners},
            {"beyond_chord", s.beyond_chord},
            {"restored_beyond_chord", s.restored_beyond_chord},
            {"new_vertices", s.new_vertices}};
}

/// Per JunctionStatus but Exact: the ideal points left out of the exact-junction rate.
json counted_apart(const eval::ExactIdealPoints& ideal) {
    json apart;
    for (std::size_t k = 1; k < eval::kJunctionStatusCount; ++k) {
        const std::string name(eval::junction_status_name(static_cast<eval::JunctionStatus>(k)));
        apart[name] = {{"edges", ideal.edges[k]}, {"corners", ideal.corners[k]}};
    }
    return apart;
}

/// The restored mesh and what the method detected, from restore() here or from files.
struct Restored {
    Mesh mesh;
    Segmentation segmentation;  // empty unless known
    std::string detection_source;
};

Restored obtain_restored(const EvaluateArguments& args, const Mesh& input,
                         const eval::Oracle& oracle) {
    if (!args.restore) {
        Restored r{eval::read_restored(args.output, input), {}, "none"};
        if (!args.segments.empty()) {
            r.segmentation.face_role = eval::read_segment_roles(args.segments, input.face_count());
            r.detection_source = "segments file (face colours)";
        }
        return r;
    }
    if (args.oracle_bands) {
        eval::OracleRestoration r = eval::restore_from_oracle(input, oracle, args.ideal);
        if (!args.output.empty()) io::write_mesh(args.output, r.mesh);
        Segmentation roles;
        roles.face_role = std::move(r.bands.face_role);
        return {std::move(r.mesh), std::move(roles), "the oracle (--oracle-bands)"};
    }
    RestoreOptions options;
    options.edges.feature = args.feature;
    if (args.paper) options = paper_variant(options);
    options.keep_segmentation = true;
    if (args.exact_normals) {
        eval::ExactNormalRestoration r = eval::restore_with_exact_normals(input, oracle, options);
        if (!args.output.empty()) io::write_mesh(args.output, r.mesh);
        return {std::move(r.mesh), std::move(r.segmentation), "restore() with exact normals"};
    }
    RestoreResult result = restore(input, options);
    if (!args.output.empty()) io::write_mesh(args.output, result.mesh);
    return {std::move(result.mesh), std::move(result.segmentation), "restore() in process"};
}

/// The exact surface the input was made from, sampled again on a finer grid: a job's program
/// milled again (with the solid it mills, for the exact junctions), or a CSG solid (for its
/// true sharp edges).
struct ExactReference {
    double h = 0.0;  // pitch of the input's grid, mm
    sim::DexelGrid grid;
    std::optional<eval::MachinedSolid> machined;
    std::optional<sim::CsgSolid> csg;
};

ExactReference exact_reference(const EvaluateArguments& args) {
    ExactReference r;
    if (!args.solid.empty()) {
        r.csg.emplace(sim::read_csg(args.solid));
        r.h = resolve_pitch(args.grid, r.csg->bounds(), 0.0);
        r.grid = sim::sample_solid(
            sim::phased_grid(r.csg->bounds(), r.h * args.sample_pitch, args.grid_phase), *r.csg);
        return r;
    }
    const sim::Job job = sim::read_job(args.job);
    r.h = resolve_pitch(args.grid, job.stock, job.pitch);
    const sim::ToolPath path = sim::read_gcode(job.program, {.start_position = job.start_position});
    sim::SimulationOptions options;
    options.pitch = r.h * args.sample_pitch;
    options.grid_phase = args.grid_phase;
    r.grid = sim::simulate(job.stock, job.tools, path, options).grid;
    r.machined.emplace(job.stock, job.tools, path, sim::SimulationOptions{.pitch = r.h});
    return r;
}

json to_json(const eval::CadMetrics& m) {
    const eval::CreaseMetrics& c = m.creases;
    // NaN (no sharp edge on one side) has no JSON number: null.
    const auto number = [](double x) { return std::isnan(x) ? json(nullptr) : json(x); };
    return {{"chamfer", m.chamfer},
            {"hausdorff", m.hausdorff},
            {"normal_consistency", m.normal_consistency},
            {"edge_chamfer_distance", number(c.ecd)},
            {"edge_f1", c.ef1},
            {"edge_precision", c.precision},
            {"edge_recall", c.recall},
            {"crease_length", c.mesh_length},
            {"true_crease_length", c.true_length},
            {"stray_crease_length", c.stray_length},
            {"crease_length_ratio", number(c.length_ratio)}};
}

json to_json(const eval::CreaseLosses& l) {
    json missed, beside, stray;
    for (std::size_t k = 0; k < eval::kCreaseLossCount; ++k) {
        json by_moves;
        for (std::size_t m = 0; m < eval::kMoveFateCount; ++m)
            by_moves[std::string(eval::move_fate_name(eval::MoveFate(m)))] = l.missed[k][m];
        missed[std::string(eval::crease_loss_name(eval::CreaseLoss(k)))] = by_moves;
    }
    for (std::size_t o = 0; o < eval::kOriginCount; ++o) {
        const std::string name(eval::origin_name(eval::Origin(o)));
        beside[name] = l.false_beside[o];
        stray[name] = l.false_stray[o];
    }
    return {{"true_length", l.true_length},
            {"missed_length", missed},
            {"mesh_length", l.mesh_length},
            {"false_length_beside_true", beside},
            {"false_length_stray", stray}};
}

/// The "cad" block: the measures of a CAD part against the CSG solid, input and output, and,
/// where restore() ran here (its segmentation known), why the output's sharp edges miss.
json cad_block(const ExactReference& reference, const Mesh& input, const Mesh& output,
               const Segmentation& segmentation, const eval::SurfaceMetrics& surface_in,
               const eval::SurfaceMetrics& surface_out, eval::CadMetricsOptions cad) {
    const eval::CurveSamples creases = eval::sample_exact_creases(
        *reference.csg, reference.grid, {.sharp_angle_deg = cad.sharp_angle_deg});
    cad.spacing = reference.grid.spec.pitch;
    const double diagonal = reference.csg->bounds().diagonal().norm();
    json losses = nullptr;
    if (!segmentation.point_fate.empty()) {
        losses = to_json(eval::find_crease_losses(
            input, output, segmentation, creases, reference.h, cad.sharp_angle_deg, cad.spacing,
            {.tolerance = cad.tolerance, .far = cad.far, .unit = diagonal}));
    }
    return {
        {"crease_losses", losses},
        {"output", to_json(eval::measure_cad_part(output, surface_out, creases, diagonal, cad))},
        {"input", to_json(eval::measure_cad_part(input, surface_in, creases, diagonal, cad))},
        {"diagonal_mm", diagonal},
        {"sharp_angle_deg", cad.sharp_angle_deg},
        {"tau_diagonals", cad.tolerance},
        {"stray_beyond_diagonals", cad.far}};
}

/// The input with its vertices where `output` (which starts with them, in order) has them:
/// the input itself unless the restoration moved vertices, as near-surface restoration does
/// within a grid cell (or, for a vertex in a cell its surfaces do not cross, the cells around
/// it: near/vertex_moves.h).
/// \throws InvalidInput if output has fewer vertices, or moved one further than the diagonal
///         of the two cells a move may span along each axis (2 sqrt(3) h).
Mesh input_as_placed(const Mesh& input, const Mesh& output, double h) {
    if (output.vertex_count() < input.vertex_count())
        throw InvalidInput("the output has fewer vertices than the input");
    Mesh placed{{output.positions.begin(), output.positions.begin() + input.vertex_count()},
                input.triangles};
    for (std::size_t v = 0; v < input.vertex_count(); ++v) {
        const double move = (placed.positions[v] - input.positions[v]).norm();
        if (move > 2.0 * std::sqrt(3.0) * h * (1.0 + 1e-9)) {
            throw InvalidInput("output vertex " + std::to_string(v) + " lies " +
                               std::to_string(move) + " mm from input vertex " + std::to_string(v) +
                               ", more than the diagonal of two grid cells");
        }
    }
    return placed;
}

std::size_t moved_count(const Mesh& input, const Mesh& placed) {
    std::size_t count = 0;
    for (std::size_t v = 0; v < input.vertex_count(); ++v)
        count += placed.positions[v] != input.positions[v];
    return count;
}

void run_evaluate(EvaluateArguments args) {
    const StageTimer total;
    const StageTimer sampling;
    const ExactReference reference = exact_reference(args);
    const double h = reference.h;
    args.restoration.pitch = args.surface.pitch = h;

    const Mesh input = weld(io::read_mesh(args.input));
    const eval::Oracle oracle = eval::read_oracle(args.oracle, input);
    const Restored restored = obtain_restored(args, input, oracle);
    const Mesh& output = restored.mesh;
    // A near-surface restoration moves input vertices (issue 14): the scores that tell the
    // output's new vertices from the input's read the input where it was moved to.
    const Mesh placed = input_as_placed(input, output, h);
    const std::size_t moved = moved_count(input, placed);

    const eval::SurfaceSamples exact = eval::sample_exact_surface(reference.grid);
    const double sampling_seconds = std::chrono::duration<double>(sampling.elapsed()).count();

    const StageTimer junctions;
    const auto first_order = eval::find_ideal_points(input, oracle, args.ideal);
    // A CSG solid's surfaces have no eval::MachinedSolid: its ideal points stay first order.
    eval::ExactIdealPoints ideal{first_order, {}, {}};
    eval::RestorationOptions on_junction = args.restoration;
    if (reference.machined) {
        args.junctions.solver.pitch = h;
        args.junctions.smooth_angle_deg = args.ideal.sharp_angle_deg;
        ideal = eval::find_exact_ideal_points(input, oracle, first_order, *reference.machined,
                                              args.junctions);
        on_junction.count_input_vertices = true;
    }
    const double junction_seconds = std::chrono::duration<double>(junctions.elapsed()).count();

    const eval::RestorationScore score =
        eval::score_restoration(placed, output, ideal.points, exact, on_junction);
    const eval::RestorationScore first =
        eval::score_restoration(placed, output, first_order, exact, args.restoration);
    const double tau = args.restoration.tolerance * h;

    json j;
    j["ideal_points_on"] =
        reference.machined ? "the exact junction" : "first-order points (eq. 5.2)";
    j["restoration_rate"] = score.rate;
    j["restoration_rate_first_order"] = first.rate;
    // The input's own rate on the exact junction: the points an input vertex already restores.
    j["restoration_rate_input"] = score.ideal_edges + score.ideal_corners == 0
                                      ? 1.0
                                      : double(score.restored_by_input_vertices) /
                                            double(score.ideal_edges + score.ideal_corners);
    j["restoration_rate_edges"] = score.rate_edges;
    j["restoration_rate_corners"] = score.rate_corners;
    j["restoration_rate_within_reach"] = score.rate_within_reach;
    j["false_insertions"] = score.false_insertions;
    j["max_new_vertex_distance"] = score.max_new_vertex_distance;
    j["ideal_points"] = to_json(score);
    j["ideal_points"]["restored_by_input_vertices"] = score.restored_by_input_vertices;
    j["ideal_points"]["counted_apart"] = counted_apart(ideal);
    j["miss_causes"] = to_json(eval::find_miss_causes(
        placed, output, ideal.points, score.ideal_distance, tau, restored.segmentation));
    j["first_order"] = {{"restoration_rate", first.rate},
                        {"restoration_rate_edges", first.rate_edges},
                        {"restoration_rate_corners", first.rate_corners},
                        {"restoration_rate_within_reach", first.rate_within_reach},
                        {"false_insertions", first.false_insertions},
                        {"ideal_points", to_json(first)},
                        {"miss_causes", to_json(eval::find_miss_causes(placed, output, first_order,
                                                                       first.ideal_distance, tau,
                                                                       restored.segmentation))}};
    j["detection_source"] = restored.detection_source;
    j["detection_precision"] = nullptr;
    j["detection_recall"] = nullptr;
    if (!restored.segmentation.face_role.empty()) {
        const auto d = eval::score_detection(restored.segmentation.face_role,
                                             eval::true_band_roles(input, oracle, args.ideal));
        j["detection_precision"] = d.bands.precision;
        j["detection_recall"] = d.bands.recall;
        j["detection"] = {{"bands", to_json(d.bands)}, {"corners", to_json(d.corners)}};
    }

    const eval::MeshValidity valid_in = eval::check_validity(input);
    const eval::MeshValidity valid_out = eval::check_validity(output);
    // Moved faces keep their corners' numbers: with moves every output face is judged.
    const std::vector<std::uint8_t> flipped =
        eval::flipped_faces(placed, output, oracle, exact,
                            moved > 0 ? eval::FlipScope::AllFaces : eval::FlipScope::ChangedFaces);
    const std::vector<std::uint8_t> flipped_in_input =
        eval::flipped_faces(input, input, oracle, exact, eval::FlipScope::AllFaces);
    j["flipped_triangles"] = std::count(flipped.begin(), flipped.end(), 1);
    j["flipped_scope"] = moved > 0 ? "all faces" : "changed faces";
    // What turned them: already turned in the input (and left so), turned by the moves, or a
    // piece the split cut.
    const auto by_origin = eval::flipped_by_origin(input, output, flipped, flipped_in_input);
    for (std::size_t o = 0; o < eval::kOriginCount; ++o)
        j["flipped_by_origin"][std::string(eval::origin_name(eval::Origin(o)))] = by_origin[o];
    j["moved_input_vertices"] = moved;
    const std::vector<std::uint8_t> turned = eval::turned_against_input(input, output);
    j["turned_against_input"] = std::count(turned.begin(), turned.end(), 1);
    j["flipped_triangles_input"] = std::count(flipped_in_input.begin(), flipped_in_input.end(), 1);
    j["self_intersections"] = valid_out.self_intersections;
    j["self_intersections_input"] = valid_in.self_intersections;
    j["nonmanifold_edges"] = valid_out.nonmanifold_edges;
    j["boundary_edges"] = valid_out.boundary_edges;
    j["validity"] = {{"input", to_json(valid_in)}, {"output", to_json(valid_out)}};

    const eval::SurfaceSamples input_samples = eval::sample_mesh(input, reference.grid.spec);
    const eval::SurfaceSamples output_samples = eval::sample_mesh(output, reference.grid.spec);
    const eval::SurfaceMetrics surface_out =
        eval::compare_surfaces(output, output_samples, exact, args.surface);
    const eval::SurfaceMetrics surface_in =
        eval::compare_surfaces(input, input_samples, exact, args.surface);
    j["surface"] = {{"output", to_json(surface_out)}, {"input", to_json(surface_in)}};
    if (reference.csg) {
        j["cad"] = cad_block(reference, input, output, restored.segmentation, surface_in,
                             surface_out, args.cad);
    }

    j["settings"] = {{"h_mm", h},
                     {"sharp_angle_deg", args.ideal.sharp_angle_deg},
                     {"tau_h", args.restoration.tolerance},
                     {"sample_pitch_h", args.sample_pitch},
                     {"edge_radius_h", args.surface.edge_radius},
                     {"edge_max_abs_dot", args.surface.edge_max_abs_dot},
                     {"edge_dihedral_deg", args.surface.edge_dihedral_deg},
                     {"f1_threshold_h", args.surface.f1_threshold},
                     {"edge_f1_threshold_h", args.surface.edge_f1_threshold},
                     {"lengths", "mm"}};
    j["time_seconds"] = {{"exact_sampling", sampling_seconds},
                         {"exact_junctions", junction_seconds},
                         {"total", std::chrono::duration<double>(total.elapsed()).count()}};

    if (!args.json.empty()) {
        const std::string text = j.dump(2) + "\n";
        io::write_atomically(args.json, [&](std::ostream& out) { out << text; });
    }
    if (args.quiet) return;
    std::ostringstream s;
    const std::size_t apart = first.ideal_edges + first.ideal_corners - ideal.points.size();
    s << "restoration rate " << score.rate * 100 << " % on "
      << j["ideal_points_on"].get<std::string>() << " (edges " << score.restored_edges << "/"
      << score.ideal_edges << ", corners " << score.restored_corners << "/" << score.ideal_corners
      << "; " << apart << " counted apart), " << score.rate_within_reach * 100 << " % of the "
      << score.ideal_edges + score.ideal_corners - score.beyond_chord
      << " points within reach of an edge split; restoration rate first order (eq. 5.2) "
      << first.rate * 100 << " %; false insertions " << score.false_insertions << ", flipped "
      << j["flipped_triangles"] << ", self-intersections " << valid_out.self_intersections
      << " (input " << valid_in.self_intersections << ")\n";
    if (j.contains("cad")) {
        const json& in = j["cad"]["input"];
        const json& out = j["cad"]["output"];
        s << "CAD part, input -> output: Edge F-score " << in["edge_f1"] << " -> " << out["edge_f1"]
          << ", Edge Chamfer Distance " << in["edge_chamfer_distance"] << " -> "
          << out["edge_chamfer_distance"] << ", crease length " << in["crease_length_ratio"]
          << " -> " << out["crease_length_ratio"] << " of the true, Chamfer " << in["chamfer"]
          << " -> " << out["chamfer"] << " diagonals\n";
    }
    std::cerr << s.str();
}

}  // namespace

void add_evaluate_command(CLI::App& app) {
    auto args = std::make_shared<EvaluateArguments>();
    CLI::App* command = app.add_subcommand(
        "evaluate",
        "Score a restored mesh against the simulator's oracle and the exact surface: restoration "
        "rate, detection, surface distances, validity (docs/results.md). Lengths are in mm, "
        "thresholds in units of the job's pitch h. With --solid, also the measures of a CAD "
        "part in units of its bounding-box diagonal (\"cad\" in the JSON).");
    command->add_option("--input", args->input, "the simulated mesh (resharp simulate -o)")
        ->required();
    command->add_option("--oracle", args->oracle, "its oracle PLY (resharp simulate --oracle)")
        ->required();
    CLI::Option* job = command->add_option(
        "--job", args->job,
        "the job file the mesh was simulated from; its surface is sampled again on a finer grid");
    command
        ->add_option("--solid", args->solid,
                     "the CSG solid file the mesh was sampled from (resharp simulate --solid), "
                     "instead of --job; its ideal points are first order (eq. 5.2)")
        ->excludes(job);
    add_grid_options(*command, args->grid,
                     "the job's; 100 cells for a solid; give what simulate was given");
    command->add_option("--output", args->output,
                        "the restored mesh (with --restore: where to write it, optional)");
    command->add_option("--segments", args->segments,
                        "the --segments PLY of the same restore run: edge and corner triangles "
                        "for detection precision and recall");
    command->add_option("--json", args->json, "write every metric as JSON");
    command->add_flag("--restore", args->restore,
                      "run restore() here on the input instead of reading --output (default "
                      "options), so detection and miss causes use the method's own labels");
    const std::map<std::string, CurvatureFeature> features{
        {"magnitude", CurvatureFeature::Magnitude}, {"signed", CurvatureFeature::Signed}};
    command->add_option("--curvature-feature", args->feature, "with --restore: as restore's")
        ->transform(CLI::CheckedTransformer(features, CLI::ignore_case))
        ->needs("--restore");
    command
        ->add_flag("--paper", args->paper,
                   "with --restore: the paper's choice wherever resharp makes another, as "
                   "restore's --paper")
        ->needs("--restore");
    command
        ->add_flag("--exact-normals", args->exact_normals,
                   "with --restore: the oracle's exact normals replace eq. 5.1 (the ceiling "
                   "of the placement step)")
        ->needs("--restore");
    command
        ->add_flag("--oracle-bands", args->oracle_bands,
                   "with --restore: split the oracle's crossing edges and corner triangles "
                   "with its exact normals, no segmentation (the ceiling of any restoration "
                   "that splits crossing edges)")
        ->excludes("--paper")
        ->excludes("--exact-normals")
        ->excludes("--curvature-feature")
        ->needs("--restore");
    command
        ->add_option("--sharp-angle", args->ideal.sharp_angle_deg,
                     "theta_s: normals further apart make a sharp junction (degrees)")
        ->capture_default_str();
    command
        ->add_option("--tolerance", args->restoration.tolerance,
                     "tau in h: an ideal point is restored by a new vertex this near")
        ->capture_default_str();
    command
        ->add_option("--sample-pitch", args->sample_pitch,
                     "pitch of the ray grid sampling the exact surface and the meshes, in h")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    command->add_option("--grid-phase", args->grid_phase, "phase of that grid, as simulate's")
        ->capture_default_str();
    command
        ->add_option("--edge-radius", args->surface.edge_radius,
                     "r of the edge-sample test in h (NDC: 0.256 h)")
        ->capture_default_str();
    command
        ->add_option("--edge-f1-threshold", args->surface.edge_f1_threshold,
                     "Edge F-score distance threshold in h (NDC: 0.32 h)")
        ->capture_default_str();
    command
        ->add_option("--edge-tolerance", args->cad.tolerance,
                     "with --solid: tau of the Edge F-score, in bounding-box diagonals")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    command->add_flag("-q,--quiet", args->quiet, "print no summary");
    command->callback([args] {
        if (args->job.empty() == args->solid.empty()) {
            throw CLI::ValidationError("--job", "give exactly one of --job and --solid");
        }
        if (!args->restore && args->output.empty()) {
            throw CLI::ValidationError("--output", "needed unless --restore is given");
        }
        run_evaluate(*args);
    });
}

}  // namespace resharp::cli
