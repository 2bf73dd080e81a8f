#include "resharp/segmentation/feature_segmentation.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "resharp/mesh/geometry.h"
#include "resharp/segmentation/edge_segmentation.h"
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

TEST(FeatureSegmentation, LabelsEveryVertexOfEveryShapeByItsSurface) {
    expect_one_patch_per_surface(test::sampled_l_block(), segment(test::sampled_l_block().mesh));
    expect_one_patch_per_surface(test::sampled_rotated_box(),
                                 segment(test::sampled_rotated_box().mesh));
}

TEST(FeatureSegmentation, MergesTheHoleWallThatRegionGrowingSplits) {
    const test::SampledShape shape = test::sampled_drilled_plate();
    const FeatureSegmentation s = segment(shape.mesh);
    EXPECT_GT(s.grown_patches, 20u);  // the wall's faces differ by more than 8 degrees here and there
    EXPECT_GT(s.merges, 0u);
    expect_one_patch_per_surface(shape, s);
    // Without merging the wall stays in pieces.
    const FeatureSegmentation unmerged = segment(shape.mesh, {.merge_angle_deg = 0.0});
    EXPECT_GT(unmerged.patch_count, shape.surfaces.size());
}

}  // namespace
}  // namespace resharp
