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
    /// Where the feature's own faces cannot be fitted (a patch one strip of facets wide), the
    /// normal field of NormalField is fitted to the faces near the vertex, of any patch, whose
    /// normals lie within this angle (degrees) of the vertex's eq. 5.1 normal. It only serves
    /// to tell one smooth surface from two (drop_smooth_crossings), not to place points.
    double near_face_angle_deg = 25.0;
};

/// A normal field about a vertex x_v: n(x) = n0 + gradient (x - x_v), n0 unit.
struct NormalField {
    Vec3 n0 = Vec3::Zero();                              ///< zero: no field
    Eigen::Matrix3d gradient = Eigen::Matrix3d::Zero();  ///< d n / d x, 1/mm
};

struct FeatureNormals {
    std::vector<Vec3> normal;  ///< per vertex (#V), as described at feature_normals()
    /// Per vertex (#V): how far (degrees) the linear fit moved eq. 5.1's normal: zero on planes,
    /// a few degrees on curved features. The split keeps that much margin when it checks that
    /// pieces face the way of their surface.
    std::vector<float> fit_correction_deg;
    /// The feature's normal field about each band vertex as the linear fit found it
    /// (NormalEstimate::LinearFit; zero where there was none, as on planes), also where the fit
    /// was not trusted to replace eq. 5.1's normal. drop_smooth_crossings() carries it across a
    /// band. Kept for band vertices only, a tenth of the vertices or fewer: 96 bytes each would
    /// cost 48 bytes per triangle for all of them, a sixth of the memory budget.
    std::vector<NormalField> fields;
    /// Per vertex (#V, or empty): v's entry in `fields`, kNoIndex for a vertex off the bands.
    std::vector<Index> field_slot;

    /// v's field, or a zero one (no field) when it has none.
    const NormalField& field(Index v) const {
        static const NormalField kNone;
        return field_slot.empty() || field_slot[v] == kNoIndex ? kNone : fields[field_slot[v]];
    }
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
