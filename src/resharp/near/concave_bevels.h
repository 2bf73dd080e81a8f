#pragma once
/// Near-surface restoration, before the moves (issue 14): the bevels a dual mesher leaves along
/// concave edges, found and given back to the band.
///
/// OpenVDB's volumeToMesh finds a crossing by interpolating the signed distance linearly
/// between voxel centres. Along a concave edge the distance at a centre in the empty corner is
/// to the edge itself, far larger than to either face, so the crossings come out early and the
/// cells put their vertices on a plane across the corner, two to three cells wide: across the
/// floor edge y = 10, z = 16 of a pocket at pitch 0.6 mm, (10.224, 16.824), (10.524, 16.524)
/// and (10.824, 16.224), the middle one in a cell the true surface does not cross. Segmentation
/// takes that strip for a narrow face of its own, and the paper's method restores its two
/// borders: two creases of about 45 degrees half a millimetre off the edge. Dissolved (its
/// faces and vertices in no patch), its vertices are vertices between patches, which the moves
/// take onto the junction of the two faces (near/vertex_moves.h).

#include <cstddef>

#include "resharp/near/vertex_moves.h"
#include "resharp/restoration/band_classification.h"
#include "resharp/restoration/input_surface.h"
#include "resharp/segmentation/feature_segmentation.h"

namespace resharp {

struct BevelDissolution {
    FeatureSegmentation features;  ///< the segmentation given, the bevels' patches dissolved
    /// bevels dissolved: strips' patches, and pieces of strips that turn a corner
    std::size_t bevels = 0;
};

/// Takes the mesh as it stands, its feature segmentation (taken over: most meshes have no bevel,
/// and a copy was 6 bytes a face of fresh memory) and bands, and the grid its vertices were
/// placed on; gives the segmentation with every concave bevel dissolved (its faces in no patch,
/// and with them the faces reached from them whose corners all lie in the bevel's corner, not all
/// on one of its faces, whatever their patch: a row beside the bevel that grew into a face's
/// patch; a vertex keeps its patch while a face around it has it, else takes the patch with the
/// most faces around it, none if no other). A bevel is a strip (a patch with few vertices for its
/// size), or where a strip is none as a whole, a piece of it whose faces' normals lie near one
/// another (a strip that turns a pocket's corner), whose vertices lie about one plane (within
/// options.max_scatter_near pitches, rms, most of them: its ends bend round a pocket's rounded
/// corners) between the planes of two patches next to the strip or next to those (each fitted to
/// its vertices off the bands, as flat, or where a patch has no plane as a whole, to those along
/// the strip: a pocket's walls round its rounded corners), parting by more than
/// options.junction_angle_deg at a concave edge, all but a tenth of its vertices (where it ends
/// at the part's sides) in front of both planes and within two pitches of where they meet
/// (farther where they meet at an acute angle, as far as the corner is as wide). A strip that
/// lies across the concave edge of a flat patch and a curved one (no plane as a whole) is a
/// bevel too where all but a tenth of its vertices face both and lie in their corner so, the
/// curved face taken as its tangent plane at its vertex off the bands nearest each (a round
/// pocket's floor circle, a hub where it meets a flange); the faces of its pieces that are
/// bevels of two planes spread as above, the rest of it not. Each
/// patch is judged on the segmentation given, so the result does not depend on the order they
/// are judged in. Bound: a pass over the vertices and faces, a plane fit per patch, per strip
/// (or piece) a test per pair of the patches within two steps of it (with a fit along it for each
/// of those with no plane as a whole; for a curved one a walk of four rings per vertex), and
/// each face once in the spread.
BevelDissolution without_concave_bevels(const InputSurface& current, FeatureSegmentation features,
                                        const BandClassification& bands, const Grid& grid,
                                        const VertexMoveOptions& options = {});

}  // namespace resharp
