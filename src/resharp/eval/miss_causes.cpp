#include "resharp/eval/miss_causes.h"

#include <algorithm>
#include <optional>
#include <vector>

#include "resharp/core/errors.h"
#include "resharp/eval/restoration_rate.h"

namespace resharp::eval {
namespace {

/// Sorted neighbours of every output vertex.
std::vector<std::vector<Index>> neighbours(const Mesh& mesh) {
    std::vector<std::vector<Index>> n(mesh.vertex_count());
    for (const Triangle& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) {
            n[t[k]].push_back(t[(k + 1) % 3]);
            n[t[k]].push_back(t[(k + 2) % 3]);
        }
    }
    for (auto& list : n) {
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
    }
    return n;
}

/// True when a new vertex (index >= first_new) neighbours every one of `ends`.
bool inserted_between(const std::vector<std::vector<Index>>& n, std::span<const Index> ends,
                      Index first_new) {
    for (Index w : n[ends[0]]) {
        if (w < first_new) continue;
        const bool joined = std::all_of(ends.begin() + 1, ends.end(), [&](Index e) {
            return std::binary_search(n[e].begin(), n[e].end(), w);
        });
        if (joined) return true;
    }
    return false;
}

/// The detection cause of a crossing edge (u, v), or nothing if the method found it.
std::optional<MissCause> edge_detection_cause(const Segmentation& s, const IdealPoint& p) {
    const Index u = p.vertices[0], v = p.vertices[1];
    if (!s.vertex_patch.empty()) {
        if (s.vertex_patch[u] == kNoIndex || s.vertex_patch[v] == kNoIndex) {
            return MissCause::NoFeaturePatch;
        }
        if (s.vertex_patch[u] == s.vertex_patch[v]) return MissCause::SamePatch;
        if (!s.is_edge_vertex[u] && !s.is_edge_vertex[v]) return MissCause::NoEdgeVertex;
        return std::nullopt;
    }
    if (s.face_role.empty()) return std::nullopt;
    // Face roles only: the edge counts as found if the face recorded for it is a band face.
    return s.face_role[p.face] == BandRole::None ? std::optional(MissCause::NotDetected)
                                                 : std::nullopt;
}

}  // namespace

std::string_view miss_cause_name(MissCause cause) {
    switch (cause) {
        case MissCause::BeyondChord:
            return "beyond_chord";
        case MissCause::NoFeaturePatch:
            return "no_feature_patch";
        case MissCause::SamePatch:
            return "same_patch";
        case MissCause::NoEdgeVertex:
            return "no_edge_vertex";
        case MissCause::CornerNotDetected:
            return "corner_not_detected";
        case MissCause::NotDetected:
            return "not_detected";
        case MissCause::NotInserted:
            return "not_inserted";
        case MissCause::PlacedFar:
            return "placed_far";
    }
    return "unknown";
}

MissCauses find_miss_causes(const Mesh& input, const Mesh& output,
                            std::span<const IdealPoint> ideal,
                            std::span<const double> ideal_distance, double tolerance,
                            const Segmentation& segmentation) {
    check_output_extends_input(input, output);
    if (ideal.size() != ideal_distance.size()) {
        throw InvalidInput("one distance per ideal point is needed");
    }
    const auto n = neighbours(output);
    const Index first_new = static_cast<Index>(input.vertex_count());
    MissCauses causes;
    for (std::size_t i = 0; i < ideal.size(); ++i) {
        const IdealPoint& p = ideal[i];
        if (p.on_boundary || ideal_distance[i] <= tolerance) continue;
        const bool is_corner = p.kind == IdealKind::Corner;
        std::optional<MissCause> cause;
        if (p.beyond_chord) {
            cause = MissCause::BeyondChord;
        } else if (is_corner && !segmentation.face_role.empty() &&
                   segmentation.face_role[p.face] != BandRole::Corner) {
            cause = MissCause::CornerNotDetected;
        } else if (!is_corner) {
            cause = edge_detection_cause(segmentation, p);
        }
        if (!cause) {
            const std::span<const Index> ends(p.vertices, is_corner ? 3 : 2);
            cause = inserted_between(n, ends, first_new) ? MissCause::PlacedFar
                                                         : MissCause::NotInserted;
        }
        auto& counts = is_corner ? causes.corners : causes.edges;
        ++counts[static_cast<std::size_t>(*cause)];
    }
    return causes;
}

}  // namespace resharp::eval
