// OpenVDB as a mesher the project did not write (extras/openvdb_mesher.h): solids sampled by the
// simulator on a fine grid are meshed by volumeToMesh at adaptivity 0, then restored; the
// restoration must finish and do no harm (issue 11's criteria).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>

#include "openvdb_mesher.h"
#include "resharp/eval/cad_metrics.h"
#include "resharp/mesh/diagnostics.h"
#include "resharp/mesh/geometry.h"
#include "resharp/near/vertex_placement.h"
#include "resharp/pipeline/restore.h"
#include "resharp/sim/csg_file.h"
#include "resharp/sim/marching_cubes.h"
#include "resharp/sim/tridexel.h"
#include "resharp/surfaces/plane_fit.h"
#include "support/grid_shapes.h"
#include "support/invariants.h"

namespace resharp {
namespace {

constexpr double kPitch = 0.5;  // h: the voxel size OpenVDB meshes at, mm
constexpr int kFine = 8;        // the simulated mesh is sampled at h / kFine

/// Six times the volume the mesh encloses: positive when its normals point out.
double six_volume(const Mesh& mesh) {
    double volume = 0.0;
    for (const Triangle& t : mesh.triangles) {
        const auto& x = mesh.positions;
        volume += x[t[0]].dot(x[t[1]].cross(x[t[2]]));
    }
    return volume;
}

struct Solid {
    std::string name;
    std::function<test::SampledShape(double)> sample;  ///< the shape sampled at a pitch
};

TEST(OpenVdbMesher, SimulatedSolidsRestoreWithoutHarm) {
    const std::vector<Solid> solids = {
        {"box", test::sampled_box},
        {"L-block", test::sampled_l_block},
        {"drilled plate", [](double pitch) { return test::sampled_drilled_plate(pitch); }},
        {"rotated box", test::sampled_rotated_box},
    };
    const RestoreOptions options;
    for (const Solid& solid : solids) {
        SCOPED_TRACE(solid.name);
        const test::SampledShape fine = solid.sample(kPitch / kFine);
        const Mesh input = extras::openvdb_dual_mesh(fine.mesh, kPitch);
        ASSERT_GT(input.face_count(), 100u);
        ASSERT_GT(six_volume(input), 0.0);  // outward, as restore() expects
        const RestoreResult r = restore(input, options);
        EXPECT_FALSE(r.report.output_unchanged);
        EXPECT_GT(r.report.edge_points_inserted, 0u);
        test::expect_no_harm(input, r, options);
    }
}

/// The share of the curve through `points` (a tenth of a pitch or less apart), sampled at its
/// points, that has a sharp edge of `mesh` (faces parting by more than 30 degrees) within
/// `tolerance` (mm).
double share_beside_a_crease(const Mesh& mesh, const std::vector<Vec3>& points, double tolerance) {
    const eval::CurveSamples creases = eval::sample_mesh_creases(mesh, 30.0, 0.1 * kPitch);
    eval::CurveSamples curve;
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const Vec3 step = points[i + 1] - points[i];
        curve.points.push_back(0.5 * (points[i] + points[i + 1]));
        curve.tangents.push_back(step.normalized());
        curve.weights.push_back(step.norm());
        curve.half_spans.push_back(0.5 * step.norm());
    }
    const std::vector<double> d = eval::crease_distances(curve, creases);
    const auto near = std::count_if(d.begin(), d.end(), [&](double x) { return x <= tolerance; });
    return static_cast<double>(near) / static_cast<double>(d.size());
}

/// The segment a-b as points a tenth of a pitch apart or less.
std::vector<Vec3> segment_points(const Vec3& a, const Vec3& b) {
    const auto steps = static_cast<int>(std::ceil((b - a).norm() / (0.1 * kPitch)));
    std::vector<Vec3> points;
    for (int i = 0; i <= steps; ++i) points.push_back(a + (b - a) * i / steps);
    return points;
}

/// share_beside_a_crease() of the segment a-b.
double share_beside_a_crease(const Mesh& mesh, const Vec3& a, const Vec3& b, double tolerance) {
    return share_beside_a_crease(mesh, segment_points(a, b), tolerance);
}

// OpenVDB bevels a concave edge over two to three cells, its middle vertices in cells the
// surface does not cross (near/concave_bevels.h): segmentation takes the bevel for a face, and
// its two borders came back as creases half a pitch off the edge. Given back to the band, the
// bevel's vertices go onto the step's faces and its edge, and the edge comes back sharp.
TEST(OpenVdbMesher, TheLBlocksConcaveEdgeComesBackSharpOnTheEdge) {
    const test::SampledShape fine = test::sampled_l_block(kPitch / kFine);
    const Mesh input = extras::openvdb_dual_mesh(fine.mesh, kPitch);
    const RestoreOptions options;
    const RestoreResult r = restore(input, options);
    const auto concave = std::find_if(fine.edges.begin(), fine.edges.end(),
                                      [](const test::ExactEdge& e) { return e.is_concave; });
    ASSERT_NE(concave, fine.edges.end());
    // A pitch off each end, where the step meets the block's sides.
    const Vec3 along = (concave->b - concave->a).normalized();
    const Vec3 a = concave->a + kPitch * along, b = concave->b - kPitch * along;
    const double tolerance = 0.1 * kPitch;
    EXPECT_GE(r.report.bevels_dissolved, 1u);
    EXPECT_LT(share_beside_a_crease(input, a, b, tolerance), 0.1);
    EXPECT_GT(share_beside_a_crease(r.mesh, a, b, tolerance), 0.9);
    test::expect_no_harm(input, r, options);
}

/// A turn by `radians` about an axis along no grid plane.
Eigen::Matrix3d turn_of(double radians) {
    return Eigen::AngleAxisd(radians, Vec3(2, -1, 3).normalized()).toRotationMatrix();
}

/// OpenVDB's mesh of `fine` turned by `turn`, at the pitch kPitch.
Mesh turned_dual_mesh(const Mesh& fine, const Eigen::Matrix3d& turn) {
    Mesh turned = fine;
    for (Vec3& x : turned.positions) x = turn * x;
    return extras::openvdb_dual_mesh(turned, kPitch);
}

// Turned off the grid axes, OpenVDB's error beside the concave edge winds across the cells and
// reaches two or three of them into each face; a plane fitted around a vertex there leaned
// towards the corner by degrees, and the faces met off the edge (none of the edge had a crease
// within 0.15 of a pitch at these three turns). The faces' own planes, which most of their
// vertices lie on exactly, bring it nearer: taken only where half the vertices around lie on
// them, 10, 13 and 38 % of it here; taken too where those vertices lie within half a pitch of
// them (in front of a band vertex's own face), 57, 35 and 80 %; 51, 29 and 85 % with
// BandVerticesOfAFaceThatMissesTheirCellGoOntoItWithinTheCellsAround below; a mean of 60 %
// before those vertices could lie a little behind the face too (kBehindFaceReach), 75 % since,
// 89 % since they may lie up to 0.7 pitches in front (kOffFaceReach; half a pitch before).
TEST(OpenVdbMesher, TheTurnedLBlocksConcaveEdgeComesBackNearerTheEdge) {
    const test::SampledShape fine = test::sampled_l_block(kPitch / kFine);
    const auto concave = std::find_if(fine.edges.begin(), fine.edges.end(),
                                      [](const test::ExactEdge& e) { return e.is_concave; });
    ASSERT_NE(concave, fine.edges.end());
    const Vec3 along = (concave->b - concave->a).normalized();
    const RestoreOptions options;
    double restored = 0.0;
    for (const double radians : {0.31, 0.45, 0.6}) {
        SCOPED_TRACE(radians);
        const Eigen::Matrix3d turn = turn_of(radians);
        const Mesh input = turned_dual_mesh(fine.mesh, turn);
        const RestoreResult r = restore(input, options);
        const Vec3 a = turn * (concave->a + kPitch * along);
        const Vec3 b = turn * (concave->b - kPitch * along);
        const double tolerance = 0.15 * kPitch;
        EXPECT_LT(share_beside_a_crease(input, a, b, tolerance), 0.05);
        restored += share_beside_a_crease(r.mesh, a, b, tolerance) / 3.0;
        test::expect_no_harm(input, r, options);
    }
    EXPECT_GT(restored, 0.8);
}

// OpenVDB displaces the rows of a face beside a concave edge into the empty corner, up to a
// quarter of a pitch off the face; those a segmentation keeps in the face's patch, off its
// band, stayed there, and the faces between them and the face's vertices on its plane made a
// crease a pitch or two off the edge. Where such a vertex lies in front of its flat face and of
// another flat face near it (within two pitches: the corner between them), it goes onto its own.
TEST(OpenVdbMesher, TheTurnedLBlocksFaceRowsBesideItsConcaveEdgeGoOntoTheirFaces) {
    const test::SampledShape fine = test::sampled_l_block(kPitch / kFine);
    const auto concave = std::find_if(fine.edges.begin(), fine.edges.end(),
                                      [](const test::ExactEdge& e) { return e.is_concave; });
    ASSERT_NE(concave, fine.edges.end());
    RestoreOptions options;
    options.keep_segmentation = true;
    std::size_t beside = 0, off_input = 0, off_output = 0;
    for (const double radians : {0.31, 0.45, 0.6}) {
        SCOPED_TRACE(radians);
        const Eigen::Matrix3d turn = turn_of(radians);
        const Mesh input = turned_dual_mesh(fine.mesh, turn);
        const RestoreResult r = restore(input, options);
        for (Index v = 0; v < input.vertex_count(); ++v) {
            const Vec3 x = turn.transpose() * input.positions[v];
            if (r.segmentation.vertex_patch[v] == kNoIndex ||
                test::distance_to_segment(x, concave->a, concave->b) > 2.0 * kPitch)
                continue;
            ++beside;
            off_input += fine.distance_to_surface(x) > 0.05 * kPitch;
            off_output +=
                fine.distance_to_surface(turn.transpose() * r.mesh.positions[v]) > 0.05 * kPitch;
        }
        test::expect_no_harm(input, r, options);
    }
    EXPECT_GT(beside, 200u);     // 272 here
    EXPECT_GT(off_input, 100u);  // 129
    EXPECT_LT(off_output, 14u);  // 77 before, 30 when this test was written, 24 since a face
                                 // that misses the vertex's cell is taken in the cells around,
                                 // 12 since its vertices may lie a little behind it, 9 since
                                 // 0.7 pitches in front
}

/// A hexagonal prism 10 mm across its flats and 6 mm tall about (6.1, 5.9, 4.2) with a
/// triangular pocket of inradius 2.2 mm, 2.5 mm deep, in its top (a small hex_prism of the CAD
/// corpus), turned about that centre and sampled by the simulator at kPitch / 4: its faces'
/// planes, its convex edges (at 120 and 90 degrees; the pocket's rim left out) and its concave
/// ones (the pocket's floor edges and the corners between its walls).
struct TurnedPrism {
    Mesh mesh;
    std::vector<Plane> faces;
    std::vector<std::pair<Vec3, Vec3>> convex_edges;
    std::vector<std::pair<Vec3, Vec3>> concave_edges;

    /// Whether x lies more than 0.05 of a pitch off every face's plane.
    bool off_surface(const Vec3& x) const {
        double nearest = std::numeric_limits<double>::infinity();
        for (const Plane& face : faces)
            nearest = std::min(nearest, std::abs(face.signed_distance(x)));
        return nearest > 0.05 * kPitch;
    }
};

/// The CSG halfspaces (with a leading comma each) of the planes through centre + turn * (reach *
/// normal) with outward normal turn * normal, adding each plane to `faces`.
std::string turned_halfspaces(const Vec3& centre, const Eigen::Matrix3d& turn,
                              const std::vector<std::pair<Vec3, double>>& normals_and_reach,
                              std::vector<Plane>& faces) {
    std::ostringstream halfspaces;
    halfspaces.precision(17);
    for (const auto& [normal, reach] : normals_and_reach) {
        const Vec3 n = turn * normal, point = centre + reach * n;
        faces.push_back({n, n.dot(point)});
        halfspaces << R"(, {"halfspace": {"point": [)" << point.x() << ", " << point.y() << ", "
                   << point.z() << R"(], "normal": [)" << n.x() << ", " << n.y() << ", " << n.z()
                   << "]}}";
    }
    return halfspaces.str();
}

/// The solid within `bounds` (a CSG box) and the halfspaces `kept` (turned_halfspaces()), less
/// the one within `bounds` and the halfspaces `cut`, sampled by the simulator at kPitch / 4.
Mesh sampled_cut(const std::string& bounds, const std::string& kept, const std::string& cut,
                 const std::string& name) {
    const sim::CsgSolid solid(sim::parse_csg(R"({"solid": {"difference": [{"intersection": [)" +
                                                 bounds + kept + R"(]}, {"intersection": [)" +
                                                 bounds + cut + "]}]}}",
                                             name));
    const sim::DexelGrid grid =
        sim::sample_solid(sim::phased_grid(solid.bounds(), kPitch / 4, 0.4142), solid);
    return sim::mesh_dexels(grid, {}).mesh;
}

/// Whether x lies within two pitches of one of `edges`.
bool beside_any(const std::vector<std::pair<Vec3, Vec3>>& edges, const Vec3& x) {
    return std::any_of(edges.begin(), edges.end(), [&](const auto& e) {
        return test::distance_to_segment(x, e.first, e.second) < 2.0 * kPitch;
    });
}

TurnedPrism turned_hex_prism(const Eigen::Matrix3d& turn) {
    const Vec3 centre(6.1, 5.9, 4.2);
    const double apothem = 5.0, half_height = 3.0, inradius = 2.2, floor = 0.5;
    const auto place = [&](const Vec3& local) { return Vec3(centre + turn * local); };
    const auto at_angle = [](double radius, double t) {
        return Vec3(radius * std::cos(t), radius * std::sin(t), 0.0);
    };
    TurnedPrism prism;
    std::vector<std::pair<Vec3, double>> sides, pocket;
    for (int k = 0; k < 6; ++k) {
        const double t = k * std::numbers::pi / 3.0, c = t + std::numbers::pi / 6.0;
        sides.emplace_back(at_angle(1.0, t), apothem);
        const double radius = apothem / std::cos(std::numbers::pi / 6.0);
        const Vec3 corner = at_angle(radius, c),
                   next = at_angle(radius, c + std::numbers::pi / 3.0);
        for (const double z : {-half_height, half_height}) {
            prism.convex_edges.emplace_back(place(corner + z * Vec3::UnitZ()),
                                            place(next + z * Vec3::UnitZ()));
        }
        prism.convex_edges.emplace_back(place(corner - half_height * Vec3::UnitZ()),
                                        place(corner + half_height * Vec3::UnitZ()));
    }
    sides.emplace_back(Vec3::UnitZ(), half_height);
    sides.emplace_back(-Vec3::UnitZ(), half_height);
    for (int k = 0; k < 3; ++k) {
        const double t = std::numbers::pi / 2.0 + k * 2.0 * std::numbers::pi / 3.0;
        pocket.emplace_back(at_angle(1.0, t), inradius);
        const Vec3 corner = at_angle(2.0 * inradius, t + std::numbers::pi / 3.0);
        const Vec3 next = at_angle(2.0 * inradius, t - std::numbers::pi / 3.0);
        prism.concave_edges.emplace_back(place(corner + floor * Vec3::UnitZ()),
                                         place(next + floor * Vec3::UnitZ()));
        prism.concave_edges.emplace_back(place(corner + floor * Vec3::UnitZ()),
                                         place(corner + half_height * Vec3::UnitZ()));
    }
    pocket.emplace_back(-Vec3::UnitZ(), -floor);
    pocket.emplace_back(Vec3::UnitZ(), half_height + 1.0);
    const std::string bounds = R"({"box": {"min": [-2, -2, -4], "max": [14, 14, 12]}})";
    const std::string prism_part = turned_halfspaces(centre, turn, sides, prism.faces);
    const std::string pocket_part = turned_halfspaces(centre, turn, pocket, prism.faces);
    prism.faces.pop_back();  // the pocket's cap lies above the prism
    prism.mesh = sampled_cut(bounds, prism_part, pocket_part, "turned hexagonal prism");
    return prism;
}

// OpenVDB puts the vertex of a cell a convex edge crosses behind both faces; off the grid axes
// it often lies nearer the other face than its own, and its own plane's foot then lies past the
// edge. Where its junction was withdrawn too (a face around it across the edge), it stayed
// behind the surface, a crease each side of it: 38 of the band vertices with a patch within two
// pitches of a convex edge here lay more than 0.05 of a pitch off every face after the
// restoration, and 4.3 % of the edges' length had no crease within 0.15 of a pitch. Such a
// vertex goes onto the other face, and into its patch (30 and 2.5 % when this test was written).
TEST(OpenVdbMesher, TheTurnedHexagonalPrismsBandVerticesGoOntoAFace) {
    RestoreOptions options;
    options.keep_segmentation = true;
    std::size_t beside = 0, off_input = 0, off_output = 0;
    double creased = 0.0;
    const std::vector<double> turns = {0.31, 0.45, 0.6};
    for (const double radians : turns) {
        SCOPED_TRACE(radians);
        const TurnedPrism prism = turned_hex_prism(turn_of(radians));
        const Mesh input = extras::openvdb_dual_mesh(prism.mesh, kPitch);
        const RestoreResult r = restore(input, options);
        std::vector<std::uint8_t> in_band(input.vertex_count(), 0);
        for (Index f = 0; f < input.face_count(); ++f) {
            if (r.segmentation.face_role[f] == BandRole::None) continue;
            for (Index v : input.triangles[f]) in_band[v] = 1;
        }
        for (Index v = 0; v < input.vertex_count(); ++v) {
            if (r.segmentation.vertex_patch[v] == kNoIndex || !in_band[v] ||
                !beside_any(prism.convex_edges, input.positions[v]))
                continue;
            ++beside;
            off_input += prism.off_surface(input.positions[v]);
            off_output += prism.off_surface(r.mesh.positions[v]);
        }
        for (const auto& [a, b] : prism.convex_edges) {
            const Vec3 along = (b - a).normalized();
            creased += share_beside_a_crease(r.mesh, a + kPitch * along, b - kPitch * along,
                                             0.15 * kPitch) /
                       static_cast<double>(prism.convex_edges.size() * turns.size());
        }
        test::expect_no_harm(input, r, options);
    }
    EXPECT_GT(beside, 1000u);    // 1359 here
    EXPECT_GT(off_input, 500u);  // 719
    EXPECT_LT(off_output, 34u);
    EXPECT_GT(creased, 0.966);
}

// OpenVDB's bevel across a concave edge off the grid axes winds across the cells, and rows of it
// that segmentation leaves between the faces lie in the empty corner, up to a pitch or more
// from the edge, in cells the edge misses. Brought as near the edge as their cells allowed,
// they stayed in front of both faces: 261 of the vertices within two pitches of the pocket's
// concave edges here lay more than 0.05 of a pitch off every face after the restoration (255
// with the convex edges' vertices above on their other face). Those go onto the nearer face
// instead (224 when this test was written; 219 since a face's row in front of it whose cell the
// face misses goes onto it within the cells around).
TEST(OpenVdbMesher, TheTurnedHexagonalPrismsPocketRowsGoOntoAFace) {
    const RestoreOptions options;
    std::size_t beside = 0, off_input = 0, off_output = 0;
    for (const double radians : {0.31, 0.45, 0.6}) {
        SCOPED_TRACE(radians);
        const TurnedPrism prism = turned_hex_prism(turn_of(radians));
        const Mesh input = extras::openvdb_dual_mesh(prism.mesh, kPitch);
        const RestoreResult r = restore(input, options);
        for (Index v = 0; v < input.vertex_count(); ++v) {
            const Vec3& x = input.positions[v];
            if (!beside_any(prism.concave_edges, x)) continue;
            ++beside;
            off_input += prism.off_surface(x);
            off_output += prism.off_surface(r.mesh.positions[v]);
        }
        test::expect_no_harm(input, r, options);
    }
    EXPECT_GT(beside, 500u);     // 745 here
    EXPECT_GT(off_input, 300u);  // 478
    EXPECT_LT(off_output, 222u);
}

/// A block 20 x 20 x 7 mm about (10.3, 9.8, 3.6) with a triangular pocket of inradius 4 mm (8
/// pitches), 4 mm deep, in its top, turned about that centre by `turn` and sampled by the
/// simulator at kPitch / 4: the pocket's corners' edges, where its walls meet at 60 degrees.
struct AcutePocket {
    Mesh mesh;
    std::vector<std::pair<Vec3, Vec3>> corners;
};

AcutePocket acute_pocket(const Eigen::Matrix3d& turn) {
    const Vec3 centre(10.3, 9.8, 3.6);
    const double half = 10.0, half_height = 3.5, inradius = 4.0, depth = 4.0;
    std::vector<std::pair<Vec3, double>> block, pocket;
    for (int axis = 0; axis < 3; ++axis) {
        const double reach = axis == 2 ? half_height : half;
        block.emplace_back(Vec3::Unit(axis), reach);
        block.emplace_back(-Vec3::Unit(axis), reach);
    }
    AcutePocket p;
    const double floor = half_height - depth;
    for (int k = 0; k < 3; ++k) {
        const double t = std::numbers::pi / 2.0 + k * 2.0 * std::numbers::pi / 3.0;
        pocket.emplace_back(Vec3(std::cos(t), std::sin(t), 0.0), inradius);
        const Vec3 corner(2.0 * inradius * std::cos(t + std::numbers::pi / 3.0),
                          2.0 * inradius * std::sin(t + std::numbers::pi / 3.0), 0.0);
        p.corners.emplace_back(centre + turn * (corner + floor * Vec3::UnitZ()),
                               centre + turn * (corner + half_height * Vec3::UnitZ()));
    }
    pocket.emplace_back(-Vec3::UnitZ(), -floor);
    pocket.emplace_back(Vec3::UnitZ(), half_height + 1.0);
    std::vector<Plane> faces;
    p.mesh = sampled_cut(R"({"box": {"min": [-8, -8, -8], "max": [28, 28, 16]}})",
                         turned_halfspaces(centre, turn, block, faces),
                         turned_halfspaces(centre, turn, pocket, faces),
                         "block with a triangular pocket");
    return p;
}

// A triangular pocket's walls meet at 60 degrees. No sample of OpenVDB's distance near the
// corner's edge lies in the pocket, so it leaves the cells along the edge with no vertex, and
// its bevel across the corner lies up to 2.3 pitches from the edge, beyond the reach of a
// bevel across a right angle and the cells around its vertices: kept as a face, its two
// borders came back as creases a pitch and a half off the edge. Now a bevel across an acute
// corner is sought as far as the corner is as wide as a right angle's, and the vertex of its
// cross-section nearest the edge goes onto it, standing for the cells left empty: the share of
// the corners' length within 0.15 of a pitch of a crease went 0.21, 0.28, 0.10 and 0.08 -> 0.38,
// 0.48, 0.37 and 0.57 at these turns (none before restoring).
TEST(OpenVdbMesher, APocketsAcuteCornersComeBackOnTheEdge) {
    const RestoreOptions options;
    double mean = 0.0;
    for (const double radians : {0.0, 0.31, 0.45, 0.6}) {
        SCOPED_TRACE(radians);
        const AcutePocket pocket = acute_pocket(turn_of(radians));
        const Mesh input = extras::openvdb_dual_mesh(pocket.mesh, kPitch);
        const RestoreResult r = restore(input, options);
        double before = 0.0, after = 0.0;
        for (const auto& [a, b] : pocket.corners) {
            const Vec3 along = (b - a).normalized();
            const Vec3 from = a + kPitch * along, to = b - kPitch * along;
            before += share_beside_a_crease(input, from, to, 0.15 * kPitch) / 3.0;
            after += share_beside_a_crease(r.mesh, from, to, 0.15 * kPitch) / 3.0;
        }
        EXPECT_LT(before, 0.05);
        EXPECT_GT(after, 0.33);
        mean += after / 4.0;
        test::expect_no_harm(input, r, options);
    }
    EXPECT_GT(mean, 0.42);
}

/// A block 16 x 16 x 6 mm with a round pocket of radius `radius` and 3 mm deep in its top, its
/// axis off the grid at (8.13, 7.91), sampled by the simulator at kPitch / kFine: the pocket's
/// floor circle (z = 3.21) is a concave edge between a cylinder and a plane.
Mesh round_pocket(double radius) {
    std::ostringstream csg;
    csg.precision(17);
    csg << R"({"solid": {"difference": [{"box": {"min": [0.17, 0.09, 0.21], "max": [16.17, 16.09, 6.21]}},
        {"cylinder": {"from": [8.13, 7.91, 3.21], "to": [8.13, 7.91, 7], "radius": )"
        << radius << "}}]}}";
    const sim::CsgSolid solid(sim::parse_csg(csg.str(), "block with a round pocket"));
    const sim::DexelGrid grid =
        sim::sample_solid(sim::phased_grid(solid.bounds(), kPitch / kFine, 0.0), solid);
    return sim::mesh_dexels(grid, {}).mesh;
}

// OpenVDB bevels a round pocket's floor circle as it does a straight concave edge: three
// vertices across it on a cone at about 45 degrees, which segmentation takes for a narrow face
// of its own (a ring). It lies on no plane, so it was kept, and its two borders came back as
// creases off the circle. Now a strip that lies in front of a flat face and of a curved one
// (its tangent plane read near each vertex), within two pitches of where they meet, is
// dissolved as a bevel is: the share of the circle within 0.15 of a pitch of a crease went
// 0.40, 0.27 and 0.24 -> 0.73, 0.40 and 0.50 at these radii (none before restoring).
TEST(OpenVdbMesher, ARoundPocketsFloorCircleComesBackOnTheCircle) {
    const RestoreOptions options;
    double mean = 0.0;
    for (const double radius : {4.0, 5.7, 7.3}) {
        SCOPED_TRACE(radius);
        const Mesh input = extras::openvdb_dual_mesh(round_pocket(radius), kPitch);
        const RestoreResult r = restore(input, options);
        std::vector<Vec3> circle;
        for (int i = 0; i <= 720; ++i) {
            const double t = i * std::numbers::pi / 360.0;
            circle.push_back(Vec3(8.13 + radius * std::cos(t), 7.91 + radius * std::sin(t), 3.21));
        }
        const double before = share_beside_a_crease(input, circle, 0.15 * kPitch);
        const double after = share_beside_a_crease(r.mesh, circle, 0.15 * kPitch);
        EXPECT_LT(before, 0.05);
        EXPECT_GT(after, 0.36);
        mean += after / 3.0;
        test::expect_no_harm(input, r, options);
    }
    EXPECT_GT(mean, 0.5);
}

/// A solid standing on a plate off the grid planes (the box [0.37, 12.21] x [0.29, 11.83] x
/// [0.41, 2.41]), given as a CSG primitive about the axis x = 6.13, y = 5.97: the circle where it
/// meets the plate's top (z = 2.41) is a concave edge between a curved face and a plane. Sampled
/// by the simulator at kPitch / kFine.
Mesh standing_on_a_plate(const std::string& primitive) {
    const sim::CsgSolid solid(sim::parse_csg(R"({"solid": {"union": [
        {"box": {"min": [0.37, 0.29, 0.41], "max": [12.21, 11.83, 2.41]}},
        )" + primitive + R"(
    ]}})",
                                             "standing on a plate"));
    const sim::DexelGrid grid =
        sim::sample_solid(sim::phased_grid(solid.bounds(), kPitch / kFine, 0.0), solid);
    return sim::mesh_dexels(grid, {}).mesh;
}

/// A boss of radius 3.3 mm (6.6 pitches) standing 2.9 mm on the plate: a cylinder.
Mesh boss_on_a_plate() {
    return standing_on_a_plate(
        R"({"cylinder": {"from": [6.13, 5.97, 1.0], "to": [6.13, 5.97, 5.31], "radius": 3.3}})");
}

/// A frustum on the plate, its cone 30 degrees off the axis (radius 4 mm where it meets the
/// plate's top, 2 mm at its top, z = 5.91), as cone_part's of the CAD corpus stands on its base.
Mesh frustum_on_a_plate() {
    return standing_on_a_plate(R"({"cone": {"from": [6.13, 5.97, 1.0], "to": [6.13, 5.97, 5.91],
                                            "radius_from": 4.806, "radius_to": 2.0}})");
}

/// Restores `fine` meshed by OpenVDB and expects the share of the concave circle of `radius`
/// where it stands on the plate within 0.15 of a pitch of a crease below 0.05 before and above
/// `at_least` after, with no harm.
void expect_circle_on_the_plate_back(const Mesh& fine, double radius, double at_least) {
    const Mesh input = extras::openvdb_dual_mesh(fine, kPitch);
    const RestoreOptions options;
    const RestoreResult r = restore(input, options);
    std::vector<Vec3> circle;
    for (int i = 0; i <= 720; ++i) {
        const double t = i * std::numbers::pi / 360.0;
        circle.push_back(Vec3(6.13 + radius * std::cos(t), 5.97 + radius * std::sin(t), 2.41));
    }
    const double tolerance = 0.15 * kPitch;
    EXPECT_LT(share_beside_a_crease(input, circle, tolerance), 0.05);
    EXPECT_GT(share_beside_a_crease(r.mesh, circle, tolerance), at_least);
    test::expect_no_harm(input, r, options);
}

// Along a concave edge between a curved face and a flat one OpenVDB displaces the two rows
// beside the edge into the empty corner, and a second-order surface fitted to the curved
// face's vertices around bends towards them: the vertices between the faces met the flat face
// off the edge or not at all, and no crease came within 0.15 of a pitch of any of the circle.
// Fitted to the vertices beyond those rows where the nearer ones lie off that fit, and allowed
// into the cells around where no surface crosses their own, they bring back a quarter of it at
// least (36 % when this test was written; the rows beside it stay where OpenVDB put them).
TEST(OpenVdbMesher, ABossesConcaveCircleComesBackOnTheCircle) {
    expect_circle_on_the_plate_back(boss_on_a_plate(), 3.3, 0.25);
}

// Where a frustum meets a plate, OpenVDB puts the vertex of the cell the concave circle crosses
// in the empty corner, in front of both faces, and segmentation gives it to the frustum: its own
// plane, fitted over the frustum's rows beside the circle (displaced as well), tilts away from
// the cone, and its foot there left it off both faces. It now goes to the junction of the plate
// and the frustum's second-order surface, as a vertex between the faces does: the share of the
// circle within 0.15 of a pitch of a crease went 0.04 -> 0.32 (the rows beside it stay where
// OpenVDB put them).
TEST(OpenVdbMesher, AFrustumsConcaveCircleComesBackOnTheCircle) {
    expect_circle_on_the_plate_back(frustum_on_a_plate(), 4.0, 0.2);
}

/// examples/cad/`file` by OpenVDB at 100 cells (pitch `h`), its voxel centres the nodes `resharp
/// simulate --solid --cells 100` samples on, from the solid sampled at h / 4, and its restoration
/// with the default options.
struct OpenVdbCadPart {
    double h = 0.0;
    Mesh input;
    RestoreResult restored;
};

OpenVdbCadPart restored_openvdb_cad_part(const std::string& file) {
    const sim::CsgSolid solid(
        sim::read_csg(std::string(RESHARP_SOURCE_DIR) + "/examples/cad/" + file));
    OpenVdbCadPart part;
    part.h = sim::pitch_for_cells(solid.bounds(), 100);
    const sim::DexelGrid fine =
        sim::sample_solid(sim::phased_grid(solid.bounds(), part.h / 4, 0.4142), solid);
    const Vec3 centres = sim::phased_grid(solid.bounds(), part.h, 0.4142).origin;
    part.input = extras::openvdb_dual_mesh(sim::mesh_dexels(fine, {}).mesh, part.h, centres);
    part.restored = restore(part.input, {});
    return part;
}

/// The horizontal circle of `radius` about `centre`, as points a tenth of a pitch apart or less
/// for a radius up to 22 mm.
std::vector<Vec3> circle_points(const Vec3& centre, double radius) {
    std::vector<Vec3> circle;
    for (int i = 0; i <= 2880; ++i) {
        const double t = i * std::numbers::pi / 1440.0;
        circle.push_back(centre + radius * Vec3(std::cos(t), std::sin(t), 0.0));
    }
    return circle;
}

// examples/cad/sphere_part.json by OpenVDB at 100 cells (h = 0.5 mm), its voxel centres the
// nodes `resharp simulate --solid --cells 100` samples on: its dome (a ball of radius 14 mm) leaves
// the top at 44 degrees along a circle of radius 9.8 mm. OpenVDB bevels that concave circle over
// two rows whose faces turn by under the sharp angle each, so no band marks much of it, and the
// vertices there, off the bands in the empty corner, stayed. A curved face's vertex off the bands
// in front of both faces, where the flat face's rows are displaced too, now goes to their
// junction: within 0.15 of a pitch of a crease 0.26 -> 0.43 of the circle (0 before restoring).
TEST(OpenVdbMesher, ASpherePartsDomeCircleComesBackOnTheCircle) {
    const OpenVdbCadPart part = restored_openvdb_cad_part("sphere_part.json");
    const std::vector<Vec3> circle = circle_points(Vec3(25, 20, 15), 9.798);
    EXPECT_LT(share_beside_a_crease(part.input, circle, 0.15 * part.h), 0.05);
    EXPECT_GT(share_beside_a_crease(part.restored.mesh, circle, 0.15 * part.h), 0.38);
    test::expect_no_harm(part.input, part.restored, {});
}

// examples/cad/cone_part.json by OpenVDB at 100 cells: its round base (radius 20 mm) has a
// 45-degree chamfer 2 mm high on its top rim. OpenVDB rounds the chamfer's two convex circles
// in steps of a few degrees from face to face, and region growing crept over them: the top, the
// chamfer and the cylinder were one region, and half of either circle came back. Regions held to
// their seed's normal (docs/method.md, *Regions held to their seed*) keep the three apart: within
// 0.15 of a pitch of a crease 0.50 -> 0.99 of the top circle, 0.40 -> 0.93 of the lower.
TEST(OpenVdbMesher, AConePartsChamferCirclesComeBack) {
    const OpenVdbCadPart part = restored_openvdb_cad_part("cone_part.json");
    const double tolerance = 0.15 * part.h;
    const std::vector<Vec3> top = circle_points(Vec3(0, 0, 8), 18);
    const std::vector<Vec3> lower = circle_points(Vec3(0, 0, 6), 20);
    EXPECT_LT(share_beside_a_crease(part.input, top, tolerance), 0.05);
    EXPECT_LT(share_beside_a_crease(part.input, lower, tolerance), 0.05);
    EXPECT_GT(share_beside_a_crease(part.restored.mesh, top, tolerance), 0.9);
    EXPECT_GT(share_beside_a_crease(part.restored.mesh, lower, tolerance), 0.85);
    test::expect_no_harm(part.input, part.restored, {});
}

/// A hub of radius 8 mm (16 pitches) along x on a flange of radius 12 mm, turned as turn_of(0.45)
/// turns (about (2, -1, 3) through the origin), sampled by the simulator at kPitch / kFine; the
/// concave circle where the hub leaves the flange's face x = 2.4 into `circle`, turned.
Mesh turned_hub_on_a_flange(std::vector<Vec3>& circle) {
    const double degrees = 0.45 * 180.0 / std::numbers::pi;
    const sim::CsgSolid solid(sim::parse_csg(R"({"solid": {"union": [
        {"cylinder": {"from": [0.4, 0.1, 0.2], "to": [2.4, 0.1, 0.2], "radius": 12}},
        {"cylinder": {"from": [2.0, 0.1, 0.2], "to": [9.6, 0.1, 0.2], "radius": 8}}
    ], "rotate": {"axis": [2, -1, 3], "degrees": )" +
                                                 std::to_string(degrees) + "}}}",
                                             "hub on a flange"));
    const Eigen::Matrix3d turn = turn_of(0.45);
    circle.clear();
    for (int i = 0; i <= 720; ++i) {
        const double t = i * std::numbers::pi / 360.0;
        circle.push_back(turn * Vec3(2.4, 0.1 + 8.0 * std::cos(t), 0.2 + 8.0 * std::sin(t)));
    }
    const sim::DexelGrid grid =
        sim::sample_solid(sim::phased_grid(solid.bounds(), kPitch / kFine, 0.0), solid);
    return sim::mesh_dexels(grid, {}).mesh;
}

// Along a hub's concave circle on a flange, turned off the grid axes, OpenVDB displaces the
// hub's rows beside the edge so far that no second-order surface fits the hub's vertices near a
// band vertex there; such a vertex in the empty corner kept its own plane's foot, off both
// faces. Where the flange's rows are displaced as well, the hub's surface fitted beyond the rows
// takes it to the junction: the share of the circle within 0.15 of a pitch of a crease went
// 0.43 -> 0.50 (the rows beside it stay where OpenVDB put them).
TEST(OpenVdbMesher, ATurnedHubsConcaveCircleComesBackOnTheCircle) {
    std::vector<Vec3> circle;
    const Mesh input = extras::openvdb_dual_mesh(turned_hub_on_a_flange(circle), kPitch);
    const RestoreOptions options;
    const RestoreResult r = restore(input, options);
    const double tolerance = 0.15 * kPitch;
    EXPECT_LT(share_beside_a_crease(input, circle, tolerance), 0.05);
    EXPECT_GT(share_beside_a_crease(r.mesh, circle, tolerance), 0.47);
    test::expect_no_harm(input, r, options);
}

/// The placement of turned_chamfered_block(): 23 degrees about (1, 2, 3), then into the
/// positive octant.
sim::Placement chamfered_block_turn() {
    return {Eigen::AngleAxisd(23.0 * std::numbers::pi / 180.0, Vec3(1, 2, 3).normalized())
                .toRotationMatrix(),
            Vec3(9.37, 8.29, 7.41)};
}

/// A block 12 x 10 x 6 mm about the origin with 45-degree chamfers 1.5 mm wide on its four top
/// edges, turned by chamfered_block_turn(); sampled by the simulator at kPitch / kFine. Its
/// chamfers' edges (the top's and the sides') go to `edges`, as their ends a pitch short.
Mesh turned_chamfered_block(std::vector<std::pair<Vec3, Vec3>>& edges) {
    const sim::CsgSolid solid(sim::parse_csg(R"({"solid": {"union": [{"intersection": [
        {"box": {"min": [-6, -5, -3], "max": [6, 5, 3]}},
        {"halfspace": {"point": [0, -5, 1.5], "normal": [0, -1, 1]}},
        {"halfspace": {"point": [0, 5, 1.5], "normal": [0, 1, 1]}},
        {"halfspace": {"point": [-6, 0, 1.5], "normal": [-1, 0, 1]}},
        {"halfspace": {"point": [6, 0, 1.5], "normal": [1, 0, 1]}}
    ]}], "rotate": {"axis": [1, 2, 3], "degrees": 23}, "translate": [9.37, 8.29, 7.41]}})",
                                             "turned chamfered block"));
    const sim::Placement turn = chamfered_block_turn();
    const auto add = [&](const Vec3& a, const Vec3& b) {
        const Vec3 along = (b - a).normalized() * kPitch;
        edges.emplace_back(turn.apply(a + along), turn.apply(b - along));
    };
    for (const double s : {-1.0, 1.0}) {
        add(Vec3(s * 4.5, -3.5, 3), Vec3(s * 4.5, 3.5, 3));  // the top's edges
        add(Vec3(-4.5, s * 3.5, 3), Vec3(4.5, s * 3.5, 3));
        add(Vec3(s * 6, -3.5, 1.5), Vec3(s * 6, 3.5, 1.5));  // the sides'
        add(Vec3(-4.5, s * 5, 1.5), Vec3(4.5, s * 5, 1.5));
    }
    const sim::DexelGrid grid =
        sim::sample_solid(sim::phased_grid(solid.bounds(), kPitch / kFine, 0.0), solid);
    return sim::mesh_dexels(grid, {}).mesh;
}

// A 45-degree chamfer's convex edges, turned off the grid axes: the faces around the vertex
// OpenVDB puts in a cell such an edge crosses, behind both faces, each turn by about half the
// edge's angle, and classification often finds no band there; that vertex stayed, and the edge
// with it. Where it lies behind both faces' planes it now goes to their junction within its
// cell: the share of those edges' length within 0.15 of a pitch of a crease went 0.944 -> 0.985.
TEST(OpenVdbMesher, AChamfersUnbandedConvexEdgesComeBack) {
    std::vector<std::pair<Vec3, Vec3>> edges;
    const Mesh input = extras::openvdb_dual_mesh(turned_chamfered_block(edges), kPitch);
    const RestoreOptions options;
    const RestoreResult r = restore(input, options);
    double near = 0.0, length = 0.0;
    for (const auto& [a, b] : edges) {
        const double share = share_beside_a_crease(r.mesh, a, b, 0.15 * kPitch);
        near += share * (b - a).norm();
        length += (b - a).norm();
    }
    EXPECT_GT(near / length, 0.965);
    test::expect_no_harm(input, r, options);
}

// A face ringing a curved one (the plate around the boss) has its centroid far from the edge
// between them, on the boss's axis, behind the boss's plane near the edge: where a side's
// centroid told which way the edge turns, that concave edge was taken for convex, and the
// plate's vertices in front of it beside the boss refused their own plane. The side's centroid
// is now that of its vertices near the vertex. And the plate's rows off the bands in front of
// it and of the boss's tangent plane nearby go onto the plate as they do in front of another
// flat face (150 -> 96 left off it).
TEST(OpenVdbMesher, APlatesBandVerticesBesideABossGoOntoThePlate) {
    const Mesh input = extras::openvdb_dual_mesh(boss_on_a_plate(), kPitch);
    RestoreOptions options;
    options.keep_segmentation = true;
    const RestoreResult r = restore(input, options);
    std::size_t beside = 0, off_input = 0, off_output = 0;
    for (Index v = 0; v < input.vertex_count(); ++v) {
        const Vec3& x = input.positions[v];
        const double radius = std::hypot(x.x() - 6.13, x.y() - 5.97);
        if (radius < 3.3 + 0.25 * kPitch || radius > 3.3 + 1.5 * kPitch || x.z() > 2.41 + kPitch)
            continue;
        ++beside;
        off_input += std::abs(x.z() - 2.41) > 0.05 * kPitch;
        off_output += std::abs(r.mesh.positions[v].z() - 2.41) > 0.05 * kPitch;
    }
    EXPECT_GT(beside, 150u);       // 187 here, within 0.125 to 0.75 mm of the boss
    EXPECT_EQ(off_input, beside);  // OpenVDB displaces them all
    EXPECT_LT(off_output, 110u);   // 166 before, 150 when this test was written, then 96
    test::expect_no_harm(input, r, options);
}

/// A block with a pocket 20 x 16.67 x 12 mm (about the stepped block's of the CAD corpus at 5/6
/// of its size), sampled by the simulator at kPitch / 4; the pocket's floor corners, where three
/// concave edges meet, go to `corners`.
Mesh pocketed_block(std::vector<Vec3>& corners) {
    const sim::CsgSolid solid(sim::parse_csg(R"({"solid": {"difference": [
        {"box": {"min": [0.37, 0.29, 0.41], "max": [24.37, 21.29, 16.41]}},
        {"box": {"min": [2.37, 2.29, 4.41], "max": [22.37, 18.96, 17.0]}}
    ]}})",
                                             "pocketed block"));
    for (const double x : {2.37, 22.37}) {
        for (const double y : {2.29, 18.96}) corners.emplace_back(x, y, 4.41);
    }
    const sim::DexelGrid grid =
        sim::sample_solid(sim::phased_grid(solid.bounds(), kPitch / 4, 0.4142), solid);
    return sim::mesh_dexels(grid, {}).mesh;
}

// OpenVDB bevels a pocket's concave edges and rounds its floor corners over a cell or two.
// - Where the vertex it puts at a corner lies in a cell no face crosses (two pitches from the
//   corner, as far from each face), it went onto the junction of the two faces nearest it, not
//   to the corner: none of the 16 corners here had a vertex within 0.1 of a pitch. Now where the
//   three faces' corner lies within the cells around it, it goes there (5 of the 16 when this
//   test was written).
// - A vertex between patches beside a corner may have a face with fewer vertices off the band
//   around it than a plane is fitted to: it stayed where OpenVDB put it, off both faces (203
//   vertices between patches here stayed put). Where those few lie on their flat face's plane,
//   that plane is taken (131 stay when this test was written).
TEST(OpenVdbMesher, APocketsCornersComeBack) {
    std::vector<Vec3> corners;
    const Mesh fine = pocketed_block(corners);
    RestoreOptions options;
    options.keep_segmentation = true;
    const double tolerance = 0.1 * kPitch;
    const auto has_vertex_at = [&](const Mesh& mesh, const Vec3& corner) {
        return std::any_of(mesh.positions.begin(), mesh.positions.end(),
                           [&](const Vec3& x) { return (x - corner).norm() <= tolerance; });
    };
    int restored = 0;
    int unmoved_between_patches = 0;
    for (const Vec3& offset :
         {Vec3(0, 0, 0), Vec3(0.13, 0.27, 0.41), Vec3(0.25, 0.1, 0.33), Vec3(0.4, 0.4, 0.2)}) {
        SCOPED_TRACE(offset.transpose());
        const Mesh input = extras::openvdb_dual_mesh(fine, kPitch, offset);
        const RestoreResult r = restore(input, options);
        for (const Vec3& corner : corners) {
            EXPECT_FALSE(has_vertex_at(input, corner));
            restored += has_vertex_at(r.mesh, corner);
        }
        for (Index v = 0; v < input.vertex_count(); ++v) {
            unmoved_between_patches += r.segmentation.vertex_patch[v] == kNoIndex &&
                                       r.mesh.positions[v] == input.positions[v];
        }
        test::expect_no_harm(input, r, options);
    }
    EXPECT_GE(restored, 4);
    EXPECT_LE(unmoved_between_patches, 160);
}

/// A pocket with rounded corners (a flat-end mill's) in the block [0.37, block_high.x()] x
/// [0.29, block_high.y()] x [0.41, 12.41]: its walls x = low.x() and high.x(), y = low.y() and
/// high.y(), its floor z = floor, open at the top. Its walls are one curved patch round its
/// corners, as mech's are.
struct RoundedPocket {
    Eigen::Vector2d block_high, low, high;
    double floor = 0.0, radius = 0.0;

    /// The block sampled by the simulator at kPitch / 4.
    Mesh sampled() const {
        const auto point = [](double x, double y, double z) {
            return "[" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) +
                   "]";
        };
        const auto box = [&](double x0, double y0, double x1, double y1) {
            return R"({"box": {"min": )" + point(x0, y0, floor) + R"(, "max": )" +
                   point(x1, y1, 13.0) + "}}";
        };
        const double r = radius;
        std::string corners;
        for (const double x : {low.x() + r, high.x() - r}) {
            for (const double y : {low.y() + r, high.y() - r}) {
                corners += R"(, {"cylinder": {"from": )" + point(x, y, floor) + R"(, "to": )" +
                           point(x, y, 13.0) + R"(, "radius": )" + std::to_string(r) + "}}";
            }
        }
        const sim::CsgSolid solid(sim::parse_csg(
            R"({"solid": {"difference": [{"box": {"min": [0.37, 0.29, 0.41], "max": )" +
                point(block_high.x(), block_high.y(), 12.41) + R"(}}, {"union": [)" +
                box(low.x() + r, low.y(), high.x() - r, high.y()) + ", " +
                box(low.x(), low.y() + r, high.x(), high.y() - r) + corners + "]}]}}",
            "pocket with rounded corners"));
        const sim::DexelGrid grid =
            sim::sample_solid(sim::phased_grid(solid.bounds(), kPitch / 4, 0.4142), solid);
        return sim::mesh_dexels(grid, {}).mesh;
    }

    /// The straight parts of the floor's four edges, a pitch short of the rounded corners.
    std::vector<std::pair<Vec3, Vec3>> straight_floor_edges() const {
        const double r = radius + kPitch, z = floor;
        return {{{low.x(), low.y() + r, z}, {low.x(), high.y() - r, z}},
                {{high.x(), low.y() + r, z}, {high.x(), high.y() - r, z}},
                {{low.x() + r, low.y(), z}, {high.x() - r, low.y(), z}},
                {{low.x() + r, high.y(), z}, {high.x() - r, high.y(), z}}};
    }
};

// OpenVDB bevels the floor edges of a pocket whose walls are one curved patch round its rounded
// corners (mech's pockets). The bevel's plane was judged against the walls' as a whole, which
// has none, and was not given back to the band: its two borders came back as creases 0.7 mm off
// the edge (mech, pitch 0.5 mm); and where a row beside the bevel grew into a wall's patch, the
// bevel's vertices, with three patches around them, stayed. Now the walls are fitted along the
// bevel and such rows go with it, and a bevel OpenVDB bends between its rows by a few degrees
// is a plane all the same (fit_plane_trimmed()). Measured: the share of the straight parts of the
// floor's edges (a pitch short of the rounded corners) within a tenth of a pitch of a crease, over
// four offsets of the grid: summed over the 16 edges 0.94 before, 7.8 when this test was written,
// 8.5 with bent bevels; at the first offset, where the edges lie as mech's pocket floor's do
// between the voxel centres (0.29 pitch past them), none of the four before, 0.66 to 0.78 of each
// after.
TEST(OpenVdbMesher, ThePocketFloorsEdgesBesideWallsRoundItsCornersComeBack) {
    const RoundedPocket pocket{{24.37, 20.29}, {3.37, 2.79}, {21.37, 17.79}, 4.41, 2.0};
    const Mesh fine = pocket.sampled();
    const RestoreOptions options;
    const double tolerance = 0.1 * kPitch;
    const std::vector<std::pair<Vec3, Vec3>> edges = pocket.straight_floor_edges();
    const std::vector<Vec3> offsets{Vec3(0.08, 0.0, 0.12), Vec3(0.0, 0.0, 0.0), Vec3(0.2, 0.2, 0.2),
                                    Vec3(0.33, 0.4, 0.05)};
    double summed = 0.0;
    for (const Vec3& offset : offsets) {
        SCOPED_TRACE(offset.transpose());
        const Mesh input = extras::openvdb_dual_mesh(fine, kPitch, offset);
        const RestoreResult r = restore(input, options);
        for (const auto& [a, b] : edges) {
            SCOPED_TRACE(a.transpose());
            EXPECT_LT(share_beside_a_crease(input, a, b, tolerance), 0.05);
            const double share = share_beside_a_crease(r.mesh, a, b, tolerance);
            if (offset == offsets.front()) {
                EXPECT_GT(share, 0.5);
            }
            summed += share;
        }
        test::expect_no_harm(input, r, options);
    }
    EXPECT_GT(summed, 5.0);
}

// Where a floor bevel's patch runs along two walls round the pocket's rounded corner (mech's
// floor edges x = 32 and y = 52), it lies on no plane, and it had too many vertices for its
// bounding box to be taken for a strip: its legs are now judged as bevels one by one. The share
// of each straight floor edge (a pitch short of the corners) within a tenth of a pitch of a
// crease: 0 for three of the four edges before (0.96 for the fourth); 0.74 to 0.96 each when this
// test was written.
TEST(OpenVdbMesher, AFloorBevelThatTurnsAPocketsCornerComesBackAlongEachWall) {
    // Each face 0.29 mm past a voxel centre of the grid at the origin, as mech's floor edges lie.
    const RoundedPocket pocket{{28.37, 24.29}, {3.37, 2.79}, {23.37, 21.79}, 4.29, 4.0};
    const Mesh input = extras::openvdb_dual_mesh(pocket.sampled(), kPitch);
    const RestoreOptions options;
    const RestoreResult r = restore(input, options);
    const double tolerance = 0.1 * kPitch;
    const std::vector<std::pair<Vec3, Vec3>> edges = pocket.straight_floor_edges();
    for (const auto& [a, b] : edges) {
        SCOPED_TRACE(a.transpose());
        EXPECT_GT(share_beside_a_crease(r.mesh, a, b, tolerance), 0.5);
    }
    test::expect_no_harm(input, r, options);
}

/// Whether y lies in the closed grid cell of x, or with `around` > 0 in the block of cells that
/// many cells around it (a thousandth of a pitch of slack).
bool in_cells(const Grid& grid, const Vec3& x, const Vec3& y, int around = 0) {
    for (int a = 0; a < 3; ++a) {
        const double cell = std::floor((x[a] - grid.origin[a]) / grid.pitch);
        const double u = (y[a] - grid.origin[a]) / grid.pitch - cell;
        if (u < -around - 1e-3 || u > 1.0 + around + 1e-3) return false;
    }
    return true;
}

// Beside the turned L-block's concave edge OpenVDB puts a few vertices of a face's band in cells
// the face does not cross. Held to their cells, they stayed off the face, and the points placed
// from the planes through them came back as far off the edge; now those of a flat face go onto
// it within the cells around (no vertex of a patch left its input cell at these turns before),
// and land on the exact face.
TEST(OpenVdbMesher, BandVerticesOfAFaceThatMissesTheirCellGoOntoItWithinTheCellsAround) {
    const test::SampledShape fine = test::sampled_l_block(kPitch / kFine);
    RestoreOptions options;
    options.keep_segmentation = true;
    std::size_t beyond = 0;
    for (const double radians : {0.45, 0.6, 0.8}) {
        SCOPED_TRACE(radians);
        const Eigen::Matrix3d turn = turn_of(radians);
        const Mesh input = turned_dual_mesh(fine.mesh, turn);
        const std::optional<Grid> grid = estimate_vertex_placement(input).grid;
        ASSERT_TRUE(grid.has_value());
        const RestoreResult r = restore(input, options);
        for (Index v = 0; v < input.vertex_count(); ++v) {
            const Vec3& y = r.mesh.positions[v];
            if (r.segmentation.vertex_patch[v] == kNoIndex ||
                in_cells(*grid, input.positions[v], y))
                continue;
            ++beyond;
            EXPECT_TRUE(in_cells(*grid, input.positions[v], y, 1)) << v;
            EXPECT_LT(fine.distance_to_surface(turn.transpose() * y), 0.01 * kPitch) << v;
        }
    }
    EXPECT_GE(beyond, 4u);  // 2, 2 and 1 here
}

}  // namespace
}  // namespace resharp
