// restore() on meshes whose vertices lie near the surface (issue 14): surface nets and grid-edge
// midpoints of small parts, with the placement and the grid named.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "resharp/mesh/geometry.h"
#include "resharp/pipeline/restore.h"
#include "resharp/sim/csg.h"
#include "resharp/sim/csg_file.h"
#include "resharp/sim/marching_cubes.h"
#include "resharp/sim/tridexel.h"
#include "support/grid_shapes.h"
#include "support/invariants.h"
#include "support/small_parts.h"

namespace resharp {
namespace {

using test::SmallPart;

struct Case {
    SmallPart part;
    sim::Mesher mesher;
    VertexMode mode;
};

RestoreOptions near_options(const Case& c) {
    RestoreOptions o;
    const sim::GridSpec spec = test::small_part_grid(c.part, 0.5);
    o.vertices.mode = c.mode;
    o.vertices.grid = {spec.pitch, spec.origin};
    o.vertices.grid_origin_given = true;
    return o;
}

class NearSurface : public ::testing::TestWithParam<Case> {};

TEST_P(NearSurface, DoesNoHarmAndMovesWithinTheCells) {
    const Case c = GetParam();
    const Mesh input = test::small_part(c.part, 0.5, c.mesher);
    const RestoreOptions options = near_options(c);
    const RestoreResult r = restore(input, options);
    EXPECT_EQ(r.report.vertex_placement, c.mode == VertexMode::Near ? "near" : "midpoint");
    EXPECT_FALSE(r.report.placement_measured);
    EXPECT_DOUBLE_EQ(r.report.grid_pitch, 0.5);
    EXPECT_GT(r.report.moved_vertices, 0u);
    EXPECT_LE(r.report.largest_move, std::sqrt(3.0) * 0.5);
    test::expect_no_harm(input, r, options);
}

INSTANTIATE_TEST_SUITE_P(
    Parts, NearSurface,
    ::testing::Values(Case{SmallPart::PocketedBlock, sim::Mesher::SurfaceNets, VertexMode::Near},
                      Case{SmallPart::BossedPlate, sim::Mesher::SurfaceNets, VertexMode::Near},
                      Case{SmallPart::TiltedWedge, sim::Mesher::SurfaceNets, VertexMode::Near},
                      Case{SmallPart::PocketedBlock, sim::Mesher::Midpoint, VertexMode::Midpoint},
                      Case{SmallPart::BossedPlate, sim::Mesher::Midpoint, VertexMode::Midpoint},
                      Case{SmallPart::TiltedWedge, sim::Mesher::Midpoint, VertexMode::Midpoint}));

/// Where the mesher's error can be told from the mesh: every surface-nets band, and the
/// stair-stepped slanted faces of midpoints. (A face across a grid axis meshed at midpoints
/// is flat at the wrong height, with nothing in the mesh to say how wrong.)
class NearerTheSurface : public ::testing::TestWithParam<Case> {};

TEST_P(NearerTheSurface, ThanTheExactPath) {
    const Case c = GetParam();
    const Mesh input = test::small_part(c.part, 0.5, c.mesher);
    const sim::CsgSolid solid = test::small_part_solid(c.part);
    RestoreOptions exact = near_options(c);
    exact.vertices.mode = VertexMode::Exact;
    const RestoreResult as_exact = restore(input, exact);
    const RestoreResult as_near = restore(input, near_options(c));
    // Over the input's vertices, where both outputs have them.
    double exact_sum = 0.0, near_sum = 0.0;
    for (std::size_t v = 0; v < input.vertex_count(); ++v) {
        exact_sum += test::distance_along_lines(solid, as_exact.mesh.positions[v]);
        near_sum += test::distance_along_lines(solid, as_near.mesh.positions[v]);
    }
    EXPECT_LT(near_sum, 0.8 * exact_sum);
}

INSTANTIATE_TEST_SUITE_P(
    Parts, NearerTheSurface,
    ::testing::Values(Case{SmallPart::PocketedBlock, sim::Mesher::SurfaceNets, VertexMode::Near},
                      Case{SmallPart::BossedPlate, sim::Mesher::SurfaceNets, VertexMode::Near},
                      Case{SmallPart::TiltedWedge, sim::Mesher::SurfaceNets, VertexMode::Near},
                      Case{SmallPart::TiltedWedge, sim::Mesher::Midpoint, VertexMode::Midpoint}));

/// Midpoints of a face off the grid axes scatter about it by up to half a pitch along their
/// edges, evenly: over the whole face they fix its plane, and every vertex goes onto it.
TEST(NearSurface, MidpointVerticesOfSlantedFacesLandOnTheirPlanes) {
    const Case c{SmallPart::TiltedWedge, sim::Mesher::Midpoint, VertexMode::Midpoint};
    const Mesh input = test::small_part(c.part, 0.5, c.mesher);
    const sim::CsgSolid solid = test::small_part_solid(c.part);
    const RestoreResult r = restore(input, near_options(c));
    std::vector<double> before, after;
    for (std::size_t v = 0; v < input.vertex_count(); ++v) {
        before.push_back(test::distance_along_lines(solid, input.positions[v]));
        after.push_back(test::distance_along_lines(solid, r.mesh.positions[v]));
    }
    const auto quantile = [](std::vector<double> x, double q) {
        const auto at =
            x.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(x.size() - 1));
        std::nth_element(x.begin(), at, x.end());
        return *at;
    };
    // Midpoints: about a quarter pitch off at the median. Moved: within a few hundredths of a
    // pitch, the planes' fitting error on this small part, for all but the vertices along the
    // edges that the segmentation leaves without a patch where a band is wide. (With planes
    // fitted over three rings only: 0.016 mm at the median, 0.070 mm at the 80th percentile.)
    EXPECT_GT(quantile(before, 0.5), 0.05) << quantile(before, 0.5);
    EXPECT_LT(quantile(after, 0.5), 0.015) << quantile(after, 0.5);
    EXPECT_LT(quantile(after, 0.8), 0.035) << quantile(after, 0.8);
}

/// A curved face scatters about a plane fitted to its vertices by its sag, which a quadratic
/// height over the plane takes out; a flat face's midpoints scatter in stairs, which none
/// follows. Midpoint fits that are bent are not taken for planes, so the vertices of the bossed
/// plate's boss, chamfer cone and dimple do not move onto chords, into the material or out of
/// it. Before the sag test 221 of its 2,324 vertices ended more than a tenth of a pitch farther
/// from the surface than the mesher put them, and their mean distance went 0.0715 -> 0.0823
/// mm; with it, 27 and 0.0715 -> 0.0730 mm (still a little farther: the fits that pass,
/// and move their vertices, are not all right). Since 2026-12-07 (the moved mesh segmented
/// anew, bent faces onto their quadratic height): 40 and 0.0715 -> 0.0732 mm (43 with a third
/// patch round), 30 of the 40 on
/// the boss, a cylinder of 6.2 pitches along the grid's z whose every layer of cells has the same
/// stairs, so that its vertices tell no more than one cross-section does (20 before).
TEST(NearSurface, MidpointVerticesOfCurvedFacesDoNotMoveOntoChords) {
    const Case c{SmallPart::BossedPlate, sim::Mesher::Midpoint, VertexMode::Midpoint};
    const Mesh input = test::small_part(c.part, 0.5, c.mesher);
    const sim::CsgSolid solid = test::small_part_solid(c.part);
    const RestoreResult r = restore(input, near_options(c));
    ASSERT_GT(r.report.moved_vertices, input.vertex_count() / 2);  // the rule is at work
    std::size_t farther = 0;
    double before = 0.0, after = 0.0;
    for (std::size_t v = 0; v < input.vertex_count(); ++v) {
        const double b = test::distance_along_lines(solid, input.positions[v]);
        const double a = test::distance_along_lines(solid, r.mesh.positions[v]);
        farther += a > b + 0.05;
        before += b;
        after += a;
    }
    EXPECT_LE(farther, 45u);
    EXPECT_LT(after, 1.03 * before) << before / static_cast<double>(input.vertex_count()) << " -> "
                                    << after / static_cast<double>(input.vertex_count()) << " mm";
}

/// Where the moved mesh's rounds end without a harmless split, a midpoint mesh is restored as
/// an exact one: the input's detection, released during the smoothing rounds, is made anew for
/// it. Here one harm round is allowed, and the tilted wedge's moved mesh needs two (as measured
/// when this test was written).
TEST(NearSurface, AMidpointMeshWhoseMovesFailIsRestoredOnTheExactPath) {
    const Case c{SmallPart::TiltedWedge, sim::Mesher::Midpoint, VertexMode::Midpoint};
    const Mesh input = test::small_part(c.part, 0.5, c.mesher);
    RestoreOptions o = near_options(c);
    o.max_harm_rounds = 1;
    const RestoreResult near = restore(input, o);
    ASSERT_EQ(near.report.moved_vertices, 0u);
    ASSERT_GT(near.report.moves_undone, 0u);
    RestoreOptions exact_options = o;
    exact_options.vertices.mode = VertexMode::Exact;
    const RestoreResult exact = restore(input, exact_options);
    EXPECT_GT(exact.report.edge_points_inserted, 0u);
    EXPECT_EQ(near.report.edge_points_inserted, exact.report.edge_points_inserted);
    EXPECT_EQ(near.report.feature_patches, exact.report.feature_patches);
    EXPECT_EQ(near.mesh.positions, exact.mesh.positions);
    EXPECT_EQ(near.mesh.triangles, exact.mesh.triangles);
}

/// A block 24 x 20 x 8 mm with a pocket 12 x 10 x 4 mm deep in its top, turned 27 degrees about
/// (2, -1, 3) and moved into the positive octant, meshed at grid-edge midpoints at the pitch
/// 0.5 (grid phase 0.37), with its 24 sharp edges (as segments a tenth of a pitch short of their
/// corners).
struct TurnedPocketedBlock {
    sim::CsgSolid solid;
    sim::GridSpec grid;
    Mesh mesh;
    std::vector<std::pair<Vec3, Vec3>> edges;

    TurnedPocketedBlock()
        : solid(sim::parse_csg(R"({"solid": {"union": [{"difference": [
              {"box": {"min": [0, 0, 0], "max": [24, 20, 8]}},
              {"box": {"min": [6, 5, 4], "max": [18, 15, 9]}}
          ]}], "rotate": {"axis": [2, -1, 3], "degrees": 27}, "translate": [9.37, 8.29, 7.41]}})",
                               "turned pocketed block")),
          grid(sim::phased_grid(solid.bounds(), 0.5, 0.37)) {
        sim::MeshingOptions meshing;
        meshing.mesher = sim::Mesher::Midpoint;
        mesh = sim::mesh_dexels(sim::sample_solid(grid, solid), meshing).mesh;
        const Eigen::Matrix3d turn =
            Eigen::AngleAxisd(27.0 * std::numbers::pi / 180.0, Vec3(2, -1, 3).normalized())
                .toRotationMatrix();
        const auto add = [&](const Vec3& a, const Vec3& b) {
            const Vec3 short_of_corners = 0.05 * (b - a).normalized();
            edges.emplace_back(turn * (a + short_of_corners) + Vec3(9.37, 8.29, 7.41),
                               turn * (b - short_of_corners) + Vec3(9.37, 8.29, 7.41));
        };
        add_box_edges(Vec3(0, 0, 0), Vec3(24, 20, 8), add);
        add_box_edges(Vec3(6, 5, 4), Vec3(18, 15, 8), add);  // the pocket: its rim at the top
    }

    /// The twelve edges of the box [lo, hi].
    template <class Add>
    static void add_box_edges(const Vec3& lo, const Vec3& hi, Add&& add) {
        for (int axis = 0; axis < 3; ++axis) {
            const int u = (axis + 1) % 3, w = (axis + 2) % 3;
            for (const double a : {lo[u], hi[u]}) {
                for (const double b : {lo[w], hi[w]}) {
                    Vec3 from = lo, to = hi;
                    from[u] = to[u] = a;
                    from[w] = to[w] = b;
                    add(from, to);
                }
            }
        }
    }

    double distance_to_edges(const Vec3& p) const {
        double nearest = std::numeric_limits<double>::infinity();
        for (const auto& [a, b] : edges) {
            const Vec3 ab = b - a;
            const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
            nearest = std::min(nearest, (a + t * ab - p).norm());
        }
        return nearest;
    }

    RestoreOptions options() const {
        RestoreOptions o;
        o.vertices.mode = VertexMode::Midpoint;
        o.vertices.grid = {grid.pitch, grid.origin};
        o.vertices.grid_origin_given = true;
        return o;
    }
};

/// The length of the mesh's sharp edges (faces parting by more than 30 degrees) for which
/// `is_false` holds of their midpoint.
template <class IsFalse>
double crease_length_where(const Mesh& mesh, IsFalse&& is_false) {
    std::map<std::pair<Index, Index>, Index> first_face;
    const std::vector<Vec3> normals = face_normals(mesh);
    const double min_cosine = std::cos(30.0 * std::numbers::pi / 180.0);
    double length = 0.0;
    for (Index f = 0; f < mesh.face_count(); ++f) {
        const Triangle& t = mesh.triangles[f];
        for (int i = 0; i < 3; ++i) {
            const auto key = std::minmax(t[i], t[(i + 1) % 3]);
            const auto [at, inserted] = first_face.emplace(key, f);
            if (inserted) continue;
            const Vec3 a = mesh.positions[key.first], b = mesh.positions[key.second];
            if (normals[at->second].dot(normals[f]) < min_cosine && is_false(0.5 * (a + b)))
                length += (b - a).norm();
        }
    }
    return length;
}

// Turned off the grid axes, a midpoint mesh's band vertices along an edge sit on grid edges
// that cross one face or the other. Three things left them on their stairs: the top's whole
// plane, whose centroid lies in the pocket it rings, took its convex edges with the pocket's
// walls for concave, and the band vertices of the top refused their plane; a vertex whose grid
// edge crosses the other face had only its own to go to; a vertex between the faces had a point
// only where every face around had a whole plane. Now the centroid is that of the vertices
// near, a vertex goes to the other face where its grid edge meets it there, and a face without a
// whole plane takes its plane near the vertex. Within a pitch and a half of an edge, vertices
// left more than a tenth of a pitch off the surface: 92 -> 14 here.
TEST(NearSurface, MidpointBandVerticesOfATurnedPocketedBlockGoOntoItsFaces) {
    const TurnedPocketedBlock block;
    const RestoreOptions options = block.options();
    const RestoreResult r = restore(block.mesh, options);
    ASSERT_EQ(r.report.vertex_placement, "midpoint");
    std::size_t beside = 0, off_before = 0, off_after = 0;
    for (Index v = 0; v < block.mesh.vertex_count(); ++v) {
        const Vec3& x = block.mesh.positions[v];
        if (block.distance_to_edges(x) > 1.5 * block.grid.pitch) continue;
        ++beside;
        const double tenth = 0.1 * block.grid.pitch;
        off_before += test::distance_along_lines(block.solid, x) > tenth;
        off_after += test::distance_along_lines(block.solid, r.mesh.positions[v]) > tenth;
    }
    EXPECT_GT(beside, 2000u);  // 2,344 here
    EXPECT_GT(off_before, beside / 2);
    EXPECT_LT(off_after, 20u);
    test::expect_no_harm(block.mesh, r, options);
}

// Where a face passes near a grid node, the crossings on the edges around the node are moved
// short of it. Each the same share of its edge short, they left a small triangle turned by up to
// 55 degrees from the face, and slivers beside it creases over 30 degrees on flat faces; held on
// a plane parallel to the face, they leave few. Crease length farther than a pitch from every
// true edge here: input 5,712 mm, restored 100 -> 3.9 mm (with two patch rounds, 4.4 and 47 with
// the same share short).
TEST(NearSurface, MidpointCrossingsNearAGridNodeLeaveNoCreaseOnAFlatFace) {
    const TurnedPocketedBlock block;
    const RestoreOptions options = block.options();
    const RestoreResult r = restore(block.mesh, options);
    const auto beyond_a_pitch = [&](const Vec3& p) {
        return block.distance_to_edges(p) > block.grid.pitch;
    };
    const double input = crease_length_where(block.mesh, beyond_a_pitch);
    const double output = crease_length_where(r.mesh, beyond_a_pitch);
    EXPECT_GT(input, 1000.0);
    EXPECT_LT(output, 15.0);
    test::expect_no_harm(block.mesh, r, options);
}

// A face within a few degrees of a grid plane, meshed at midpoints, is long treads of one height
// and short risers; segmentation breaks it into patches, and over a patch the least-squares
// plane of the midpoints tilts by degrees, leaving some of them farther off it than their grid
// edges allow: that plane was refused, and the face kept its stairs. The plane nearest it that
// passes within every vertex's edge is taken instead. A block turned 8 degrees about the grid's
// z (its sides 8 degrees off grid planes): of the vertices of its sides two pitches and more from
// its top and bottom, those more than a tenth of a pitch off the surface 483 -> 300 (the
// input's 522), their median distance 0.079 -> 0.037 mm, with two patch rounds; 154 and 0.017 mm
// with three.
TEST(NearSurface, MidpointFacesNearAGridPlaneTakeThePlaneWithinTheirEdges) {
    const sim::CsgSolid solid(sim::parse_csg(R"({"solid": {"union": [
        {"box": {"min": [0, 0, 0], "max": [16, 12, 5]}}
    ], "rotate": {"axis": [0, 0, 1], "degrees": 8}, "translate": [3.37, 2.29, 1.41]}})",
                                             "block turned 8 degrees"));
    sim::MeshingOptions meshing;
    meshing.mesher = sim::Mesher::Midpoint;
    const sim::GridSpec grid = sim::phased_grid(solid.bounds(), 0.5, 0.37);
    const Mesh input = sim::mesh_dexels(sim::sample_solid(grid, solid), meshing).mesh;
    RestoreOptions options;
    options.vertices.mode = VertexMode::Midpoint;
    options.vertices.grid = {grid.pitch, grid.origin};
    options.vertices.grid_origin_given = true;
    const RestoreResult r = restore(input, options);
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(8.0 * std::numbers::pi / 180.0, Vec3::UnitZ()).toRotationMatrix();
    std::size_t sides = 0, off_before = 0, off_after = 0;
    std::vector<double> after;
    for (Index v = 0; v < input.vertex_count(); ++v) {
        const Vec3 local = turn.transpose() * (input.positions[v] - Vec3(3.37, 2.29, 1.41));
        const double to_side = std::min({std::abs(local.x()), std::abs(local.x() - 16.0),
                                         std::abs(local.y()), std::abs(local.y() - 12.0)});
        const double to_top_or_bottom = std::min(std::abs(local.z()), std::abs(local.z() - 5.0));
        if (to_side > 0.5 || to_top_or_bottom < 1.0) continue;  // on a side, off its top and bottom
        ++sides;
        off_before += test::distance_along_lines(solid, input.positions[v]) > 0.05;
        const double moved = test::distance_along_lines(solid, r.mesh.positions[v]);
        off_after += moved > 0.05;
        after.push_back(moved);
    }
    const auto median = after.begin() + static_cast<std::ptrdiff_t>(after.size() / 2);
    std::nth_element(after.begin(), median, after.end());
    EXPECT_GT(sides, 700u);  // 756 here
    EXPECT_GT(off_before, sides / 2);
    EXPECT_LT(off_after, 400u);
    EXPECT_LT(*median, 0.055);
    test::expect_no_harm(input, r, options);
}

// A cylinder's wall meshed at midpoints is stairs; segmentation breaks it into strips, each
// with a plane of its own as a patch's, and vertices moved onto those planes left creases over
// 30 degrees where the strips meet. A patch without a plane as a whole whose vertices around lie
// on a bent face now goes onto that face's quadratic height along its grid edges. A boss of
// radius 12 pitches on a plate, turned off the grid axes: crease length on its wall, half a
// millimetre and more from its circles, 216 -> 58 mm (149 with the other changes of 2026-12-07
// alone), with two patch rounds; 53 mm with three; the input's 847.
TEST(NearSurface, MidpointVerticesOfATurnedBossGoOntoItsCurveNotOntoStrips) {
    const sim::CsgSolid solid(sim::parse_csg(R"({"solid": {"union": [{"union": [
        {"box": {"min": [-10, -10, 0], "max": [10, 10, 4]}},
        {"cylinder": {"from": [0, 0, 2], "to": [0, 0, 12], "radius": 6}}
    ]}], "rotate": {"axis": [2, -1, 3], "degrees": 27}, "translate": [14.37, 13.29, 12.41]}})",
                                             "turned boss"));
    sim::MeshingOptions meshing;
    meshing.mesher = sim::Mesher::Midpoint;
    const Mesh input =
        sim::mesh_dexels(sim::sample_solid(sim::phased_grid(solid.bounds(), 0.5, 0.37), solid),
                         meshing)
            .mesh;
    const RestoreOptions options;  // the placement and the grid measured
    const RestoreResult r = restore(input, options);
    ASSERT_EQ(r.report.vertex_placement, "midpoint");
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(27.0 * std::numbers::pi / 180.0, Vec3(2, -1, 3).normalized())
            .toRotationMatrix();
    const auto on_the_wall = [&](const Vec3& p) {
        const Vec3 local = turn.transpose() * (p - Vec3(14.37, 13.29, 12.41));
        const double radius = std::hypot(local.x(), local.y());
        return std::abs(radius - 6.0) < 0.5 && local.z() > 4.5 && local.z() < 11.5;
    };
    const double in = crease_length_where(input, on_the_wall);
    const double out = crease_length_where(r.mesh, on_the_wall);
    EXPECT_GT(in, 500.0);
    EXPECT_LT(out, 90.0);
    test::expect_no_harm(input, r, options);
}

/// examples/cad/chamfered_block.json meshed by surface nets at 100 cells (h = 0.5 mm), as
/// `resharp simulate --solid --cells 100 --mesher surface-nets` meshes it: its chamfers are
/// strips nine cells wide.
Mesh chamfered_block_by_surface_nets() {
    const sim::CsgSolid solid(
        sim::read_csg(std::string(RESHARP_SOURCE_DIR) + "/examples/cad/chamfered_block.json"));
    const sim::DexelGrid grid = sim::sample_solid(
        sim::phased_grid(solid.bounds(), sim::pitch_for_cells(solid.bounds(), 100), 0.4142), solid);
    sim::MeshingOptions meshing;
    meshing.mesher = sim::Mesher::SurfaceNets;
    return sim::mesh_dexels(grid, meshing).mesh;
}

// The chamfered block by surface nets has faces without points that its moves turn more than
// 90 degrees against the input faces nearest them (as measured when this test was written):
// the harm check finds them in the first round. Their moves are given up within the harm
// rounds, the moved mesh is not restored again, and those vertices keep their input places.
TEST(NearSurface, MovesTheHarmCheckRefusesAreGivenUpWithinTheHarmRounds) {
    const Mesh input = chamfered_block_by_surface_nets();
    RestoreOptions one_round;
    one_round.max_harm_rounds = 1;
    const RestoreResult given_up = restore(input, one_round);
    ASSERT_EQ(given_up.report.moved_vertices, 0u);  // the first round found harm: exact path
    const RestoreOptions options;
    const RestoreResult r = restore(input, options);
    ASSERT_EQ(r.report.vertex_placement, "near");
    EXPECT_EQ(r.report.move_rounds, 1u);
    EXPECT_GE(r.report.harm_rounds, 2u);
    EXPECT_GT(r.report.moves_undone, 0u);
    EXPECT_GT(r.report.moved_vertices, 0u);
    EXPECT_GT(r.report.edge_points_inserted, 0u);
    std::size_t moved = 0;
    for (std::size_t v = 0; v < input.vertex_count(); ++v) {
        moved += r.mesh.positions[v] != input.positions[v];
    }
    EXPECT_EQ(moved, r.report.moved_vertices);
    test::expect_no_harm(input, r, options);
}

/// A knife edge of `degrees` (a block cut by two planes through its tip, the line x = 30,
/// y = 10), turned 27 degrees about (2, -1, 3), meshed by `mesher` at 60 cells.
struct TurnedBlade {
    Mesh mesh;

    TurnedBlade(sim::Mesher mesher, double degrees) {
        const double half = degrees * std::numbers::pi / 360.0;
        auto side = [&](double sign) {
            return R"({"halfspace": {"point": [30, 10, 0], "normal": [)" +
                   std::to_string(std::sin(half)) + ", " + std::to_string(sign * std::cos(half)) +
                   ", 0]}}";
        };
        const std::string json =
            R"({"solid": {"intersection": [{"box": {"min": [0, 0, 0], "max": [40, 20, 20]}}, )" +
            side(1.0) + ", " + side(-1.0) + R"(], "rotate": {"axis": [2, -1, 3], "degrees": 27}}})";
        const sim::CsgSolid solid(sim::parse_csg(json, "turned blade"));
        const sim::GridSpec grid =
            sim::phased_grid(solid.bounds(), sim::pitch_for_cells(solid.bounds(), 60), 0.4142);
        sim::MeshingOptions meshing;
        meshing.mesher = mesher;
        mesh = sim::mesh_dexels(sim::sample_solid(grid, solid), meshing).mesh;
    }
};

// Near its tip the blade is thinner than the midpoint moves, and a moved face there lay nearer
// the other side's input faces than its own, turned against them. The harm check weighs the
// faces beyond the two rings on midpoint meshes too: with the rings alone 3 such faces were
// left (as measured when this test was written).
TEST(NearSurface, AMidpointBladesFacesAreJudgedAgainstItsOtherSide) {
    const TurnedBlade blade(sim::Mesher::Midpoint, 20.0);
    const RestoreOptions options;
    const RestoreResult r = restore(blade.mesh, options);
    ASSERT_EQ(r.report.vertex_placement, "midpoint");
    EXPECT_GT(r.report.moved_vertices, 0u);
    test::expect_no_harm(blade.mesh, r, options);
}

// Within a few cells of its tip a blade is thinner than a cell, and a near-surface mesher's
// vertices there may lie on either face: on near-surface meshes points whose crossing edge's
// ends turn by more than kNearEdgeSpikeAngleDeg are refused, on the exact path none is (the
// spike test's count holds the corner triangles it refuses too: 2 on the exact path here, as
// measured when this test was written; 41 on the near one).
TEST(NearSurface, TheEdgeSpikeTestRunsOnNearSurfaceMeshesOnly) {
    const TurnedBlade exact(sim::Mesher::MarchingCubes, 30.0);
    const RestoreResult restored = restore(exact.mesh);
    ASSERT_EQ(restored.report.vertex_placement, "exact");

    const TurnedBlade near(sim::Mesher::SurfaceNets, 30.0);
    const RestoreOptions options;
    const RestoreResult r = restore(near.mesh, options);
    ASSERT_EQ(r.report.vertex_placement, "near");
    EXPECT_GT(r.report.refused_by_spike_test, restored.report.refused_by_spike_test + 10);
    EXPECT_GT(r.report.edge_points_inserted, 0u);  // the block's own edges
    test::expect_no_harm(near.mesh, r, options);
}

// A flat strip of facets tells how a small cylinder turns only where the vertices lie on the
// surface: on a surface-nets mesh the border of a wide chamfer is such a strip too
// (FeatureNormalOptions::vertices_on_surface), and its edge would pass for smooth.
// restore() reads no field off one on a near-surface mesh, whatever the caller's options say,
// though on the exact path the same mesh restores otherwise with them.
TEST(NearSurface, ReadsNoFieldOffAFlatStripOfANearSurfaceMesh) {
    const Mesh input = chamfered_block_by_surface_nets();
    RestoreOptions with;
    RestoreOptions without;
    without.normals.vertices_on_surface = false;
    const RestoreResult near = restore(input, with);
    ASSERT_EQ(near.report.vertex_placement, "near");
    const RestoreResult near_without = restore(input, without);
    EXPECT_EQ(near.mesh.positions, near_without.mesh.positions);
    EXPECT_EQ(near.mesh.triangles, near_without.mesh.triangles);
    with.vertices.mode = without.vertices.mode = VertexMode::Exact;
    EXPECT_NE(restore(input, with).mesh.positions, restore(input, without).mesh.positions);
}

TEST(NearSurface, ExactModeMovesNothing) {
    const Mesh input = test::small_part(SmallPart::PocketedBlock, 0.5, sim::Mesher::SurfaceNets);
    RestoreOptions o =
        near_options({SmallPart::PocketedBlock, sim::Mesher::SurfaceNets, VertexMode::Exact});
    const RestoreResult r = restore(input, o);
    EXPECT_EQ(r.report.vertex_placement, "exact");
    EXPECT_EQ(r.report.moved_vertices, 0u);
    EXPECT_TRUE(
        std::equal(input.positions.begin(), input.positions.end(), r.mesh.positions.begin()));
}

TEST(NearSurface, KeepsWhatBecameOfThePointsAndMoves) {
    const Case c{SmallPart::PocketedBlock, sim::Mesher::SurfaceNets, VertexMode::Near};
    const Mesh input = test::small_part(c.part, 0.5, c.mesher);
    RestoreOptions o = near_options(c);
    o.keep_segmentation = true;
    const RestoreResult r = restore(input, o);
    const Segmentation& s = r.segmentation;
    ASSERT_EQ(s.point_fate.size(), input.face_count());
    ASSERT_EQ(s.move_planned.size(), input.vertex_count());
    // Every moved vertex was planned; every face cut into pieces with a new point is Inserted,
    // and only band faces have a fate.
    for (Index v = 0; v < input.vertex_count(); ++v) {
        if (r.mesh.positions[v] != input.positions[v]) {
            EXPECT_TRUE(s.move_planned[v]) << v;
        }
    }
    std::size_t inserted = 0;
    for (Index f = 0; f < input.face_count(); ++f) {
        inserted += s.point_fate[f] == PointFate::Inserted;
        EXPECT_EQ(s.point_fate[f] == PointFate::None, s.face_role[f] == BandRole::None) << f;
    }
    for (Index o_face = 0; o_face < r.mesh.face_count(); ++o_face) {
        const Triangle& t = r.mesh.triangles[o_face];
        const bool has_new =
            std::any_of(t.begin(), t.end(), [&](Index v) { return v >= input.vertex_count(); });
        if (has_new) {
            EXPECT_EQ(s.point_fate[r.source_face[o_face]], PointFate::Inserted);
        }
    }
    EXPECT_GT(inserted, 0u);
    EXPECT_EQ(r.report.edge_points_inserted + r.report.corner_points_inserted > 0, inserted > 0);
}

TEST(NearSurface, AMeshGivenUpLendsItsFacesToTheRoundsAndComesBackWholeWhenCancelled) {
    // A near round borrows the triangles of a mesh its caller gave up: the result is a copy's,
    // and cancelled at any question, inside a round too, the mesh comes back whole.
    const Case c{SmallPart::PocketedBlock, sim::Mesher::SurfaceNets, VertexMode::Near};
    const Mesh input = test::small_part(c.part, 0.5, c.mesher);
    for (int threads : {1, 2}) {
        RestoreOptions options = near_options(c);
        options.threads = threads;
        int asked = 0;
        options.stop.cancelled = [&] { return ++asked < 0; };  // counts, never stops
        const RestoreResult copied = restore(input, options);
        ASSERT_GT(copied.report.moved_vertices, 0u);
        const int whole = asked;
        ASSERT_GT(whole, 2);
        Mesh given = input;
        const RestoreResult taken = restore(std::move(given), options);
        EXPECT_EQ(taken.mesh.positions, copied.mesh.positions);
        EXPECT_EQ(taken.mesh.triangles, copied.mesh.triangles);
        for (int stop_at = 1; stop_at <= whole; ++stop_at) {
            int count = 0;
            options.stop.cancelled = [&] { return ++count >= stop_at; };
            Mesh cancelled = input;
            const RestoreResult back = restore(std::move(cancelled), options);
            EXPECT_TRUE(back.report.output_unchanged) << stop_at;
            EXPECT_EQ(back.mesh.triangles, input.triangles) << stop_at;
            EXPECT_EQ(back.mesh.positions, input.positions) << stop_at;
        }
    }
}

}  // namespace
}  // namespace resharp
