#pragma once
/// Feature normals at the vertices of edge and corner triangles (paper §5.1, eq. 5.1).

#include <vector>

#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/mesh.h"
#include "resharp/restoration/band_classification.h"

namespace resharp {

/// How the normal of a band vertex's own feature is estimated.
enum class NormalEstimate {
    /// Eq. 5.1: the angle-weighted mean of the vertex's faces on its feature (the paper).
    AngleWeighted,
    /// A linear fit of the feature's face normals around the vertex (its faces and its
    /// same-feature neighbours' faces), evaluated at the vertex. Those faces all lie on one side
    /// of a band vertex, so on a curved feature their mean is the normal half a face inward;
    /// the fit extrapolates to the vertex itself. Exact on planes, as eq. 5.1.
    LinearFit,
};

struct FeatureNormalOptions {
    NormalEstimate estimate = NormalEstimate::LinearFit;
    /// A fitted normal further than this (degrees) from eq. 5.1's is not trusted; eq. 5.1's is
    /// used instead.
    double max_fit_correction_deg = 15.0;
    /// Faces whose normal lies further than this (degrees) from the first fit are left out and
    /// the fit is repeated once. The normals of one ball-end pass are linear in position (a
    /// sphere's normal is (x - c) / r), so on a single pass the residuals are tiny; faces beyond
    /// a scallop cusp that region growing let into the patch are not, and would tilt the fit.
    /// 180 keeps every face.
    double max_fit_residual_deg = 1.4;
    /// Where the feature's own faces cannot be fitted (a patch one strip of facets wide, or
    /// with no face wholly its own around the vertex), the normal field of NormalField is
    /// fitted to the faces near the vertex, of any patch, whose normals lie within this angle
    /// (degrees) of the vertex's eq. 5.1 normal. It only serves to tell one smooth surface from
    /// two (drop_smooth_crossings), not to place points.
    double near_face_angle_deg = 25.0;
    /// The mesh's vertices lie on the surface (exact crossings). Then a few faces around a
    /// vertex are a coarse sampling of one surface, whose turn the faces beside them tell:
    /// - where the feature's own faces around a vertex are coplanar but lie along one strip (a
    ///   facet strip of a cylinder a few cells in radius, along a grid axis), that field too is
    ///   fitted to the faces near the vertex;
    /// - the continuation field (FeatureNormals::continuation_field) is kept apart from the
    ///   field: where the vertex has fewer than ten faces of its own, that of the faces off the
    ///   bands within three rings; where the fit's trimming left faces out, that of all of them.
    /// restore() turns it off on near-surface and midpoint meshes: there a coplanar strip is not
    /// always a strip of one smooth surface (on a surface-nets mesh the border of a wide chamfer
    /// is one too), and the faces near it would make its edge look smooth.
    bool vertices_on_surface = true;
};

/// A normal field about a vertex x_v: n(x) = n0 + gradient (x - x_v), n0 unit.
struct NormalField {
    Vec3 n0 = Vec3::Zero();                              ///< zero: no field
    Eigen::Matrix3d gradient = Eigen::Matrix3d::Zero();  ///< d n / d x, 1/mm
};

/// The feature normals of the band vertices. Kept for those alone, a tenth of the vertices or
/// fewer: a normal, its correction and a field for every vertex would cost 62 bytes per
/// triangle, a fifth of the memory budget.
class FeatureNormals {
public:
    FeatureNormals() = default;
    /// No normal at any of `vertex_count` vertices.
    explicit FeatureNormals(std::size_t vertex_count) : slot_(vertex_count, kNoIndex) {}

    /// v's normal, as described at feature_normals(); zero where it has none.
    const Vec3& normal(Index v) const {
        static const Vec3 kZero = Vec3::Zero();
        return has_slot(v) ? normals_[slot_[v]] : kZero;
    }
    /// How far (degrees) the linear fit moved eq. 5.1's normal at v: zero on planes, a few
    /// degrees on curved features. The split keeps that much margin when it checks that
    /// pieces face the way of their surface.
    float fit_correction_deg(Index v) const { return has_slot(v) ? corrections_[slot_[v]] : 0.0f; }
    /// The feature's normal field about v as the linear fit found it (NormalEstimate::
    /// LinearFit; zero where there was none, as on planes), also where the fit was not trusted
    /// to replace eq. 5.1's normal. drop_smooth_crossings() carries it across a band.
    const NormalField& field(Index v) const {
        static const NormalField kNone;
        return has_slot(v) && !fields_.empty() ? fields_[slot_[v]] : kNone;
    }

    /// The field drop_smooth_crossings() carries from v across a band: field(v) unless
    /// feature_normals() kept one apart (FeatureNormalOptions::vertices_on_surface), where the
    /// field that places v's normal cannot tell how its feature turns.
    const NormalField& continuation_field(Index v) const {
        if (has_slot(v) && !continuations_.empty() && !continuations_[slot_[v]].n0.isZero(0.0))
            return continuations_[slot_[v]];
        return field(v);
    }

    /// Makes room for `entries` vertices' normals (and fields, as kept) without moving them
    /// as add() makes room one by one.
    void reserve(std::size_t entries) {
        normals_.reserve(entries);
        corrections_.reserve(entries);
        if (with_fields_) fields_.reserve(entries);
        if (with_continuations_) continuations_.reserve(entries);
    }

    /// Makes room for v's normal, zero, with no correction and no field, if it has none.
    void add(Index v) {
        if (has_slot(v)) return;
        slot_[v] = static_cast<Index>(normals_.size());
        normals_.push_back(Vec3::Zero());
        corrections_.push_back(0.0f);
        if (with_fields_) fields_.emplace_back();
        if (with_continuations_) continuations_.emplace_back();
    }
    /// Keeps a field for every vertex with a normal (LinearFit), from now on.
    void keep_fields() {
        with_fields_ = true;
        fields_.resize(normals_.size());
    }
    /// Keeps a continuation field apart from the field for every vertex with a normal, from
    /// now on (none set: the field).
    void keep_continuation_fields() {
        with_continuations_ = true;
        continuations_.resize(normals_.size());
    }
    /// Forgets the continuation fields (once drop_smooth_crossings() has read them).
    void drop_continuation_fields() {
        with_continuations_ = false;
        continuations_ = {};
    }
    /// Takes v's field away (a zero field: none), if it has one.
    void drop_field(Index v) {
        if (has_slot(v) && !fields_.empty()) fields_[slot_[v]] = NormalField{};
    }
    /// v's entries, for a vertex add() made room for.
    Vec3& normal_at(Index v) { return normals_[slot_[v]]; }
    float& fit_correction_at(Index v) { return corrections_[slot_[v]]; }
    NormalField& field_at(Index v) { return fields_[slot_[v]]; }
    NormalField& continuation_field_at(Index v) { return continuations_[slot_[v]]; }

private:
    bool has_slot(Index v) const { return !slot_.empty() && slot_[v] != kNoIndex; }

    std::vector<Index> slot_;          ///< per vertex (#V): its entry below, or kNoIndex
    std::vector<Vec3> normals_;        ///< per entry
    std::vector<float> corrections_;   ///< per entry
    std::vector<NormalField> fields_;  ///< per entry with keep_fields(), else empty
    /// per entry with keep_continuation_fields(), else empty; zero where field() serves
    std::vector<NormalField> continuations_;
    bool with_fields_ = false;
    bool with_continuations_ = false;
};

/// Per vertex (#V): at each vertex of an edge or corner triangle, N = sum(theta_i N_i) /
/// sum(theta_i) over the incident faces of the vertex's own feature patch (eq. 5.1), normalised;
/// theta_i is the face's angle at the vertex. Faces whose three vertices all lie on that patch are
/// preferred: a face that only leans into the patch from a band would tilt N towards the
/// neighbouring feature. A vertex all of whose faces lie in bands takes the mean of its same-patch
/// neighbours' normals. Zero at vertices off the bands, without a patch, or where nothing can tell.
/// With NormalEstimate::LinearFit the eq. 5.1 normal is then refined by the fit where it is well
/// posed.
/// \throws InvalidInput if an angle option lies outside [0, 180] degrees.
FeatureNormals feature_normals(const Mesh& mesh, const Connectivity& connectivity,
                               const std::vector<Vec3>& face_normals,
                               const std::vector<Index>& face_patch,
                               const std::vector<Index>& vertex_patch,
                               const BandClassification& bands,
                               const FeatureNormalOptions& options = {});

}  // namespace resharp
