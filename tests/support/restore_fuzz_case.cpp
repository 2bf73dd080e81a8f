#include "support/restore_fuzz_case.h"

#include <algorithm>
#include <chrono>
#include <optional>
#include <random>
#include <tuple>
#include <vector>

#include "resharp/pipeline/restore.h"
#include "support/harm_criteria.h"
#include "support/small_parts.h"

namespace resharp::test {
namespace {

/// The fuzzer's bytes read from the front; past the end every read gives its lowest value, so
/// every byte string is a case.
class ByteReader {
public:
    explicit ByteReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

    bool empty() const { return next_ >= bytes_.size(); }
    /// An integer in [lo, hi] from the next two bytes (hi - lo below 65536).
    std::size_t integer(std::size_t lo, std::size_t hi) {
        const std::size_t raw = byte() | (byte() << 8);
        return lo + raw % (hi - lo + 1);
    }
    /// A number in [0, 1] from the next two bytes.
    double fraction() { return static_cast<double>(integer(0, 65535)) / 65535.0; }

private:
    std::size_t byte() { return empty() ? 0 : bytes_[next_++]; }

    std::span<const std::uint8_t> bytes_;
    std::size_t next_ = 0;
};

struct Seed {
    Mesh mesh;
    double pitch = 0.5;
};

/// The parts by four meshers, 2,584 to 5,920 triangles; made once.
const std::vector<Seed>& seeds() {
    static const std::vector<Seed> parts = [] {
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
            out.push_back({small_part(part, pitch, mesher), pitch});
        }
        return out;
    }();
    return parts;
}

/// Each damage changes at most this many faces or vertices (times 4 for dropped runs; jitter
/// may move every vertex).
constexpr std::size_t kMaxChanged = 64;
/// Damages per case at most.
constexpr int kMaxSteps = 8;

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

/// Merges the second vertex of a random face into its first, everywhere (the merged vertex
/// stays, unused).
void merge_vertices(Mesh& mesh, std::size_t count, std::mt19937& random) {
    for (std::size_t i = 0; i < count; ++i) {
        const Triangle t = mesh.triangles[random_face(mesh, random)];
        for (Triangle& u : mesh.triangles) {
            for (Index& v : u) v = v == t[1] ? t[0] : v;
        }
    }
}

/// The questions restore() may ask its stop callback: once before each stage, the three stages
/// of a harm round once per round (restore.h, RestoreOptions::stop). Near-surface restoration
/// runs the stages once more for the moves (twice for midpoints), then once per round of moves,
/// and the exact path at the end if the moves were all given up.
std::size_t question_bound(std::size_t rounds, bool moves = false, std::size_t move_rounds = 0) {
    const std::size_t once = kStageCount + 3 * (rounds - 1);
    return moves ? once * (move_rounds + 3) : once;
}

/// A deadline missed by more than this is not honoured: one stage of restore() on these meshes
/// takes well under a second, even with the sanitizers.
constexpr std::chrono::seconds kDeadlineGrace{3};

/// Damages `mesh` and fills `request` as the bytes say.
void read_case(ByteReader& in, const Seed& seed, Mesh& mesh, RestoreFuzzInput& request) {
    request.options.threads = 1;
    request.options.max_harm_rounds = static_cast<int>(in.integer(1, 8));
    std::mt19937 random(static_cast<std::uint32_t>(in.integer(0, 65535)));
    for (int step = 0; step < kMaxSteps && !in.empty(); ++step) {
        const std::size_t kind = in.integer(0, 7);
        const std::size_t count = in.integer(1, kMaxChanged);
        switch (kind) {
            case 0: {
                const double amplitude = in.fraction() * 0.3 * seed.pitch;
                jitter(mesh, amplitude, in.fraction(), random);
                break;
            }
            case 1:
                drop_run(mesh, count * in.integer(1, 4), random);
                break;
            case 2:
            case 3:
                duplicate_faces(mesh, count, kind == 3, random);
                break;
            case 4:
                flip_faces(mesh, count, random);
                break;
            case 5:
                merge_vertices(mesh, count, random);
                break;
            case 6:
                request.stop_at = count % question_bound(8) + 1;
                break;
            default:
                request.deadline = std::chrono::milliseconds(in.integer(0, 300));
        }
    }
}

/// An output flagged unchanged is the input less removed duplicates.
std::string given_back_problem(const Mesh& input, const RestoreResult& r) {
    if (r.mesh.positions != input.positions) return "unchanged output with other positions";
    if (r.source_face.size() != r.mesh.face_count()) return "unchanged output, bad source faces";
    for (std::size_t o = 0; o < r.mesh.face_count(); ++o) {
        if (r.source_face[o] >= input.face_count() ||
            r.mesh.triangles[o] != input.triangles[r.source_face[o]]) {
            return "unchanged output with a changed face " + std::to_string(o);
        }
    }
    return "";
}

std::string harm_problem(const Mesh& input, const RestoreResult& r) {
    const HarmFound h = find_harm(input, r.mesh, r.source_face, criteria_for(r.report));
    if (!h.any()) return "";
    return "harm: moved " + std::to_string(h.moved_input_vertices) + ", bad sources " +
           std::to_string(h.bad_source_faces) + ", lost faces " + std::to_string(h.lost_faces) +
           ", turned " + std::to_string(h.turned_faces) + ", boundary +" +
           std::to_string(h.added_boundary_edges) + ", non-manifold +" +
           std::to_string(h.added_nonmanifold_edges) + ", inconsistent +" +
           std::to_string(h.added_inconsistent_edges) + ", self-intersections +" +
           std::to_string(h.new_self_intersections);
}

}  // namespace

RestoreFuzzInput read_restore_fuzz_input(std::span<const std::uint8_t> bytes) {
    ByteReader in(bytes);
    const Seed& seed = seeds()[in.integer(0, seeds().size() - 1)];
    RestoreFuzzInput request;
    request.mesh = seed.mesh;
    read_case(in, seed, request.mesh, request);
    return request;
}

std::string restore_fuzz_case(std::span<const std::uint8_t> bytes) {
    RestoreFuzzInput request = read_restore_fuzz_input(bytes);
    const Mesh& mesh = request.mesh;

    std::size_t asked = 0;
    if (request.stop_at > 0) {
        request.options.stop.cancelled = [&] { return ++asked >= request.stop_at; };
    }
    const auto start = std::chrono::steady_clock::now();
    if (request.deadline) request.options.stop.deadline = start + *request.deadline;
    const RestoreResult r = restore(mesh, request.options);
    const auto elapsed = std::chrono::steady_clock::now() - start;

    const std::size_t rounds = static_cast<std::size_t>(request.options.max_harm_rounds);
    if (r.report.harm_rounds > rounds) {
        return "harm rounds " + std::to_string(r.report.harm_rounds) + " > " +
               std::to_string(rounds);
    }
    if (asked > question_bound(rounds, r.report.vertex_placement != "exact", r.report.move_rounds))
        return "asked to stop " + std::to_string(asked) + " times";
    if (request.deadline && elapsed > *request.deadline + kDeadlineGrace) {
        return "deadline missed by more than " + std::to_string(kDeadlineGrace.count()) + " s";
    }
    const bool stopped = (request.stop_at > 0 && asked >= request.stop_at) ||
                         r.report.unchanged_reason == "cancelled";
    if (stopped && (!r.report.output_unchanged || r.mesh.triangles != mesh.triangles)) {
        return "stopped but the output is not the input";
    }
    return r.report.output_unchanged ? given_back_problem(mesh, r) : harm_problem(mesh, r);
}

}  // namespace resharp::test
