#include "resharp/restoration/point_guard.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "resharp/core/assert.h"
#include "resharp/core/errors.h"
#include "resharp/core/parallel.h"
#include "resharp/mesh/geometry.h"
#include "resharp/restoration/pieces.h"

namespace resharp {
namespace {

/// Relative area below which a piece counts as collapsed: far below any real triangle of a
/// grid mesh, far above rounding noise.
constexpr double kCollapsedAreaRatio = 1e-12;

/// The margin (degrees) of a vertex's reference normal where it has no feature normal, and the
/// most any feature normal's is taken to be.
constexpr double kNoFeatureNormalMarginDeg = 30.0;

/// A piece within this angle (degrees) of a side's feature normal lies on that side: as far as
/// a fitted feature normal may be from eq. 5.1's and still be trusted, its error on curved sides.
const double kOnASideDeg = FeatureNormalOptions{}.max_fit_correction_deg;

double sin_deg(double degrees) { return std::sin(degrees * std::numbers::pi / 180.0); }

/// The normal a piece at an input vertex must agree with, and how far (degrees) that normal
/// may be off the true surface: the piece must face within 90 degrees less that margin of it.
struct Reference {
    const Vec3& normal;
    double margin_deg;
};

/// The vertex's feature normal, trusted to within its fit correction: on a curved feature the
/// estimate is that much off, and a piece standing almost on edge to it may lean past the true
/// surface (on planes the correction is zero). Where the fit was not trusted and eq. 5.1's
/// normal kept, the fitted field still says how fast the feature turns: eq. 5.1's mean of the
/// vertex's faces is the normal about half a face inward, so it is trusted to within the
/// field's turn over half the face judged, or its angle to the field's normal if larger (on
/// impeller a kept normal 2.8 degrees off the exact one, 1.3 off the field's, let a piece turn
/// against the surface). Where a vertex has no feature normal (all its faces lie in bands), its
/// plain vertex normal, which leans towards the band by up to half the edge's angle: a piece
/// must face within 60 degrees of it.
struct ReferenceNormals {
    const FeatureNormals& feature;
    const std::vector<Vec3>& vertex;
    /// v's reference for a piece of a face whose longest edge is `extent` long.
    Reference at(Index v, double extent) const {
        if (feature.normal(v).isZero(0.0)) return {vertex[v], kNoFeatureNormalMarginDeg};
        return {feature.normal(v), std::min(margin_deg(v, extent), kNoFeatureNormalMarginDeg)};
    }
    const Vec3& normal(Index v) const {
        return feature.normal(v).isZero(0.0) ? vertex[v] : feature.normal(v);
    }

private:
    double margin_deg(Index v, double extent) const {
        const NormalField& field = feature.field(v);
        if (field.n0.isZero(0.0) || field.n0 == feature.normal(v))
            return feature.fit_correction_deg(v);
        const double turn_deg = 0.5 * extent * field.gradient.norm() * 180.0 / std::numbers::pi;
        return std::max(angle_deg(field.n0, feature.normal(v)), turn_deg);
    }
};

/// Two edge points of a face are merged only this close, relative to the face's longest edge:
/// the point moves along the sharp edge by no more on the faces across the edge it joins. On
/// the CAD corpus a quarter gained little more (one row of 54 by more than 0.005 of Edge
/// F-score) and let impeller's harm check undo 15 % more points.
constexpr double kMergeReach = 0.1;

/// Why a piece may not be emitted, in the order the checks run.
enum class Fault {
    None,
    Quality,  ///< collapsed, or turned against its vertices' reference normals
    Guard,    ///< turned against the face it replaces, or too close to flipping across thin
              ///< material (see docs/method.md, "The guard")
};

/// Judges single pieces of a split face by their normals.
class PieceJudge {
public:
    PieceJudge(const InputSurface& input, const ReferenceNormals& reference,
               const PieceVertices& ids, double thin_material_angle_deg)
        : input_(input),
          reference_(reference),
          ids_(ids),
          thin_cosine_(std::cos(thin_material_angle_deg * std::numbers::pi / 180.0)) {}

    /// The worst fault of the pieces face f is cut into with `slots`.
    Fault fault_of(const PointSlots& slots, Index f) const {
        Fault worst = Fault::None;
        for_each_piece(input_.mesh, slots, ids_, f, [&](Index a, Index b, Index c) {
            const Fault found = piece_fault(f, a, b, c);
            if (worst == Fault::None || found == Fault::Quality) worst = found;
        });
        return worst;
    }

private:
    /// Piece (a, b, c) of face f:
    /// - Quality: it has no area, or turns against the reference normal of an input vertex;
    /// - Guard: it turns against face f although f itself is sound at the piece's input
    ///   vertices (the paper's §5.3 flip: M' projects outside the face it is derived from;
    ///   only where f leans past a vertex's surface may pieces rightly turn from f), or it
    ///   joins vertices whose references differ by more than the thin-material angle (material too
    ///   thin for the mesh) and does not clear each of them by twice its margin: there the
    ///   piece stands almost on edge to both surfaces, and an error in either normal flips it.
    Fault piece_fault(Index f, Index a, Index b, Index c) const {
        const Vec3 n =
            (ids_.position(b) - ids_.position(a)).cross(ids_.position(c) - ids_.position(a));
        const double extent_squared = longest_edge_squared(input_.mesh, f);
        if (n.norm() <= kCollapsedAreaRatio * extent_squared) return Fault::Quality;
        const bool thin = spans_thin_material(a, b, c);
        const Vec3& face_normal = input_.normals.face[f];
        bool face_leans_past_surface = false;
        Fault found = Fault::None;
        for (Index v : {a, b, c}) {
            if (!ids_.is_original(v)) continue;
            const Reference r = reference_.at(v, std::sqrt(extent_squared));
            if (r.normal.isZero(0.0)) continue;
            const double min_cosine = sin_deg(r.margin_deg);
            if (n.dot(r.normal) <= min_cosine * n.norm() && !lies_on_a_side_next_to(v, n)) {
                return Fault::Quality;
            }
            if (thin && n.dot(r.normal) <= sin_deg(std::min(2.0 * r.margin_deg, 89.0)) * n.norm()) {
                found = Fault::Guard;
            }
            face_leans_past_surface =
                face_leans_past_surface || face_normal.dot(r.normal) <= min_cosine;
        }
        if (!face_leans_past_surface && n.dot(face_normal) <= 0.0) return Fault::Guard;
        return found;
    }

    /// Whether piece normal n lies on a side next to v, v having no feature normal of its own:
    /// within kOnASideDeg of the feature normal of a vertex of v's ring. Such a vertex has all
    /// its faces in bands (a near-surface vertex moved onto the junction of the sides, the
    /// middle row of a wide band); on the sharp edge the surface faces as either side does, but
    /// its vertex normal leans to the side with more of its faces, and a piece lying on the
    /// other side can face away from it by more than the 60 degrees the reference allows (65 on
    /// a turned block meshed by surface nets, where that left a notch in the restored edge).
    /// A piece that lies on no side is still judged by the vertex normal alone: taking any side
    /// within 60 degrees let pieces across mech's and impeller's narrow features turn against
    /// the exact surface. Bound: the vertex's ring.
    bool lies_on_a_side_next_to(Index v, const Vec3& n) const {
        if (!reference_.feature.normal(v).isZero(0.0)) return false;
        const double min_cosine = std::cos(kOnASideDeg * std::numbers::pi / 180.0) * n.norm();
        bool on_a_side = false;
        for_each_ring_vertex(input_.mesh, input_.connectivity, v, [&](Index u) {
            const Vec3& side = reference_.feature.normal(u);
            on_a_side = on_a_side || (!side.isZero(0.0) && n.dot(side) > min_cosine);
        });
        return on_a_side;
    }

    bool spans_thin_material(Index a, Index b, Index c) const {
        const std::array<Index, 3> v{a, b, c};
        for (int i = 0; i < 3; ++i) {
            for (int j = i + 1; j < 3; ++j) {
                if (!ids_.is_original(v[i]) || !ids_.is_original(v[j])) continue;
                if (reference_.normal(v[i]).dot(reference_.normal(v[j])) < thin_cosine_)
                    return true;
            }
        }
        return false;
    }

    const InputSurface& input_;
    const ReferenceNormals& reference_;
    const PieceVertices& ids_;
    double thin_cosine_;
};

/// The per-face and per-half-edge flags of a guard run, allocated once for all the runs of a
/// guard call: a run leaves `queued` clear (it pops every face it queues), and clear() clears
/// the rest through the list of faces touched, so a run costs what it works on, not the mesh.
struct GuardFlags {
    std::vector<std::uint8_t> queued;   ///< per face (#F): in the worklist
    std::vector<std::uint8_t> touched;  ///< per face (#F): a slot of it was set
    std::vector<std::uint8_t> snapped;  ///< per half-edge (#3F): its edge was snapped once
    std::vector<Index> touched_faces;   ///< the faces `touched` marks, in the order touched

    explicit GuardFlags(std::size_t face_count)
        : queued(face_count, 0), touched(face_count, 0), snapped(3 * face_count, 0) {}

    /// Snapping sets a half-edge of a face it touches and its twin, of a face it touches too.
    void clear() {
        for (Index f : touched_faces) {
            touched[f] = 0;
            std::fill_n(snapped.begin() + 3 * f, 3, std::uint8_t{0});
        }
        touched_faces.clear();
    }
};

/// Faces with a point that need a check, and the faces to check again after a repair. Each
/// face is queued at most once at a time.
class Worklist {
public:
    Worklist(std::vector<std::uint8_t>& queued, std::span<const Index> first)
        : faces_(first.begin(), first.end()), queued_(queued) {
        for (Index f : first) queued_[f] = 1;
    }
    bool empty() const { return next_ == faces_.size(); }
    Index pop() {
        const Index f = faces_[next_++];
        queued_[f] = 0;
        return f;
    }
    void push(Index f) {
        if (queued_[f]) return;
        queued_[f] = 1;
        faces_.push_back(f);
    }

private:
    std::vector<Index> faces_;
    std::vector<std::uint8_t>& queued_;  ///< per face (#F), clear when the list is empty
    std::size_t next_ = 0;
};

/// Whether point p was withdrawn (an empty list withdraws none).
bool is_withdrawn(std::span<const std::uint8_t> withdrawn, Index p) {
    return !withdrawn.empty() && withdrawn[p] != 0;
}

/// Whether face f had a point at the start of the run that `before` withdrew points for.
bool had_points_before(const SharpPoints& candidates, std::span<const std::uint8_t> before,
                       Index f) {
    bool any = false;
    candidates.slots.for_each_point(f, [&](Index p) { any = any || !is_withdrawn(before, p); });
    return any;
}

/// The slots being decided, and the repairs that change them. Every change is one of two
/// kinds, which is what bounds the work: a point leaves a slot for good (a slot never gets a
/// point back), or an edge's point is replaced by the corner point of one of its faces or by
/// the point of another edge of one of its faces, or an edge without a point takes the corner
/// point of a face across the edge beside it, at most once per edge (`snapped`). So there are
/// at most as many changes as slots holding a point at the start, plus as many as edges.
class Repairs {
public:
    /// `slots`: the candidates' less the `withdrawn` points, or what an earlier run left of them.
    Repairs(const InputSurface& input, const SharpPoints& candidates,
            std::span<const std::uint8_t> withdrawn, PointSlots slots, const PieceVertices& ids,
            const PieceJudge& judge, GuardFlags& flags)
        : input_(input),
          c_(input.connectivity),
          candidates_(candidates),
          withdrawn_(withdrawn),
          slots_(std::move(slots)),
          ids_(ids),
          judge_(judge),
          first_corner_point_(static_cast<Index>(candidates.edge_points)),
          flags_(flags) {}

    const PointSlots& slots() const { return slots_; }
    /// The slots decided; the repairs are done with.
    PointSlots take_slots() && { return std::move(slots_); }
    Fault fault_of(Index f) const { return judge_.fault_of(slots_, f); }
    /// Whether a repair has changed a slot of face f (its fault may differ from the start's).
    bool touched(Index f) const { return flags_.touched[f] != 0; }

    /// Makes face f split soundly by changing as little as possible, in this order:
    /// - put one of its two edge points on the other's edge too (try_merging()): two close
    ///   points out of order along the sharp edge make a flipped sliver, and one point on both
    ///   edges still restores the sharp edge through both;
    /// - drop a single edge point (the first that is enough, in slot order), but a corner point
    ///   that the corner triangle across put on the edge only after the point of a crossing
    ///   edge that f holds inside (first_single_drop()), and only after trying that corner
    ///   point on an edge of f that has none (try_spreading_corner_across());
    /// - in a corner triangle, split one edge, then two, at the corner point instead of their
    ///   own points where those lie beyond the corner (beyond_corner()): where a sharp edge ends
    ///   at a corner, eq. 5.2's mid-plane can put its point past the corner, on the edge's
    ///   extension, and the corner is where that edge really stops. Its point there restores
    ///   nothing of the edge, the corner point the corner;
    /// - drop the corner point alone;
    /// - split one edge, then two, at the corner point, whatever their points;
    /// - drop every point of the face.
    /// Returns the number of points dropped.
    std::size_t repair(Index f) {
        if (try_merging(f)) return 0;
        if (first_single_drop(f)) return 1;
        if (const std::optional<std::size_t> dropped = try_spreading_corner_across(f)) {
            return *dropped;
        }
        if (drop_corner_across(f)) return 1;
        if (try_snapping(f, true)) return 0;
        if (slot(f, 3) != kNoIndex && replace_if_sound(f, 1u << 3, kNoIndex)) return 1;
        if (try_snapping(f, false)) return 0;
        std::size_t dropped = 0;
        for (int i = 0; i < 4; ++i) {
            if (slot(f, i) == kNoIndex) continue;
            set(f, i, kNoIndex);
            ++dropped;
        }
        return dropped;
    }

private:
    /// Slot i of face f: its half-edges 0..2, then its corner (3).
    Index slot(Index f, int i) const { return slots_.slot(f, i); }

    /// Whether edge i of face f holds the corner point of the corner triangle across it (put
    /// there because its own point lies beyond its chord, or snapped), not one of f's own.
    bool holds_corner_across(Index f, int i) const {
        const Index p = slot(f, i);
        return p != kNoIndex && p >= first_corner_point_ && p != slot(f, 3);
    }

    /// The single-drop step of repair(): drops the first point of face f whose drop alone is
    /// enough, in slot order among its edges, except that an edge holding the corner point of
    /// the corner triangle across comes last, after the crossing edge's point f holds inside.
    /// Such a face lies where a sharp edge ends at a corner of mixed convexity (a slot's rim
    /// meeting the bottom face): its inner point and the corner point lie on one line with
    /// the vertex beyond the corner on the wrong side, and dropping the corner point there
    /// broke the corner triangle, whose pieces then turned over and lost all their points.
    /// (The corner point's own drop is drop_corner_across().)
    bool first_single_drop(Index f) {
        bool corner_across = false;
        for (int i = 0; i < 3; ++i) {
            if (holds_corner_across(f, i)) {
                corner_across = true;
            } else if (slot(f, i) != kNoIndex && replace_if_sound(f, 1u << i, kNoIndex)) {
                return true;
            }
        }
        if (!corner_across) return false;
        const Index inside = slot(f, 3);
        return inside != kNoIndex && inside < first_corner_point_ &&
               replace_if_sound(f, 1u << 3, kNoIndex);
    }

    /// Drops the first corner point of a corner triangle across an edge of face f whose drop
    /// alone is enough.
    bool drop_corner_across(Index f) {
        for (int i = 0; i < 3; ++i) {
            if (holds_corner_across(f, i) && replace_if_sound(f, 1u << i, kNoIndex)) return true;
        }
        return false;
    }

    /// Whether edge i of face f holds the corner point of the face across it.
    bool holds_corner_of_face_across(Index f, int i) const {
        const Index twin = c_.twin[3 * f + static_cast<Index>(i)];
        return twin != kNoIndex && holds_corner_across(f, i) &&
               slots_.corner_point(face_of(twin)) == slot(f, i);
    }

    /// The spreading step of repair(): face f holds on an edge the corner point of the face
    /// across it, and an edge of f that has no point and was never snapped takes that corner
    /// point too if f then splits without fault (the first such edge in slot order). Beside a
    /// corner of mixed convexity (a pocket's wall meeting its rim) the face next to the corner
    /// triangle reaches across the sharp edge that ends at the corner: its other edge crosses
    /// that edge's extension past the corner, where eq. 5.2 puts a point that restores nothing
    /// (inside the face across if beyond its chord). With the corner point on both edges, f's
    /// corner between them is cut off by the faces across. A point inside f, or inside the face
    /// across the new edge, within merging reach of the corner point is the one it replaces,
    /// and goes; another point inside f stops the step. The new edge lies between faces that
    /// had points at the start (had_points_before()): guard_points_again() finds the faces whose
    /// work can change across such edges alone. Gives the number of points dropped; nullopt if
    /// no edge takes the corner point.
    std::optional<std::size_t> try_spreading_corner_across(Index f) {
        for (int i = 0; i < 3; ++i) {
            if (!holds_corner_of_face_across(f, i)) continue;
            const Index corner = slot(f, i);
            const bool inside = slot(f, 3) != kNoIndex;
            if (inside && !holds_point_inside_near(f, corner)) return std::nullopt;
            for (int j = 0; j < 3; ++j) {
                const Index h = 3 * f + static_cast<Index>(j);
                if (slot(f, j) != kNoIndex || flags_.snapped[h] || c_.twin[h] == kNoIndex ||
                    !had_points_before(candidates_, withdrawn_, face_of(c_.twin[h]))) {
                    continue;
                }
                if (!replace_if_sound(f, 1u << j, corner, inside ? 1u << 3 : 0u)) continue;
                mark_snapped(f, j);
                const Index across = face_of(c_.twin[h]);
                const bool drop_across = holds_point_inside_near(across, corner);
                if (drop_across) set(across, 3, kNoIndex);
                return std::size_t{inside} + std::size_t{drop_across};
            }
        }
        return std::nullopt;
    }

    /// Whether face g holds inside the point of a crossing edge within merging reach of point
    /// `near`.
    bool holds_point_inside_near(Index g, Index near) const {
        const Index inside = slot(g, 3);
        if (inside == kNoIndex || inside >= first_corner_point_) return false;
        return (ids_.position(ids_.of_point(inside)) - ids_.position(ids_.of_point(near))).norm() <=
               merge_reach(g);
    }

    /// Sets slot i of face f, and for an edge the same slot seen from the face across it.
    void set(Index f, int i, Index value) {
        slots_.set_slot(f, i, value);
        touch(f);
        if (i == 3) return;
        const Index twin = c_.twin[3 * f + static_cast<Index>(i)];
        if (twin == kNoIndex) return;
        slots_.set_edge_point(twin, value);
        touch(face_of(twin));
    }
    void touch(Index f) {
        if (flags_.touched[f]) return;
        flags_.touched[f] = 1;
        flags_.touched_faces.push_back(f);
    }
    void mark_snapped(Index f, int i) {
        const Index h = 3 * f + static_cast<Index>(i);
        flags_.snapped[h] = 1;
        if (c_.twin[h] != kNoIndex) flags_.snapped[c_.twin[h]] = 1;
    }
    /// Whether face f would split without fault with `replacement` in its slots `slots` (a bit
    /// per slot, 0..3) and no point in its slots `cleared`. Changes nothing.
    bool sound_with(Index f, unsigned slots, Index replacement, unsigned cleared = 0) {
        std::array<Index, 4> kept{};
        for (int i = 0; i < 4; ++i) {
            kept[static_cast<std::size_t>(i)] = slot(f, i);
            if (slots & (1u << i)) slots_.set_slot(f, i, replacement);
            if (cleared & (1u << i)) slots_.set_slot(f, i, kNoIndex);
        }
        const bool sound = fault_of(f) == Fault::None;
        for (int i = 0; i < 4; ++i) slots_.set_slot(f, i, kept[static_cast<std::size_t>(i)]);
        return sound;
    }

    /// Puts `replacement` in the slots of face f in `slots` (a bit per slot, 0..3), and clears
    /// its slots `cleared`, if the face then splits without fault; leaves them as they were
    /// otherwise.
    bool replace_if_sound(Index f, unsigned slots, Index replacement, unsigned cleared = 0) {
        if (!sound_with(f, slots, replacement, cleared)) return false;
        for (int i = 0; i < 4; ++i) {
            if (slots & (1u << i)) set(f, i, replacement);
            if (cleared & (1u << i)) set(f, i, kNoIndex);
        }
        return true;
    }

    /// Splits the edges of face f in `edges` (a bit per edge slot) at f's corner point instead of
    /// their own points if the face then splits without fault. Two snapped edges leave the
    /// corner between them joined to the corner point by the faces across them alone.
    bool snap_if_sound(Index f, unsigned edges) {
        if (!replace_if_sound(f, edges, slots_.corner_point(f))) return false;
        for (int i = 0; i < 3; ++i) {
            if (edges & (1u << i)) mark_snapped(f, i);
        }
        return true;
    }

    /// The point of edge i of face f lies beyond f's corner point: the corner point lies
    /// between it and the next point of its sharp edge, the one other edge point of the face
    /// across.
    bool beyond_corner(Index f, int i) const {
        const Index h = 3 * f + static_cast<Index>(i);
        const Index point = slots_.edge_point(h), twin = c_.twin[h];
        if (twin == kNoIndex) return false;
        Index next = kNoIndex;
        for (Index k = 3 * face_of(twin); k < 3 * face_of(twin) + 3; ++k) {
            const Index p = slots_.edge_point(k);
            if (k == twin || p == kNoIndex) continue;
            if (next != kNoIndex) return false;
            next = p;
        }
        if (next == kNoIndex) return false;
        const Vec3& corner = ids_.position(ids_.of_point(slots_.corner_point(f)));
        return (ids_.position(ids_.of_point(point)) - corner)
                   .dot(ids_.position(ids_.of_point(next)) - corner) < 0.0;
    }

    /// The snapping steps of repair(): one edge, then two, among the edges of face f that hold
    /// a point (beyond the corner if `beyond_only`) and were never snapped, the first set that is
    /// enough in slot order; none if f has no corner point or an edge of f is on it already.
    bool try_snapping(Index f, bool beyond_only) {
        if (slots_.corner_point(f) == kNoIndex) return false;
        unsigned may_snap = 0;
        for (int i = 0; i < 3; ++i) {
            if (slot(f, i) == slots_.corner_point(f)) return false;
            if (slot(f, i) == kNoIndex || flags_.snapped[3 * f + static_cast<Index>(i)]) continue;
            if (!beyond_only || beyond_corner(f, i)) may_snap |= 1u << i;
        }
        for (unsigned edges : {1u, 2u, 4u, 3u, 5u, 6u}) {
            if ((edges & may_snap) == edges && snap_if_sound(f, edges)) return true;
        }
        return false;
    }

    /// The merging step of repair(): where face f holds two edge points no farther apart than
    /// kMergeReach and no corner point, the point of one edge also goes on the other (both
    /// slots of that edge), if f then splits without fault. The corner between the two edges is
    /// then cut off by the faces across them alone (for_each_piece()). Dropping a point instead
    /// leaves the band beside its edge unrestored, two creases a pitch from the true edge: on
    /// stepped_block turned at 200 cells 279 points were refused so, 128 with merging.
    bool try_merging(Index f) {
        if (slot(f, 3) != kNoIndex) return false;
        std::array<int, 3> edges{};
        int count = 0;
        for (int i = 0; i < 3; ++i) {
            if (slot(f, i) != kNoIndex) edges[static_cast<std::size_t>(count++)] = i;
        }
        if (count != 2 || slot(f, edges[0]) == slot(f, edges[1])) return false;
        // A point that came onto its edge by a merge or snap stays where it is, and takes no
        // other: so a point goes only onto an edge of a face that holds it among the
        // candidates, and is not carried along the band from face to face. Except the corner
        // point of the face across: it was snapped onto the edge it shares with f (its edge's
        // point lay past the corner), and f's other point, this close, lies past the corner
        // too (mixed convexity, see try_spreading_corner_across()); it goes one face on, onto
        // the other edge, and no farther (f holds no corner point).
        int keep_only = -1;  // edges[keep_only] is snapped: its point stays and goes on
        for (int k = 0; k < 2; ++k) {
            const int i = edges[static_cast<std::size_t>(k)];
            if (!flags_.snapped[3 * f + static_cast<Index>(i)]) continue;
            if (keep_only >= 0 || !holds_corner_of_face_across(f, i)) return false;
            keep_only = k;
        }
        if ((point_at(f, edges[0]) - point_at(f, edges[1])).norm() > merge_reach(f)) return false;
        if (keep_only == 1 || (keep_only < 0 && keep_second_first(f, edges[0], edges[1]))) {
            std::swap(edges[0], edges[1]);
        }
        for (int k = 0; k < (keep_only < 0 ? 2 : 1); ++k) {
            const int keep = edges[static_cast<std::size_t>(k)];
            const int change = edges[static_cast<std::size_t>(1 - k)];
            if (replace_if_sound(f, 1u << change, slot(f, keep))) {
                mark_snapped(f, change);
                return true;
            }
        }
        return false;
    }

    /// How near two points of face f must lie to be merged (kMergeReach).
    double merge_reach(Index f) const {
        return kMergeReach * std::sqrt(longest_edge_squared(input_.mesh, f));
    }

    /// The position of the point in slot i of face f.
    const Vec3& point_at(Index f, int i) const { return ids_.position(ids_.of_point(slot(f, i))); }

    /// Whether a merge keeps the point of face f's edge `second` before that of `first`: where
    /// dropping one of them alone would mend the face, that one is off its place, and the other
    /// is kept first (on frogface's scallops, 90.60 % of the ideal points restored where the
    /// geometric order alone restored 90.14 %); else the point first in geometric order.
    bool keep_second_first(Index f, int first, int second) {
        const bool dropping_first_mends = sound_with(f, 1u << first, kNoIndex);
        const bool dropping_second_mends = sound_with(f, 1u << second, kNoIndex);
        if (dropping_first_mends != dropping_second_mends) return dropping_first_mends;
        return lexicographically_less(point_at(f, second), point_at(f, first));
    }

    const InputSurface& input_;
    const Connectivity& c_;
    const SharpPoints& candidates_;
    std::span<const std::uint8_t> withdrawn_;
    PointSlots slots_;
    const PieceVertices& ids_;
    const PieceJudge& judge_;
    Index first_corner_point_;
    GuardFlags& flags_;  ///< which faces a slot of was set, and which edges were snapped
};

/// Every slot of `accepted` holds the point it held among the candidates, a point a face of its
/// edge held among the candidates (a snapped or merged edge), the corner point of a face across
/// an edge of one of them (a corner point spread or merged one face on), or none: the guard
/// only takes away.
[[maybe_unused]] bool only_takes_away(const PointSlots& accepted, const SharpPoints& candidates,
                                      const Connectivity& c) {
    auto held_by = [&](Index f, Index id) {
        bool held = false;
        candidates.slots.for_each_point(f, [&](Index p) { held = held || p == id; });
        return held;
    };
    auto corner_beside = [&](Index f, Index id) {
        for (Index k = 3 * f; k < 3 * f + 3; ++k) {
            if (c.twin[k] != kNoIndex && candidates.slots.corner_point(face_of(c.twin[k])) == id)
                return true;
        }
        return false;
    };
    for (Index h = 0; h < 3 * accepted.face_count(); ++h) {
        const Index id = accepted.edge_point(h);
        if (id == kNoIndex || id == candidates.slots.edge_point(h)) continue;
        const Index twin = c.twin[h];
        bool allowed = held_by(face_of(h), id) || corner_beside(face_of(h), id);
        if (twin != kNoIndex)
            allowed = allowed || held_by(face_of(twin), id) || corner_beside(face_of(twin), id);
        if (!allowed) return false;
    }
    for (Index f = 0; f < accepted.face_count(); ++f) {
        const Index id = accepted.corner_point(f);
        if (id != kNoIndex && id != candidates.slots.corner_point(f)) return false;
    }
    return true;
}

/// Face f's candidate slots less the withdrawn points, written into the slots of face `into`
/// of `slots`.
void start_face(const SharpPoints& candidates, std::span<const std::uint8_t> withdrawn, Index f,
                PointSlots& slots, Index into) {
    auto kept = [&](Index p) { return p == kNoIndex || is_withdrawn(withdrawn, p) ? kNoIndex : p; };
    for (int k = 0; k < 4; ++k) slots.set_slot(into, k, kept(candidates.slots.slot(f, k)));
}

/// The candidates' slots less the withdrawn points.
PointSlots starting_slots(const SharpPoints& candidates, std::span<const std::uint8_t> withdrawn) {
    PointSlots slots = candidates.slots;
    if (!withdrawn.empty()) slots.empty_slots_of([&](Index p) { return withdrawn[p] != 0; });
    return slots;
}

std::vector<Index> faces_with_points(const PointSlots& slots) {
    std::vector<Index> faces;
    for (Index f = 0; f < slots.face_count(); ++f) {
        if (slots.has_points(f)) faces.push_back(f);
    }
    return faces;
}

/// Per-face flags of guard_points_again()'s search for the faces to guard again, made once for
/// all its runs: each run's region marks are cleared through its list of faces (clear()).
struct RegionFlags {
    std::vector<std::uint8_t> repaired;       ///< per face (#F): repaired by the last guard
    std::vector<std::uint8_t> expand_anyway;  ///< per face (#F): searched across if left alone
    std::vector<std::uint8_t> in_region;      ///< per face (#F): in the current run's region
    std::vector<std::uint8_t> is_border;      ///< per face (#F): on the current region's border

    RegionFlags(const GuardedPoints& previous, std::size_t face_count)
        : repaired(face_count, 0),
          expand_anyway(face_count, 0),
          in_region(face_count, 0),
          is_border(face_count, 0) {
        for (const GuardRepair& r : previous.repairs) repaired[r.face] = 1;
    }
    void clear(const std::vector<Index>& region) {
        for (Index f : region) in_region[f] = is_border[f] = 0;
    }
};

/// The faces to guard again after more points were withdrawn, ascending, marked in
/// `flags.in_region` (and the border's in `flags.is_border`): the faces that had points at the
/// last run's start (candidates less `before`) reached, across edges between such faces, from
/// one that lost a point since (one of `now` but not of `before`; every such face is one of
/// `holders` or lies across an edge of one), or one of `reshaped` that had points. The search
/// stops at the faces the last run left alone (never repaired, slots as they started), which
/// become the border, unless `flags.expand_anyway` marks them. A repair of a border face, or a
/// change to its slots, is the only way the faces beyond can be drawn in (they push only their
/// neighbours, and pushing a face left alone does nothing), so the region suffices if the run
/// leaves its border alone.
/// Bound: each face joins the list once, and is looked at from its three edges.
std::vector<Index> faces_to_guard_again(const Connectivity& c, const SharpPoints& candidates,
                                        const GuardedPoints& previous,
                                        std::span<const std::uint8_t> before,
                                        std::span<const std::uint8_t> now,
                                        std::span<const Index> holders,
                                        std::span<const Index> reshaped, RegionFlags& flags) {
    const PointSlots& slots = candidates.slots;
    auto had_points = [&](Index f) { return had_points_before(candidates, before, f); };
    auto lost_a_point = [&](Index f) {
        bool lost = false;
        slots.for_each_point(
            f, [&](Index p) { lost = lost || (now[p] != 0 && !is_withdrawn(before, p)); });
        return lost;
    };
    PointSlots started(1);  // one face's start
    auto left_alone = [&](Index f) {
        if (flags.repaired[f] || flags.expand_anyway[f]) return false;
        start_face(candidates, before, f, started, 0);
        return started.same_at(0, previous.accepted, f);
    };
    std::vector<Index> expand;  // the faces whose neighbours join
    auto seed = [&](Index f) {
        if (flags.in_region[f] || !lost_a_point(f)) return;
        flags.in_region[f] = 1;
        expand.push_back(f);
    };
    for (Index f : holders) {
        seed(f);
        for (Index k = 0; k < 3; ++k) {
            if (c.twin[3 * f + k] != kNoIndex) seed(face_of(c.twin[3 * f + k]));
        }
    }
    for (Index f : reshaped) {
        if (flags.in_region[f] || !had_points(f)) continue;
        flags.in_region[f] = 1;
        expand.push_back(f);
    }
    std::vector<Index> region = expand;
    for (std::size_t i = 0; i < expand.size(); ++i) {
        for (Index k = 0; k < 3; ++k) {
            const Index twin = c.twin[3 * expand[i] + k];
            if (twin == kNoIndex) continue;
            const Index g = face_of(twin);
            if (flags.in_region[g] || !had_points(g)) continue;
            flags.in_region[g] = 1;
            region.push_back(g);
            if (left_alone(g)) {
                flags.is_border[g] = 1;
            } else {
                expand.push_back(g);
            }
        }
    }
    std::sort(region.begin(), region.end());
    return region;
}

/// Marks `flags.expand_anyway` on the faces that had points (had_points_before()) within
/// `depth` steps of `faces` across edges between such faces, `faces` included. Bound: each face
/// is marked once, and looked at from its three edges.
void expand_beyond(const Connectivity& c, const SharpPoints& candidates,
                   std::span<const std::uint8_t> before, std::vector<Index> faces, int depth,
                   RegionFlags& flags) {
    for (Index f : faces) flags.expand_anyway[f] = 1;
    for (int step = 0; step < depth && !faces.empty(); ++step) {
        std::vector<Index> next;
        for (Index f : faces) {
            for (Index k = 0; k < 3; ++k) {
                const Index twin = c.twin[3 * f + k];
                if (twin == kNoIndex) continue;
                const Index g = face_of(twin);
                if (flags.expand_anyway[g] || !had_points_before(candidates, before, g)) continue;
                flags.expand_anyway[g] = 1;
                next.push_back(g);
            }
        }
        faces = std::move(next);
    }
}

/// Checks the faces of `first` (ascending) and repairs the faulty ones, appending each repair
/// to `log`. Bound: a face is popped once at the start and once per repair of a face across
/// one of its edges; repairs are bounded as Repairs says (GuardReport::repairs).
void repair_faults(const Connectivity& c, std::span<const Index> first, Repairs& repairs,
                   std::vector<std::uint8_t>& queued, std::vector<GuardRepair>& log) {
    // The faults of the faces as they start, judged in parallel (a face's fault reads only its
    // own slots): the worklist pops each of them once before any face it pushes, and takes
    // this verdict where no repair has set a slot of the face since.
    std::vector<Fault> at_start(first.size());
    for_each_index(first.size(), 256,
                   [&](std::size_t i) { at_start[i] = repairs.fault_of(first[i]); });
    Worklist work(queued, first);
    for (std::size_t popped = 0; !work.empty(); ++popped) {
        const Index f = work.pop();
        if (!repairs.slots().has_points(f)) continue;
        const Fault fault =
            popped < first.size() && !repairs.touched(f) ? at_start[popped] : repairs.fault_of(f);
        if (fault == Fault::None) continue;
        const std::size_t dropped = repairs.repair(f);
        log.push_back({f, fault == Fault::Quality, static_cast<std::uint32_t>(dropped)});
        for (Index k = 0; k < 3; ++k) {
            const Index twin = c.twin[3 * f + k];
            if (twin != kNoIndex) work.push(face_of(twin));
        }
    }
}

GuardReport report_of(const std::vector<GuardRepair>& log) {
    GuardReport report;
    for (const GuardRepair& r : log) {
        (r.by_quality ? report.refused_by_quality : report.refused_by_guard) += r.dropped;
    }
    report.repairs = log.size();
    return report;
}

void validate(const GuardOptions& options, const SharpPoints& candidates,
              std::span<const std::uint8_t> withdrawn) {
    if (!(options.thin_material_angle_deg > 0.0 && options.thin_material_angle_deg <= 180.0)) {
        throw InvalidInput("guard: thin-material angle must lie in (0, 180] degrees");
    }
    if (!withdrawn.empty() && withdrawn.size() != candidates.points.size()) {
        throw InvalidInput("guard: " + std::to_string(withdrawn.size()) + " withdrawal flags for " +
                           std::to_string(candidates.points.size()) + " points");
    }
}

/// The guard on `slots`, starting from the faces `first` (ascending); `log` holds the repairs
/// kept from an earlier run, if any. `flags` must be clear; the run leaves in them the faces
/// whose slots it set.
GuardedPoints guard_slots(const InputSurface& input, const FeatureNormals& feature_normals,
                          const SharpPoints& candidates, std::span<const std::uint8_t> withdrawn,
                          PointSlots slots, std::span<const Index> first,
                          std::vector<GuardRepair> log, const GuardOptions& options,
                          GuardFlags& flags) {
    const PieceVertices ids(input.mesh, candidates.points);
    const ReferenceNormals reference{feature_normals, input.normals.vertex};
    const PieceJudge judge(input, reference, ids, options.thin_material_angle_deg);
    Repairs repairs(input, candidates, withdrawn, std::move(slots), ids, judge, flags);
    repair_faults(input.connectivity, first, repairs, flags.queued, log);
    GuardedPoints out{std::move(repairs).take_slots(), report_of(log), std::move(log)};
    RESHARP_EXPENSIVE_ASSERT(only_takes_away(out.accepted, candidates, input.connectivity));
    return out;
}

}  // namespace

GuardedPoints guard_points(const InputSurface& input, const FeatureNormals& feature_normals,
                           const SharpPoints& candidates, std::span<const std::uint8_t> withdrawn,
                           const GuardOptions& options) {
    validate(options, candidates, withdrawn);
    PointSlots slots = starting_slots(candidates, withdrawn);
    const std::vector<Index> first = faces_with_points(slots);
    GuardFlags flags(input.mesh.face_count());
    return guard_slots(input, feature_normals, candidates, withdrawn, std::move(slots), first, {},
                       options, flags);
}

GuardedPoints guard_points_again(const InputSurface& input, const FeatureNormals& feature_normals,
                                 const SharpPoints& candidates, const GuardedPoints& previous,
                                 std::span<const std::uint8_t> withdrawn_before,
                                 std::span<const std::uint8_t> withdrawn,
                                 std::span<const Index> holders, std::span<const Index> reshaped,
                                 const GuardOptions& options) {
    validate(options, candidates, withdrawn_before);
    validate(options, candidates, withdrawn);
    for (auto [faces, what] : {std::pair{holders, "holder"}, std::pair{reshaped, "reshaped"}}) {
        for (Index f : faces) {
            if (f >= input.mesh.face_count()) {
                throw InvalidInput(std::string("guard: ") + what + " face " + std::to_string(f) +
                                   " of " + std::to_string(input.mesh.face_count()));
            }
        }
    }
    if (withdrawn.empty()) return guard_points(input, feature_normals, candidates, {}, options);
    const std::size_t face_count = input.mesh.face_count();
    GuardFlags flags(face_count);
    RegionFlags region_flags(previous, face_count);
    // The slots every run starts from: the region's from the candidates (start_face()), the
    // faces beyond keep what they came to. A run that must be redone sets back what it changed.
    PointSlots slots = previous.accepted;
    auto set_back = [&](const std::vector<Index>& faces) {
        for (Index f : faces) {
            for (int k = 0; k < 4; ++k) slots.set_slot(f, k, previous.accepted.slot(f, k));
        }
    };
    auto guard_region = [&](const std::vector<Index>& region) {
        std::vector<Index> first;
        for (Index f : region) {
            start_face(candidates, withdrawn, f, slots, f);
            if (slots.has_points(f)) first.push_back(f);
        }
        std::vector<GuardRepair> kept;
        for (const GuardRepair& r : previous.repairs) {
            if (!region_flags.in_region[r.face]) kept.push_back(r);
        }
        return guard_slots(input, feature_normals, candidates, withdrawn, std::move(slots), first,
                           std::move(kept), options, flags);
    };
    // Guarded again until the run leaves the border alone, each time searched across the
    // border faces it did not leave alone and the faces within 2^run - 1 steps beyond them: a
    // cascade of repairs along a band moves the border a face or two a run (impeller's went on
    // past 16 runs one face at a time), so the region grows the more the more runs it took
    // (impeller's: 8 runs, 444 faces, where every face searched across made 5,874). After
    // kRegionRuns, with every face searched across, which stops at no border. A run
    // costs what its region holds (the flags and slots are set back through lists), not the
    // mesh. Bound: kRegionRuns + 1 runs.
    constexpr int kRegionRuns = 8;
    for (int run = 0;; ++run) {
        if (run == kRegionRuns) {
            std::fill(region_flags.expand_anyway.begin(), region_flags.expand_anyway.end(), 1);
        }
        const std::vector<Index> region =
            faces_to_guard_again(input.connectivity, candidates, previous, withdrawn_before,
                                 withdrawn, holders, reshaped, region_flags);
        GuardedPoints out = guard_region(region);
        std::vector<Index> disturbed;  // border faces the run did not leave alone
        for (const GuardRepair& r : out.repairs) {
            if (region_flags.is_border[r.face]) disturbed.push_back(r.face);
        }
        for (Index f : region) {
            if (region_flags.is_border[f] && !out.accepted.same_at(f, previous.accepted, f)) {
                disturbed.push_back(f);
            }
        }
        const bool border_left_alone = disturbed.empty();
        if (border_left_alone) return out;
        expand_beyond(input.connectivity, candidates, withdrawn_before, std::move(disturbed),
                      (1 << run) - 1, region_flags);
        slots = std::move(out.accepted);
        set_back(region);
        set_back(flags.touched_faces);
        flags.clear();
        region_flags.clear(region);
    }
}

}  // namespace resharp
