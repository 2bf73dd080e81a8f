// libFuzzer target for restore() itself (not a reader): the input picks one of a few small parts
// the simulator makes at start-up and damages it the ways other meshers and exports damage
// meshes (jitter, faces dropped, duplicated or turned over, vertices merged), and may ask
// restore() to stop. It aborts when restore() throws, breaks a bound it states (harm rounds,
// questions to the stop callback, a deadline), or gives back a mesh worse than its input by
// the criteria of tests/support/harm_criteria.h, checked apart from the library's own check.

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <random>
#include <tuple>
#include <vector>

#include "resharp/pipeline/restore.h"
#include "support/harm_criteria.h"
#include "support/small_parts.h"

namespace resharp::fuzz {
namespace {

struct Seed {
    Mesh mesh;
    double pitch = 0.5;
};

/// The parts, each under 10k triangles, by several meshers.
const std::vector<Seed>& seeds() {
    static const std::vector<Seed> parts = [] {
        using test::SmallPart;
        const std::vector<std::tuple<SmallPart, double, sim::Mesher>> made{
            {SmallPart::PocketedBlock, 0.5, sim::Mesher::MarchingCubes},
            {SmallPart::BossedPlate, 0.5, sim::Mesher::MarchingCubes},
            {SmallPart::TiltedWedge, 0.5, sim::Mesher::MarchingCubes},
            {SmallPart::PocketedBlock, 0.6, sim::Mesher::SurfaceNets},
            {SmallPart::BossedPlate, 0.6, sim::Mesher::Midpoint},
            {SmallPart::TiltedWedge, 0.7, sim::Mesher::Bisection},
        };
        std::vector<Seed> out;
        for (const auto& [part, pitch, mesher] : made) {
            out.push_back({test::small_part(part, pitch, mesher), pitch});
        }
        return out;
    }();
    return parts;
}

void fail(const char* what, std::size_t count) {
    std::fprintf(stderr, "restore_fuzzer: %s (%zu)\n", what, count);
    std::abort();
}

/// Each call changes at most `kMaxChanged` faces or vertices (the whole mesh for jitter).
constexpr std::size_t kMaxChanged = 64;

Index random_face(const Mesh& mesh, std::mt19937& random) {
    return std::uniform_int_distribution<Index>(0,
                                                static_cast<Index>(mesh.face_count() - 1))(random);
}

void jitter(Mesh& mesh, double amplitude, double share, std::mt19937& random) {
    std::uniform_real_distribution<double> offset(-amplitude, amplitude);
    std::bernoulli_distribution chosen(share);
    for (Vec3& p : mesh.positions) {
        if (chosen(random)) p += Vec3(offset(random), offset(random), offset(random));
    }
}

/// A run of consecutive faces (neighbours in space: the mesher writes cell by cell), leaving
/// at least one face.
void drop_run(Mesh& mesh, std::size_t length, std::mt19937& random) {
    length = std::min(length, mesh.face_count() - 1);
    if (length == 0) return;
    const std::size_t start =
        std::uniform_int_distribution<std::size_t>(0, mesh.face_count() - length)(random);
    const auto first = mesh.triangles.begin() + static_cast<std::ptrdiff_t>(start);
    mesh.triangles.erase(first, first + static_cast<std::ptrdiff_t>(length));
}

void duplicate_faces(Mesh& mesh, std::size_t count, bool turned, std::mt19937& random) {
    for (std::size_t i = 0; i < count; ++i) {
        Triangle t = mesh.triangles[random_face(mesh, random)];
        if (turned) std::swap(t[1], t[2]);
        mesh.triangles.push_back(t);
    }
}

void flip_faces(Mesh& mesh, std::size_t count, std::mt19937& random) {
    for (std::size_t i = 0; i < count; ++i) {
        Triangle& t = mesh.triangles[random_face(mesh, random)];
        std::swap(t[1], t[2]);
    }
}

/// Merges the second vertex of a random face into its first, everywhere (the mesh keeps the
/// merged vertex's position, unused).
void merge_vertices(Mesh& mesh, std::size_t count, std::mt19937& random) {
    for (std::size_t i = 0; i < count; ++i) {
        const Triangle t = mesh.triangles[random_face(mesh, random)];
        for (Triangle& u : mesh.triangles) {
            for (Index& v : u) v = v == t[1] ? t[0] : v;
        }
    }
}

/// The questions restore() may ask its stop callback: once before each stage, the three stages
/// of a harm round once per round (restore.h, RestoreOptions::stop).
std::size_t question_bound(std::size_t rounds) { return kStageCount + 3 * (rounds - 1); }

/// A deadline missed by more than this is not honoured: one stage of restore() on these meshes
/// takes well under a second, even with the sanitizers.
constexpr std::chrono::seconds kDeadlineGrace{3};

void check_given_back(const Mesh& input, const RestoreResult& r) {
    if (r.mesh.positions != input.positions) fail("unchanged output with other positions", 0);
    for (std::size_t o = 0; o < r.mesh.face_count(); ++o) {
        if (r.mesh.triangles[o] != input.triangles[r.source_face[o]]) {
            fail("unchanged output with a changed face", o);
        }
    }
}

void check_no_harm(const Mesh& input, const RestoreResult& r) {
    const test::HarmFound h = test::find_harm(input, r.mesh, r.source_face);
    if (h.moved_input_vertices > 0) fail("input vertices moved", h.moved_input_vertices);
    if (h.bad_source_faces > 0) fail("bad source faces", h.bad_source_faces);
    if (h.turned_faces > 0) fail("faces turned against the input", h.turned_faces);
    if (h.added_boundary_edges > 0) fail("boundary edges added", h.added_boundary_edges);
    if (h.added_nonmanifold_edges > 0) fail("non-manifold edges added", h.added_nonmanifold_edges);
    if (h.added_inconsistent_edges > 0) {
        fail("inconsistent edges added", h.added_inconsistent_edges);
    }
    if (h.new_self_intersections > 0) fail("self-intersections added", h.new_self_intersections);
}

int run(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    const Seed& seed = seeds()[in.ConsumeIntegralInRange<std::size_t>(0, seeds().size() - 1)];
    Mesh mesh = seed.mesh;
    RestoreOptions options;
    options.threads = 1;
    options.max_harm_rounds = in.ConsumeIntegralInRange(1, 8);
    std::mt19937 random(in.ConsumeIntegral<std::uint32_t>());
    std::size_t stop_at = 0;  // the question the stop callback says yes to; 0: never
    std::optional<std::chrono::milliseconds> deadline;
    for (int step = 0; step < 8 && in.remaining_bytes() > 0; ++step) {
        const std::size_t count = in.ConsumeIntegralInRange<std::size_t>(1, kMaxChanged);
        switch (in.ConsumeIntegralInRange(0, 7)) {
            case 0:
                jitter(mesh, in.ConsumeProbability<double>() * 0.3 * seed.pitch,
                       in.ConsumeProbability<double>(), random);
                break;
            case 1:
                drop_run(mesh, count * in.ConsumeIntegralInRange<std::size_t>(1, 4), random);
                break;
            case 2:
                duplicate_faces(mesh, count, false, random);
                break;
            case 3:
                duplicate_faces(mesh, count, true, random);
                break;
            case 4:
                flip_faces(mesh, count, random);
                break;
            case 5:
                merge_vertices(mesh, count, random);
                break;
            case 6:
                stop_at = count % question_bound(8) + 1;
                break;
            default:
                deadline = std::chrono::milliseconds(in.ConsumeIntegralInRange(0, 300));
        }
    }

    std::size_t asked = 0;
    if (stop_at > 0) options.stop.cancelled = [&] { return ++asked >= stop_at; };
    const auto start = std::chrono::steady_clock::now();
    if (deadline) options.stop.deadline = start + *deadline;
    const RestoreResult r = restore(mesh, options);
    const auto elapsed = std::chrono::steady_clock::now() - start;

    if (r.report.harm_rounds > static_cast<std::size_t>(options.max_harm_rounds)) {
        fail("more harm rounds than allowed", r.report.harm_rounds);
    }
    if (asked > question_bound(static_cast<std::size_t>(options.max_harm_rounds))) {
        fail("asked to stop more often than stages run", asked);
    }
    if (deadline && elapsed > *deadline + kDeadlineGrace) {
        fail("deadline not honoured (ms)",
             static_cast<std::size_t>(
                 std::chrono::duration_cast<std::chrono::milliseconds>(elapsed).count()));
    }
    const bool stopped =
        (stop_at > 0 && asked >= stop_at) || r.report.unchanged_reason == "cancelled";
    if (stopped && (!r.report.output_unchanged || r.mesh.triangles != mesh.triangles)) {
        fail("stopped but the output is not the input", 0);
    }
    if (r.report.output_unchanged) {
        check_given_back(mesh, r);
    } else {
        check_no_harm(mesh, r);
    }
    return 0;
}

}  // namespace
}  // namespace resharp::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return resharp::fuzz::run(data, size);
}
