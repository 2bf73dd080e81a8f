#include "resharp/pipeline/option_table.h"

#include <array>

namespace resharp {
namespace {

// A field of one of RestoreOptions' stage structs, or of RestoreOptions itself, as a plain
// function pointer, so that the table is a constant array and its entries one line each.
template <auto Stage, auto Member>
auto& nested(RestoreOptions& o) {
    return (o.*Stage).*Member;
}
template <auto Member>
auto& top(RestoreOptions& o) {
    return o.*Member;
}

using R = RestoreOptions;

constexpr std::array<std::pair<std::string_view, CurvatureFeature>, 2> kFeatures{{
    {"magnitude", CurvatureFeature::Magnitude},
    {"signed", CurvatureFeature::Signed},
}};
constexpr std::array<std::pair<std::string_view, NormalEstimate>, 2> kEstimates{{
    {"fit", NormalEstimate::LinearFit},
    {"angle-weighted", NormalEstimate::AngleWeighted},
}};

constexpr std::array<std::pair<std::string_view, PointPlacement>, 2> kPlacements{{
    {"tangent-planes", PointPlacement::TangentPlanes},
    {"second-order", PointPlacement::SecondOrder},
}};

constexpr std::array<std::pair<std::string_view, VertexMode>, 4> kVertexModes{{
    {"auto", VertexMode::Auto},
    {"exact", VertexMode::Exact},
    {"near", VertexMode::Near},
    {"midpoint", VertexMode::Midpoint},
}};

const std::array<OptionInfo, 26> kTable{{
    {"vertex-placement",
     "where the mesher put the vertices: 'exact' on the surface (the paper's method: no vertex "
     "moves), 'near' it (cell means: surface nets, OpenVDB), at grid-edge 'midpoint's, or "
     "'auto': measured from the mesh, exact when unclear",
     ChoiceField<VertexMode>{&nested<&R::vertices, &VertexOptions::mode>, kVertexModes}, false,
     "vertices"},
    {"curvature-feature",
     "what k-means clusters: 'signed' (k1, k2) as the paper, or 'magnitude' (|k|min, |k|max), "
     "which keeps concave and convex edges together",
     ChoiceField<CurvatureFeature>{&nested<&R::edges, &EdgeSegmentationOptions::feature>,
                                   kFeatures},
     true},
    {"normals",
     "feature normals at band vertices: 'angle-weighted' is eq. 5.1 as the paper; 'fit' "
     "extrapolates the feature's face normals to the vertex, exact on planes and better on "
     "curved features",
     ChoiceField<NormalEstimate>{&nested<&R::normals, &FeatureNormalOptions::estimate>, kEstimates},
     true},
    {"max-fit-correction", "a fitted normal further than this (degrees) from eq. 5.1's is not used",
     ValueField<double>{&nested<&R::normals, &FeatureNormalOptions::max_fit_correction_deg>}},
    {"max-fit-residual",
     "faces whose normal is further than this (degrees) from the first fit, such as faces "
     "beyond a scallop cusp, are left out of the second; 180 keeps all",
     ValueField<double>{&nested<&R::normals, &FeatureNormalOptions::max_fit_residual_deg>}},
    {"kmeans-tolerance", "eps_K (paper eq. 3.2): k-means stops when centres move less (1/length)",
     ValueField<double>{&nested<&R::edges, &EdgeSegmentationOptions::kmeans_tolerance>}},
    {"max-kmeans-iterations", "safety bound on k-means iterations",
     ValueField<int>{&nested<&R::edges, &EdgeSegmentationOptions::max_kmeans_iterations>}},
    {"bridge-walk", "P (paper 3.3): vertices a walk may visit to bridge a broken edge",
     ValueField<int>{&nested<&R::edges, &EdgeSegmentationOptions::max_bridge_walk>}},
    {"flat-spread", "edge vertices whose one-ring normals spread less (degrees) are flat",
     ValueField<double>{&nested<&R::edges, &EdgeSegmentationOptions::flat_normal_spread_deg>}},
    {"region-angle",
     "eps_theta (paper 4): neighbouring faces closer than this (degrees) grow into one patch",
     ValueField<double>{&nested<&R::features, &FeatureSegmentationOptions::max_normal_angle_deg>}},
    {"tiny-patch", "patches with fewer faces are tiny and absorbed (paper 4)",
     ValueField<std::size_t>{&nested<&R::features, &FeatureSegmentationOptions::tiny_patch_faces>}},
    {"band-interior-fraction",
     "patches with fewer interior vertices than this share are chamfer bands",
     ValueField<double>{
         &nested<&R::features, &FeatureSegmentationOptions::band_interior_fraction>}},
    {"merge-angle",
     "touching patches whose normals differ less (degrees) along their border are merged",
     ValueField<double>{&nested<&R::features, &FeatureSegmentationOptions::merge_angle_deg>}},
    {"curved-region-faces",
     "a region this large only grows into faces near its seed's normal, so growth cannot creep "
     "around a scallop cusp; 0 grows without limit (paper); on near-surface meshes any other "
     "value holds every region to its seed from its first face, within 1.5 times the region "
     "angle",
     ValueField<std::size_t>{
         &nested<&R::features, &FeatureSegmentationOptions::curved_region_faces>},
     true},
    {"merge-over-sharp-borders",
     "plain greedy merging (paper): may join patches through smooth borders even where they "
     "meet at a sharp border elsewhere",
     FlagField{&nested<&R::features, &FeatureSegmentationOptions::keep_sharp_borders_apart>, false},
     true},
    {"unconfirmed-border-angle",
     "a patch border without edge vertices is a sharp edge when the patches' normals differ "
     "more (degrees); 180 is the paper's rule",
     ValueField<double>{&nested<&R::bands, &ClassificationOptions::unconfirmed_border_angle_deg>},
     true},
    {"smooth-border-angle",
     "a patch border whose patches' normals differ less (degrees) is never a sharp edge, even "
     "with edge vertices; 0 is the paper's rule",
     ValueField<double>{&nested<&R::bands, &ClassificationOptions::smooth_border_angle_deg>}, true},
    {"smooth-continuation-angle",
     "a crossing edge whose two sides' fitted normal fields, carried to its middle, differ less "
     "(degrees) continues one smooth surface and is not restored; 0 is the paper's rule",
     ValueField<double>{&nested<&R::bands, &ClassificationOptions::smooth_continuation_angle_deg>},
     true},
    {"placement",
     "new points where the band's sides meet: 'tangent-planes' is eq. 5.2 / 5.3 as the paper; "
     "'second-order' meets their fitted curved surfaces, on the edge of a hole or a scallop, "
     "and puts a point beyond its crossing edge's chord inside the face that holds it",
     ChoiceField<PointPlacement>{&nested<&R::points, &SharpPointOptions::placement>, kPlacements},
     true},
    {"spike-angle",
     "corner points are refused when normals around the corner differ more (degrees, paper "
     "5.3)",
     ValueField<double>{&nested<&R::points, &SharpPointOptions::spike_angle_deg>}},
    {"thin-angle",
     "the guard: pieces joining vertices whose normals differ more (degrees) stand across thin "
     "material and must clear both surfaces by a wider margin",
     ValueField<double>{&nested<&R::guard, &GuardOptions::thin_material_angle_deg>}},
    {"fold-angle",
     "the harm check: adjacent output faces whose normals differ more (degrees) than their "
     "input faces' did are folded, and their points undone",
     ValueField<double>{&nested<&R::harm, &HarmCheckOptions::fold_angle_deg>}},
    {"no-crossing-check",
     "skip the harm check's test of every new piece against the faces near it (faster; a "
     "self-intersection is then no longer ruled out)",
     FlagField{&nested<&R::harm, &HarmCheckOptions::check_crossings>, false}},
    {"harm-rounds",
     "rounds of guard, split and harm check at most; past them the mesh comes back unchanged",
     ValueField<int>{&top<&R::max_harm_rounds>}},
    {"keep-duplicate-faces",
     "keep exact duplicate faces (same vertices, same orientation) instead of removing all but "
     "the first copy",
     FlagField{&nested<&R::repair, &MeshRepairOptions::remove_duplicate_faces>, false}},
    {"threads", "worker threads, 0 for all cores; the output does not depend on it",
     ValueField<int>{&top<&R::threads>}},
}};

}  // namespace

std::span<const OptionInfo> restore_option_table() { return kTable; }

}  // namespace resharp
