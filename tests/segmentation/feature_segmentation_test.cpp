#include "resharp/segmentation/feature_segmentation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "resharp/core/errors.h"
#include "resharp/mesh/geometry.h"
#include "resharp/segmentation/edge_segmentation.h"
#include "resharp/sim/csg.h"
#include "resharp/sim/marching_cubes.h"
#include "resharp/sim/solids.h"
#include "resharp/sim/tridexel.h"
#include "support/grid_shapes.h"

namespace resharp {
namespace {

FeatureSegmentation segment(const Mesh& mesh, const FeatureSegmentationOptions& options = {}) {
    const Connectivity c = build_connectivity(mesh);
    const auto fn = face_normals(mesh);
    const auto k = estimate_principal_curvatures(mesh, c, vertex_normals(mesh, c));
    const EdgeSegmentation edges = segment_edges(mesh, c, k, fn);
    return segment_features(mesh, c, fn, edges.is_edge, options);
}

/// Every patch holds the vertices of exactly one exact surface, and every surface one patch.
void expect_one_patch_per_surface(const test::SampledShape& shape, const FeatureSegmentation& s) {
    std::map<Index, std::set<int>> surfaces_of_patch;
    std::map<int, std::set<Index>> patches_of_surface;
    for (Index v = 0; v < shape.mesh.vertex_count(); ++v) {
        ASSERT_NE(s.vertex_patch[v], kNoIndex) << "vertex " << v << " has no patch";
        surfaces_of_patch[s.vertex_patch[v]].insert(shape.surface_ids[v]);
        patches_of_surface[shape.surface_ids[v]].insert(s.vertex_patch[v]);
    }
    for (const auto& [patch, surfaces] : surfaces_of_patch) {
        EXPECT_EQ(surfaces.size(), 1u) << "patch " << patch;
    }
    for (const auto& [surface, patches] : patches_of_surface) {
        EXPECT_EQ(patches.size(), 1u) << "surface " << surface;
    }
    EXPECT_EQ(s.patch_count, shape.surfaces.size());
}

TEST(FeatureSegmentation, BoxHasSixFacesAndItsBandsApart) {
    const test::SampledShape shape = test::sampled_box();
    const FeatureSegmentation s = segment(shape.mesh);
    expect_one_patch_per_surface(shape, s);
    EXPECT_GE(s.band_patches, 12u);  // at least one grown band per box edge
    // Band faces are exactly the faces whose vertices lie on two or more surfaces.
    for (Index f = 0; f < shape.mesh.face_count(); ++f) {
        const Triangle& t = shape.mesh.triangles[f];
        const bool mixed = shape.surface_ids[t[0]] != shape.surface_ids[t[1]] ||
                           shape.surface_ids[t[1]] != shape.surface_ids[t[2]];
        EXPECT_EQ(s.face_patch[f] == kNoIndex, mixed) << "face " << f;
    }
}

TEST(FeatureSegmentation, GrownRegionsCoverEveryFaceAndAreCheckedAgainstTheMesh) {
    const test::SampledShape shape = test::sampled_box();
    const Mesh& mesh = shape.mesh;
    const Connectivity c = build_connectivity(mesh);
    const auto fn = face_normals(mesh);
    const GrownRegions grown = grow_feature_regions(mesh, c, fn);
    ASSERT_EQ(grown.face_region.size(), mesh.face_count());
    for (Index r : grown.face_region) EXPECT_LT(r, grown.count);
    EXPECT_EQ(segment(mesh).grown_patches, grown.count);
    const std::vector<std::uint8_t> no_edges(mesh.vertex_count(), 0);
    GrownRegions short_one = grown;
    short_one.face_region.pop_back();  // regions of a mesh with a face less
    EXPECT_THROW(segment_features(mesh, c, fn, short_one, no_edges), InvalidInput);
    GrownRegions beyond = grown;
    beyond.face_region[0] = static_cast<Index>(grown.count);  // a region the count leaves out
    EXPECT_THROW(segment_features(mesh, c, fn, beyond, no_edges), InvalidInput);
}

TEST(FeatureSegmentation, LabelsEveryVertexOfEveryShapeByItsSurface) {
    expect_one_patch_per_surface(test::sampled_l_block(), segment(test::sampled_l_block().mesh));
    expect_one_patch_per_surface(test::sampled_rotated_box(),
                                 segment(test::sampled_rotated_box().mesh));
}

TEST(FeatureSegmentation, MergesTheHoleWallThatRegionGrowingSplits) {
    const test::SampledShape shape = test::sampled_drilled_plate();
    const FeatureSegmentation s = segment(shape.mesh);
    EXPECT_GT(s.grown_patches,
              20u);  // the wall's faces differ by more than 8 degrees here and there
    EXPECT_GT(s.merges, 0u);
    expect_one_patch_per_surface(shape, s);
    // Without merging the wall stays in pieces.
    const FeatureSegmentation unmerged = segment(shape.mesh, {.merge_angle_deg = 0.0});
    EXPECT_GT(unmerged.patch_count, shape.surfaces.size());
}

/// A sheet folded along x = 0.25 (off the grid lines, so band faces straddle it), its crease
/// fading from 40 degrees at y = 0 to nothing at y = 30, like the cusp between two ball-end
/// passes that flattens out: z = -tan(20 deg) (1 - y / 30) |x - 0.25| on a 0.5 grid.
Mesh fading_crease() {
    const double slope = std::tan(20.0 * std::numbers::pi / 180.0);
    const Index columns = 41, rows = 61;
    Mesh mesh;
    for (Index j = 0; j < rows; ++j) {
        for (Index i = 0; i < columns; ++i) {
            const double x = -10.0 + 0.5 * i, y = 0.5 * j;
            mesh.positions.emplace_back(x, y, -slope * (1.0 - y / 30.0) * std::abs(x - 0.25));
        }
    }
    for (Index j = 0; j + 1 < rows; ++j) {
        for (Index i = 0; i + 1 < columns; ++i) {
            const Index a = columns * j + i;
            mesh.triangles.push_back({a, a + 1, a + columns + 1});
            mesh.triangles.push_back({a, a + columns + 1, a + columns});
        }
    }
    return mesh;
}

TEST(FeatureSegmentation, KeepsTheSidesOfAFadingCreaseApart) {
    const Mesh mesh = fading_crease();
    const Index left = 41 * 2 + 18, right = 41 * 2 + 23;  // (-1, 1) and (1.5, 1): 40 degrees apart
    const FeatureSegmentation ours = segment(mesh);
    ASSERT_NE(ours.vertex_patch[left], kNoIndex);
    ASSERT_NE(ours.vertex_patch[right], kNoIndex);
    EXPECT_NE(ours.vertex_patch[left], ours.vertex_patch[right]);
    // The paper's growth and merging join the two sides where the crease has faded.
    const FeatureSegmentation paper =
        segment(mesh, {.curved_region_faces = 0, .keep_sharp_borders_apart = false});
    EXPECT_EQ(paper.vertex_patch[left], paper.vertex_patch[right]);
}

/// A flat face (z = 0, x < 0) and a face 45 degrees off it (beyond the rounding), rounded into
/// each other over seven rows of faces each turning 5.625 degrees from the last, as a dual
/// mesher rounds a sharp edge over the cells it crosses; 20 rows of 0.5 on either side, 60 rows
/// along y. `slope` gets, per face, the angle of its row (degrees).
Mesh rounded_edge(std::vector<double>& slope) {
    std::vector<double> row_angle(20, 0.0);
    for (int k = 1; k <= 7; ++k) row_angle.push_back(5.625 * k);
    row_angle.insert(row_angle.end(), 20, 45.0);
    std::vector<Vec3> profile{Vec3(-10.0, 0.0, 0.0)};
    for (double degrees : row_angle) {
        const double a = degrees * std::numbers::pi / 180.0;
        profile.push_back(profile.back() + 0.5 * Vec3(std::cos(a), 0.0, std::sin(a)));
    }
    const auto columns = static_cast<Index>(profile.size());
    const Index rows = 61;
    Mesh mesh;
    for (Index j = 0; j < rows; ++j) {
        for (const Vec3& p : profile) mesh.positions.push_back(p + Vec3(0.0, 0.5 * j, 0.0));
    }
    slope.clear();
    for (Index j = 0; j + 1 < rows; ++j) {
        for (Index i = 0; i + 1 < columns; ++i) {
            const Index a = columns * j + i;
            mesh.triangles.push_back({a, a + 1, a + columns + 1});
            mesh.triangles.push_back({a, a + columns + 1, a + columns});
            slope.insert(slope.end(), 2, row_angle[i]);
        }
    }
    return mesh;
}

// Growth under the growing angle (8 degrees) creeps over a rounding whose rows turn by less,
// and takes both faces into one region; held to its seed's normal from its first face on,
// within 1.5 growing angles (near_surface_settings(), restore()'s on near-surface meshes), no
// region takes faces of both.
TEST(FeatureSegmentation, RegionsHeldToTheirSeedStopAtARoundedEdge) {
    std::vector<double> slope;
    const Mesh mesh = rounded_edge(slope);
    const Connectivity c = build_connectivity(mesh);
    const auto fn = face_normals(mesh);
    auto regions_of = [&](double degrees, const GrownRegions& grown) {
        std::set<Index> regions;
        for (Index f = 0; f < mesh.face_count(); ++f) {
            if (slope[f] == degrees) regions.insert(grown.face_region[f]);
        }
        return regions;
    };
    const GrownRegions unlimited = grow_feature_regions(mesh, c, fn, {.curved_region_faces = 0});
    EXPECT_EQ(unlimited.count, 1u);
    const GrownRegions held = grow_feature_regions(mesh, c, fn, near_surface_settings({}));
    const std::set<Index> flat = regions_of(0.0, held), steep = regions_of(45.0, held);
    EXPECT_EQ(flat.size(), 1u);
    EXPECT_EQ(steep.size(), 1u);
    EXPECT_NE(*flat.begin(), *steep.begin());
    EXPECT_THROW(grow_feature_regions(mesh, c, fn, {.curved_seed_reach = 0.5}), InvalidInput);
    EXPECT_THROW(grow_feature_regions(mesh, c, fn, {.curved_seed_reach = 30.0}), InvalidInput);
}

// A one-triangle-wide strip is a band when the share of its vertices labelled edge vertices
// reaches band_edge_fraction: on the box with two vertices in five labelled, its strips are
// bands at a third (near_surface_settings()) and fewer of them at a half.
TEST(FeatureSegmentation, AStripIsABandFromTheShareOfEdgeVerticesAsked) {
    const test::SampledShape shape = test::sampled_box();
    const Connectivity c = build_connectivity(shape.mesh);
    const auto fn = face_normals(shape.mesh);
    std::vector<std::uint8_t> two_in_five(shape.mesh.vertex_count());
    for (Index v = 0; v < two_in_five.size(); ++v) two_in_five[v] = v % 5 < 2;
    const FeatureSegmentationOptions third{.band_edge_fraction =
                                               near_surface_settings({}).band_edge_fraction};
    EXPECT_DOUBLE_EQ(third.band_edge_fraction, 1.0 / 3.0);
    const FeatureSegmentation at_third = segment_features(shape.mesh, c, fn, two_in_five, third);
    const FeatureSegmentation at_half = segment_features(shape.mesh, c, fn, two_in_five, {});
    EXPECT_GE(at_third.band_patches, 12u);
    EXPECT_LT(at_half.band_patches, at_third.band_patches);
    EXPECT_THROW(segment_features(shape.mesh, c, fn, two_in_five, {.band_edge_fraction = 1.5}),
                 InvalidInput);
}

/// A block [0.37, 10.21] x [0.29, 8.13] x [0.41, 6.2929] (faces 0..5 as in sampled_box()) with
/// a 45-degree chamfer along its top front edge: -y + z <= 3.4 (face 6), meeting the top at
/// y = 2.8929, on a grid of pitch 0.5 with nodes at multiples of it. There the last chamfer
/// vertices (y = 2.6 on the grid line z = 6) and the first top vertices (z = 6.2929 on the grid
/// line y = 3) make a row of faces leaning 36 degrees from the top and 9 from the chamfer, which
/// grows into the chamfer's patch; the top vertices of that row, 0.21 pitch beyond the edge, lie
/// on the top (chamfered_block at 100 cells has such rows along its four chamfers).
test::SampledShape leaning_chamfer_block() {
    test::SampledShape shape;
    std::vector<sim::HalfSpace> faces;
    const Eigen::AlignedBox3d box(Vec3(0.37, 0.29, 0.41), Vec3(10.21, 8.13, 6.2929));
    for (int a = 0; a < 3; ++a) {
        faces.push_back({-Vec3::Unit(a), -box.min()[a], 2 * a});
        faces.push_back({Vec3::Unit(a), box.max()[a], 2 * a + 1});
    }
    faces.push_back({Vec3(0.0, -1.0, 1.0).normalized(), 3.4 / std::sqrt(2.0), 6});
    const sim::ConvexPolytope solid(faces);
    sim::OracleMesh meshed =
        sim::mesh_dexels(sim::sample_solid(sim::grid_enclosing(solid.bounds(), 0.5), solid));
    shape.mesh = std::move(meshed.mesh);
    shape.surface_ids = std::move(meshed.surface_ids);
    return shape;
}

TEST(FeatureSegmentation, LabelsAVertexOfARowThatGrewIntoTheOtherPatchByItsOwnSurface) {
    const test::SampledShape shape = leaning_chamfer_block();
    const Mesh& mesh = shape.mesh;
    // The row is there: faces with corners on the chamfer and on the top, leaning 9 degrees from
    // the chamfer.
    const Vec3 chamfer_normal = Vec3(0.0, -1.0, 1.0).normalized();
    const auto normals = face_normals(mesh);
    std::size_t leaning = 0;
    for (Index f = 0; f < mesh.face_count(); ++f) {
        std::set<int> surfaces;
        for (Index v : mesh.triangles[f]) surfaces.insert(shape.surface_ids[v]);
        leaning += surfaces == std::set<int>{5, 6} && normals[f].dot(chamfer_normal) > 0.98;
    }
    ASSERT_GT(leaning, 10u);
    // Its top vertices (y = 3), away from the side faces, take the top's patch, which the vote
    // gave to none of them: seen from any neighbour on either patch they lie at elevation 0.
    const FeatureSegmentation s = segment(mesh);
    std::map<Index, std::size_t> top_patches;  // patch -> top vertices
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
        if (shape.surface_ids[v] == 5) ++top_patches[s.vertex_patch[v]];
    }
    const Index top = std::max_element(top_patches.begin(), top_patches.end(), [](auto a, auto b) {
                          return a.second < b.second;
                      })->first;
    std::size_t row = 0;
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
        const Vec3& x = mesh.positions[v];
        if (shape.surface_ids[v] != 5 || std::abs(x.y() - 3.0) > 1e-9 || x.x() < 1.0 || x.x() > 9.5)
            continue;
        ++row;
        EXPECT_EQ(s.vertex_patch[v], top) << "vertex " << v << " at x = " << x.x();
    }
    EXPECT_GE(row, 15u);
    // The chamfer's vertices all share one patch, and it is not the top's.
    std::set<Index> chamfer_patches;
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
        if (shape.surface_ids[v] == 6) chamfer_patches.insert(s.vertex_patch[v]);
    }
    ASSERT_EQ(chamfer_patches.size(), 1u);
    EXPECT_NE(*chamfer_patches.begin(), top);
}

/// A block 20 x 20 x 8 with a blind counterbore of radius 5 and depth 3.75 along z, on a unit
/// grid whose lines keep off its faces: the counterbore of plate_holes_bosses at 100 cells.
TEST(FeatureSegmentation, JoinsTheColumnsOfACounterboresShortWallIntoFeaturePatches) {
    const sim::CsgNode block{.shape = sim::BoxShape{Vec3::Zero(), Vec3(20.0, 20.0, 8.0)}};
    const sim::CsgNode bore{.shape = sim::ConeShape{4.75, 5.0, 5.0},
                            .placement = {Eigen::Matrix3d::Identity(), Vec3(10.0, 10.0, 4.25)}};
    const sim::CsgSolid solid(
        sim::CsgNode{.op = sim::CsgOp::Difference, .operands = {block, bore}});
    const sim::OracleMesh meshed =
        sim::mesh_dexels(sim::sample_solid(sim::phased_grid(solid.bounds(), 1.0, 0.37), solid));
    const auto wall_id = static_cast<std::int32_t>(std::distance(
        solid.surfaces().begin(),
        std::find_if(solid.surfaces().begin(), solid.surfaces().end(),
                     [](const sim::CsgSurface& s) { return s.kind == sim::SurfaceKind::Cone; })));
    const FeatureSegmentation s = segment(meshed.mesh);
    auto wall_corners = [&](Index f) {
        const Triangle& t = meshed.mesh.triangles[f];
        return std::count_if(t.begin(), t.end(),
                             [&](Index v) { return meshed.surface_ids[v] == wall_id; });
    };
    auto on_wall = [&](Index f) { return wall_corners(f) == 3; };
    std::size_t wall_faces = 0, in_patches = 0;
    std::set<Index> wall_patches;
    for (Index f = 0; f < meshed.mesh.face_count(); ++f) {
        if (!on_wall(f)) continue;
        ++wall_faces;
        if (s.face_patch[f] == kNoIndex) continue;
        ++in_patches;
        wall_patches.insert(s.face_patch[f]);
    }
    // Its columns of facets turn by more than the growth angle and are each a tiny patch, with
    // no feature of their surface to join: without the joining every one is band. Columns one
    // cell wide, their vertices all edge vertices, are bands from the start and part the wall
    // into arcs.
    EXPECT_GE(s.tiny_joined, 1u);
    EXPECT_GE(in_patches, wall_faces * 3 / 4);
    for (Index f = 0; f < meshed.mesh.face_count(); ++f) {
        if (wall_corners(f) == 0) EXPECT_EQ(wall_patches.count(s.face_patch[f]), 0u) << f;
    }
}

}  // namespace
}  // namespace resharp
