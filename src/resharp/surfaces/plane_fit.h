#pragma once
/// A plane fitted to points by total least squares: through their centroid, normal along the
/// covariance's smallest eigenvector (the line of Pearson 1901, one dimension up). Near-surface
/// restoration (near/vertex_moves.h) fits one to the vertices of a feature patch around a
/// vertex, where the mesher left them scattered about the true face.

#include <optional>
#include <span>
#include <vector>

#include "resharp/core/types.h"
#include "resharp/surfaces/junction.h"

namespace resharp {

/// The points x with normal . x = offset; normal unit.
struct Plane {
    Vec3 normal = Vec3::UnitZ();
    double offset = 0.0;

    double signed_distance(const Vec3& x) const { return normal.dot(x) - offset; }
    Vec3 projection(const Vec3& x) const { return x - signed_distance(x) * normal; }
};

struct PlaneFit {
    Plane plane;
    Vec3 centroid = Vec3::Zero();
    double rms_distance = 0.0;  ///< root mean square distance of the points to the plane
};

/// Takes three points or more and a direction the normal should face (its sign only: the
/// normal ends up within 90 degrees of it). None when the points do not span a plane (fewer
/// than three, or all on one line within rounding).
std::optional<PlaneFit> fit_plane(std::span<const Vec3> points, const Vec3& facing);

/// The plane most of the points lie on, where a few lie off it. From `first`, their
/// least-squares plane, the tenth of the points kept farthest from the last plane is dropped and
/// the rest fitted again, until they scatter about their plane by at most `exact` (root mean
/// square): that fit, of the points kept (left in `kept`), is given. None where that would leave
/// fewer than half the points, or fewer than `min_points`: points on a curved face lie on no
/// plane, and a narrow strip of them near one does not hold half.
std::optional<PlaneFit> fit_plane_trimmed(std::span<const Vec3> points, const Vec3& facing,
                                          const PlaneFit& first, double exact,
                                          std::size_t min_points, std::vector<Vec3>& kept);

/// fit_plane_trimmed() as a face's plane: a flat face's vertices with those a mesher put off the
/// face beside its edges (OpenVDB's, where it interpolates the signed distance across a concave
/// corner, up to a quarter of a pitch off over two or three cells). None also where the points
/// kept lie on two parallel lines (two values or fewer, 10 exact apart, across the line through
/// the first point and the most others): any two such lines lie in a plane, as two columns of the
/// vertices surface nets leave down a hole along a grid axis do (without this test 142 of the
/// 165 vertices between patches of the pocketed block of the tests reached their edge, against
/// 157 or more with it; which patch it refused there was not traced). `kept` is scratch, reused
/// from call to call.
std::optional<PlaneFit> fit_plane_of_most(std::span<const Vec3> points, const Vec3& facing,
                                          const PlaneFit& first, double exact,
                                          std::size_t min_points, std::vector<Vec3>& kept);

/// How the points spread within the plane of `fit`: the smaller of their two variances along
/// the plane over the larger (0 for points on a line, 1 for a round spread). A plane fitted
/// exactly to a line of points and one beside it says nothing of a face: any such points lie on
/// one plane.
double in_plane_spread(std::span<const Vec3> points, const PlaneFit& fit);

/// The point of a second-order surface fitted to points over the point `at`: the points' heights
/// over `plane` fitted by least squares as w = c0 + c1 u + c2 v + c3 u^2 + c4 u v + c5 v^2 in a
/// frame of the plane centred on at's foot, and the point c0 above that foot. Near-surface
/// restoration moves a vertex on a curved face onto it, where a plane through the face's
/// vertices around it would leave the face by its sag.
struct HeightFit {
    Vec3 point = Vec3::Zero();  ///< on the fitted surface, over at's foot on the plane
    double rms_distance = 0.0;  ///< root mean square of the points' height residuals
    Vec3 foot = Vec3::Zero();   ///< at's foot on the plane: the frame's origin
    Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();  ///< tangent_frame() of the normal
    double scale = 1.0;  ///< u and v are lengths along the frame's axes over this
    Eigen::Vector<double, 6> coefficients = Eigen::Vector<double, 6>::Zero();  ///< c0 ... c5

    /// The height above the plane less the fitted height at p's foot, with its gradient: zero
    /// on the surface, positive on the plane normal's side, and over the gradient's length a
    /// distance to first order near it (surfaces/junction.h meets it with other surfaces).
    SurfaceValue evaluate(const Vec3& p) const;
};

/// None with fewer than 10 points or where they do not fix the six coefficients (all near one
/// line or conic of the plane, within rounding).
std::optional<HeightFit> fit_height_quadric(std::span<const Vec3> points, const Plane& plane,
                                            const Vec3& at);

}  // namespace resharp
