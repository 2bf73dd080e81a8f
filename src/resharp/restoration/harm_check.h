#pragma once
/// The do-no-harm check: after the split, every output face that replaced an input face is held
/// against the input surface it replaces. It reads the input and the split mesh and says which
/// input faces' pieces do harm; undoing them is the pipeline's (restore()).

#include <cstddef>
#include <vector>

#include "resharp/restoration/input_surface.h"
#include "resharp/restoration/split.h"

namespace resharp {

struct HarmCheckOptions {
    /// Two adjacent output faces whose normals differ by more than this (degrees) are folded,
    /// unless the input faces they replace already differed by as much.
    double fold_angle_deg = 150.0;
    /// Test every piece against the faces near it for crossings (the most costly of the three
    /// checks).
    bool check_crossings = true;
};

struct HarmReport {
    /// Pieces turned more than 90 degrees against every input face nearest their centroid or
    /// one of their vertices (searched within two rings of their source face), or of no area.
    std::size_t turned = 0;
    std::size_t folded = 0;    ///< pieces folded onto an adjacent output face
    std::size_t crossing = 0;  ///< pieces meeting, or coming within rounding of, a nearby face
    /// The input faces whose pieces do harm, ascending: the faces to leave unsplit.
    std::vector<Index> harmful_faces;

    bool is_harmless() const { return harmful_faces.empty(); }
};

/// Takes the input surface and its split; checks the pieces of every split face (faces left
/// whole are the input's own and are not judged). A fault between a piece and another split
/// face's piece blames both faces.
/// \throws InvalidInput if the fold angle is not in (90, 180].
HarmReport check_harm(const InputSurface& input, const SplitMesh& output,
                      const HarmCheckOptions& options = {});

}  // namespace resharp
