#include "resharp/segmentation/feature_segmentation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include "resharp/core/disjoint_sets.h"
#include "resharp/core/errors.h"
#include "resharp/mesh/geometry.h"

namespace resharp {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

void validate(const FeatureSegmentationOptions& o) {
    if (!(o.max_normal_angle_deg > 0.0 && o.max_normal_angle_deg < 180.0)) {
        throw InvalidInput("region growing angle must lie in (0, 180) degrees");
    }
    if (!(o.band_interior_fraction >= 0.0 && o.band_interior_fraction <= 1.0)) {
        throw InvalidInput("band interior fraction must lie in [0, 1]");
    }
    if (!(o.merge_angle_deg >= 0.0 && o.merge_angle_deg < 180.0)) {
        throw InvalidInput("merge angle must lie in [0, 180) degrees");
    }
}

/// §4 steps 1-3: breadth-first growth across manifold edges while neighbouring face normals
/// differ by less than the angle. Seeds are taken in face order, so ids are deterministic.
std::vector<Index> grow_regions(const Connectivity& c, const std::vector<Vec3>& normals,
                                double max_angle_deg, std::size_t& region_count) {
    const double min_cosine = std::cos(max_angle_deg * kDegree);
    std::vector<Index> region(normals.size(), kNoIndex);
    std::vector<Index> queue;
    Index next = 0;
    for (Index seed = 0; seed < normals.size(); ++seed) {
        if (region[seed] != kNoIndex) continue;
        region[seed] = next;
        queue.assign(1, seed);
        for (std::size_t head = 0; head < queue.size(); ++head) {
            const Index u = queue[head];
            for (Index k = 0; k < 3; ++k) {
                const Index twin = c.twin[3 * u + k];
                if (twin == kNoIndex) continue;
                const Index v = face_of(twin);
                if (region[v] == kNoIndex && normals[u].dot(normals[v]) > min_cosine) {
                    region[v] = next;
                    queue.push_back(v);
                }
            }
        }
        ++next;
    }
    region_count = next;
    return region;
}

/// Distinct values of face_patch over the ring of v, skipping kNoIndex; rings are small.
void ring_patches(const Connectivity& c, const std::vector<Index>& face_patch, Index v,
                  std::vector<Index>& out) {
    out.clear();
    for (Index f : c.faces_around(v)) {
        const Index p = face_patch[f];
        if (p != kNoIndex && std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
    }
}

struct PatchCensus {
    std::vector<std::size_t> faces, vertices, interior_vertices, edge_vertices;
};

PatchCensus take_census(const Mesh& mesh, const Connectivity& c, const std::vector<Index>& region,
                        std::size_t count, const std::vector<std::uint8_t>& is_edge) {
    PatchCensus census{std::vector<std::size_t>(count, 0), std::vector<std::size_t>(count, 0),
                       std::vector<std::size_t>(count, 0), std::vector<std::size_t>(count, 0)};
    for (Index r : region) ++census.faces[r];
    std::vector<Index> patches;
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
        ring_patches(c, region, v, patches);
        for (Index p : patches) {
            ++census.vertices[p];
            census.edge_vertices[p] += is_edge[v];
        }
        if (patches.size() == 1) ++census.interior_vertices[patches[0]];
    }
    return census;
}

enum class PatchRole : unsigned char { Feature, Band, Tiny };

std::vector<PatchRole> assign_roles(const PatchCensus& census,
                                    const FeatureSegmentationOptions& o) {
    std::vector<PatchRole> role(census.faces.size(), PatchRole::Feature);
    for (std::size_t p = 0; p < role.size(); ++p) {
        const auto vertices = static_cast<double>(census.vertices[p]);
        const bool one_triangle_wide =
            static_cast<double>(census.interior_vertices[p]) < o.band_interior_fraction * vertices;
        const bool on_edge_vertices = 2 * census.edge_vertices[p] >= census.vertices[p];
        if (one_triangle_wide && on_edge_vertices) {
            role[p] = PatchRole::Band;
        } else if (census.faces[p] < o.tiny_patch_faces) {
            role[p] = PatchRole::Tiny;
        }
    }
    return role;
}

/// §4: a tiny patch joins the feature patch it shares most edges with; one that touches no
/// feature patch lies inside an edge region and becomes band. Repeated so that a cluster of
/// tiny patches drains into its feature neighbour from the outside in.
std::size_t absorb_tiny(const Connectivity& c, std::vector<Index>& region,
                        std::vector<PatchRole>& role) {
    std::size_t absorbed = 0;
    std::vector<std::pair<Index, std::size_t>> shared;  // (feature patch, shared edges)
    bool changed = true;
    while (changed) {
        changed = false;
        std::vector<std::vector<std::pair<Index, std::size_t>>> votes(role.size());
        for (std::size_t h = 0; h < c.twin.size(); ++h) {
            const Index twin = c.twin[h];
            if (twin == kNoIndex) continue;
            const Index mine = region[face_of(static_cast<Index>(h))];
            const Index theirs = region[face_of(twin)];
            if (role[mine] != PatchRole::Tiny || role[theirs] != PatchRole::Feature) continue;
            auto& v = votes[mine];
            auto it = std::find_if(v.begin(), v.end(), [&](auto& e) { return e.first == theirs; });
            if (it == v.end()) v.emplace_back(theirs, 1);
            else ++it->second;
        }
        std::vector<Index> target(role.size(), kNoIndex);
        for (Index p = 0; p < role.size(); ++p) {
            if (votes[p].empty()) continue;
            target[p] = std::max_element(votes[p].begin(), votes[p].end(), [](auto& a, auto& b) {
                            return a.second < b.second || (a.second == b.second && a.first > b.first);
                        })->first;
        }
        for (Index& r : region) {
            if (target[r] != kNoIndex) r = target[r];
        }
        for (Index p = 0; p < role.size(); ++p) {
            if (target[p] == kNoIndex) continue;
            role[p] = PatchRole::Band;  // emptied: its faces now carry the target's id
            ++absorbed;
            changed = true;
        }
    }
    for (PatchRole& r : role) {
        if (r == PatchRole::Tiny) r = PatchRole::Band;  // no feature neighbour: an edge region
    }
    return absorbed;
}

/// Angle-weighted normal at v of the ring faces in patch p (eq. 5.1 restricted to one patch).
Vec3 patch_normal_at(const Mesh& mesh, const Connectivity& c, const std::vector<Vec3>& normals,
                     const std::vector<Index>& face_patch, Index v, Index p) {
    Vec3 sum = Vec3::Zero();
    for (Index f : c.faces_around(v)) {
        if (face_patch[f] == p) sum += corner_angle(mesh, f, corner_of(mesh.triangles[f], v)) * normals[f];
    }
    return sum.normalized();
}

/// Greedy merging of over-segmented patches (§4, Fig. 5): every vertex shared by two patches
/// votes the angle between the two patches' normals there; pairs are merged in order of
/// increasing median angle while it stays below the merge angle.
std::size_t merge_patches(const Mesh& mesh, const Connectivity& c, const std::vector<Vec3>& normals,
                          double merge_angle_deg, std::vector<Index>& face_patch,
                          std::size_t patch_count) {
    std::vector<std::tuple<Index, Index, double>> votes;
    std::vector<Index> patches;
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
        ring_patches(c, face_patch, v, patches);
        std::sort(patches.begin(), patches.end());
        for (std::size_t a = 0; a < patches.size(); ++a) {
            const Vec3 na = patch_normal_at(mesh, c, normals, face_patch, v, patches[a]);
            for (std::size_t b = a + 1; b < patches.size(); ++b) {
                const Vec3 nb = patch_normal_at(mesh, c, normals, face_patch, v, patches[b]);
                votes.emplace_back(patches[a], patches[b], angle_deg(na, nb));
            }
        }
    }
    std::sort(votes.begin(), votes.end());
    std::vector<std::tuple<double, Index, Index>> pairs;  // (median angle, a, b)
    for (std::size_t i = 0; i < votes.size();) {
        std::size_t j = i;
        while (j < votes.size() && std::get<0>(votes[j]) == std::get<0>(votes[i]) &&
               std::get<1>(votes[j]) == std::get<1>(votes[i])) {
            ++j;
        }
        pairs.emplace_back(std::get<2>(votes[i + (j - i) / 2]), std::get<0>(votes[i]),
                           std::get<1>(votes[i]));
        i = j;
    }
    std::sort(pairs.begin(), pairs.end());
    DisjointSets sets(patch_count);
    std::size_t merges = 0;
    for (const auto& [angle, a, b] : pairs) {
        if (angle >= merge_angle_deg) break;
        merges += sets.unite(a, b);
    }
    for (Index& p : face_patch) {
        if (p != kNoIndex) p = sets.find(p);
    }
    return merges;
}

/// Renumbers patch ids densely in order of first face; returns the count.
std::size_t compact_ids(std::vector<Index>& face_patch, std::size_t id_bound) {
    std::vector<Index> dense(id_bound, kNoIndex);
    Index next = 0;
    for (Index& p : face_patch) {
        if (p == kNoIndex) continue;
        if (dense[p] == kNoIndex) dense[p] = next++;
        p = dense[p];
    }
    return next;
}

/// §4 step 4: each vertex joins the patch with the most faces in its one-ring (ties: lower id).
std::vector<Index> label_vertices(const Mesh& mesh, const Connectivity& c,
                                  const std::vector<Index>& face_patch) {
    std::vector<Index> label(mesh.vertex_count(), kNoIndex);
    std::vector<std::pair<Index, int>> counts;
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
        counts.clear();
        for (Index f : c.faces_around(v)) {
            const Index p = face_patch[f];
            if (p == kNoIndex) continue;
            auto it = std::find_if(counts.begin(), counts.end(), [&](auto& e) { return e.first == p; });
            if (it == counts.end()) counts.emplace_back(p, 1);
            else ++it->second;
        }
        int best = 0;
        for (const auto& [p, n] : counts) {
            if (n > best || (n == best && p < label[v])) {
                best = n;
                label[v] = p;
            }
        }
    }
    return label;
}

}  // namespace

FeatureSegmentation segment_features(const Mesh& mesh, const Connectivity& connectivity,
                                     const std::vector<Vec3>& face_normals,
                                     const std::vector<std::uint8_t>& is_edge_vertex,
                                     const FeatureSegmentationOptions& options) {
    validate(options);
    FeatureSegmentation s;
    std::vector<Index> region =
        grow_regions(connectivity, face_normals, options.max_normal_angle_deg, s.grown_patches);
    const PatchCensus census =
        take_census(mesh, connectivity, region, s.grown_patches, is_edge_vertex);
    std::vector<PatchRole> role = assign_roles(census, options);
    s.band_patches = static_cast<std::size_t>(std::count(role.begin(), role.end(), PatchRole::Band));
    s.tiny_absorbed = absorb_tiny(connectivity, region, role);

    for (Index& r : region) {
        if (role[r] == PatchRole::Band) r = kNoIndex;
    }
    s.merges = merge_patches(mesh, connectivity, face_normals, options.merge_angle_deg, region,
                             s.grown_patches);
    s.patch_count = compact_ids(region, s.grown_patches);
    s.face_patch = std::move(region);
    s.vertex_patch = label_vertices(mesh, connectivity, s.face_patch);
    return s;
}

}  // namespace resharp
