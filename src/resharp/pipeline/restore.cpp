#include "resharp/pipeline/restore.h"

#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "resharp/core/assert.h"
#include "resharp/core/errors.h"
#include "resharp/core/parallel.h"
#include "resharp/core/stage_timer.h"
#include "resharp/curvature/local_height.h"
#include "resharp/mesh/duplicate_faces.h"
#include "resharp/near/concave_bevels.h"
#include "resharp/near/vertex_moves.h"
#include "resharp/near/vertex_placement.h"
#include "resharp/restoration/harm_check.h"
#include "resharp/restoration/point_guard.h"
#include "resharp/restoration/sharp_points.h"

namespace resharp {

std::string_view stage_name(Stage stage) {
    switch (stage) {
        case Stage::MeshBuilding:
            return "mesh building";
        case Stage::Curvature:
            return "curvature";
        case Stage::EdgeSegmentation:
            return "edge segmentation";
        case Stage::FeatureSegmentation:
            return "feature segmentation";
        case Stage::Classification:
            return "classification";
        case Stage::FeatureNormals:
            return "feature normals";
        case Stage::VertexMoves:
            return "vertex moves";
        case Stage::SharpPoints:
            return "sharp points";
        case Stage::Guard:
            return "guard";
        case Stage::Split:
            return "split";
        case Stage::HarmCheck:
            return "harm check";
    }
    return "unknown";
}

namespace {

/// Midpoint meshes: rounds of segmenting the mesh moved so far and moving its vertices onto
/// their patches' planes (Pipeline::plan_moves()). A third changed stepped_block turned by 0.01
/// in Edge F-score when its band vertices stayed on their stairs; once they went onto their
/// faces (2026-12-07), it brought the CAD rows' mean 0.503 -> 0.517 (chamfered_block turned
/// 0.890 -> 0.928, hex_prism aligned 0.698 -> 0.731, cone_part aligned 0.203 -> 0.239, the
/// rest within 0.02), mech 0.688 -> 0.707, impeller 0.322 -> 0.343 (faces flipped against the
/// exact surface 112 -> 79), frogface 0.811 -> 0.801, for about 7 % more time on mech.
constexpr int kMidpointPatchRounds = 3;

void validate_mesh(const Mesh& mesh) {
    if (mesh.triangles.empty()) throw InvalidInput("the mesh has no triangles");
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        if (!mesh.positions[v].allFinite()) {
            throw InvalidInput("vertex " + std::to_string(v) + " has a NaN or infinite coordinate");
        }
    }
    // The largest vertex id first, a loop without branches: only a mesh that fails looks for
    // the first triangle at fault.
    Index largest = 0;
    for (const Triangle& t : mesh.triangles)
        largest = std::max(largest, std::max({t[0], t[1], t[2]}));
    if (largest < mesh.vertex_count()) return;
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
        for (Index v : mesh.triangles[f]) {
            if (v >= mesh.vertex_count()) {
                throw InvalidInput("triangle " + std::to_string(f) + " uses vertex " +
                                   std::to_string(v) + " but there are only " +
                                   std::to_string(mesh.vertex_count()) + " vertices");
            }
        }
    }
}

void validate_options(const RestoreOptions& options) {
    if (options.threads < 0) throw InvalidInput("thread count must not be negative");
    if (options.max_harm_rounds < 1) throw InvalidInput("harm rounds must be at least 1");
}

/// Times stages into `times` and asks `stop` before each.
class StageClock {
public:
    StageClock(std::array<std::chrono::nanoseconds, kStageCount>& times, const StopWhen& stop)
        : times_(times), stop_(stop) {}

    template <class Work>
    void run(Stage stage, Work&& work) {
        if (stop_.should_stop()) throw Cancelled("restore() was asked to stop");
        const StageTimer timer;
        work();
        times_[static_cast<std::size_t>(stage)] += timer.elapsed();
    }

private:
    std::array<std::chrono::nanoseconds, kStageCount>& times_;
    const StopWhen& stop_;
};

/// Per candidate point (#P): set for the points the slots of `faces` hold.
void withdraw_points_of(const std::vector<Index>& faces, const PointSlots& slots,
                        std::vector<std::uint8_t>& withdrawn, std::size_t& count) {
    for (Index f : faces) {
        slots.for_each_point(f, [&](Index p) {
            count += withdrawn[p] == 0;
            withdrawn[p] = 1;
        });
    }
}

/// With a reference: the harmful faces that hold no point did harm by their moves (every
/// face the check judges holds points or has a moved corner). Gives those moves up through the
/// reference (see restore_bands()); gives the faces within three rings of the vertices put
/// back, whose guard and check read what changed (none if no move was given up).
std::vector<Index> give_up_moves_of_pointless(const InputSurface& input,
                                              const HarmReference& reference,
                                              const PointSlots& accepted,
                                              const std::vector<Index>& harmful,
                                              BandRestoration& r) {
    std::vector<Index> without_points;
    for (Index f : harmful) {
        if (!accepted.has_points(f)) without_points.push_back(f);
    }
    if (without_points.empty()) return {};
    const std::vector<Index> put_back = reference.give_up_moves(without_points);
    RESHARP_ASSERT(!put_back.empty());
    r.moves_given_up += put_back.size();
    // A face's guard reads its corners' normals and its neighbours' slots; the normals made
    // again reach the corners of the faces around the vertices put back.
    constexpr int kReach = 3;
    return faces_within_rings(input.mesh, input.connectivity, put_back, kReach);
}

/// Per face (#F): 1 where the slots of `after` differ from those of `before` (so its pieces do).
std::vector<std::uint8_t> changed_faces(const PointSlots& before, const PointSlots& after) {
    std::vector<std::uint8_t> changed(after.face_count(), 0);
    for_each_index(changed.size(), 8192, [&](std::size_t f) {
        changed[f] = !before.same_at(static_cast<Index>(f), after, static_cast<Index>(f));
    });
    return changed;
}

/// Whether two guard results accept the same slots with the same counts.
[[maybe_unused]] bool same_guard(const GuardedPoints& a, const GuardedPoints& b) {
    return a.accepted == b.accepted && a.report.refused_by_quality == b.report.refused_by_quality &&
           a.report.refused_by_guard == b.report.refused_by_guard &&
           a.report.repairs == b.report.repairs;
}

/// The input as its own split: no face replaced.
SplitMesh unchanged(const Mesh& mesh) {
    SplitMesh out;
    out.mesh = mesh;
    out.source_face.resize(mesh.face_count());
    for (Index f = 0; f < mesh.face_count(); ++f) out.source_face[f] = f;
    return out;
}

/// Invariants of a split the harm check accepted: the input vertices first and unchanged, every
/// source face valid and in order, pieces only on faces with a crossing edge or a corner role.
[[maybe_unused]] bool is_sound_split(const InputSurface& input, const BandClassification& bands,
                                     const SplitMesh& split) {
    const Mesh& in = input.mesh;
    if (split.mesh.vertex_count() < in.vertex_count()) return false;
    if (!std::equal(in.positions.begin(), in.positions.end(), split.mesh.positions.begin()))
        return false;
    if (split.source_face.size() != split.mesh.face_count()) return false;
    for (std::size_t o = 0; o < split.source_face.size(); ++o) {
        const Index f = split.source_face[o];
        if (f >= in.face_count() || (o > 0 && f < split.source_face[o - 1])) return false;
        const bool may_be_split = bands.face_role[f] != BandRole::None ||
                                  bands.is_crossing[3 * f] || bands.is_crossing[3 * f + 1] ||
                                  bands.is_crossing[3 * f + 2];
        if (split.mesh.triangles[o] != in.triangles[f] && !may_be_split) return false;
    }
    return true;
}

/// Invariant of the split: it adds no boundary, non-manifold or inconsistent edge (every edge
/// point splits both faces of its edge; no point lies on a defective edge).
[[maybe_unused]] bool adds_no_open_or_nonmanifold_edge(const InputSurface& input,
                                                       const SplitMesh& split) {
    const MeshDiagnostics before = diagnose(input.mesh, input.connectivity);
    const MeshDiagnostics after = diagnose(split.mesh, build_connectivity(split.mesh));
    return after.boundary_edges <= before.boundary_edges &&
           after.nonmanifold_edges <= before.nonmanifold_edges &&
           after.inconsistent_edges <= before.inconsistent_edges;
}

}  // namespace

namespace {

/// detect_bands()'s last two stages, on the segmentations `d` holds.
void classify_and_fit_normals(const Mesh& mesh, Detection& d, const RestoreOptions& options,
                              StageClock& clock) {
    const Connectivity& connectivity = *d.connectivity;
    clock.run(Stage::Classification, [&] {
        d.bands = classify_bands(mesh, connectivity, d.normals.face, d.edges.is_edge,
                                 d.features.face_patch, d.features.vertex_patch, options.bands);
    });
    clock.run(Stage::FeatureNormals, [&] {
        d.feature_normals =
            feature_normals(mesh, connectivity, d.normals.face, d.features.face_patch,
                            d.features.vertex_patch, d.bands, options.normals);
        d.bands =
            drop_smooth_crossings(mesh, connectivity, d.bands, d.feature_normals, options.bands);
        d.feature_normals.drop_continuation_fields();  // nothing after reads them
    });
}

/// detect_bands(), its segmentations and what follows them taking the options
/// options_for_segmentation() gives once the normals and curvatures are estimated: a caller
/// measures the vertices' placement meanwhile, on which the growth of the regions and the
/// feature normals depend (adopt()). The normals and curvatures run in parallel, the
/// segmentations mostly on one thread each. `stop` is asked between stages.
template <class OptionsForSegmentation>
Detection detect_bands_calling(const Mesh& mesh, std::shared_ptr<const Connectivity> shared,
                               const StopWhen& stop,
                               OptionsForSegmentation&& options_for_segmentation) {
    Detection d;
    d.connectivity = std::move(shared);
    const Connectivity& connectivity = *d.connectivity;
    StageClock clock(d.stage_time, stop);
    clock.run(Stage::MeshBuilding, [&] { d.normals = surface_normals(mesh, connectivity); });
    PrincipalCurvatures curvatures;
    clock.run(Stage::Curvature, [&] {
        curvatures = estimate_principal_curvatures(mesh, connectivity, d.normals.vertex);
    });
    const RestoreOptions& options = options_for_segmentation();
    GrownRegions regions;
    auto grow = [&] {
        regions = grow_feature_regions(mesh, connectivity, d.normals.face, options.features);
    };
    auto find_edges = [&] {
        d.edges = segment_edges(mesh, connectivity, curvatures, d.normals.face, options.edges);
    };
    if (tbb::this_task_arena::max_concurrency() < 2) {
        clock.run(Stage::EdgeSegmentation, find_edges);
        clock.run(Stage::FeatureSegmentation, grow);
    } else {
        // The edge segmentation and the growth of the feature regions read neither's result, and
        // both are mostly serial: the edges go to a second thread while this one grows the
        // regions. If the growth throws (cancelled), the group's destructor cancels and waits
        // for the edges before `d` goes.
        tbb::task_group beside;
        beside.run(find_edges);
        clock.run(Stage::FeatureSegmentation, grow);
        clock.run(Stage::EdgeSegmentation, [&] { beside.wait(); });
    }
    clock.run(Stage::FeatureSegmentation, [&] {
        d.features = segment_features(mesh, connectivity, d.normals.face, std::move(regions),
                                      d.edges.is_edge, options.features);
    });
    classify_and_fit_normals(mesh, d, options, clock);
    return d;
}

}  // namespace

Detection detect_bands(const Mesh& mesh, std::shared_ptr<const Connectivity> connectivity,
                       const RestoreOptions& options) {
    return detect_bands_calling(mesh, std::move(connectivity), options.stop,
                                [&]() -> const RestoreOptions& { return options; });
}

Detection detect_bands(const Mesh& mesh, Connectivity connectivity, const RestoreOptions& options) {
    return detect_bands(mesh, std::make_shared<const Connectivity>(std::move(connectivity)),
                        options);
}

namespace {

/// check_harm() of `split` (of `input`) against `input`, or, given a reference, against the
/// input `input` was moved from.
HarmReport held_against(const InputSurface& input, const HarmReference* reference,
                        const SplitMesh& split, const RestoreOptions& options,
                        std::span<const std::uint8_t> changed) {
    if (!reference) {
        HarmReport harm = check_harm(input, split, options.harm, changed);
        RESHARP_EXPENSIVE_ASSERT(changed.empty() ||
                                 harm.harmful_faces ==
                                     check_harm(input, split, options.harm).harmful_faces);
        return harm;
    }
    return check_harm(input, split, options.harm, changed,
                      {reference->moved, reference->input_positions});
}

}  // namespace

Detection detect_bands_after_moves(const Mesh& mesh, const Detection& before,
                                   SurfaceNormals unmoved, std::span<const std::uint8_t> moved,
                                   const RestoreOptions& options) {
    Detection d;
    d.connectivity = before.connectivity;
    d.edges = before.edges;
    d.features = before.features;
    StageClock clock(d.stage_time, options.stop);
    clock.run(Stage::MeshBuilding, [&] {
        d.normals = surface_normals_after_moves(mesh, *d.connectivity, std::move(unmoved), moved);
    });
    classify_and_fit_normals(mesh, d, options, clock);
    return d;
}

BandRestoration restore_bands(const InputSurface& input, const BandClassification& bands,
                              const FeatureNormals& feature_normals, const RestoreOptions& options,
                              const HarmReference* reference) {
    validate_options(options);
    BandRestoration r;
    StageClock clock(r.stage_time, options.stop);
    clock.run(Stage::SharpPoints, [&] {
        r.points = place_sharp_points(input.mesh, input.connectivity, input.normals.face, bands,
                                      feature_normals, options.points);
    });
    std::vector<std::uint8_t> withdrawn(r.points.points.size(), 0);
    std::vector<std::uint8_t> withdrawn_before;  // the flags of the last round's guard
    std::vector<Index> harmful;                  // the faces the last check found harmful
    std::vector<Index> reshaped;                 // the faces near the moves the last check gave up
    GuardedPoints checked;                       // the last guard's result, its split checked
    // Bound: max_harm_rounds; and every round that does not end the loop withdraws at least one
    // point or gives up at least one move (harmful faces are split faces, which hold points, or,
    // with a reference, faces with a moved corner).
    for (int round = 0; round < options.max_harm_rounds; ++round) {
        // The last round's split goes before this round's guard allocates: the guard reads the
        // last round's slots (`checked`), never its split, so one split at most is alive while
        // the guard runs (peak memory).
        r.output = {};
        GuardedPoints guarded;
        clock.run(Stage::Guard, [&] {
            // Nothing is withdrawn before the first check: no flags to read. Later rounds guard
            // again only the faces whose work the withdrawn points can change.
            guarded = round == 0 ? guard_points(input, feature_normals, r.points, {}, options.guard)
                                 : guard_points_again(input, feature_normals, r.points, checked,
                                                      withdrawn_before, withdrawn, harmful,
                                                      reshaped, options.guard);
            RESHARP_EXPENSIVE_ASSERT(
                round == 0 || same_guard(guarded, guard_points(input, feature_normals, r.points,
                                                               withdrawn, options.guard)));
        });
        r.guard.refused_by_quality += guarded.report.refused_by_quality;
        r.guard.refused_by_guard += guarded.report.refused_by_guard;
        r.guard.repairs += guarded.report.repairs;
        // After the first round only the faces near those whose pieces changed are judged again
        // (check_harm()): the faces the last check found harmful lost their points. Once that is
        // known, the last round's slots go before the split allocates (peak memory).
        // (Untimed: one pass over the faces, and no stage of its own to ask `stop` before.)
        std::vector<std::uint8_t> changed;
        if (round > 0) {
            changed = changed_faces(checked.accepted, guarded.accepted);
            // Faces whose corners went back (every harmful face without points is one) kept
            // their slots, not their pieces.
            for (Index f : reshaped) changed[f] = 1;
        }
        checked = std::move(guarded);
        clock.run(Stage::Split,
                  [&] { r.output = split_faces(input.mesh, r.points.points, checked.accepted); });
        HarmReport harm;
        clock.run(Stage::HarmCheck,
                  [&] { harm = held_against(input, reference, r.output, options, changed); });
        ++r.rounds;
        if (round == 0) r.first_harm = harm;
        if (harm.is_harmless()) {
            RESHARP_EXPENSIVE_ASSERT(is_sound_split(input, bands, r.output));
            RESHARP_EXPENSIVE_ASSERT(adds_no_open_or_nonmanifold_edge(input, r.output));
            r.accepted = std::move(checked.accepted);
            r.withdrawn = std::move(withdrawn);
            return r;
        }
        [[maybe_unused]] const std::size_t before = r.undone_points + r.moves_given_up;
        if (reference) {
            reshaped = give_up_moves_of_pointless(input, *reference, checked.accepted,
                                                  harm.harmful_faces, r);
        }
        withdrawn_before = withdrawn;
        withdraw_points_of(harm.harmful_faces, checked.accepted, withdrawn, r.undone_points);
        harmful = std::move(harm.harmful_faces);
        RESHARP_ASSERT(r.undone_points + r.moves_given_up > before);
    }
    r.rounds_exhausted = true;
    r.output = unchanged(input.mesh);
    r.accepted = std::move(checked.accepted);
    r.withdrawn = std::move(withdrawn);
    return r;
}

namespace {

/// Per face (#F): how far the points of each edge or corner triangle got in `r`.
std::vector<PointFate> point_fates(const BandClassification& bands, const BandRestoration& r) {
    std::vector<PointFate> fate(bands.face_role.size(), PointFate::None);
    const bool kept = !r.rounds_exhausted;
    for (Index f = 0; f < fate.size(); ++f) {
        if (bands.face_role[f] == BandRole::None) continue;
        bool candidate = false, withdrawn = false;
        r.points.slots.for_each_point(f, [&](Index p) {
            candidate = true;
            withdrawn = withdrawn || (p < r.withdrawn.size() && r.withdrawn[p]);
        });
        const bool accepted = r.accepted.face_count() > 0 && r.accepted.has_points(f);
        fate[f] = accepted && kept        ? PointFate::Inserted
                  : accepted || withdrawn ? PointFate::UndoneByHarm
                  : candidate             ? PointFate::RefusedByGuard
                                          : PointFate::NotPlaced;
    }
    return fate;
}

/// How many of the points `r` inserted are edge points put inside a face of their crossing edge
/// (SharpPoints::face_points): edge points the candidates hold in a face's inner slot.
std::size_t face_points_inserted(const BandRestoration& r) {
    if (r.points.face_points == 0) return 0;
    std::vector<std::uint8_t> in_face(r.points.points.size(), 0);
    for (Index f = 0; f < r.points.slots.face_count(); ++f) {
        const Index p = r.points.slots.corner_point(f);
        if (p != kNoIndex && p < r.points.edge_points) in_face[p] = 1;
    }
    return static_cast<std::size_t>(std::count_if(r.output.point_of_new_vertex.begin(),
                                                  r.output.point_of_new_vertex.end(),
                                                  [&](Index p) { return in_face[p] != 0; }));
}

/// A near round's moved mesh: the planned places, and the faces of the mesh they were planned
/// on. A mesh its caller gave up (restore(Mesh&&)) lends its triangles for the round and has
/// them back when the round ends, however it ends: nothing reads them meanwhile (the harm check
/// reads the moved mesh's, HarmReference). Else they are copied: 12 bytes a face of fresh
/// memory at the restoration's peak (mech by surface nets: 4 MB, about 1,000 page faults).
class RoundMesh {
public:
    RoundMesh(const Mesh& mesh, Mesh* lender, std::vector<Vec3> places) : lender_(lender) {
        RESHARP_ASSERT(!lender || lender == &mesh);
        moved_.positions = std::move(places);
        moved_.triangles = lender ? std::move(lender->triangles) : mesh.triangles;
    }
    ~RoundMesh() {
        if (lender_) lender_->triangles = std::move(moved_.triangles);
    }
    RoundMesh(const RoundMesh&) = delete;
    RoundMesh& operator=(const RoundMesh&) = delete;

    const Mesh& mesh() const { return moved_; }
    /// Puts vertex v back at its input place: its move given up during the round.
    void put_back(Index v, const Vec3& input_place) { moved_.positions[v] = input_place; }
    /// The places, given back for the next round (the mesh holds none after).
    std::vector<Vec3> take_places() { return std::move(moved_.positions); }

private:
    Mesh* lender_;
    Mesh moved_;
};

/// restore() on one mesh: the one place that sequences the stages and fills the report.
class Pipeline {
public:
    /// `owned`: the input itself where its caller gave it up (restore(Mesh&&)), else null;
    /// `dropped` receives the duplicate faces taken out of it.
    Pipeline(const Mesh& input, Mesh* owned, const RestoreOptions& options, RestoreResult& result,
             DroppedFaces& dropped)
        : input_(input),
          input_faces_(input.face_count()),
          owned_(owned),
          dropped_(dropped),
          options_(options),
          result_(result),
          report_(result.report) {}

    void run() {
        const StageTimer building;
        Connectivity connectivity = build_connectivity(input_);
        const DuplicateFaces found = find_duplicate_faces(input_, connectivity);
        // With removal off the mesh is restored as if it had none (the report still counts
        // them). A reference, not a copy: `kept` holds an index per face.
        const DuplicateFaces none;
        const DuplicateFaces& duplicates = options_.repair.remove_duplicate_faces ? found : none;
        report_.duplicate_faces_removed = duplicates.removed;
        report_.opposite_face_pairs = duplicates.opposite_pairs;
        // The input's defects only fill the report. With a second thread they are counted
        // beside the stages after the detection (the restoration's serial stretches leave that
        // thread idle), on the input's connectivity, which the detection then holds; unless
        // duplicates are removed, and a connectivity of the faces kept replaces the input's.
        const bool count_beside =
            duplicates.removed == 0 && tbb::this_task_arena::max_concurrency() >= 2;
        if (!count_beside) report_.input = diagnose(input_, connectivity, found);
        // Without duplicates the input is the mesh restored; with them, a copy without them,
        // or the input itself less them where its caller gave it up (no second mesh).
        const bool copy = duplicates.removed > 0 && !owned_;
        const Mesh working = copy ? keep_faces(input_, duplicates.kept) : Mesh{};
        if (duplicates.removed > 0 && owned_) dropped_ = drop_faces(*owned_, duplicates.kept);
        const Mesh& mesh = copy ? working : input_;
        if (duplicates.removed > 0) {
            connectivity = {};  // the input's goes first: one connectivity alive at a time
            connectivity = build_connectivity(mesh);
        }
        report_.stage_time[static_cast<std::size_t>(Stage::MeshBuilding)] += building.elapsed();

        PlacementChoice placement;
        Detection detection;
        measure_placement_and_detect(mesh,
                                     std::make_shared<const Connectivity>(std::move(connectivity)),
                                     placement, detection);
        add_times(detection.stage_time);
        // After `detection`: if a stage throws, the group's destructor waits for the count
        // before the connectivity it reads goes.
        tbb::task_group beside;
        if (count_beside) {
            beside.run([&] { report_.input = diagnose(input_, *detection.connectivity, found); });
        }
        if (placement.placement == VertexPlacement::Exact) {
            take(restore_detected(mesh, detection, duplicates));
        } else {
            restore_near(mesh, detection, placement, duplicates, beside);
        }
        const StageTimer waiting;
        beside.wait();
        report_.stage_time[static_cast<std::size_t>(Stage::MeshBuilding)] += waiting.elapsed();
        if (duplicates.removed > 0) {
            for (Index& f : result_.source_face) f = duplicates.kept[f];
        }
    }

private:
    struct PlacementChoice {
        VertexPlacement placement = VertexPlacement::Exact;
        Grid grid;
    };

    /// The caller's placement, or the measured one; exact wherever there is no grid to bound
    /// the moves by. Fills the report's placement fields.
    PlacementChoice choose_placement(const Mesh& mesh) {
        const VertexOptions& v = options_.vertices;
        if (v.mode == VertexMode::Exact) return {};
        const std::optional<Grid> given =
            v.grid.pitch > 0.0 && v.grid_origin_given ? std::optional<Grid>(v.grid) : std::nullopt;
        PlacementEstimate estimate = estimate_vertex_placement(mesh, given);
        if (v.grid.pitch > 0.0 && !v.grid_origin_given && estimate.grid &&
            std::abs(estimate.grid->pitch - v.grid.pitch) > 1e-6 * v.grid.pitch) {
            estimate.reason += "; the grid found is not of the pitch given";
            estimate.grid.reset();
        }
        report_.placement_measured = v.mode == VertexMode::Auto;
        report_.placement_reason = estimate.reason;
        PlacementChoice choice;
        choice.placement = v.mode == VertexMode::Near       ? VertexPlacement::Near
                           : v.mode == VertexMode::Midpoint ? VertexPlacement::Midpoint
                                                            : estimate.placement;
        if (!estimate.grid) choice.placement = VertexPlacement::Exact;
        if (choice.placement == VertexPlacement::Exact) return {};
        choice.grid = *estimate.grid;
        report_.vertex_placement = to_string(choice.placement);
        report_.grid_pitch = choice.grid.pitch;
        return choice;
    }

    /// The placement measurement and the detection on the input: both paths start from the
    /// input's detection, and the measurement reads only the mesh. With a second thread in the
    /// arena the measurement runs beside the detection's normals and curvatures, which run in
    /// parallel (it is up to a quarter of restore()'s time on an STL file, issue 11's speed
    /// budget); with one, it runs first, so that its buffers are gone before the detection
    /// allocates (the peak-memory budget). The detection stays on the calling thread, which is
    /// the one StopWhen::cancelled is promised to be asked from. The segmentations wait for the
    /// measurement: how the regions grow and what the feature normals may read off a flat strip
    /// depend on where the vertices lie (adopt()).
    void measure_placement_and_detect(const Mesh& mesh,
                                      std::shared_ptr<const Connectivity> connectivity,
                                      PlacementChoice& placement, Detection& detection) {
        if (tbb::this_task_arena::max_concurrency() < 2) {
            placement = choose_placement(mesh);
            adopt(placement);
            detection = detect_bands(mesh, std::move(connectivity), options_);
            return;
        }
        // If the detection throws (cancelled), the group's destructor waits for the
        // measurement before `placement` goes out of scope.
        tbb::task_group beside;
        beside.run([&] { placement = choose_placement(mesh); });
        detection = detect_bands_calling(mesh, std::move(connectivity), options_.stop,
                                         [&]() -> const RestoreOptions& {
                                             beside.wait();
                                             adopt(placement);
                                             return options_;
                                         });
    }

    /// Adapts the options to a mesh whose vertices lie as `choice` says: a flat strip of facets,
    /// or a few faces around a vertex, tell a smooth surface's turn only where the vertices lie
    /// on the surface (FeatureNormalOptions::vertices_on_surface), and moved faces may come
    /// nearer a thin blade's other side than their own face, which the harm check's turned test
    /// then weighs (HarmCheckOptions::beyond_rings); a blade thinner than a cell has its
    /// vertices on either face, and no point goes on its tip (kNearEdgeSpikeAngleDeg). Near: also
    /// the feature segmentation's near-surface settings (near_surface_settings()).
    void adopt(const PlacementChoice& choice) {
        if (choice.placement != VertexPlacement::Exact) {
            options_.normals.vertices_on_surface = false;
            options_.harm.beyond_rings = true;
            options_.points.edge_spike_angle_deg = kNearEdgeSpikeAngleDeg;
        }
        if (choice.placement == VertexPlacement::Near) {
            options_.features = near_surface_settings(options_.features);
        }
    }

    /// Records what `detection` found on `mesh` and restores its bands, the split held against
    /// `reference` if given; the segmentations go first (nothing after reads them).
    BandRestoration restore_detected(const Mesh& mesh, Detection& detection,
                                     const DuplicateFaces& duplicates,
                                     const HarmReference* reference = nullptr) {
        record(detection);
        if (options_.keep_segmentation) keep(detection, duplicates);
        // What the rest does not read goes before the rest allocates (peak memory).
        detection.edges = {};
        detection.features = {};
        BandRestoration restored = restore_bands(detection.surface(mesh), detection.bands,
                                                 detection.feature_normals, options_, reference);
        if (options_.keep_segmentation) {
            result_.segmentation.point_fate =
                on_input_faces(point_fates(detection.bands, restored), duplicates, PointFate::None);
        }
        return restored;
    }

    void take(BandRestoration restored) {
        add_times(restored.stage_time);
        record(restored);
        result_.mesh = std::move(restored.output.mesh);
        result_.source_face = std::move(restored.output.source_face);
    }

    /// Where the vertices go (near/vertex_moves.h). Near: band vertices onto the planes of the
    /// patches found. Midpoint: first every vertex onto the plane of its neighbourhood, which
    /// takes the stairs out of slanted faces, then, three times, onto the planes of the patches
    /// found on the mesh so far (kMidpointPatchRounds). Midpoint: `input` keeps only its normals
    /// after (the moved mesh and the fallback are segmented anew).
    VertexMoves plan_moves(const InputSurface& surface, Detection& input,
                           const PlacementChoice& choice) {
        StageClock clock(report_.stage_time, options_.stop);
        const VertexMoveOptions& options = options_.vertices.moves;
        const std::vector<Vec3>& from = surface.mesh.positions;
        MoveRule rule{choice.placement, choice.grid, FitScope::Patches};
        VertexMoves moves;
        if (choice.placement == VertexPlacement::Near) {
            clock.run(Stage::VertexMoves, [&] {
                // The moved mesh is segmented as the input is, so its bevels go too.
                BevelDissolution bevels = without_concave_bevels(surface, std::move(input.features),
                                                                 input.bands, choice.grid, options);
                report_.bevels_dissolved = bevels.bevels;
                input.features = std::move(bevels.features);
                moves = plan_vertex_moves(surface, from, input.features.vertex_patch, input.bands,
                                          rule, options);
            });
            return moves;
        }
        rule.scope = FitScope::Neighbourhood;
        clock.run(Stage::VertexMoves, [&] {
            moves = plan_vertex_moves(surface, from, {}, input.bands, rule, options);
        });
        // Nothing after reads the input's segmentations, bands and feature normals but the
        // fallback, which detects anew: they go before the smoothing rounds allocate (peak
        // memory).
        input.edges = {};
        input.features = {};
        input.bands = {};
        input.feature_normals = {};
        // The stairless mesh segments into the faces, but near their edges, where the fits
        // straddle two faces, into bands wider than the true ones; with its patches' vertices
        // on their whole planes it segments as an exact mesh does, and its patches reach the
        // edges (stepped_block turned, 100 cells: Edge F-score 0.10 -> 0.50).
        rule.scope = FitScope::Patches;
        const RestoreOptions stairless = stairless_options();
        std::optional<Detection> smoothed;
        for (int round = 0; round < kMidpointPatchRounds; ++round) {
            const Mesh current = moved_mesh(surface.mesh, moves);
            // The last round's detection goes before this one's allocates: the moves planned
            // from it are all that is read of it (peak memory: a third detection alive).
            smoothed.reset();
            smoothed = detect_bands(current, input.connectivity, stairless);
            add_times(smoothed->stage_time);
            clock.run(Stage::VertexMoves, [&] {
                moves = plan_vertex_moves(smoothed->surface(current), from,
                                          smoothed->features.vertex_patch, smoothed->bands, rule,
                                          options);
            });
        }
        return moves;
    }

    /// Midpoint: the options a mesh whose vertices sit on fitted surfaces is segmented with:
    /// elevation ties there are left to the vote (FeatureSegmentationOptions::
    /// inside_view_breaks_ties).
    RestoreOptions stairless_options() const {
        RestoreOptions stairless = options_;
        stairless.features.inside_view_breaks_ties = false;
        return stairless;
    }

    /// The detection the moved mesh `moved` is restored with. Near: the input's segmentations
    /// (the moves stay within the cells), its normals made again around the moved vertices
    /// (`input` gives them up). Midpoint: the moved mesh segmented anew. The segmentation of
    /// the last round's mesh is a round behind the moves, whose vertices near the edges went
    /// onto their faces only in this one: it left faces around them out of every patch, and a
    /// band vertex of a flat face got the normal of the one sliver of its patch beside it, 16
    /// degrees off (stepped_block turned at 100 cells: Edge F-score 0.757 -> 0.787).
    Detection detect_after_moves(const Mesh& moved, Detection& input, VertexPlacement placement,
                                 const std::vector<std::uint8_t>& moved_flags) const {
        if (placement == VertexPlacement::Midpoint) {
            input.normals = {};  // the fallback detects anew (peak memory)
            return detect_bands(moved, input.connectivity, stairless_options());
        }
        return detect_bands_after_moves(moved, input, std::move(input.normals), moved_flags,
                                        options_);
    }

    /// Near-surface restoration (issue 14, near/vertex_moves.h): vertices moved onto the sides
    /// fitted around them, the paper's method on the moved mesh, and the result held against
    /// the input itself; moves whose faces do harm are given up within the harm rounds
    /// (restore_bands()). Where those rounds run out, the exact path on the input.
    /// `beside`: the work run beside the restoration, which reads the input mesh.
    void restore_near(const Mesh& mesh, Detection& input, const PlacementChoice& choice,
                      const DuplicateFaces& duplicates, tbb::task_group& beside) {
        const InputSurface surface = input.surface(mesh);
        const bool midpoint = choice.placement == VertexPlacement::Midpoint;
        VertexMoves moves = plan_moves(surface, input, choice);
        if (options_.keep_segmentation) result_.segmentation.move_planned = moves.moved;
        // Moves that turn a face over are given up before the first round, not after it.
        const std::size_t planned = moves.moved_count;
        moves = without_turned_over_faces(mesh, *input.connectivity, std::move(moves));
        report_.moves_undone += planned - moves.moved_count;
        // A vertex moved onto another patch's face is that patch's in the moved mesh: its
        // feature normal and crossing edges (near/vertex_moves.h). It stays so where the harm
        // rounds give its move up, and in the fallback on the input: a band vertex between the
        // two faces, either patch's as much as the other's. (Midpoint: the moved mesh is
        // segmented anew, detect_after_moves().)
        if (!midpoint) {
            input.features.vertex_patch =
                patches_after_moves(std::move(input.features.vertex_patch), moves);
        }
        // Nothing but the fallback below reads the input's bands and feature normals: where
        // rounds follow, they go before the rounds allocate, and the fallback makes them anew
        // (peak memory). Midpoint: gone already, with the segmentations.
        const bool released = !midpoint && moves.moved_count > 0;
        if (released) {
            input.bands = {};
            input.feature_normals = {};
        }
        // The rounds may borrow the input's triangles (RoundMesh): the counting beside, which
        // reads them, ends first (it is long done by now: it started with the moves' planning).
        Mesh* const lender = owned_ && &mesh == owned_ ? owned_ : nullptr;
        if (lender) beside.wait();
        if (moves.moved_count > 0) {
            ++report_.move_rounds;
            // The moved mesh takes the planned places for the round, which reads only the
            // flags, and gives them back after it: one copy of them alive, not two (peak memory).
            // The input's normals likewise: nothing in the round reads them (the harm check
            // takes the input's face normals from the moved mesh's, check_harm()), and they
            // come back unless the round ends the restoration.
            BandRestoration restored;
            Detection detection;
            {
                RoundMesh moved(mesh, lender, std::move(moves.position));
                detection = detect_after_moves(moved.mesh(), input, choice.placement, moves.moved);
                add_times(detection.stage_time);
                auto give_up = [&](const std::vector<Index>& faces) {
                    return give_up_moves(mesh, faces, moved, moves.moved, detection);
                };
                const HarmReference reference{mesh.positions, moves.moved, give_up};
                restored = restore_detected(moved.mesh(), detection, duplicates, &reference);
                moves.position = moved.take_places();
            }
            report_.moves_undone += restored.moves_given_up;
            moves = recounted(mesh.positions, std::move(moves));
            if (!restored.rounds_exhausted) {
                take(std::move(restored));
                report_.output_unchanged = false;  // the moves changed it, points or not
                report_.moved_vertices = moves.moved_count;
                report_.largest_move = moves.largest_move;
                return;
            }
            input.normals = surface_normals_after_moves(mesh, *input.connectivity,
                                                        std::move(detection.normals), moves.moved);
        }
        report_.moves_undone += moves.moved_count;
        if (midpoint) {
            input = detect_bands(mesh, input.connectivity, options_);
            add_times(input.stage_time);
        } else if (released) {
            StageClock clock(report_.stage_time, options_.stop);
            classify_and_fit_normals(mesh, input, options_, clock);
        }
        take(restore_detected(mesh, input, duplicates));
    }

    /// The round's give_up_moves (HarmReference): the moved corners of `faces` go back to their
    /// places in `mesh` (the input), in the round's moved mesh and its flags `moved`, and the
    /// detection's normals are made again around them.
    static std::vector<Index> give_up_moves(const Mesh& mesh, const std::vector<Index>& faces,
                                            RoundMesh& round, std::vector<std::uint8_t>& moved,
                                            Detection& detection) {
        std::vector<Index> put_back;
        std::vector<std::uint8_t> flags(mesh.vertex_count(), 0);
        for (Index f : faces) {
            for (Index v : round.mesh().triangles[f]) {  // the input's may be lent to the round
                if (!moved[v]) continue;
                moved[v] = 0;
                flags[v] = 1;
                round.put_back(v, mesh.positions[v]);
                put_back.push_back(v);
            }
        }
        std::sort(put_back.begin(), put_back.end());
        detection.normals = surface_normals_after_moves(round.mesh(), *detection.connectivity,
                                                        std::move(detection.normals), flags);
        return put_back;
    }

    void add_times(const std::array<std::chrono::nanoseconds, kStageCount>& times) {
        for (std::size_t s = 0; s < kStageCount; ++s) report_.stage_time[s] += times[s];
    }

    void keep(const Detection& d, const DuplicateFaces& duplicates) {
        Segmentation& s = result_.segmentation;
        s.is_edge_vertex = d.edges.is_edge;
        s.vertex_patch = d.features.vertex_patch;
        s.face_patch = on_input_faces(d.features.face_patch, duplicates, kNoIndex);
        s.face_role = on_input_faces(d.bands.face_role, duplicates, BandRole::None);
    }

    /// Per-face values of the mesh restored (#F less removed duplicates) on the input's faces;
    /// `none` on the removed ones.
    template <class T>
    std::vector<T> on_input_faces(std::vector<T> values, const DuplicateFaces& duplicates,
                                  T none) const {
        if (duplicates.removed == 0) return values;
        std::vector<T> all(input_faces_, none);
        for (std::size_t i = 0; i < duplicates.kept.size(); ++i)
            all[duplicates.kept[i]] = values[i];
        return all;
    }

    void record(const Detection& d) {
        const EdgeSegmentation& e = d.edges;
        report_.edge_vertices = e.edge_vertex_count();
        report_.clustered_edge_vertices = e.clustered_edge_vertices;
        report_.isolated_edge_vertices_removed = e.isolated_removed;
        report_.bridge_vertices_added = e.bridge_vertices_added;
        report_.flat_edge_vertices_removed = e.flat_removed;
        report_.kmeans_iterations = e.kmeans_iterations;
        const FeatureSegmentation& f = d.features;
        report_.feature_patches = f.patch_count;
        report_.grown_patches = f.grown_patches;
        report_.band_patches = f.band_patches;
        report_.tiny_patches_absorbed = f.tiny_absorbed;
        report_.tiny_patches_joined = f.tiny_joined;
        report_.patch_merges = f.merges;
        report_.crossing_edges = d.bands.crossing_edges;
        report_.edge_triangles = d.bands.edge_triangles;
        report_.corner_triangles = d.bands.corner_triangles;
    }

    void record(const BandRestoration& r) {
        report_.refused_by_flip_test = r.points.refused_by_flip_test;
        report_.refused_by_spike_test = r.points.refused_by_spike_test;
        report_.first_order_points = r.points.first_order_fallbacks;
        report_.refused_missing_normal = r.points.missing_normal;
        report_.refused_by_quality = r.guard.refused_by_quality;
        report_.refused_by_guard = r.guard.refused_by_guard;
        report_.guard_repairs = r.guard.repairs;
        report_.harm_turned = r.first_harm.turned;
        report_.harm_folded = r.first_harm.folded;
        report_.harm_crossing = r.first_harm.crossing;
        report_.harm_rounds = r.rounds;
        report_.undone_points = r.undone_points;
        report_.split_triangles = r.output.split_faces;
        const std::size_t new_vertices = r.output.point_of_new_vertex.size();
        report_.corner_points_inserted = static_cast<std::size_t>(
            std::count_if(r.output.point_of_new_vertex.begin(), r.output.point_of_new_vertex.end(),
                          [&](Index p) { return p >= r.points.edge_points; }));
        report_.edge_points_inserted = new_vertices - report_.corner_points_inserted;
        report_.face_points_inserted = face_points_inserted(r);
        report_.output_unchanged = new_vertices == 0;
        if (r.rounds_exhausted) report_.unchanged_reason = "harm rounds exhausted";
    }

    const Mesh& input_;  ///< less its duplicates once dropped from `owned_`
    std::size_t input_faces_;
    Mesh* owned_;
    DroppedFaces& dropped_;
    /// The caller's options, as adopt() adapts them to the vertices' placement.
    RestoreOptions options_;
    RestoreResult& result_;
    RestoreReport& report_;
};

/// The input as restore() returns it when it gives up.
void give_back_input(const Mesh& input, RestoreResult& result, std::string_view reason) {
    SplitMesh same = unchanged(input);
    result.mesh = std::move(same.mesh);
    result.source_face = std::move(same.source_face);
    result.report.output_unchanged = true;
    result.report.unchanged_reason = reason;
}

/// restore() of `input`; `owned`: the same mesh where the caller gave it up, else null.
RestoreResult restore_mesh(const Mesh& input, Mesh* owned, const RestoreOptions& options) {
    validate_mesh(input);
    validate_options(options);
    RestoreResult result;
    RestoreReport& report = result.report;
    report.input_vertices = input.vertex_count();
    report.input_triangles = input.face_count();
    const StageTimer total;
    tbb::task_arena arena(options.threads == 0 ? tbb::task_arena::automatic : options.threads);
    DroppedFaces dropped;
    try {
        arena.execute([&] { Pipeline(input, owned, options, result, dropped).run(); });
    } catch (const Cancelled&) {
        if (owned) put_back_faces(*owned, dropped);
        give_back_input(input, result, "cancelled");
    }
    report.total_time = total.elapsed();
    report.output_vertices = result.mesh.vertex_count();
    report.output_triangles = result.mesh.face_count();
    return result;
}

}  // namespace

RestoreResult restore(const Mesh& input, const RestoreOptions& options) {
    return restore_mesh(input, nullptr, options);
}

RestoreResult restore(Mesh&& input, const RestoreOptions& options) {
    return restore_mesh(input, &input, options);
}

}  // namespace resharp
