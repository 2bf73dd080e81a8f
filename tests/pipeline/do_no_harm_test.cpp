// restore()'s promise on meshes it was not made for: it always finishes within its stated
// bounds, and what it gives back is never worse than what it got (docs/method.md, "Do no harm").

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <random>
#include <thread>

#include "resharp/core/errors.h"
#include "resharp/io/mesh_io.h"
#include "resharp/mesh/diagnostics.h"
#include "resharp/mesh/geometry.h"
#include "resharp/pipeline/restore.h"
#include "support/grid_shapes.h"
#include "support/harm_criteria.h"
#include "support/invariants.h"

namespace resharp {
namespace {

/// The drilled plate damaged the ways other meshers and careless exports damage meshes.
Mesh perturbed(const Mesh& mesh, double pitch, int kind, std::mt19937& random) {
    Mesh out = mesh;
    std::uniform_int_distribution<std::size_t> face(0, mesh.face_count() - 1);
    switch (kind) {
        case 0: {  // every vertex off the surface by up to a tenth of a cell (near-surface meshers)
            std::uniform_real_distribution<double> jitter(-0.1 * pitch, 0.1 * pitch);
            for (Vec3& p : out.positions) p += Vec3(jitter(random), jitter(random), jitter(random));
            break;
        }
        case 1:  // a few faces dropped: holes
            for (int i = 0; i < 5; ++i) out.triangles.erase(out.triangles.begin() + face(random));
            break;
        case 2:  // a few faces written twice, one of them turned over
            for (int i = 0; i < 5; ++i) out.triangles.push_back(out.triangles[face(random)]);
            out.triangles.push_back(out.triangles[face(random)]);
            std::swap(out.triangles.back()[1], out.triangles.back()[2]);
            break;
        default:  // a few faces turned over in place
            for (int i = 0; i < 5; ++i) {
                Triangle& t = out.triangles[face(random)];
                std::swap(t[1], t[2]);
            }
    }
    return out;
}

TEST(DoNoHarm, PerturbedPlatesFinishAndComeOutNoWorse) {
    const test::SampledShape shape = test::sampled_drilled_plate();
    std::mt19937 random(11);
    const RestoreOptions options;
    for (int kind = 0; kind < 4; ++kind) {
        SCOPED_TRACE("perturbation " + std::to_string(kind));
        const Mesh input = perturbed(shape.mesh, shape.pitch, kind, random);
        const RestoreResult r = restore(input, options);
        EXPECT_GT(r.report.edge_points_inserted, 0u);  // still restores the rest
        test::expect_no_harm(input, r, options);
    }
}

TEST(DoNoHarm, EveryMeshersPlateComesOutNoWorse) {
    const RestoreOptions options;
    for (sim::Mesher mesher :
         {sim::Mesher::Bisection, sim::Mesher::Midpoint, sim::Mesher::SurfaceNets}) {
        SCOPED_TRACE(sim::to_string(mesher));
        const test::SampledShape shape = test::sampled_drilled_plate(0.5, mesher);
        const RestoreResult r = restore(shape.mesh, options);
        test::expect_no_harm(shape.mesh, r, options);
    }
}

TEST(DoNoHarm, TheMeshThatHungRestoresWithinItsBounds) {
    const Mesh input = weld(io::read_mesh(RESHARP_TEST_DATA_DIR "/relief_hang.stl"));
    ASSERT_EQ(input.face_count(), 113174u);
    const RestoreOptions options;
    const RestoreResult r = restore(input, options);
    EXPECT_EQ(r.report.duplicate_faces_removed, 1798u);
    EXPECT_GT(r.report.edge_points_inserted, 1000u);
    EXPECT_LE(r.report.harm_rounds, static_cast<std::size_t>(options.max_harm_rounds));
    // The guard's bound: at most three repairs per slot that held a point at the start (each
    // crossing edge fills two slots, each corner one).
    EXPECT_LE(r.report.guard_repairs,
              3 * r.report.harm_rounds * (2 * r.report.crossing_edges + r.report.corner_triangles));
    test::expect_input_vertices_preserved(input, r.mesh);
    test::expect_closed_manifold(r.mesh);  // the input less its duplicates is closed
}

TEST(DoNoHarm, EveryTriangleTwiceRestoresLikeTheCleanMesh) {
    const test::SampledShape shape = test::sampled_drilled_plate();
    Mesh doubled = shape.mesh;
    for (const Triangle& t : shape.mesh.triangles) doubled.triangles.push_back(t);
    const RestoreResult clean = restore(shape.mesh);
    const RestoreResult twice = restore(doubled);
    EXPECT_EQ(twice.report.duplicate_faces_removed, shape.mesh.face_count());
    EXPECT_EQ(twice.mesh.positions, clean.mesh.positions);
    EXPECT_EQ(twice.mesh.triangles, clean.mesh.triangles);
    EXPECT_EQ(twice.source_face, clean.source_face);  // the first copies are the ones kept
    // Kept on request: the duplicates then make every edge non-manifold and nothing is restored.
    RestoreOptions keep;
    keep.repair.remove_duplicate_faces = false;
    EXPECT_EQ(restore(doubled, keep).report.duplicate_faces_removed, 0u);
}

TEST(DoNoHarm, AMeshGivenUpRestoresAsACopyAndComesBackWholeWhenCancelled) {
    const test::SampledShape shape = test::sampled_drilled_plate();
    Mesh doubled = shape.mesh;
    for (std::size_t f = 0; f < shape.mesh.face_count(); f += 7)
        doubled.triangles.push_back(shape.mesh.triangles[f]);
    const RestoreResult copied = restore(doubled);
    ASSERT_GT(copied.report.duplicate_faces_removed, 0u);
    Mesh given = doubled;
    const RestoreResult taken = restore(std::move(given));
    EXPECT_EQ(taken.mesh.positions, copied.mesh.positions);
    EXPECT_EQ(taken.mesh.triangles, copied.mesh.triangles);
    EXPECT_EQ(taken.source_face, copied.source_face);
    EXPECT_EQ(taken.report.duplicate_faces_removed, copied.report.duplicate_faces_removed);
    EXPECT_EQ(taken.report.edge_points_inserted, copied.report.edge_points_inserted);
    // Cancelled after the duplicates were dropped (restore() asks only after that): the input
    // comes back whole, and so does the mesh given up.
    int asked = 0;
    RestoreOptions cancel;
    cancel.stop.cancelled = [&] { return ++asked >= 2; };
    Mesh cancelled = doubled;
    const RestoreResult back = restore(std::move(cancelled), cancel);
    EXPECT_TRUE(back.report.output_unchanged);
    EXPECT_EQ(back.mesh.triangles, doubled.triangles);
    EXPECT_EQ(cancelled.triangles, doubled.triangles);  // NOLINT(bugprone-use-after-move)
}

TEST(DoNoHarm, OppositeFacesAreKeptAndCounted) {
    const test::SampledShape shape = test::sampled_box();
    Mesh sheet = shape.mesh;
    const Triangle t = shape.mesh.triangles[0];
    sheet.triangles.push_back({t[0], t[2], t[1]});
    const RestoreResult r = restore(sheet);
    EXPECT_EQ(r.report.duplicate_faces_removed, 0u);
    EXPECT_EQ(r.report.opposite_face_pairs, 1u);
    EXPECT_EQ(r.source_face.back(), sheet.face_count() - 1);  // still there
}

TEST(DoNoHarm, ADeadlineOrACancellationGivesTheInputBack) {
    const test::SampledShape shape = test::sampled_drilled_plate();
    RestoreOptions late;
    late.stop.deadline = std::chrono::steady_clock::now();
    const RestoreResult r = restore(shape.mesh, late);
    EXPECT_TRUE(r.report.output_unchanged);
    EXPECT_EQ(r.report.unchanged_reason, "cancelled");
    EXPECT_EQ(r.mesh.triangles, shape.mesh.triangles);
    EXPECT_EQ(r.mesh.positions, shape.mesh.positions);
    // A callback that says stop at its fourth question: the pipeline is inside, not done.
    int asked = 0;
    RestoreOptions cancel;
    cancel.stop.cancelled = [&] { return ++asked >= 4; };
    const RestoreResult c = restore(shape.mesh, cancel);
    EXPECT_EQ(asked, 4);
    EXPECT_TRUE(c.report.output_unchanged);
    EXPECT_EQ(c.mesh.triangles, shape.mesh.triangles);
    // Asked but never firing: the same output as without it.
    RestoreOptions patient;
    patient.stop.cancelled = [] { return false; };
    EXPECT_EQ(restore(shape.mesh, patient).mesh.triangles, restore(shape.mesh).mesh.triangles);
}

TEST(DoNoHarm, CancellationIsAskedFromTheCallingThreadOnly) {
    // restore() runs the placement measurement beside the detection on a second thread; the
    // callback must still be asked only where StopWhen promises.
    const test::SampledShape shape = test::sampled_drilled_plate();
    RestoreOptions options;
    options.threads = 2;
    const std::thread::id caller = std::this_thread::get_id();
    std::atomic<int> asked = 0, asked_elsewhere = 0;
    options.stop.cancelled = [&] {
        ++asked;
        if (std::this_thread::get_id() != caller) ++asked_elsewhere;
        return false;
    };
    EXPECT_FALSE(restore(shape.mesh, options).report.output_unchanged);
    EXPECT_GT(asked.load(), 0);
    EXPECT_EQ(asked_elsewhere.load(), 0);
}

TEST(DoNoHarm, HarmThatOutlastsTheRoundsGivesTheInputBack) {
    // With one round allowed, any harm the first round finds cannot be undone in time: the
    // jittered plate (which needs a second round) comes back unchanged.
    const test::SampledShape shape = test::sampled_drilled_plate();
    std::mt19937 random(3);
    const Mesh input = perturbed(shape.mesh, shape.pitch, 0, random);
    const RestoreResult full = restore(input);
    ASSERT_GT(full.report.harm_rounds, 1u) << "the case no longer needs a second round";
    RestoreOptions one;
    one.max_harm_rounds = 1;
    const RestoreResult r = restore(input, one);
    EXPECT_TRUE(r.report.output_unchanged);
    EXPECT_EQ(r.report.unchanged_reason, "harm rounds exhausted");
    EXPECT_EQ(r.mesh.triangles, input.triangles);
    EXPECT_THROW(restore(input, {.max_harm_rounds = 0}), InvalidInput);
}

}  // namespace
}  // namespace resharp
