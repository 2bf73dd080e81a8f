#include "resharp/restoration/harm_check.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "resharp/core/assert.h"
#include "resharp/core/errors.h"
#include "resharp/mesh/geometry.h"
#include "resharp/mesh/uniform_grid.h"
#include "resharp/restoration/clearance.h"
#include "resharp/restoration/outer_box.h"
#include "resharp/restoration/simple_fan.h"

namespace resharp {
namespace {

/// Tolerance of the crossing test relative to the face's size: far below any feature of a grid
/// mesh, far above rounding in coordinates of a part (see clearance.h).
constexpr double kTouchRatio = 1e-9;

/// Cosine below -this is a turn of more than 90 degrees (about 90.0001): see turns_against().
constexpr double kRightAngleMargin = 1e-6;

/// What two triangles share: how many vertices, one of them, and whether one holds an edge of
/// the other the other way round (faces sharing an edge meet beyond it only by folding onto
/// each other, which the fold check judges).
struct Sharing {
    int count = 0;
    Index vertex = kNoIndex;
    bool opposite_edge = false;
};

Sharing sharing_of(const Triangle& s, const Triangle& t) {
    Sharing shared;
    std::array<int, 3> in_t{-1, -1, -1};  // per vertex of s, its corner in t
    for (int k = 0; k < 3; ++k) {
        for (int m = 0; m < 3; ++m) {
            if (s[k] != t[m]) continue;
            in_t[k] = m;
            shared.vertex = s[k];
            ++shared.count;
        }
    }
    for (int k = 0; k < 3 && shared.count >= 2; ++k) {
        const int from = in_t[k], to = in_t[(k + 1) % 3];  // s's edge k runs s[k] -> s[k + 1]
        shared.opposite_edge |= from >= 0 && to >= 0 && from == (to + 1) % 3;
    }
    return shared;
}

/// An output triangle as the crossing test reads it: its vertex ids, corners, unit normal and
/// box, made where a test needs it rather than stored for every piece.
struct Shape {
    Triangle id;
    std::array<const Vec3*, 3> p;
    const Vec3* n;
    Box3 box;

    Shape(const Triangle& t, std::span<const Vec3> x, const Vec3& normal)
        : id(t), p{&x[t[0]], &x[t[1]], &x[t[2]]}, n(&normal), box(x[t[0]]) {
        box.extend(x[t[1]]).extend(x[t[2]]);
    }
    IdTriangle exact() const { return IdTriangle::make(id, *p[0], *p[1], *p[2], *n); }
};

/// Whether every corner of b lies more than `tolerance` beyond one of the planes through a's
/// edges that hold a's normal (facing out: counter-clockwise about it). Then b lies more than
/// `tolerance` from a. The planes' normals keep the edges' lengths, so that heights come out
/// scaled by them and no root is taken; a degenerate triangle parts nothing.
bool parted_by_an_edge(const Shape& a, const Shape& b, double tolerance) {
    for (int k = 0; k < 3; ++k) {
        const Vec3& from = *a.p[k];
        const Vec3 out = (*a.p[(k + 1) % 3] - from).cross(*a.n);
        const double length_squared = out.squaredNorm();
        if (!(length_squared > 0.0)) continue;
        const double offset = out.dot(from), limit = tolerance * tolerance * length_squared;
        auto beyond = [&](const Vec3* x) {
            const double height = out.dot(*x) - offset;
            return height > 0.0 && height * height > limit;
        };
        if (beyond(b.p[0]) && beyond(b.p[1]) && beyond(b.p[2])) return true;
    }
    return false;
}

/// Whether two boxes lie more than `tolerance` apart along one of the axes (then the boxes,
/// and whatever they hold, lie more than `tolerance` apart).
bool boxes_apart(const Box3& a, const Box3& b, double tolerance) {
    for (int k = 0; k < 3; ++k) {
        if (a.min()[k] > b.max()[k] + tolerance || b.min()[k] > a.max()[k] + tolerance) return true;
    }
    return false;
}

/// What the checks found on one split face's pieces.
struct FaceVerdict {
    std::uint32_t turned = 0, folded = 0, crossing = 0;
    bool is_harmful() const { return turned + folded + crossing > 0; }
};

/// One thread's scratch: which input vertices and faces the current gather reached (cleared
/// by the next one, through the lists), the faces within two rings and their boxes. The marks
/// are bytes: numbered gatherings in four bytes need no clearing and took 2.5 % fewer of the
/// check's instructions on a midpoint mesh, but raised the peak memory of a restoration,
/// which this check sets, by 2 to 6 %.
struct Scratch {
    std::vector<std::uint8_t> vertex_mark, face_mark;
    std::vector<Index> vertices;
    /// The candidates: the faces within two rings (the first ring_count), then the faces
    /// beyond them that the turned check weighs too (HarmChecker::find_far_candidates()).
    std::vector<Index> faces;
    std::size_t ring_count = 0;
    std::vector<Box3> boxes;
    /// per face and piece of the split face judged: the piece turns against the face
    Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic> against;
    Scratch(std::size_t vertex_count, std::size_t face_count)
        : vertex_mark(vertex_count, 0), face_mark(face_count, 0) {}
};

/// Whether triangle t has a corner `moved` flags (an input vertex; empty flags: none moved).
bool has_moved_corner(const Triangle& t, std::span<const std::uint8_t> moved) {
    return std::any_of(t.begin(), t.end(), [&](Index v) { return v < moved.size() && moved[v]; });
}

/// The split faces of an output mesh, numbered in input order, and their pieces, numbered
/// from 0 in output order: all of them, or with `whole_apart` those of the faces with points
/// alone, the faces left whole with moved corners numbering none (their normals are known).
class SplitFaces {
public:
    /// Takes the split (source faces ascending), the input mesh, the altered faces (ascending:
    /// the split's own, or with the faces of moved corners) and the moved flags (#V or empty).
    SplitFaces(const SplitMesh& output, const Mesh& input, const std::vector<Index>& altered,
               [[maybe_unused]] std::span<const std::uint8_t> moved, bool whole_apart)
        : number_(input.face_count(), kNoIndex) {
        const Index* source = output.source_face.data();
        const Index count = static_cast<Index>(output.source_face.size());
        face_.reserve(altered.size());
        first_output_.reserve(altered.size());
        first_piece_.reserve(altered.size() + 1);
        // The split faces are the altered ones: a split face's pieces are the run of its
        // output faces, and every face before it that is not altered is one output face, so
        // its run starts where the runs before it put it.
        Index extra = 0;  // output faces beyond one per input face, before f's
        for (Index f : altered) {
            const Index o = f + extra;
            Index end = o + 1;
            while (end < count && source[end] == f) ++end;
            number_[f] = static_cast<Index>(face_.size());
            face_.push_back(f);
            first_output_.push_back(o);
            first_piece_.push_back(piece_count_);
            // One output face with the input face's corners is the face left whole (a face
            // with points holds a new vertex in every piece; two edges snapped onto its corner
            // point leave it one piece).
            const bool whole = end == o + 1 && output.mesh.triangles[o] == input.triangles[f];
            if (!whole || !whole_apart) piece_count_ += end - o;
            extra += end - o - 1;
        }
        first_piece_.push_back(piece_count_);
        RESHARP_EXPENSIVE_ASSERT(is_as_scanned(output, input, moved));
    }

    std::size_t size() const { return face_.size(); }
    std::size_t piece_count() const { return piece_count_; }
    Index face(Index i) const { return face_[i]; }
    /// The number of input face f among the split faces, or kNoIndex if f was left whole.
    Index number(Index f) const { return number_[f]; }
    /// The pieces of split face i: output faces first_output(i) on, numbers first_piece(i) ..
    /// first_piece(i + 1) - 1 unless the face is whole (is_whole()).
    Index first_piece(Index i) const { return first_piece_[i]; }
    Index first_output(Index i) const { return first_output_[i]; }
    /// Split face i is left whole, its corners moved, and numbers no piece (`whole_apart`).
    bool is_whole(Index i) const { return first_piece_[i + 1] == first_piece_[i]; }
    Index piece_count(Index i) const {
        return is_whole(i) ? 1 : first_piece_[i + 1] - first_piece_[i];
    }

private:
    /// Whether the split faces are those a scan of every output face finds: the runs of more
    /// than one face, and the runs of one whose corners are not their source's or are moved.
    bool is_as_scanned(const SplitMesh& output, const Mesh& input,
                       std::span<const std::uint8_t> moved) const {
        std::vector<Index> scanned;
        const auto& source = output.source_face;
        for (std::size_t o = 0; o < source.size();) {
            std::size_t end = o + 1;
            while (end < source.size() && source[end] == source[o]) ++end;
            const Triangle& t = output.mesh.triangles[o];
            if (end > o + 1 || t != input.triangles[source[o]] || has_moved_corner(t, moved)) {
                scanned.push_back(source[o]);
            }
            o = end;
        }
        return scanned == face_;
    }

    std::vector<Index> number_;        ///< per input face (#F)
    std::vector<Index> face_;          ///< per split face (#S): its input face, ascending
    std::vector<Index> first_output_;  ///< per split face (#S)
    std::vector<Index> first_piece_;   ///< per split face (#S + 1)
    Index piece_count_ = 0;
};

/// The input faces split in `output` or left whole there with a moved corner, ascending. A face
/// left whole is its input face, so its moved corners are its input corners: the moved
/// vertices' rings find those faces, and no output face is compared with its source.
std::vector<Index> altered_with_moves(const InputSurface& input, const SplitMesh& output,
                                      std::span<const std::uint8_t> moved) {
    return faces_with_moved_corner(input.mesh, input.connectivity, moved, output.altered_faces);
}

class HarmChecker {
public:
    HarmChecker(const InputSurface& input, const SplitMesh& output, const HarmCheckOptions& options,
                std::span<const std::uint8_t> changed, const MovedVertices& moves)
        : input_(input),
          output_(output),
          moved_(moves.moved),
          input_positions_(moves.moved.empty() ? std::span<const Vec3>(input.mesh.positions)
                                               : moves.input_positions),
          min_fold_cosine_(std::cos(options.fold_angle_deg * std::numbers::pi / 180.0)),
          half_fold_cosine_(std::cos(options.fold_angle_deg * std::numbers::pi / 360.0)),
          check_crossings_(options.check_crossings),
          split_(output, input.mesh,
                 moved_.empty() ? output.altered_faces : altered_with_moves(input, output, moved_),
                 moved_, !moved_.empty()),
          piece_normal_(split_.piece_count()),
          split_box_(split_.size()),
          harmful_(split_.size(), 0) {
        if (!moved_.empty()) make_unmoved_normals();
        choose_judged(changed);
        describe_pieces();
        far_first_.assign(split_.size() + 1, 0);
        if (options.beyond_rings) find_far_candidates();
        if (check_crossings_) find_simple_fans();
    }

    HarmReport run() {
        tbb::enumerable_thread_specific<Scratch> scratch(input_.mesh.vertex_count(),
                                                         input_.mesh.face_count());
        tbb::enumerable_thread_specific<HarmReport> sums;  // each thread's counts
        // A thread's scratch and counts looked up once a range, not once a face.
        using Range = tbb::blocked_range<std::size_t>;
        tbb::parallel_for(Range(0, judged_list_.size()), [&](const Range& range) {
            Scratch& local = scratch.local();
            HarmReport& sum = sums.local();
            for (std::size_t k = range.begin(); k != range.end(); ++k) {
                const Index i = judged_list_[k];
                const FaceVerdict verdict = judge(i, local);
                sum.turned += verdict.turned;
                sum.folded += verdict.folded;
                sum.crossing += verdict.crossing;
                if (verdict.is_harmful()) mark_harmful(i);
            }
        });
        HarmReport report;
        for (const HarmReport& sum : sums) {
            report.turned += sum.turned;
            report.folded += sum.folded;
            report.crossing += sum.crossing;
        }
        for (Index i = 0; i < split_.size(); ++i) {
            if (harmful_[i]) report.harmful_faces.push_back(split_.face(i));
        }
        return report;
    }

private:
    void mark_harmful(Index i) const {
        std::atomic_ref<std::uint8_t>(harmful_[i]).store(1, std::memory_order_relaxed);
    }

    /// Input face g's unit normal: the surface's own, or with moves (see check_harm()) that of a
    /// split face made again from its input corners.
    const Vec3& input_normal(Index g) const {
        if (moved_.empty()) return input_.normals.face[g];
        const Index j = split_.number(g);
        return j == kNoIndex ? input_.normals.face[g] : unmoved_normal_[j];
    }

    /// Per split face, the unit normal of its input face, as surface_normals() makes it.
    void make_unmoved_normals() {
        unmoved_normal_.resize(split_.size());
        const auto& x = input_positions_;
        tbb::parallel_for(Index{0}, static_cast<Index>(split_.size()), [&](Index i) {
            const Triangle& t = input_.mesh.triangles[split_.face(i)];
            unmoved_normal_[i] = triangle_normal(x[t[0]], x[t[1]], x[t[2]]);
        });
    }

    const Triangle& piece_triangle(Index i, Index k) const {
        return output_.mesh.triangles[split_.first_output(i) + k];
    }
    /// The unit normal of piece k of split face i.
    const Vec3& piece_normal(Index i, Index k) const {
        return split_.is_whole(i) ? input_.normals.face[split_.face(i)]
                                  : piece_normal_[split_.first_piece(i) + k];
    }
    Shape piece_shape(Index i, Index k) const {
        return Shape(piece_triangle(i, k), output_.mesh.positions, piece_normal(i, k));
    }

    /// Which split faces to judge (all, or those within two rings of a changed face), and which
    /// to describe: those and the split faces within two rings of them, which their checks read.
    void choose_judged(std::span<const std::uint8_t> changed) {
        judged_.assign(split_.size(), changed.empty() ? 1 : 0);
        described_.assign(split_.size(), changed.empty() ? 1 : 0);
        if (!changed.empty()) {
            Scratch scratch(input_.mesh.vertex_count(), input_.mesh.face_count());
            std::vector<Index> changed_faces;
            for (Index f = 0; f < changed.size(); ++f) {
                if (changed[f]) changed_faces.push_back(f);
            }
            const std::vector<Index> judged = split_faces_near(changed_faces, judged_, scratch);
            split_faces_near(judged, described_, scratch);
        }
        for (Index i = 0; i < split_.size(); ++i) {
            if (judged_[i]) judged_list_.push_back(i);
        }
    }

    /// Marks in `marks` (per split face) the split faces within two rings of `faces` (input
    /// faces); gives them as input faces. Bound: #faces times the size of a two-ring.
    std::vector<Index> split_faces_near(const std::vector<Index>& faces,
                                        std::vector<std::uint8_t>& marks, Scratch& scratch) const {
        std::vector<Index> near;
        for (Index f : faces) {
            gather_two_rings(f, scratch);
            for (Index g : scratch.faces) {
                const Index j = split_.number(g);
                if (j == kNoIndex || marks[j]) continue;
                marks[j] = 1;
                near.push_back(g);
            }
        }
        return near;
    }

    /// The unit normal of every described piece (zero for a degenerate one), and the box of
    /// every described split face's pieces.
    void describe_pieces() {
        const auto& x = output_.mesh.positions;
        tbb::parallel_for(Index{0}, static_cast<Index>(split_.size()), [&](Index i) {
            if (!described_[i]) return;
            Box3 box;
            for (Index k = 0; k < split_.piece_count(i); ++k) {
                const Triangle& t = piece_triangle(i, k);
                if (!split_.is_whole(i)) {
                    piece_normal_[split_.first_piece(i) + k] =
                        triangle_normal(x[t[0]], x[t[1]], x[t[2]]);
                }
                box.extend(x[t[0]]).extend(x[t[1]]).extend(x[t[2]]);
            }
            split_box_[i] = OuterBox(box);
        });
    }

    /// Marks the vertices of judged split faces around which the output is a simple fan (see
    /// is_simple_fan()): only pairs with a piece of a judged face ask.
    void find_simple_fans() {
        const Index input_vertices = static_cast<Index>(input_.mesh.vertex_count());
        const Index output_vertices = static_cast<Index>(output_.mesh.vertex_count());
        simple_fan_.assign(output_vertices, 0);
        std::vector<std::uint8_t> wanted(output_vertices, 0);
        for (Index i : judged_list_) {
            for (Index k = 0; k < split_.piece_count(i); ++k) {
                for (Index v : piece_triangle(i, k)) wanted[v] = 1;
            }
        }
        const PiecesAround around = pieces_around_new_vertices();
        tbb::parallel_for(Index{0}, output_vertices, [&](Index v) {
            if (!wanted[v]) return;
            Fan fan;
            if (v < input_vertices) {
                add_input_fan(v, fan);
            } else {
                for (Index k = around.first[v - input_vertices];
                     k < around.first[v - input_vertices + 1]; ++k) {
                    const Index o = around.output[k];
                    fan.add(output_.mesh.triangles[o], v, normal_of_piece(o));
                }
            }
            simple_fan_[v] = is_simple_fan(output_.mesh.positions, v, fan);
        });
    }

    /// Adds to `fan` the output faces around input vertex v: its input faces left whole, and
    /// the pieces of the split ones that hold v (all of them if v moved: every face with a moved
    /// corner counts as split).
    void add_input_fan(Index v, Fan& fan) const {
        for (Index g : input_.connectivity.faces_around(v)) {
            const Index j = split_.number(g);
            if (j == kNoIndex) {
                fan.add(input_.mesh.triangles[g], v, input_normal(g));
                continue;
            }
            for (Index k = 0; k < split_.piece_count(j); ++k) {
                const Triangle& t = piece_triangle(j, k);
                if (t[0] == v || t[1] == v || t[2] == v) {
                    fan.add(t, v, piece_normal(j, k));
                }
            }
        }
    }

    /// The normal of output face o, a piece of a split face.
    const Vec3& normal_of_piece(Index o) const {
        const Index i = split_.number(output_.source_face[o]);
        return piece_normal(i, o - split_.first_output(i));
    }

    /// Whether output vertex v is an input vertex in its input place: not a new point, not
    /// moved. Every face around a new vertex is split or moved, so its pieces are its fan.
    bool is_input_vertex(Index v) const {
        return v < input_.mesh.vertex_count() && (moved_.empty() || !moved_[v]);
    }

    /// Per new vertex (output vertex #V in + i): the pieces that hold it, as output faces,
    /// entries first[i] .. first[i + 1] - 1 (CSR, like Connectivity's rings). A moved input
    /// vertex's pieces are found through its faces instead (add_input_fan()): kept here, they
    /// took 8 bytes per corner of every piece of a midpoint mesh, whose every vertex moves.
    struct PiecesAround {
        std::vector<Index> first, output;
    };
    PiecesAround pieces_around_new_vertices() const {
        const Index input_vertices = static_cast<Index>(input_.mesh.vertex_count());
        PiecesAround around;
        around.first.assign(output_.mesh.vertex_count() - input_vertices + 1, 0);
        auto for_each_new_corner = [&](auto&& visit) {
            for (Index i = 0; i < split_.size(); ++i) {
                if (!described_[i]) continue;
                for (Index k = 0; k < split_.piece_count(i); ++k) {
                    for (Index v : piece_triangle(i, k)) {
                        if (v >= input_vertices) visit(v - input_vertices, i, k);
                    }
                }
            }
        };
        for_each_new_corner([&](Index n, Index, Index) { ++around.first[n + 1]; });
        for (std::size_t n = 1; n < around.first.size(); ++n)
            around.first[n] += around.first[n - 1];
        around.output.resize(around.first.back());
        std::vector<Index> fill(around.first.begin(), around.first.end() - 1);
        for_each_new_corner([&](Index n, Index i, Index k) {
            around.output[fill[n]++] = split_.first_output(i) + k;
        });
        return around;
    }

    /// The three checks on the pieces of split face number i.
    FaceVerdict judge(Index i, Scratch& scratch) const {
        const Index f = split_.face(i);
        gather_two_rings(f, scratch);
        for (Index k = far_first_[i]; k < far_first_[i + 1]; ++k) add_candidate(far_[k], scratch);
        FaceVerdict verdict;
        const std::array<bool, 6> against = turning_against_some(i, scratch);
        const bool may_fold = may_fold_anywhere(i);
        for (Index k = 0; k < split_.piece_count(i); ++k) {
            if (against[k]) {
                verdict.turned +=
                    is_turned(f, piece_triangle(i, k), piece_normal(i, k), k, scratch);
            }
            if (may_fold) verdict.folded += is_folded(i, k);
        }
        if (check_crossings_) {
            verdict.crossing += count_crossing_pieces(
                i, std::span<const Index>(scratch.faces).first(scratch.ring_count));
        }
        return verdict;
    }

    /// Lists in scratch.faces the input faces within two rings of f: the faces around the
    /// vertices of the faces around f's vertices. Gathering those vertices first visits each
    /// of the ~12 ring vertices' faces once, not each first-ring face's three rings.
    void gather_two_rings(Index f, Scratch& scratch) const {
        for (Index u : scratch.vertices) scratch.vertex_mark[u] = 0;
        for (Index g : scratch.faces) scratch.face_mark[g] = 0;
        scratch.vertices.clear();
        scratch.faces.clear();
        scratch.boxes.clear();
        for (Index v : input_.mesh.triangles[f]) {
            for (Index g : input_.connectivity.faces_around(v)) {
                for (Index u : input_.mesh.triangles[g]) {
                    if (scratch.vertex_mark[u]) continue;
                    scratch.vertex_mark[u] = 1;
                    scratch.vertices.push_back(u);
                }
            }
        }
        for (Index u : scratch.vertices) {
            for (Index g : input_.connectivity.faces_around(u)) add_candidate(g, scratch);
        }
        scratch.ring_count = scratch.faces.size();
    }

    static void add_candidate(Index g, Scratch& scratch) {
        if (scratch.face_mark[g]) return;
        scratch.face_mark[g] = 1;
        scratch.faces.push_back(g);
    }

    /// Per judged split face, the input faces beyond the face itself that its turned check (a)
    /// weighs besides the two rings, as the do-no-harm criterion counts the input faces nearest
    /// a query point anywhere (docs/method.md): the other side of a thin wall or web, nearer to
    /// a new point than its own face. Those are the faces whose boxes meet its reach box
    /// (reach_box_of()) and share no vertex with it, where one of them turns against one of its
    /// pieces. Where none does, they could only show a piece not turned that the rings alone
    /// call turned: leaving them out then refuses more, never less, and spares the judging most
    /// of them. Found in passes over the input's faces: the faces that turn against a piece,
    /// for kReachBoxesPerPass judged faces a pass, then all of them for the few judged faces
    /// that have one; faces within the rings may come again (judge() takes each once).
    void find_far_candidates() {
        std::vector<std::uint8_t> has_turned(split_.size(), 0);
        const std::span<const Index> judged(judged_list_);
        for (std::size_t first = 0; first < judged.size(); first += kReachBoxesPerPass) {
            const std::size_t count = std::min(kReachBoxesPerPass, judged.size() - first);
            for (const FarPair& p : far_pairs(judged.subspan(first, count), true)) {
                has_turned[p.first] = 1;
            }
        }
        std::vector<Index> beside;  // the judged faces with a face turned against them
        for (Index i : judged_list_) {
            if (has_turned[i]) beside.push_back(i);
        }
        std::vector<FarPair> pairs = far_pairs(beside, false);
        std::sort(pairs.begin(), pairs.end());
        pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
        for (const FarPair& p : pairs) ++far_first_[p.first + 1];
        for (std::size_t i = 1; i < far_first_.size(); ++i) far_first_[i] += far_first_[i - 1];
        far_.reserve(pairs.size());
        for (const FarPair& p : pairs) far_.push_back(p.second);
    }

    /// Judged faces whose reach boxes one pass of find_far_candidates() keeps: the boxes and
    /// their grid take a few MB whatever the mesh. A midpoint mesh has every face judged, and
    /// its restoration peaks in this check: all of mech's at once, in doubles, took its peak
    /// from 265 to 353 bytes per input triangle (the budget is 300), in floats to 319.
    static constexpr std::size_t kReachBoxesPerPass = std::size_t{1} << 17;

    /// (split face number, input face)
    using FarPair = std::pair<Index, Index>;

    /// The pairs (i, g) for split face i in `judged`, g an input face whose box meets i's reach
    /// box and that shares no vertex with it; with `turned_only`, only those where g turns
    /// against one of i's pieces. One pass over the input's faces against a grid of those reach
    /// boxes.
    std::vector<FarPair> far_pairs(std::span<const Index> judged, bool turned_only) const {
        if (judged.empty()) return {};
        std::vector<OuterBox> reach(judged.size());  // floats: half the memory
        tbb::parallel_for(std::size_t{0}, judged.size(),
                          [&](std::size_t j) { reach[j] = OuterBox(reach_box_of(judged[j])); });
        Box3 all;
        double size = 0.0;
        for (std::size_t j = 0; j < judged.size(); ++j) {
            all.extend(reach[j].box());
            size += input_face_box(split_.face(judged[j])).sizes().maxCoeff();
        }
        // Cells of twice the judged faces' mean size, at most eight per judged face: a face's
        // box meets a few, each holding a few reach boxes, and no cell array spans the part's
        // volume at the scale of its faces (fresh pages cost more than the queries).
        const double mean_cell = 2.0 * size / double(judged.size());
        const detail::UniformGrid grid(
            judged.size(), [&](std::size_t j) { return reach[j].box(); },
            mean_cell > 0.0 ? mean_cell : 1.0, 8 * judged.size());
        tbb::enumerable_thread_specific<std::vector<FarPair>> found;
        using Range = tbb::blocked_range<Index>;
        tbb::parallel_for(Range(0, static_cast<Index>(input_.mesh.face_count())),
                          [&](const Range& range) {
                              std::vector<FarPair>& mine = found.local();
                              for (Index g = range.begin(); g != range.end(); ++g) {
                                  const Box3 box = input_face_box(g);
                                  if (!box.intersects(all)) continue;
                                  grid.for_each_meeting(box, [&](Index j) {
                                      const Index i = judged[j];
                                      if (!reach[j].may_meet(box) || touches_face(i, g)) return;
                                      if (!turned_only || turns_against_a_piece(i, g))
                                          mine.emplace_back(i, g);
                                  });
                              }
                          });
        std::vector<FarPair> pairs;
        for (const std::vector<FarPair>& mine : found) {
            pairs.insert(pairs.end(), mine.begin(), mine.end());
        }
        return pairs;
    }

    /// Whether input face g shares a vertex with split face i's input face.
    bool touches_face(Index i, Index g) const {
        const Triangle& t = input_.mesh.triangles[split_.face(i)];
        const Triangle& u = input_.mesh.triangles[g];
        return std::any_of(u.begin(), u.end(),
                           [&](Index v) { return v == t[0] || v == t[1] || v == t[2]; });
    }

    /// Whether input face g turns against one of split face i's pieces.
    bool turns_against_a_piece(Index i, Index g) const {
        for (Index k = 0; k < split_.piece_count(i); ++k) {
            if (turns_against(piece_normal(i, k), g)) return true;
        }
        return false;
    }

    /// The box of split face i's pieces widened by the farthest of their corners from its face
    /// (at its input place), and the tie: every input face nearer one of the pieces' query points
    /// (is_turned()) than the face itself meets it. A centroid is no farther from the face than
    /// its piece's farthest corner (the distance to a triangle is convex), and an input vertex is
    /// one of the face's corners.
    Box3 reach_box_of(Index i) const {
        const Index f = split_.face(i);
        const auto& x = output_.mesh.positions;
        Box3 box;
        double reach = 0.0;  // squared
        for (Index k = 0; k < split_.piece_count(i); ++k) {
            for (Index v : piece_triangle(i, k)) {
                box.extend(x[v]);
                if (!is_input_vertex(v)) reach = std::max(reach, distance_squared(x[v], f));
            }
        }
        const Vec3 margin = Vec3::Constant(std::sqrt(reach) + tie_of(f));
        return Box3(box.min() - margin, box.max() + margin);
    }

    /// The box of input face g at its input place.
    Box3 input_face_box(Index g) const {
        const Triangle& t = input_.mesh.triangles[g];
        const Vec3 &a = input_positions_[t[0]], &b = input_positions_[t[1]],
                   &c = input_positions_[t[2]];
        return Box3(a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c));
    }

    /// Distances to a query point that differ by no more than this count as equal (see
    /// turned_at_point()).
    double tie_of(Index f) const {
        return kTouchRatio *
               std::sqrt(longest_edge_squared(input_positions_, input_.mesh.triangles[f]));
    }

    /// The boxes of scratch.faces, made the first time a piece of the face needs them.
    void ensure_boxes(Scratch& scratch) const {
        if (!scratch.boxes.empty()) return;
        for (Index g : scratch.faces) scratch.boxes.push_back(input_face_box(g));
    }

    /// Per piece of split face number i: whether it turns against one of the candidates (or
    /// has no area), the only case (a) has anything to measure; and in scratch.against, per
    /// piece and candidate, whether it turns against that one (turns_against()). One pass over
    /// the candidates, each normal read once for all the pieces (summed in the same order as
    /// Vec3::dot).
    std::array<bool, 6> turning_against_some(Index i, Scratch& scratch) const {
        const Index count = split_.piece_count(i);
        scratch.against.resize(static_cast<Eigen::Index>(scratch.faces.size()), count);
        std::array<Vec3, 6> m;
        std::array<bool, 6> some{};
        for (Index k = 0; k < count; ++k) {
            m[k] = piece_normal(i, k);
            some[k] = m[k].isZero(0.0);
        }
        for (std::size_t j = 0; j < scratch.faces.size(); ++j) {  // Bound: the two-ring's faces
            const Vec3& g = input_normal(scratch.faces[j]);
            for (Index k = 0; k < count; ++k) {
                const bool against =
                    (g.x() * m[k].x() + g.y() * m[k].y()) + g.z() * m[k].z() < -kRightAngleMargin;
                scratch.against(static_cast<Eigen::Index>(j), k) = against;
                some[k] = some[k] || against;
            }
        }
        return some;
    }

    /// (a) Whether piece t (piece k, normal n) of split face f turns more than 90 degrees
    /// against all the input faces nearest one of its query points (its vertices and centroid;
    /// ties go to the piece), or has no area. Called for the pieces that turn against some
    /// candidate.
    bool is_turned(Index f, const Triangle& t, const Vec3& n, Index k, Scratch& candidates) const {
        if (n.isZero(0.0)) return true;
        ensure_boxes(candidates);
        const auto& x = output_.mesh.positions;
        for (Index v : t) {
            if (is_input_vertex(v) ? turned_at_input_vertex(v, n)
                                   : turned_at_point(x[v], n, f, k, candidates)) {
                return true;
            }
        }
        return turned_at_point((x[t[0]] + x[t[1]] + x[t[2]]) / 3.0, n, f, k, candidates);
    }

    /// Whether unit normal n turns more than 90 degrees against input face g. The margin,
    /// far below any real turn, keeps rounding from counting a piece that lies in one plane of
    /// a right-angled edge as turned against the other plane's faces.
    bool turns_against(const Vec3& n, Index g) const {
        return input_normal(g).dot(n) < -kRightAngleMargin;
    }

    /// At an input vertex the nearest input faces are the faces around it.
    bool turned_at_input_vertex(Index v, const Vec3& n) const {
        const auto ring = input_.connectivity.faces_around(v);
        return std::all_of(ring.begin(), ring.end(), [&](Index g) { return turns_against(n, g); });
    }

    /// Whether the candidates nearest to q that n turns against are strictly nearer than every
    /// other candidate. Measured in the order that needs the fewest distances: the piece's own
    /// face f first (the nearest, as a rule, and almost never turned against), then the faces
    /// turned against that may come nearer than f, then, only if one did, the other faces
    /// that may come as near as it. The distance to a face's box skips the faces that cannot.
    /// Strictly nearer means by more than kTouchRatio of f's size: where q is nearest an input
    /// edge or vertex, the faces holding it are equally near, and rounding, which the scale,
    /// the position and the order of the mesh change, must not decide which is nearer.
    /// (k: the piece's column in candidates.against.)
    bool turned_at_point(const Vec3& q, const Vec3& n, Index f, Index k,
                         const Scratch& candidates) const {
        constexpr double kInfinity = std::numeric_limits<double>::infinity();
        const double other = turns_against(n, f) ? kInfinity : distance_squared(q, f);
        double against = kInfinity;
        const auto turned = candidates.against.col(k);
        for (std::size_t j = 0; j < candidates.faces.size(); ++j) {
            if (!turned(j) || least_distance_squared(q, candidates.boxes[j]) >= other) continue;
            against = std::min(against, distance_squared(q, candidates.faces[j]));
        }
        if (against == kInfinity) return false;  // no face turned against is near enough
        const double reach = std::sqrt(against) + tie_of(f);  // as near as the faces turned against
        if (!(reach < std::sqrt(other))) return false;
        for (std::size_t j = 0; j < candidates.faces.size(); ++j) {
            const Index g = candidates.faces[j];
            if (g == f || turned(j) ||
                least_distance_squared(q, candidates.boxes[j]) > reach * reach) {
                continue;
            }
            if (distance_squared(q, g) <= reach * reach) return false;
        }
        return true;
    }

    /// A lower bound of the squared distance from q to the face in `box`, shrunk far beyond
    /// rounding so that it never exceeds the measured distance.
    static double least_distance_squared(const Vec3& q, const Box3& box) {
        return box.squaredExteriorDistance(q) * (1.0 - 1e-12);
    }

    double distance_squared(const Vec3& q, Index g) const {
        const Triangle& t = input_.mesh.triangles[g];
        const auto& x = input_positions_;
        return squared_distance_to_triangle(q, x[t[0]], x[t[1]], x[t[2]]);
    }

    /// Whether a piece of split face number i may fold onto an output face across one of its
    /// edges (the pieces of i and the output faces of the faces across i's edges). Where all
    /// their normals lie within half the fold angle of the face's, no two differ by the fold
    /// angle (the triangle inequality on the sphere); the slack covers rounding.
    bool may_fold_anywhere(Index i) const {
        const Index f = split_.face(i);
        const Vec3& n = input_normal(f);
        auto within = [&](const Vec3& m) { return n.dot(m) > half_fold_cosine_ + 1e-12; };
        auto all_within = [&](Index g) {
            const Index j = split_.number(g);
            if (j == kNoIndex) return within(input_normal(g));
            for (Index k = 0; k < split_.piece_count(j); ++k) {
                if (!within(piece_normal(j, k))) return false;
            }
            return true;
        };
        if (!all_within(f)) return true;
        for (Index k = 0; k < 3; ++k) {
            const Index twin = input_.connectivity.twin[3 * f + k];
            if (twin != kNoIndex && !all_within(face_of(twin))) return true;
        }
        return false;
    }

    /// (b) Whether piece k of split face number i folds onto an output face across one of its
    /// edges: their normals differ by more than the fold angle where the input faces they
    /// replace did not (a piece and its own face's pieces replace one face).
    bool is_folded(Index i, Index k) const {
        const Index f = split_.face(i);
        const Triangle& t = piece_triangle(i, k);
        for (int e = 0; e < 3; ++e) {
            const std::optional<Across> across = face_across(i, k, t[(e + 1) % 3], t[e]);
            if (!across || piece_normal(i, k).dot(*across->normal) >= min_fold_cosine_) continue;
            const Index g = across->source;
            const bool input_folded =
                g != f && input_normal(f).dot(input_normal(g)) < min_fold_cosine_;
            if (!input_folded) return true;
        }
        return false;
    }

    /// An output face across an edge: the input face it is or was cut from, and its normal.
    struct Across {
        Index source;
        const Vec3* normal;
    };

    /// The output face other than piece k of split face i holding the directed edge a -> b,
    /// among the pieces of i and the output faces of the faces across its edges, in that
    /// order; none for a boundary or non-manifold edge.
    std::optional<Across> face_across(Index i, Index k, Index a, Index b) const {
        auto holds = [&](const Triangle& t) {
            return (t[0] == a && t[1] == b) || (t[1] == a && t[2] == b) || (t[2] == a && t[0] == b);
        };
        auto search = [&](Index g) -> std::optional<Across> {
            const Index j = split_.number(g);
            if (j == kNoIndex) {
                if (holds(input_.mesh.triangles[g])) return Across{g, &input_normal(g)};
                return std::nullopt;
            }
            for (Index m = 0; m < split_.piece_count(j); ++m) {
                if ((j != i || m != k) && holds(piece_triangle(j, m))) {
                    return Across{g, &piece_normal(j, m)};
                }
            }
            return std::nullopt;
        };
        const Index f = split_.face(i);
        std::optional<Across> found = search(f);
        for (Index edge = 0; edge < 3 && !found; ++edge) {
            const Index twin = input_.connectivity.twin[3 * f + edge];
            if (twin != kNoIndex) found = search(face_of(twin));
        }
        return found;
    }

    /// (c) How many pieces of split face number i meet another of its pieces or an output face
    /// of an input face within two rings (the candidates) whose box meets theirs. A judged
    /// split face before it already checked its pieces against these (the relation is
    /// symmetric); a crossing with another split face blames it too. Faces wholly beyond the
    /// face's cap plane (see cap_of) cannot reach its pieces; which pairs need a test, may_meet
    /// says.
    std::uint32_t count_crossing_pieces(Index i, std::span<const Index> candidates) const {
        const Index f = split_.face(i);
        const Index count = split_.piece_count(i);
        std::array<std::optional<Shape>, 6> own;
        Box3 box;
        for (Index k = 0; k < count; ++k) box.extend(own[k].emplace(piece_shape(i, k)).box);
        const double tolerance = kTouchRatio * std::sqrt(box.sizes().squaredNorm());
        std::array<bool, 6> meets{};
        for (Index a = 0; a < count; ++a) {
            for (Index b = a + 1; b < count; ++b) {
                if (may_meet(*own[a], *own[b], tolerance)) meets[a] = meets[b] = true;
            }
        }
        auto test_against = [&](const Shape& other) {
            bool met = false;
            for (Index a = 0; a < count; ++a) {
                if (!may_meet(*own[a], other, tolerance)) continue;
                meets[a] = true;
                met = true;
            }
            return met;
        };
        const Cap cap = cap_of(i, own, tolerance);
        const auto& x = input_positions_;
        for (Index g : candidates) {
            if (g == f) continue;
            const Index j = split_.number(g);
            if (j == kNoIndex) {
                const Shape whole(input_.mesh.triangles[g], x, input_normal(g));
                if (whole.box.intersects(box) && !lies_beyond(cap, f, g)) test_against(whole);
                continue;
            }
            if (g < f && judged_[j]) continue;  // (tested)
            if (!split_box_[j].may_meet(box)) continue;
            // The exact box of j's pieces decides; their shapes are made only past it (on a
            // midpoint mesh, whose every face is judged, an array of six made for every
            // candidate cost more than the tests).
            const Index their_count = split_.piece_count(j);
            Box3 their_box;
            for (Index k = 0; k < their_count; ++k) {
                for (Index v : piece_triangle(j, k)) their_box.extend(output_.mesh.positions[v]);
            }
            if (!their_box.intersects(box)) continue;
            bool met = false;
            for (Index k = 0; k < their_count; ++k) met |= test_against(piece_shape(j, k));
            if (met) mark_harmful(j);
        }
        return static_cast<std::uint32_t>(std::count(meets.begin(), meets.begin() + count, true));
    }

    /// Whether piece s and output face t need the intersection test and meet by it. They need
    /// none if their boxes lie apart; if they share an edge (the fold check's); if they share
    /// only a vertex around which the output is a simple fan, for there they meet nowhere else
    /// (is_simple_fan()); or if they share nothing and a plane through an edge of one, holding
    /// its normal, leaves the other more than the tolerance beyond (parted_by_an_edge(): the
    /// separating axes of two triangles that triangles_meet() tries last, as segment tests).
    /// The fan certificate replaces, for its pairs, the test's tolerance by exact sectors: it
    /// proves they do not cross, not that they keep the tolerance apart.
    bool may_meet(const Shape& s, const Shape& t, double tolerance) const {
        if (boxes_apart(s.box, t.box, tolerance)) return false;
        const Sharing shared = sharing_of(s.id, t.id);
        if (shared.opposite_edge) return false;
        if (shared.count == 1 && simple_fan_[shared.vertex]) return false;
        if (shared.count == 0 &&
            (parted_by_an_edge(t, s, tolerance) || parted_by_an_edge(s, t, tolerance))) {
            return false;
        }
        return triangles_meet(s.exact(), t.exact(), tolerance);
    }

    /// A half-space holding every piece of a split face: n . x >= offset (if `holds`).
    struct Cap {
        Vec3 n = Vec3::Zero();
        double offset = 0.0;
        double tolerance = 0.0;
        bool holds = false;
    };

    /// The plane of split face number i, turned to the side of the vertices its pieces (`own`)
    /// add, when they all lie clearly on one side: the pieces lie in the hull of the face and
    /// those vertices.
    Cap cap_of(Index i, const std::array<std::optional<Shape>, 6>& own, double tolerance) const {
        const Index f = split_.face(i);
        const Vec3& n = input_normal(f);
        const double offset = n.dot(input_positions_[input_.mesh.triangles[f][0]]);
        int above = 0, below = 0, added = 0;
        for (Index k = 0; k < split_.piece_count(i); ++k) {
            for (int m = 0; m < 3; ++m) {
                if (is_input_vertex(own[k]->id[m])) continue;
                const double height = n.dot(*own[k]->p[m]) - offset;
                above += height > tolerance;
                below += height < -tolerance;
                ++added;
            }
        }
        if (above == added) return {n, offset, tolerance, true};
        if (below == added) return {-n, -offset, tolerance, true};
        return {};
    }

    /// Whether unsplit face g lies beyond the cap, but for the vertices it shares with f.
    bool lies_beyond(const Cap& cap, Index f, Index g) const {
        if (!cap.holds) return false;
        const Triangle& own = input_.mesh.triangles[f];
        for (Index v : input_.mesh.triangles[g]) {
            if (v == own[0] || v == own[1] || v == own[2]) continue;
            if (cap.n.dot(input_positions_[v]) >= cap.offset - cap.tolerance) return false;
        }
        return true;
    }

    const InputSurface& input_;
    const SplitMesh& output_;
    std::span<const std::uint8_t> moved_;    ///< #V or empty: input vertices the output moved
    std::span<const Vec3> input_positions_;  ///< #V: the input's places of the vertices
    double min_fold_cosine_;
    double half_fold_cosine_;  ///< of half the fold angle
    bool check_crossings_;
    SplitFaces split_;
    std::vector<Vec3> unmoved_normal_;     ///< per split face, with moves: its input normal
    std::vector<Vec3> piece_normal_;       ///< per numbered piece (SplitFaces): its unit normal
    std::vector<OuterBox> split_box_;      ///< per split face: around the box of its pieces
    std::vector<std::uint8_t> judged_;     ///< per split face: judged by this check
    std::vector<std::uint8_t> described_;  ///< per split face: its pieces' normals made
    std::vector<Index> judged_list_;       ///< the judged split faces, ascending
    /// Per split face (#S + 1, CSR): its far candidates (find_far_candidates()) are
    /// far_[far_first_[i] .. far_first_[i + 1]).
    std::vector<Index> far_first_;
    std::vector<Index> far_;
    /// Per output vertex (#V out), with the crossing check: 1 where is_simple_fan() holds (only
    /// vertices of judged split faces are looked at).
    std::vector<std::uint8_t> simple_fan_;
    /// Per split face: its pieces do harm, or a crossing with them blames it; set from any
    /// thread. A flag, not each face's counts (12 bytes a face), is what outlives the judging.
    mutable std::vector<std::uint8_t> harmful_;
};

}  // namespace

HarmReport check_harm(const InputSurface& input, const SplitMesh& output,
                      const HarmCheckOptions& options, std::span<const std::uint8_t> changed,
                      const MovedVertices& moves) {
    if (!(options.fold_angle_deg > 90.0 && options.fold_angle_deg <= 180.0)) {
        throw InvalidInput("harm check: fold angle must lie in (90, 180] degrees");
    }
    if (!changed.empty() && changed.size() != input.mesh.face_count()) {
        throw InvalidInput("harm check: " + std::to_string(changed.size()) + " change flags for " +
                           std::to_string(input.mesh.face_count()) + " faces");
    }
    if (!moves.moved.empty() && moves.moved.size() != input.mesh.vertex_count()) {
        throw InvalidInput("harm check: " + std::to_string(moves.moved.size()) +
                           " move flags for " + std::to_string(input.mesh.vertex_count()) +
                           " vertices");
    }
    if (!moves.moved.empty() && moves.input_positions.size() != input.mesh.vertex_count()) {
        throw InvalidInput("harm check: " + std::to_string(moves.input_positions.size()) +
                           " input positions for " + std::to_string(input.mesh.vertex_count()) +
                           " vertices");
    }
    RESHARP_EXPENSIVE_ASSERT(output.source_face.size() == output.mesh.face_count());
    RESHARP_EXPENSIVE_ASSERT(std::is_sorted(output.source_face.begin(), output.source_face.end()));
    return HarmChecker(input, output, options, changed, moves).run();
}

}  // namespace resharp
