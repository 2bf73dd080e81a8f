#pragma once
/// Feature-based segmentation (paper §4): faces are grown into patches of similar normal, the
/// one-triangle-wide chamfer bands are set apart as edge regions (the paper's combination with
/// the edge-based result), tiny patches are absorbed (or, left over, joined into a small surface
/// of their own), over-segmented patches are merged
/// greedily, and every vertex joins the patch with the most faces in its one-ring.

#include <cstdint>
#include <utility>
#include <vector>

#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/mesh.h"

namespace resharp {

struct FeatureSegmentationOptions {
    /// eps_theta, §4 step 2: neighbouring faces whose normals differ less than this (degrees)
    /// grow into one patch.
    double max_normal_angle_deg = 8.0;
    /// §4: patches with fewer faces than this are tiny and absorbed by a neighbour.
    std::size_t tiny_patch_faces = 25;
    /// A patch is a chamfer band (an edge region, not a feature) when fewer than this share of
    /// its vertices are interior to it and at least band_edge_fraction are edge vertices: a band
    /// is one triangle wide, a real face of two grid cells or more has a row of interior
    /// vertices.
    double band_interior_fraction = 0.1;
    /// See band_interior_fraction: a half on exact meshes; near_surface_settings() asks a third.
    double band_edge_fraction = 0.5;
    /// Greedy merging, §4 and Fig. 5: two touching patches whose normals, compared at the
    /// vertices they share, differ by less than this (degrees, median over the border) are one
    /// surface that region growing split.
    double merge_angle_deg = 15.0;
    /// Growth of a curved region (§4 step 2, our addition): once a region holds this many
    /// faces it only takes faces whose normal is still within eps_theta of its seed's. Growth
    /// from neighbour to neighbour creeps along a scallop cusp to where the cusp flattens out
    /// and so joins two ball-end passes that meet at a sharp cusp elsewhere; keeping curved
    /// regions small keeps them on one side, and merging joins them again where borders are
    /// smooth. Planar regions (chamfer bands, flat faces) grow without limit. 0: no limit (the
    /// paper).
    std::size_t curved_region_faces = 300;
    /// How far from its seed's normal such a limited region still takes faces, in growing
    /// angles (eps_theta): 1 on exact meshes; near_surface_settings() gives more.
    double curved_seed_reach = 1.0;
    /// Greedy merging (our addition): two patches are never joined, directly or through a chain
    /// of smooth borders, when a patch of one meets a patch of the other at a border of merge
    /// angle or more. False: the paper's plain greedy merging.
    bool keep_sharp_borders_apart = true;
    /// Vertex labels (our addition): where a border vertex lies as near two patches' tangent
    /// planes seen from its neighbours on them, those seen from neighbours inside each patch
    /// decide before the vote (docs/method.md). False: the vote decides such ties. Midpoint
    /// restoration's segmentations of its stairless meshes, whose vertices sit on fitted planes,
    /// take false (restore(): a tilted wedge's moved vertices twice as far off their faces).
    bool inside_view_breaks_ties = true;
};

struct FeatureSegmentation {
    /// Per face (#F): feature patch id in [0, patch_count), or kNoIndex for faces of chamfer
    /// bands (edge regions).
    std::vector<Index> face_patch;
    /// Per vertex (#V): the feature patch with the most faces in the vertex's one-ring, or
    /// kNoIndex when no incident face belongs to a feature patch.
    std::vector<Index> vertex_patch;
    std::size_t patch_count = 0;    ///< feature patches after absorbing and merging
    std::size_t grown_patches = 0;  ///< patches straight out of region growing
    std::size_t band_patches = 0;   ///< grown patches recognised as chamfer bands
    std::size_t tiny_absorbed = 0;  ///< tiny patches absorbed by a neighbour
    /// Sets of tiny patches left without a feature neighbour that joined into a feature patch:
    /// a small surface of their own (a counterbore's wall a few cells high).
    std::size_t tiny_joined = 0;
    std::size_t merges = 0;  ///< greedy merges of over-segmented patches
};

/// Into `counts` (cleared first): the feature patches of the faces around v (face_patch, #F;
/// kNoIndex left out), in the order first met, each with how many of those faces it has. §4
/// step 4 labels a vertex with the patch that has the most.
void count_ring_patches(const Connectivity& connectivity, const std::vector<Index>& face_patch,
                        Index v, std::vector<std::pair<Index, int>>& counts);

/// Mean of the unit normals of v's ring faces in patch p (face_patch, #F), leaving out faces that
/// touch vertex `away` when one is given; normalised, zero if no face qualifies. Unweighted:
/// these normals vote and compare patches, where the faces of a grid mesh are alike enough and
/// skipping eq. 5.1's corner angles keeps them cheap.
Vec3 patch_mean_normal(const Mesh& mesh, const Connectivity& connectivity,
                       const std::vector<Vec3>& face_normals, const std::vector<Index>& face_patch,
                       Index v, Index p, Index away = kNoIndex);

/// The regions of §4 steps 1-3, before any patch is told a band, absorbed or merged.
struct GrownRegions {
    std::vector<Index> face_region;  ///< per face (#F): its region, in [0, count)
    std::size_t count = 0;
};

/// Takes the mesh, its connectivity and unit face normals (#F; zero for degenerate faces, which
/// never join a region by growing); gives the regions grown across edges whose faces' normals
/// differ by less than max_normal_angle_deg (curved ones limited by curved_region_faces). Reads
/// no edge labels, so it may run beside segment_edges().
/// \throws InvalidInput if an option is out of range.
GrownRegions grow_feature_regions(const Mesh& mesh, const Connectivity& connectivity,
                                  const std::vector<Vec3>& face_normals,
                                  const FeatureSegmentationOptions& options = {});

/// Takes `options`; gives them as restore() segments a near-surface mesh with: every region
/// held to its seed's normal from its first face on, within 1.5 growing angles
/// (curved_region_faces 1, curved_seed_reach 1.5), so that growth does not creep over the rows
/// by which a dual mesher rounds a sharp edge, and a one-triangle-wide strip a band when a third
/// of its vertices are edge vertices (band_edge_fraction). Growth without limit (0, the paper)
/// keeps the paper's settings.
FeatureSegmentationOptions near_surface_settings(FeatureSegmentationOptions options);

/// Takes the mesh, its connectivity, unit face normals (#F), the regions grow_feature_regions()
/// gave for them with the same options, and the edge-vertex labels of segment_edges (#V);
/// gives the patches: bands set apart, tiny patches absorbed or joined, the rest merged, vertices
/// labelled.
/// \throws InvalidInput if an option is out of range, or the regions are not one per face of
/// this mesh, each below their count.
FeatureSegmentation segment_features(const Mesh& mesh, const Connectivity& connectivity,
                                     const std::vector<Vec3>& face_normals, GrownRegions regions,
                                     const std::vector<std::uint8_t>& is_edge_vertex,
                                     const FeatureSegmentationOptions& options = {});

/// Both steps on one thread: grow_feature_regions(), then segment_features() of its regions.
FeatureSegmentation segment_features(const Mesh& mesh, const Connectivity& connectivity,
                                     const std::vector<Vec3>& face_normals,
                                     const std::vector<std::uint8_t>& is_edge_vertex,
                                     const FeatureSegmentationOptions& options = {});

}  // namespace resharp
