#include "resharp/restoration/split.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <numbers>
#include <span>

#include "resharp/mesh/geometry.h"
#include "resharp/restoration/clearance.h"

namespace resharp {
namespace {

/// Vertex ids of the split: below `original_count` an input vertex, above it new point
/// `id - original_count`.
class SplitVertices {
public:
    SplitVertices(const Mesh& mesh, const SharpPoints& points)
        : mesh_(mesh), points_(points), original_count_(static_cast<Index>(mesh.vertex_count())) {}

    bool is_original(Index id) const { return id < original_count_; }
    Index of_point(Index point) const { return original_count_ + point; }
    const Vec3& position(Index id) const {
        return is_original(id) ? mesh_.positions[id] : points_.points[id - original_count_];
    }

private:
    const Mesh& mesh_;
    const SharpPoints& points_;
    Index original_count_;
};

/// A face's boundary after insertion: its corners with the edge points between them.
struct FacePolygon {
    std::array<Index, 6> ids{};
    int size = 0;
    void push(Index id) { ids[static_cast<std::size_t>(size++)] = id; }
    Index at(int i) const { return ids[static_cast<std::size_t>((i + size) % size)]; }
};

bool has_points(const SharpPoints& p, Index f) {
    return p.corner_point[f] != kNoIndex || p.edge_point[3 * f] != kNoIndex ||
           p.edge_point[3 * f + 1] != kNoIndex || p.edge_point[3 * f + 2] != kNoIndex;
}

FacePolygon boundary_of(const Mesh& mesh, const SharpPoints& p, const SplitVertices& ids, Index f) {
    FacePolygon polygon;
    for (Index k = 0; k < 3; ++k) {
        polygon.push(mesh.triangles[f][k]);
        if (p.edge_point[3 * f + k] != kNoIndex)
            polygon.push(ids.of_point(p.edge_point[3 * f + k]));
    }
    return polygon;
}

/// Shape quality of a triangle, 1 for equilateral and 0 for degenerate: 4 sqrt(3) area over
/// the sum of squared edge lengths. Ranks triangles like their smallest angle, without
/// trigonometry.
double shape_quality(const SplitVertices& ids, Index a, Index b, Index c) {
    const Vec3 &pa = ids.position(a), &pb = ids.position(b), &pc = ids.position(c);
    const double edges =
        (pb - pa).squaredNorm() + (pc - pb).squaredNorm() + (pa - pc).squaredNorm();
    if (edges == 0.0) return 0.0;
    return 2.0 * std::sqrt(3.0) * (pb - pa).cross(pc - pa).norm() / edges;
}

/// Relative area below which a piece counts as collapsed: far below any real triangle of a
/// grid mesh, far above rounding noise.
constexpr double kCollapsedAreaRatio = 1e-12;

double sin_deg(double degrees) { return std::sin(degrees * std::numbers::pi / 180.0); }

/// The normal a piece at an input vertex must agree with, and how far (degrees) that normal
/// may be off the true surface: the piece must face within 90 degrees less that margin of it.
struct Reference {
    const Vec3& normal;
    double margin_deg;
};

/// The vertex's feature normal, trusted to within its fit correction: on a curved feature the
/// estimate is that much off, and a piece standing almost on edge to it may lean past the true
/// surface (on planes the correction is zero). Where a vertex has no feature normal (all its
/// faces lie in bands), its plain vertex normal, which leans towards the band by up to half
/// the edge's angle: a piece must face within 60 degrees of it.
struct ReferenceNormals {
    const FeatureNormals& feature;
    const std::vector<Vec3>& vertex;
    Reference at(Index v) const {
        if (feature.normal[v].isZero(0.0)) return {vertex[v], 30.0};
        return {feature.normal[v], std::min<double>(feature.fit_correction_deg[v], 30.0)};
    }
};

/// Why a piece may not be emitted, in the order the checks run.
enum class Fault {
    None,
    Quality,  ///< collapsed, or turned against its vertices' reference normals
    Guard,    ///< turned against the face it replaces, too close to flipping across thin
              ///< material, or meeting another triangle (see docs/method.md, "The guard")
};

/// Judges single pieces of a split face by their normals (the intersection check is
/// Clearance's).
class PieceJudge {
public:
    PieceJudge(const Mesh& mesh, const std::vector<Vec3>& face_normals,
               const ReferenceNormals& reference, const SplitVertices& ids, double spike_angle_deg)
        : mesh_(mesh),
          face_normals_(face_normals),
          reference_(reference),
          ids_(ids),
          thin_cosine_(std::cos(spike_angle_deg * std::numbers::pi / 180.0)) {}

    const SplitVertices& ids() const { return ids_; }

    /// Piece (a, b, c) of face f:
    /// - Quality: it has no area, or turns against the reference normal of an input vertex;
    /// - Guard: it turns against face f although f itself is sound at the piece's input
    ///   vertices (the paper's §5.3 flip: M' projects outside the face it is derived from;
    ///   only where f leans past a vertex's surface may pieces rightly turn from f), or it
    ///   joins vertices whose references differ by more than the spike angle (material too
    ///   thin for the mesh) and does not clear each of them by twice its margin: there the
    ///   piece stands almost on edge to both surfaces, and an error in either normal flips it.
    Fault fault(Index f, Index a, Index b, Index c) const {
        const Vec3 n =
            (ids_.position(b) - ids_.position(a)).cross(ids_.position(c) - ids_.position(a));
        if (n.norm() <= kCollapsedAreaRatio * longest_edge_squared(f)) return Fault::Quality;
        const bool thin = spans_thin_material(a, b, c);
        const Vec3& face_normal = face_normals_[f];
        bool face_leans_past_surface = false;
        Fault found = Fault::None;
        for (Index v : {a, b, c}) {
            if (!ids_.is_original(v)) continue;
            const Reference r = reference_.at(v);
            if (r.normal.isZero(0.0)) continue;
            const double min_cosine = sin_deg(r.margin_deg);
            if (n.dot(r.normal) <= min_cosine * n.norm()) return Fault::Quality;
            if (thin && n.dot(r.normal) <= sin_deg(std::min(2.0 * r.margin_deg, 89.0)) * n.norm()) {
                found = Fault::Guard;
            }
            face_leans_past_surface =
                face_leans_past_surface || face_normal.dot(r.normal) <= min_cosine;
        }
        if (!face_leans_past_surface && n.dot(face_normal) <= 0.0) return Fault::Guard;
        return found;
    }

private:
    double longest_edge_squared(Index f) const {
        const Triangle& t = mesh_.triangles[f];
        double longest = 0.0;
        for (int k = 0; k < 3; ++k) {
            longest = std::max(
                longest, (mesh_.positions[t[(k + 1) % 3]] - mesh_.positions[t[k]]).squaredNorm());
        }
        return longest;
    }

    bool spans_thin_material(Index a, Index b, Index c) const {
        const std::array<Index, 3> v{a, b, c};
        for (int i = 0; i < 3; ++i) {
            for (int j = i + 1; j < 3; ++j) {
                if (!ids_.is_original(v[i]) || !ids_.is_original(v[j])) continue;
                if (reference_.at(v[i]).normal.dot(reference_.at(v[j]).normal) < thin_cosine_)
                    return true;
            }
        }
        return false;
    }

    const Mesh& mesh_;
    const std::vector<Vec3>& face_normals_;
    const ReferenceNormals& reference_;
    const SplitVertices& ids_;
    double thin_cosine_;
};

/// Emits the pieces of face f, counter-clockwise like the face. With a corner point: a fan
/// around it (Fig. 7b). Otherwise: an ear at each corner whose two edges were split (it lies on
/// one feature, cut off by the new sharp edge), then the rest as one triangle or a quad split
/// along the diagonal that gives the better-shaped worse triangle, never along an original edge.
template <class Emit>
void emit_pieces(const Mesh& mesh, const SharpPoints& p, const SplitVertices& ids, Index f,
                 Emit&& emit) {
    const FacePolygon polygon = boundary_of(mesh, p, ids, f);
    if (p.corner_point[f] != kNoIndex) {
        // An edge split at the corner point itself (see repair_face) leaves its two pieces empty.
        const Index centre = ids.of_point(p.corner_point[f]);
        for (int i = 0; i < polygon.size; ++i) {
            if (polygon.at(i) != centre && polygon.at(i + 1) != centre) {
                emit(polygon.at(i), polygon.at(i + 1), centre);
            }
        }
        return;
    }
    FacePolygon rest;
    for (int i = 0; i < polygon.size; ++i) {
        const Index id = polygon.at(i);
        if (ids.is_original(id) && !ids.is_original(polygon.at(i - 1)) &&
            !ids.is_original(polygon.at(i + 1))) {
            emit(polygon.at(i - 1), id, polygon.at(i + 1));
        } else {
            rest.push(id);
        }
    }
    if (rest.size == 3) {
        emit(rest.at(0), rest.at(1), rest.at(2));
        return;
    }
    const bool may_use_02 = !(ids.is_original(rest.at(0)) && ids.is_original(rest.at(2)));
    const bool may_use_13 = !(ids.is_original(rest.at(1)) && ids.is_original(rest.at(3)));
    const double quality_02 = std::min(shape_quality(ids, rest.at(0), rest.at(1), rest.at(2)),
                                       shape_quality(ids, rest.at(0), rest.at(2), rest.at(3)));
    const double quality_13 = std::min(shape_quality(ids, rest.at(1), rest.at(2), rest.at(3)),
                                       shape_quality(ids, rest.at(1), rest.at(3), rest.at(0)));
    if (may_use_02 && (!may_use_13 || quality_02 >= quality_13)) {
        emit(rest.at(0), rest.at(1), rest.at(2));
        emit(rest.at(0), rest.at(2), rest.at(3));
    } else {
        emit(rest.at(1), rest.at(2), rest.at(3));
        emit(rest.at(1), rest.at(3), rest.at(0));
    }
}

/// Tolerance of the intersection test relative to the face's size: far below any feature of a
/// grid mesh, far above rounding in coordinates of a part (see clearance.h).
constexpr double kTouchRatio = 1e-9;

/// A piece as the clearance check keeps it: its vertex ids and unit normal.
struct StoredPiece {
    Triangle id{};
    Vec3 n;
};

/// The pieces of one face with their normals (at most six: a fan around a corner point in a
/// hexagon).
struct Pieces {
    std::array<StoredPiece, 6> piece{};
    int size = 0;
};

/// Keeps the pieces of every touched face (a face with points at the start) clear of the
/// triangles near them: the other pieces of the face, unsplit faces and other faces' pieces.
/// Holds the current pieces of all touched faces, refreshed as points are dropped; a face's
/// pieces always lie in the box of the face and its starting points, so the nearby faces found
/// once stay a complete list.
class Clearance {
public:
    Clearance(const Mesh& mesh, const Connectivity& connectivity,
              const std::vector<Vec3>& face_normals, const SharpPoints& p, const PieceJudge& judge,
              std::span<const Index> touched)
        : mesh_(mesh),
          face_normals_(face_normals),
          p_(p),
          judge_(judge),
          number_(numbers_of(mesh, touched)),
          pieces_(touched.size()),
          nearby_(mesh, connectivity, touched, number_, describe(touched)) {
        tbb::parallel_for(std::size_t{0}, touched.size(),
                          [&](std::size_t i) { refresh(touched[i]); });
    }

    /// The faces whose boxes meet touched face f's.
    std::span<const Index> nearby(Index f) const { return nearby_.of(number_[f]); }
    bool is_touched(Index f) const { return number_[f] != kNoIndex; }

    /// Call after f's points changed.
    void refresh(Index f) { pieces_[number_[f]] = current_pieces(f); }

    /// Whether the pieces f would be cut into now meet nothing. With `later_only`, pieces of
    /// touched faces before f are skipped (when every touched face is checked, each pair once).
    bool is_clear(Index f, bool later_only = false) const {
        return is_clear(f, current_pieces(f), later_only);
    }
    /// As is_clear, with f's stored pieces (equal to its current ones after refresh(f)).
    bool stored_pieces_are_clear(Index f, bool later_only) const {
        return is_clear(f, pieces_[number_[f]], later_only);
    }

private:
    Pieces current_pieces(Index f) const {
        Pieces out;
        emit_pieces(mesh_, p_, judge_.ids(), f, [&](Index a, Index b, Index c) {
            const IdTriangle t = triangle_of(Triangle{a, b, c});
            out.piece[static_cast<std::size_t>(out.size++)] = {t.id, t.n};
        });
        return out;
    }

    bool is_clear(Index f, const Pieces& mine, bool later_only) const {
        std::array<IdTriangle, 6> own;
        for (int i = 0; i < mine.size; ++i) own[i] = triangle_of(mine.piece[i]);
        const double tolerance = this->tolerance(f);
        for (int i = 0; i < mine.size; ++i) {
            for (int j = i + 1; j < mine.size; ++j) {
                if (triangles_meet(own[i], own[j], tolerance)) return false;
            }
        }
        for (Index g : nearby(f)) {
            const bool split = is_touched(g) && has_points(p_, g);
            if (split && later_only && g < f) continue;
            auto meets_own = [&](const IdTriangle& other) {
                for (int i = 0; i < mine.size; ++i) {
                    if (triangles_meet(own[i], other, tolerance)) return true;
                }
                return false;
            };
            if (!split) {
                const Triangle& t = mesh_.triangles[g];
                if (meets_own(IdTriangle::make(t, mesh_.positions[t[0]], mesh_.positions[t[1]],
                                               mesh_.positions[t[2]], face_normals_[g]))) {
                    return false;
                }
                continue;
            }
            const Pieces& theirs = pieces_[number_[g]];
            for (int k = 0; k < theirs.size; ++k) {
                if (meets_own(triangle_of(theirs.piece[k]))) return false;
            }
        }
        return true;
    }

    static std::vector<Index> numbers_of(const Mesh& mesh, std::span<const Index> touched) {
        std::vector<Index> number(mesh.face_count(), kNoIndex);
        for (std::size_t i = 0; i < touched.size(); ++i) number[touched[i]] = static_cast<Index>(i);
        return number;
    }
    IdTriangle triangle_of(const Triangle& t) const {
        const SplitVertices& ids = judge_.ids();
        return IdTriangle::make(t, ids.position(t[0]), ids.position(t[1]), ids.position(t[2]));
    }
    IdTriangle triangle_of(const StoredPiece& piece) const {
        const SplitVertices& ids = judge_.ids();
        const Triangle& t = piece.id;
        return IdTriangle::make(t, ids.position(t[0]), ids.position(t[1]), ids.position(t[2]),
                                piece.n);
    }
    Box3 hull_box(Index f) const {
        Box3 box;
        for (Index v : mesh_.triangles[f]) box.extend(mesh_.positions[v]);
        for_each_point(f, [&](const Vec3& x) { box.extend(x); });
        return box;
    }
    double tolerance(Index f) const {
        return kTouchRatio * std::sqrt(hull_box(f).sizes().squaredNorm());
    }
    std::vector<TouchedFace> describe(std::span<const Index> touched) const {
        std::vector<TouchedFace> faces(touched.size());
        tbb::parallel_for(std::size_t{0}, touched.size(),
                          [&](std::size_t i) { faces[i] = describe_face(touched[i]); });
        return faces;
    }
    /// Its box and, when all its points lie clearly to one side of its plane, that plane.
    TouchedFace describe_face(Index f) const {
        TouchedFace face{hull_box(f), Vec3::Zero(), 0.0, tolerance(f)};
        const Vec3& n = face_normals_[f];
        const double offset = n.dot(mesh_.positions[mesh_.triangles[f][0]]);
        int above = 0, below = 0, count = 0;
        for_each_point(f, [&](const Vec3& x) {
            const double height = n.dot(x) - offset;
            above += height > face.tolerance;
            below += height < -face.tolerance;
            ++count;
        });
        if (above == count) {
            face.cap_normal = n;
            face.cap_offset = offset;
        } else if (below == count) {
            face.cap_normal = -n;
            face.cap_offset = -offset;
        }
        return face;
    }
    template <class Visit>
    void for_each_point(Index f, Visit&& visit) const {
        for (int k = 0; k < 3; ++k) {
            if (p_.edge_point[3 * f + k] != kNoIndex) visit(p_.points[p_.edge_point[3 * f + k]]);
        }
        if (p_.corner_point[f] != kNoIndex) visit(p_.points[p_.corner_point[f]]);
    }

    const Mesh& mesh_;
    const std::vector<Vec3>& face_normals_;
    const SharpPoints& p_;
    const PieceJudge& judge_;
    std::vector<Index> number_;  ///< per face (#F): its number among the touched faces, or kNoIndex
    std::vector<Pieces> pieces_;
    NearbyFaces nearby_;
};

/// The slots of face f that may hold a point: its three half-edges and its corner.
struct PointSlots {
    std::array<Index*, 4> slot{};
    std::array<Index*, 4> twin_slot{};  ///< the same edge point seen from the other face
};

PointSlots slots_of(const Connectivity& c, SharpPoints& p, Index f) {
    PointSlots s;
    for (Index k = 0; k < 3; ++k) {
        const Index h = 3 * f + k;
        s.slot[k] = &p.edge_point[h];
        s.twin_slot[k] = c.twin[h] != kNoIndex ? &p.edge_point[c.twin[h]] : nullptr;
    }
    s.slot[3] = &p.corner_point[f];
    return s;
}

void clear_slot(const PointSlots& s, int i) {
    *s.slot[i] = kNoIndex;
    if (s.twin_slot[i] != nullptr) *s.twin_slot[i] = kNoIndex;
}

/// Tries `replacement` in slot i of face f; keeps it (on both faces of the edge) if the face
/// then splits without fault.
template <class IsSound>
bool try_slot(Index f, const PointSlots& s, int i, Index replacement, const IsSound& is_sound) {
    const Index kept = *s.slot[i];
    *s.slot[i] = replacement;
    const bool sound = is_sound(f);
    *s.slot[i] = kept;
    if (!sound) return false;
    *s.slot[i] = replacement;
    if (s.twin_slot[i] != nullptr) *s.twin_slot[i] = replacement;
    return true;
}

/// Makes face f split soundly by changing as little as possible, in this order:
/// - drop a single point (the first that is enough, in slot order): two close points out of
///   order along the sharp edge make a flipped sliver, and the one kept still restores the edge;
/// - in a corner triangle, split one edge at the corner point instead of its own point: where a
///   sharp edge ends at a corner, eq. 5.2 can put the point beyond the corner on the edge's
///   extension, and the corner is where that edge really stops;
/// - drop every point of the face.
/// Returns the number of points dropped.
template <class IsSound>
std::size_t repair_face(const Connectivity& c, SharpPoints& p, Index f, const IsSound& is_sound) {
    const PointSlots s = slots_of(c, p, f);
    for (int i = 0; i < 4; ++i) {
        if (*s.slot[i] != kNoIndex && try_slot(f, s, i, kNoIndex, is_sound)) return 1;
    }
    const Index corner = p.corner_point[f];
    const bool has_snapped_edge =
        *s.slot[0] == corner || *s.slot[1] == corner || *s.slot[2] == corner;
    for (int i = 0; i < 3 && corner != kNoIndex && !has_snapped_edge; ++i) {
        if (*s.slot[i] != kNoIndex && try_slot(f, s, i, corner, is_sound)) return 1;
    }
    std::size_t dropped = 0;
    for (int i = 0; i < 4; ++i) {
        if (*s.slot[i] == kNoIndex) continue;
        clear_slot(s, i);
        ++dropped;
    }
    return dropped;
}

std::vector<Index> faces_with_points(const Mesh& mesh, const SharpPoints& p) {
    std::vector<Index> faces;
    for (Index f = 0; f < mesh.face_count(); ++f) {
        if (has_points(p, f)) faces.push_back(f);
    }
    return faces;
}

/// Points dropped so that every split is sound, by the first fault that made a face drop them.
struct Dropped {
    std::size_t quality = 0;
    std::size_t guard = 0;
};

/// Faces with a point that need a check, and the faces to check again after a repair. Each
/// face is queued at most once at a time; a face's verdict computed up front stands until the
/// face is queued again.
class Worklist {
public:
    Worklist(std::size_t face_count, std::span<const Index> first)
        : faces_(first.begin(), first.end()), queued_(face_count, 0) {
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
    std::vector<std::uint8_t> queued_;
    std::size_t next_ = 0;
};

void queue_faces_across(const Connectivity& c, Index f, Worklist& work) {
    for (Index k = 0; k < 3; ++k) {
        const Index twin = c.twin[3 * f + k];
        if (twin != kNoIndex) work.push(face_of(twin));
    }
}

/// Repairs faces until every face with points splits with pieces the judge accepts. A
/// worklist holds the faces to check: first all faces with points, then, after a repair, the
/// faces across its edges, whose split changed too. Repairs only drop points or move an edge's
/// point onto a corner point once, so it ends.
void drop_points_of_faulty_pieces(const Mesh& mesh, const Connectivity& c, const PieceJudge& judge,
                                  std::span<const Index> touched, SharpPoints& p,
                                  Dropped& dropped) {
    auto fault_of = [&](Index f) {
        Fault worst = Fault::None;
        emit_pieces(mesh, p, judge.ids(), f, [&](Index a, Index b, Index cc) {
            const Fault fault = judge.fault(f, a, b, cc);
            if (worst == Fault::None || fault == Fault::Quality) worst = fault;
        });
        return worst;
    };
    auto is_sound = [&](Index f) { return fault_of(f) == Fault::None; };
    Worklist work(mesh.face_count(), touched);
    while (!work.empty()) {
        const Index f = work.pop();
        if (!has_points(p, f)) continue;
        const Fault fault = fault_of(f);
        if (fault == Fault::None) continue;
        (fault == Fault::Quality ? dropped.quality : dropped.guard) +=
            repair_face(c, p, f, is_sound);
        queue_faces_across(c, f, work);
    }
}

/// Then the same repair until no piece meets another triangle. All faces are first checked
/// in parallel; after a repair, the faces whose split changed (the face and those across its
/// edges) and the faces near them are checked again, since they were checked against the
/// pieces that changed.
void drop_points_of_meeting_pieces(const Mesh& mesh, const Connectivity& c,
                                   const std::vector<Vec3>& face_normals, const PieceJudge& judge,
                                   std::span<const Index> first_touched, SharpPoints& p,
                                   Dropped& dropped) {
    std::vector<Index> touched;
    std::copy_if(first_touched.begin(), first_touched.end(), std::back_inserter(touched),
                 [&](Index f) { return has_points(p, f); });
    Clearance clearance(mesh, c, face_normals, p, judge, touched);
    std::vector<std::uint8_t> verdict_is_current(mesh.face_count(), 0),
        first_clear(mesh.face_count(), 0);
    tbb::parallel_for(std::size_t{0}, touched.size(), [&](std::size_t i) {
        first_clear[touched[i]] = clearance.stored_pieces_are_clear(touched[i], true);
        verdict_is_current[touched[i]] = 1;
    });
    auto is_sound = [&](Index f) {
        bool sound = true;
        emit_pieces(mesh, p, judge.ids(), f, [&](Index a, Index b, Index cc) {
            sound = sound && judge.fault(f, a, b, cc) == Fault::None;
        });
        return sound && clearance.is_clear(f);
    };
    Worklist work(mesh.face_count(), touched);
    auto recheck = [&](Index g) {
        verdict_is_current[g] = 0;
        work.push(g);
    };
    while (!work.empty()) {
        const Index f = work.pop();
        if (!has_points(p, f)) continue;
        const bool clear =
            verdict_is_current[f] ? first_clear[f] : clearance.stored_pieces_are_clear(f, false);
        verdict_is_current[f] = 0;
        if (clear) continue;
        dropped.guard += repair_face(c, p, f, is_sound);
        std::array<Index, 4> changed{f, kNoIndex, kNoIndex, kNoIndex};
        for (Index k = 0; k < 3; ++k) {
            const Index twin = c.twin[3 * f + k];
            if (twin != kNoIndex && clearance.is_touched(face_of(twin)))
                changed[k + 1] = face_of(twin);
        }
        for (Index g : changed) {
            if (g == kNoIndex) continue;
            clearance.refresh(g);
            recheck(g);
            for (Index near : clearance.nearby(g)) {
                if (clearance.is_touched(near)) recheck(near);
            }
        }
    }
}

/// Output index of each surviving point, in points order.
std::vector<Index> number_surviving_points(const SharpPoints& p, Index first) {
    std::vector<std::uint8_t> used(p.points.size(), 0);
    for (Index id : p.edge_point)
        if (id != kNoIndex) used[id] = 1;
    for (Index id : p.corner_point)
        if (id != kNoIndex) used[id] = 1;
    std::vector<Index> number(p.points.size(), kNoIndex);
    for (std::size_t i = 0; i < used.size(); ++i) {
        if (used[i]) number[i] = first++;
    }
    return number;
}

}  // namespace

Mesh split_band_triangles(const Mesh& mesh, const Connectivity& connectivity,
                          const std::vector<Vec3>& face_normals,
                          const FeatureNormals& feature_normals,
                          const std::vector<Vec3>& vertex_normals, SharpPoints& points,
                          SplitReport& report, std::vector<Index>& source_face,
                          const SplitOptions& options) {
    const SplitVertices ids(mesh, points);
    const ReferenceNormals reference{feature_normals, vertex_normals};
    const PieceJudge judge(mesh, face_normals, reference, ids, options.spike_angle_deg);
    const std::vector<Index> touched = faces_with_points(mesh, points);
    Dropped dropped;
    drop_points_of_faulty_pieces(mesh, connectivity, judge, touched, points, dropped);
    if (options.check_clearance) {
        drop_points_of_meeting_pieces(mesh, connectivity, face_normals, judge, touched, points,
                                      dropped);
    }
    report.refused_by_quality = dropped.quality;
    report.refused_by_guard = dropped.guard;

    const Index original_count = static_cast<Index>(mesh.vertex_count());
    const std::vector<Index> number = number_surviving_points(points, original_count);
    Mesh out;
    out.positions = mesh.positions;
    for (std::size_t i = 0; i < number.size(); ++i) {
        if (number[i] != kNoIndex) out.positions.push_back(points.points[i]);
    }
    report.new_vertices = out.positions.size() - mesh.vertex_count();

    auto output_id = [&](Index id) {
        return ids.is_original(id) ? id : number[id - original_count];
    };
    out.triangles.reserve(mesh.face_count() + 4 * report.new_vertices);
    source_face.clear();
    source_face.reserve(out.triangles.capacity());
    for (Index f = 0; f < mesh.face_count(); ++f) {
        if (!has_points(points, f)) {
            out.triangles.push_back(mesh.triangles[f]);
            source_face.push_back(f);
            continue;
        }
        ++report.split_faces;
        emit_pieces(mesh, points, ids, f, [&](Index a, Index b, Index c) {
            out.triangles.push_back({output_id(a), output_id(b), output_id(c)});
            source_face.push_back(f);
        });
    }
    report.output_faces = out.triangles.size();
    return out;
}

}  // namespace resharp
