#pragma once
/// New points on the ideal sharp edges and corners (paper §5.2-5.3): one per crossing edge where
/// the two sides' surfaces meet, one per corner triangle where three meet, each kept only if it
/// passes the flip test (eq. 5.4-5.5) or the spike test. The sides' surfaces are their tangent
/// planes (eq. 5.2, 5.3) or their second-order fits (surfaces/local_quadric.h), which meet on a
/// curved edge where the planes meet off it.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/mesh.h"
#include "resharp/restoration/band_classification.h"
#include "resharp/restoration/feature_normals.h"

namespace resharp {

/// Which surfaces of the band's sides a new point lies on.
enum class PointPlacement {
    /// Eq. 5.2 / 5.3: the feature's tangent planes at the band vertices (the paper).
    TangentPlanes,
    /// The features' second-order surfaces (FeatureNormals::field) at the band vertices,
    /// met by Newton's method from the tangent planes' point; that point where they do not meet
    /// within a crossing edge's length of it. Where eq. 5.4 fails (the point lies beyond the
    /// crossing edge's chord) the point goes inside the face of the edge that holds it instead
    /// of being refused (docs/method.md, "Second-order placement").
    SecondOrder,
};

struct SharpPointOptions {
    PointPlacement placement = PointPlacement::SecondOrder;
    /// §5.3: a corner point is refused when two of the normals around the corner triangle
    /// differ by more than this (degrees): nearly opposite normals make a spike.
    double spike_angle_deg = 150.0;
    /// The spike test on crossing edges (our addition): a point is refused where the normals of
    /// the edge's ends differ by more than this (degrees). 180: none is (the paper, and exact
    /// meshes). restore() asks kNearEdgeSpikeAngleDeg on meshes whose vertices lie near the
    /// surface, not on it.
    double edge_spike_angle_deg = 180.0;
};

/// SharpPointOptions::edge_spike_angle_deg on near-surface and midpoint meshes. A blade whose
/// faces turn by more than this (a wedge under 45 degrees) is thinner than a cell for more than
/// a cell back from its tip; a mesher that puts vertices up to a cell off the surface may put
/// them there on either face, and the pieces cut at points between them faced the other side
/// (impeller by OpenVDB: 62 pieces turned against the exact surface, along two such blades; 0
/// with the test, and 0.004 of its Edge F-score less).
inline constexpr double kNearEdgeSpikeAngleDeg = 135.0;

/// Which point, if any, each place of the mesh that can hold one holds: the crossing edges
/// and the corner triangles. Point numbers index a point list kept beside it (SharpPoints).
/// Only faces that were ever given a point keep slots (the bands, a few percent of the faces):
/// four slots for every face cost 16 bytes per input triangle for each set of slots alive, and
/// the placement and the guard keep one each (the peak-memory budget).
class PointSlots {
public:
    PointSlots() = default;
    /// Empty slots for `face_count` faces.
    explicit PointSlots(std::size_t face_count) : row_of_face_(face_count, kNoIndex) {}

    std::size_t face_count() const { return row_of_face_.size(); }
    /// How many faces keep slots: those ever given a point (the memory it holds).
    std::size_t faces_with_slots() const { return rows_.size(); }
    /// Slot k of face f: the point on its half-edge 3f + k (k < 3), then the point inside it
    /// (k = 3); kNoIndex where there is none.
    Index slot(Index f, int k) const {
        const Index row = row_of_face_[f];
        return row == kNoIndex ? kNoIndex : rows_[row][static_cast<std::size_t>(k)];
    }
    /// Sets slot k of face f alone (not the twin half-edge's).
    void set_slot(Index f, int k, Index point) {
        Index& row = row_of_face_[f];
        if (row == kNoIndex) {
            if (point == kNoIndex) return;
            row = static_cast<Index>(rows_.size());
            rows_.push_back({kNoIndex, kNoIndex, kNoIndex, kNoIndex});
        }
        rows_[row][static_cast<std::size_t>(k)] = point;
    }
    /// The point of half-edge h: on both half-edges of a crossing edge that has one.
    Index edge_point(Index h) const { return slot(h / 3, static_cast<int>(h % 3)); }
    void set_edge_point(Index h, Index point) { set_slot(h / 3, static_cast<int>(h % 3), point); }
    /// The point inside face f: a corner triangle's corner point, or the point of a crossing
    /// edge of the face that lies beyond the edge's chord over it.
    Index corner_point(Index f) const { return slot(f, 3); }
    void set_corner_point(Index f, Index point) { set_slot(f, 3, point); }

    /// True when face f has a point on one of its edges or inside it.
    bool has_points(Index f) const {
        const Index row = row_of_face_[f];
        if (row == kNoIndex) return false;
        const std::array<Index, 4>& r = rows_[row];
        return r[0] != kNoIndex || r[1] != kNoIndex || r[2] != kNoIndex || r[3] != kNoIndex;
    }
    /// Calls visit(point) for each slot of face f that holds one: its three edges, then its
    /// corner (an edge snapped onto the corner point is visited twice).
    template <class Visit>
    void for_each_point(Index f, Visit&& visit) const {
        const Index row = row_of_face_[f];
        if (row == kNoIndex) return;
        for (Index p : rows_[row]) {
            if (p != kNoIndex) visit(p);
        }
    }
    /// Empties every slot whose point `drop` takes.
    template <class Drop>
    void empty_slots_of(Drop&& drop) {
        for (std::array<Index, 4>& row : rows_) {
            for (Index& p : row) {
                if (p != kNoIndex && drop(p)) p = kNoIndex;
            }
        }
    }
    /// Whether face f holds here what face g holds in `other`.
    bool same_at(Index f, const PointSlots& other, Index g) const {
        for (int k = 0; k < 4; ++k) {
            if (slot(f, k) != other.slot(g, k)) return false;
        }
        return true;
    }
    /// The same points in the same slots of the same number of faces.
    friend bool operator==(const PointSlots& a, const PointSlots& b) {
        if (a.face_count() != b.face_count()) return false;
        for (Index f = 0; f < a.face_count(); ++f) {
            if (!a.same_at(f, b, f)) return false;
        }
        return true;
    }

private:
    std::vector<Index> row_of_face_;  ///< per face (#F): its row of slots, or kNoIndex: none
    std::vector<std::array<Index, 4>> rows_;  ///< slots 0..3 of the faces that have a row
};

struct SharpPoints {
    /// The new points: points on crossing edges in face order, then points of crossing edges
    /// inside faces in sweep order of their edges, then corner points in face order.
    std::vector<Vec3> points;
    PointSlots slots;  ///< where each point goes
    /// Points of crossing edges, the first `edge_points` of `points`; with those put inside a
    /// face of their edge (`face_points` of them, in the face's corner_point slot).
    std::size_t edge_points = 0;
    std::size_t face_points = 0;
    std::size_t corner_points = 0;
    /// crossing edges failing eq. 5.4 (incl. parallel normals), with second-order placement
    /// only those whose point no face of the edge holds
    std::size_t refused_by_flip_test = 0;
    /// Crossing edges and corner triangles failing the spike test.
    std::size_t refused_by_spike_test = 0;
    std::size_t missing_normal = 0;  ///< crossing edges or corners with an unknown normal
    /// Points placed on the tangent planes because the second-order surfaces did not meet near
    /// them (PointPlacement::SecondOrder only).
    std::size_t first_order_fallbacks = 0;
};

/// Eq. 5.2: the point on both tangent planes (a, n_a) and (b, n_b) and on the plane through
/// (a + b) / 2 normal to n_a x n_b; nullopt when the normals are parallel.
std::optional<Vec3> edge_point(const Vec3& a, const Vec3& n_a, const Vec3& b, const Vec3& n_b);

/// Eq. 5.4-5.5: true when the chamfer edge a-b runs between the two planes' traces in the
/// section normal to the edge, i.e. the new point lies between a and b and the split triangles
/// keep their orientation.
bool passes_flip_test(const Vec3& a, const Vec3& n_a, const Vec3& b, const Vec3& n_b);

/// Eq. 5.3: the common point of the three tangent planes; nullopt when they do not meet in
/// one point.
std::optional<Vec3> corner_point(const Vec3& a, const Vec3& n_a, const Vec3& b, const Vec3& n_b,
                                 const Vec3& c, const Vec3& n_c);

/// Takes the classification and the feature normals and their fields (#V) and gives the accepted
/// points. A corner point also goes on each crossing edge of its corner triangle that has no
/// point and that it lies beyond (docs/method.md, "Corner points beyond an edge without a
/// point"), in both half-edges' slots, as the guard's snapping puts it.
/// \throws InvalidInput if an option is out of range.
SharpPoints place_sharp_points(const Mesh& mesh, const Connectivity& connectivity,
                               const std::vector<Vec3>& face_normals,
                               const BandClassification& bands,
                               const FeatureNormals& feature_normals,
                               const SharpPointOptions& options = {});

}  // namespace resharp
