#include "resharp/restoration/harm_check.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "resharp/core/assert.h"
#include "resharp/core/errors.h"
#include "resharp/mesh/geometry.h"
#include "resharp/restoration/clearance.h"

namespace resharp {
namespace {

/// Tolerance of the crossing test relative to the face's size: far below any feature of a grid
/// mesh, far above rounding in coordinates of a part (see clearance.h).
constexpr double kTouchRatio = 1e-9;

/// Cosine below -this is a turn of more than 90 degrees (about 90.0001): see turns_against().
constexpr double kRightAngleMargin = 1e-6;

/// Per input face (#F + 1): where its output faces start; input face f became output faces
/// first[f] .. first[f + 1] - 1.
std::vector<Index> output_ranges(const SplitMesh& output, std::size_t input_faces) {
    std::vector<Index> first(input_faces + 1, 0);
    for (Index source : output.source_face) ++first[source + 1];
    for (std::size_t f = 1; f < first.size(); ++f) first[f] += first[f - 1];
    return first;
}

/// Whether t holds an edge of s the other way round: two faces that only the fold check needs
/// to compare, since faces sharing an edge meet beyond it only by folding onto each other.
bool shares_opposite_edge(const Triangle& s, const Triangle& t) {
    for (int k = 0; k < 3; ++k) {
        for (int m = 0; m < 3; ++m) {
            if (s[k] == t[(m + 1) % 3] && s[(k + 1) % 3] == t[m]) return true;
        }
    }
    return false;
}

/// What the checks found on one split face's pieces.
struct FaceVerdict {
    std::uint32_t turned = 0, folded = 0, crossing = 0;
    bool is_harmful() const { return turned + folded + crossing > 0; }
};

/// A ball holding a face: a lower bound of any point's distance to it, for a few flops.
struct Ball {
    Vec3 centre;
    double radius;
};

/// One thread's scratch: the last split face that met each input face, a list of faces and
/// their balls.
struct Scratch {
    std::vector<Index> mark;
    std::vector<Index> faces;
    std::vector<Ball> balls;
    explicit Scratch(std::size_t face_count) : mark(face_count, kNoIndex) {}
};

class HarmChecker {
public:
    HarmChecker(const InputSurface& input, const SplitMesh& output, const HarmCheckOptions& options)
        : input_(input),
          output_(output),
          min_fold_cosine_(std::cos(options.fold_angle_deg * std::numbers::pi / 180.0)),
          first_(output_ranges(output, input.mesh.face_count())),
          split_(split_faces()),
          number_(numbers_of_split_faces()),
          blamed_(input.mesh.face_count(), 0),
          check_crossings_(options.check_crossings),
          split_boxes_(check_crossings_ ? split_boxes() : std::vector<Box3>{}) {}

    HarmReport run() {
        std::vector<FaceVerdict> verdicts(split_.size());
        tbb::enumerable_thread_specific<Scratch> scratch(input_.mesh.face_count());
        tbb::parallel_for(std::size_t{0}, split_.size(), [&](std::size_t i) {
            verdicts[i] = judge(static_cast<Index>(i), scratch.local());
        });
        HarmReport report;
        for (std::size_t i = 0; i < split_.size(); ++i) {
            report.turned += verdicts[i].turned;
            report.folded += verdicts[i].folded;
            report.crossing += verdicts[i].crossing;
            if (verdicts[i].is_harmful()) blamed_[split_[i]] = 1;
        }
        for (Index f = 0; f < blamed_.size(); ++f) {
            if (blamed_[f]) report.harmful_faces.push_back(f);
        }
        return report;
    }

private:
    std::vector<Index> split_faces() const {
        std::vector<Index> faces;
        for (Index f = 0; f + 1 < first_.size(); ++f) {
            if (first_[f + 1] - first_[f] > 1) faces.push_back(f);
        }
        return faces;
    }
    std::vector<Index> numbers_of_split_faces() const {
        std::vector<Index> number(input_.mesh.face_count(), kNoIndex);
        for (std::size_t i = 0; i < split_.size(); ++i) number[split_[i]] = static_cast<Index>(i);
        return number;
    }
    bool is_split(Index f) const { return number_[f] != kNoIndex; }

    Vec3 output_normal(Index o) const {
        const Triangle& t = output_.mesh.triangles[o];
        const auto& x = output_.mesh.positions;
        return triangle_normal(x[t[0]], x[t[1]], x[t[2]]);
    }
    IdTriangle output_triangle(Index o) const {
        const Triangle& t = output_.mesh.triangles[o];
        const auto& x = output_.mesh.positions;
        return IdTriangle::make(t, x[t[0]], x[t[1]], x[t[2]]);
    }

    /// The three checks on the pieces of split face number i.
    FaceVerdict judge(Index i, Scratch& scratch) const {
        const Index f = split_[i];
        gather_two_rings(f, i, scratch);
        FaceVerdict verdict;
        for (Index o = first_[f]; o < first_[f + 1]; ++o) {
            const Vec3 n = output_normal(o);
            verdict.turned += is_turned(o, n, scratch);
            verdict.folded += is_folded(f, o, n);
        }
        if (check_crossings_) verdict.crossing += count_crossing_pieces(f, scratch.faces);
        return verdict;
    }

    /// Lists in scratch.faces the input faces within two rings of f: the faces sharing a vertex
    /// with a face that shares a vertex with f.
    void gather_two_rings(Index f, Index stamp, Scratch& scratch) const {
        scratch.faces.clear();
        auto add = [&](Index g) {
            if (scratch.mark[g] == stamp) return;
            scratch.mark[g] = stamp;
            scratch.faces.push_back(g);
        };
        for (Index v : input_.mesh.triangles[f]) {
            for (Index g : input_.connectivity.faces_around(v)) add(g);
        }
        const std::size_t first_ring = scratch.faces.size();
        for (std::size_t j = 0; j < first_ring; ++j) {
            for (Index v : input_.mesh.triangles[scratch.faces[j]]) {
                for (Index g : input_.connectivity.faces_around(v)) add(g);
            }
        }
        scratch.balls.clear();
    }

    /// The balls of scratch.faces, made the first time a piece of the face needs them.
    void ensure_balls(Scratch& scratch) const {
        if (!scratch.balls.empty()) return;
        for (Index g : scratch.faces) scratch.balls.push_back(ball_of(g));
    }

    Ball ball_of(Index g) const {
        const Triangle& t = input_.mesh.triangles[g];
        const auto& x = input_.mesh.positions;
        const Vec3 centre = (x[t[0]] + x[t[1]] + x[t[2]]) / 3.0;
        const double radius =
            std::sqrt(std::max({(x[t[0]] - centre).squaredNorm(), (x[t[1]] - centre).squaredNorm(),
                                (x[t[2]] - centre).squaredNorm()}));
        return {centre, radius};
    }

    /// (a) Whether piece o, of unit normal n (zero: no area), turns more than 90 degrees
    /// against all the input faces nearest one of its query points (its vertices and centroid;
    /// ties go to the piece). Only faces it turns against can be the reason, so where it turns
    /// against none of the candidates there is nothing to measure.
    bool is_turned(Index o, const Vec3& n, Scratch& candidates) const {
        if (n.isZero(0.0)) return true;
        const bool turns_against_some =
            std::any_of(candidates.faces.begin(), candidates.faces.end(),
                        [&](Index g) { return turns_against(n, g); });
        if (!turns_against_some) return false;
        ensure_balls(candidates);
        const Triangle& t = output_.mesh.triangles[o];
        const auto& x = output_.mesh.positions;
        for (Index v : t) {
            if (v < input_.mesh.vertex_count() ? turned_at_input_vertex(v, n)
                                               : turned_at_point(x[v], n, candidates)) {
                return true;
            }
        }
        return turned_at_point((x[t[0]] + x[t[1]] + x[t[2]]) / 3.0, n, candidates);
    }

    /// Whether unit normal n turns more than 90 degrees against input face g. The margin,
    /// far below any real turn, keeps rounding from counting a piece that lies in one plane of
    /// a right-angled edge as turned against the other plane's faces.
    bool turns_against(const Vec3& n, Index g) const {
        return input_.normals.face[g].dot(n) < -kRightAngleMargin;
    }

    /// At an input vertex the nearest input faces are the faces around it.
    bool turned_at_input_vertex(Index v, const Vec3& n) const {
        const auto ring = input_.connectivity.faces_around(v);
        return std::all_of(ring.begin(), ring.end(), [&](Index g) { return turns_against(n, g); });
    }

    /// Whether the nearest face to q that n turns against is nearer than every other candidate.
    /// Faces whose ball shows they cannot change that answer are not measured: a face turned
    /// against n matters only if it may come nearer than both nearest so far, another only if
    /// it may come nearer than the nearest so far of its kind and of the turned faces.
    bool turned_at_point(const Vec3& q, const Vec3& n, const Scratch& candidates) const {
        double nearest_against = std::numeric_limits<double>::infinity();
        double nearest_other = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < candidates.faces.size() && nearest_other > 0.0; ++j) {
            const Ball& ball = candidates.balls[j];
            const double reach = std::max(0.0, (q - ball.centre).norm() - ball.radius);
            const double bound = reach * reach * (1.0 - 1e-12);
            const Index g = candidates.faces[j];
            if (turns_against(n, g)) {
                if (bound > nearest_against || bound >= nearest_other) continue;
                nearest_against = std::min(nearest_against, distance_squared(q, g));
            } else {
                if (bound > std::min(nearest_other, nearest_against)) continue;
                nearest_other = std::min(nearest_other, distance_squared(q, g));
            }
        }
        return nearest_against < nearest_other;
    }

    double distance_squared(const Vec3& q, Index g) const {
        const Triangle& t = input_.mesh.triangles[g];
        const auto& x = input_.mesh.positions;
        return squared_distance_to_triangle(q, x[t[0]], x[t[1]], x[t[2]]);
    }

    /// (b) Whether piece o of split face f, of unit normal n, folds onto an output face across
    /// one of its edges: their normals differ by more than the fold angle where the input
    /// faces they replace did not (a piece and its own face's pieces replace one face).
    bool is_folded(Index f, Index o, const Vec3& n) const {
        const Triangle& t = output_.mesh.triangles[o];
        for (int k = 0; k < 3; ++k) {
            const Index across = output_face_across(f, o, t[(k + 1) % 3], t[k]);
            if (across == kNoIndex) continue;
            const Index g = output_.source_face[across];
            const Vec3 other = is_split(g) ? output_normal(across) : input_.normals.face[g];
            if (n.dot(other) >= min_fold_cosine_) continue;
            const bool input_folded =
                g != f && input_.normals.face[f].dot(input_.normals.face[g]) < min_fold_cosine_;
            if (!input_folded) return true;
        }
        return false;
    }

    /// The output face other than o holding the directed edge a -> b, among the pieces of f and
    /// of the faces across f's edges; kNoIndex if none (a boundary or non-manifold edge).
    Index output_face_across(Index f, Index o, Index a, Index b) const {
        auto holds = [&](Index g) {
            const Triangle& t = output_.mesh.triangles[g];
            for (int k = 0; k < 3; ++k) {
                if (t[k] == a && t[(k + 1) % 3] == b) return true;
            }
            return false;
        };
        auto search = [&](Index source) {
            for (Index g = first_[source]; g < first_[source + 1]; ++g) {
                if (g != o && holds(g)) return g;
            }
            return kNoIndex;
        };
        Index found = search(f);
        for (Index k = 0; k < 3 && found == kNoIndex; ++k) {
            const Index twin = input_.connectivity.twin[3 * f + k];
            if (twin != kNoIndex) found = search(face_of(twin));
        }
        return found;
    }

    /// (c) How many pieces of split face f meet another of its pieces or an output face of an
    /// input face within two rings of f (the candidates) whose box meets theirs. A split face
    /// before f already checked its pieces against f's (the relation is symmetric); a crossing
    /// with another split face blames it too. Faces sharing an edge are left to the fold check
    /// (b), and faces wholly beyond f's cap plane (see cap_of) cannot reach its pieces.
    std::uint32_t count_crossing_pieces(Index f, const std::vector<Index>& candidates) const {
        const Box3& box = split_boxes_[number_[f]];
        const double tolerance = kTouchRatio * std::sqrt(box.sizes().squaredNorm());
        const Cap cap = cap_of(f, tolerance);
        std::array<IdTriangle, 6> pieces;
        std::array<bool, 6> meets{};
        const int count = static_cast<int>(first_[f + 1] - first_[f]);
        for (int i = 0; i < count; ++i) pieces[i] = output_triangle(first_[f] + i);
        // Pairs sharing an edge are the fold check's.
        auto needs_test = [&](const Triangle& s, const Triangle& t) {
            return !shares_opposite_edge(s, t);
        };
        for (int i = 0; i < count; ++i) {
            for (int j = i + 1; j < count; ++j) {
                if (needs_test(pieces[i].id, pieces[j].id) &&
                    triangles_meet(pieces[i], pieces[j], tolerance)) {
                    meets[i] = meets[j] = true;
                }
            }
        }
        for (Index g : candidates) {
            if (g == f) continue;
            if (is_split(g)) {
                if (g < f || !split_boxes_[number_[g]].intersects(box)) continue;
            } else if (lies_beyond(cap, f, g) || !input_box(g).intersects(box)) {
                continue;
            }
            for (Index other = first_[g]; other < first_[g + 1]; ++other) {
                const Triangle& ids = output_.mesh.triangles[other];
                std::optional<IdTriangle> them;  // made only if a piece needs the test
                for (int i = 0; i < count; ++i) {
                    if (!needs_test(pieces[i].id, ids)) continue;
                    if (!them) them = output_triangle(other);
                    if (!triangles_meet(pieces[i], *them, tolerance)) continue;
                    meets[i] = true;
                    if (is_split(g)) {
                        std::atomic_ref<std::uint8_t>(blamed_[g])
                            .store(1, std::memory_order_relaxed);
                    }
                }
            }
        }
        return static_cast<std::uint32_t>(std::count(meets.begin(), meets.begin() + count, true));
    }

    /// Per split face (in split_ order): the box of its pieces.
    std::vector<Box3> split_boxes() const {
        std::vector<Box3> boxes(split_.size());
        tbb::parallel_for(std::size_t{0}, split_.size(),
                          [&](std::size_t i) { boxes[i] = split_box(split_[i]); });
        return boxes;
    }

    /// The box of split face f's output: every piece lies in it.
    Box3 split_box(Index f) const {
        Box3 box;
        for (Index o = first_[f]; o < first_[f + 1]; ++o) {
            for (Index v : output_.mesh.triangles[o]) box.extend(output_.mesh.positions[v]);
        }
        return box;
    }
    Box3 input_box(Index g) const {
        Box3 box;
        for (Index v : input_.mesh.triangles[g]) box.extend(input_.mesh.positions[v]);
        return box;
    }

    /// A half-space holding every piece of a split face: n . x >= offset (n zero: none).
    struct Cap {
        Vec3 n = Vec3::Zero();
        double offset = 0.0;
        double tolerance = 0.0;
    };

    /// The plane of split face f, turned to the side of the vertices its pieces add, when they
    /// all lie clearly on one side: the pieces lie in the hull of f and those vertices.
    Cap cap_of(Index f, double tolerance) const {
        const Vec3& n = input_.normals.face[f];
        const double offset = n.dot(input_.mesh.positions[input_.mesh.triangles[f][0]]);
        int above = 0, below = 0, added = 0;
        for (Index o = first_[f]; o < first_[f + 1]; ++o) {
            for (Index v : output_.mesh.triangles[o]) {
                if (v < input_.mesh.vertex_count()) continue;
                const double height = n.dot(output_.mesh.positions[v]) - offset;
                above += height > tolerance;
                below += height < -tolerance;
                ++added;
            }
        }
        if (above == added) return {n, offset, tolerance};
        if (below == added) return {-n, -offset, tolerance};
        return {};
    }

    /// Whether unsplit face g lies beyond the cap, but for the vertices it shares with f.
    bool lies_beyond(const Cap& cap, Index f, Index g) const {
        if (cap.n.isZero(0.0)) return false;
        const Triangle& own = input_.mesh.triangles[f];
        for (Index v : input_.mesh.triangles[g]) {
            if (v == own[0] || v == own[1] || v == own[2]) continue;
            if (cap.n.dot(input_.mesh.positions[v]) >= cap.offset - cap.tolerance) return false;
        }
        return true;
    }

    const InputSurface& input_;
    const SplitMesh& output_;
    double min_fold_cosine_;
    std::vector<Index> first_;
    std::vector<Index> split_;   ///< the split input faces, ascending
    std::vector<Index> number_;  ///< per input face (#F): its index in split_, or kNoIndex
    mutable std::vector<std::uint8_t> blamed_;  ///< per input face (#F), set from any thread
    bool check_crossings_;
    std::vector<Box3> split_boxes_;  ///< per split face, with the crossing check
};

}  // namespace

HarmReport check_harm(const InputSurface& input, const SplitMesh& output,
                      const HarmCheckOptions& options) {
    if (!(options.fold_angle_deg > 90.0 && options.fold_angle_deg <= 180.0)) {
        throw InvalidInput("harm check: fold angle must lie in (90, 180] degrees");
    }
    RESHARP_EXPENSIVE_ASSERT(output.source_face.size() == output.mesh.face_count());
    RESHARP_EXPENSIVE_ASSERT(std::is_sorted(output.source_face.begin(), output.source_face.end()));
    return HarmChecker(input, output, options).run();
}

}  // namespace resharp
