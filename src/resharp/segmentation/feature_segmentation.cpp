#include "resharp/segmentation/feature_segmentation.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <span>
#include <string>
#include <tuple>

#include "resharp/core/disjoint_sets.h"
#include "resharp/core/errors.h"
#include "resharp/core/parallel.h"
#include "resharp/mesh/geometric_order.h"
#include "resharp/mesh/geometry.h"

namespace resharp {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

/// Near: the faces a region takes before it holds to its seed's normal
/// (curved_region_faces, 300 on exact meshes), here one: the seed.
/// A dual mesher rounds a sharp edge over the cells it crosses, in steps of a few degrees from
/// face to face, so that growth under the growing angle crept from a face over the rounding onto
/// the next face: cone_part aligned by OpenVDB at 100 cells came out of region growing with its
/// top and its 45-degree chamfer in one region, and with them its cylinder. Held to the seed, a
/// region ends where the faces have turned by the angle; curved faces come out in pieces, which
/// merging joins again, as on exact meshes past 300 faces (docs/method.md, *Regions held to
/// their seed*: OpenVDB's mean Edge F-score on the CAD corpus and the benchmark parts 0.808 ->
/// 0.830, cone_part aligned 0.655 -> 0.821).
constexpr std::size_t kNearRegionFaces = 1;
/// Near: how far from its seed's normal a region still takes faces, in growing angles
/// (curved_seed_reach; 1 on exact meshes). Held within the growing
/// angle itself, a boss 6.6 cells in radius came out in pieces two cells wide, tiny patches,
/// and 0.21 of its circle on the plate came back on a crease (OpenVdbMesher's test asks 0.25);
/// the mean Edge F-score above was 0.827 at 1, 0.828 at 1.25, 0.830 at 1.5, 0.827 at 1.875
/// and 0.824 at 2.5.
constexpr double kNearSeedReach = 1.5;
/// Near: the share of a one-triangle-wide strip's vertices that must be edge vertices for it to
/// be a band (band_edge_fraction; a half on exact meshes). Strips of a dual mesher's bands fell
/// short of a half and were kept as features, their edges lost: a third lifted OpenVDB's mean
/// Edge F-score on the CAD corpus and the benchmark parts 0.830 -> 0.838 (stepped_block aligned
/// 0.897 -> 0.939, spool 0.830 -> 0.885; sphere_part 0.852 -> 0.841) and surface nets' 0.906 ->
/// 0.909 (docs/method.md, *Bands of a third of edge vertices*). Until the harm check weighed
/// the faces beyond its rings, a round pocket's floor circle next to a thin wall then came out
/// with faces turned against the input.
constexpr double kNearBandEdgeFraction = 1.0 / 3.0;

void validate(const FeatureSegmentationOptions& o) {
    if (!(o.max_normal_angle_deg > 0.0 && o.max_normal_angle_deg < 180.0)) {
        throw InvalidInput("region growing angle must lie in (0, 180) degrees");
    }
    if (!(o.band_interior_fraction >= 0.0 && o.band_interior_fraction <= 1.0)) {
        throw InvalidInput("band interior fraction must lie in [0, 1]");
    }
    if (!(o.band_edge_fraction >= 0.0 && o.band_edge_fraction <= 1.0)) {
        throw InvalidInput("band edge-vertex fraction must lie in [0, 1]");
    }
    if (!(o.merge_angle_deg >= 0.0 && o.merge_angle_deg < 180.0)) {
        throw InvalidInput("merge angle must lie in [0, 180) degrees");
    }
    if (!(o.curved_seed_reach >= 1.0 && o.curved_seed_reach * o.max_normal_angle_deg < 180.0)) {
        throw InvalidInput(
            "curved regions' seed reach must be at least 1 and, times the growing angle, under 180 "
            "degrees");
    }
}

/// The sides of face f in geometric order: its half-edge across from its first corner in
/// sweep order first (side k is half-edge 3f + k). A face's index, the rotation of its corners
/// and its orientation leave it.
std::array<int, 3> sides_in_sweep_order(const Mesh& mesh, Index f) {
    const std::array<Index, 3> corners = corners_in_sweep_order(mesh, f);
    const std::array<Index, 3>& t = mesh.triangles[f];
    std::array<int, 3> order{};
    for (int k = 0; k < 3; ++k) {
        const int j = t[0] == corners[k] ? 0 : (t[1] == corners[k] ? 1 : 2);
        order[k] = (j + 1) % 3;  // half-edge (j + 1) % 3 is opposite corner j
    }
    return order;
}

/// Whether every two faces of `faces` have normals within max_angle_deg of each other: true
/// when all lie within half that angle of their mean direction (a sufficient test, O(faces)). Then
/// a seed's normal never refuses a face of them, whichever face seeds.
bool normals_within_angle(const std::vector<Vec3>& normals, std::span<const Index> faces,
                          double max_angle_deg) {
    Vec3 mean = Vec3::Zero();
    for (Index f : faces) mean += normals[f];
    const double length = mean.norm();
    if (length == 0.0) return false;
    mean /= length;
    const double min_cosine = std::cos(0.5 * max_angle_deg * kDegree);
    return std::all_of(faces.begin(), faces.end(),
                       [&](Index f) { return mean.dot(normals[f]) >= min_cosine; });
}

/// Growth settings shared by the two passes of grow_regions().
struct Growth {
    const Mesh& mesh;
    const Connectivity& c;
    const std::vector<Vec3>& normals;
    double min_cosine;  // of the growing angle
    std::size_t curved_limit;
    double seed_min_cosine;  // of the angle a limited region keeps to its seed's normal
};

/// Breadth-first growth of region `id` from `seed` over the faces open(f) holds for, along
/// `links` (growth_links(): manifold edges whose faces' normals differ by less than the angle);
/// past `curved_limit` faces (more than 0) only into faces within the seed's reach. Leaves
/// the region's faces in `taken`, in the order taken. Until the limit a face's open sides are
/// crossed in geometric (sweep) order, so the region does not depend on how the mesh numbers
/// its faces or corners. The links, not the normals, are read until the limit: most of the
/// growth's time was spent waiting for the normals of faces far apart in memory.
template <class Open>
void grow_from(const Growth& g, const std::vector<std::uint8_t>& links, Index seed, Open&& open,
               Index id, std::vector<Index>& region, std::vector<Index>& taken) {
    taken.assign(1, seed);
    region[seed] = id;
    // Bound: a face joins a region, and `taken`, once.
    for (std::size_t head = 0; head < taken.size(); ++head) {
        const Index u = taken[head];
        std::array<Index, 3> across{kNoIndex, kNoIndex, kNoIndex};  // per side: an open face
        int open_sides = 0;
        for (int k = 0; k < 3; ++k) {
            if (!(links[u] >> k & 1u)) continue;
            const Index v = face_of(g.c.twin[3 * u + k]);
            if (open(v)) across[k] = v, ++open_sides;
        }
        // Past the limit the region is every face reachable under both tests from those taken
        // so far, whatever the order: only the first curved_limit faces depend on it. One open
        // side has no order to keep.
        const bool in_order = open_sides > 1 && taken.size() < g.curved_limit;
        const std::array<int, 3> sides =
            in_order ? sides_in_sweep_order(g.mesh, u) : std::array<int, 3>{0, 1, 2};
        for (int k : sides) {
            const Index v = across[k];
            if (v == kNoIndex || !open(v)) continue;  // (two sides of a face may lead to one)
            const bool limited = taken.size() >= g.curved_limit;
            if (limited && g.normals[seed].dot(g.normals[v]) <= g.seed_min_cosine) continue;
            region[v] = id;
            taken.push_back(v);
        }
    }
}

/// Grows the faces of one component again as limited regions, seeded in sweep order: the first
/// face not yet taken seeds the next region, as the face order of a mesher sweeping its grid
/// slab by slab would. Numbers them in `region` from 0; returns how many there are. The links
/// lead only to faces of the component: others may be growing in `region` meanwhile.
Index regrow_in_sweep_order(const Growth& g, const std::vector<std::uint8_t>& links,
                            std::span<const Index> component, std::vector<Index>& region) {
    constexpr Index kOpen = kNoIndex - 1;  // ids stay below #F
    for (Index f : component) region[f] = kOpen;
    FacesInSweepOrder seeds(g.mesh, component);
    auto open = [&](Index f) { return region[f] == kOpen; };
    std::vector<Index> taken;
    Index next = 0;
    // Bound: every seed starts a region that takes at least itself, so at most |component|.
    for (Index seed = seeds.next(open); seed != kNoIndex; seed = seeds.next(open)) {
        grow_from(g, links, seed, open, next++, region, taken);
    }
    return next;
}

/// Per face, bit k set where growth may cross its half-edge k: a manifold edge whose faces'
/// normals differ by less than the angle (the dot product is the same bits either way round, so
/// the links are symmetric, and those of a component lead only into it). Taken in parallel:
/// these tests are most of the first pass's work, and both passes then follow links.
std::vector<std::uint8_t> growth_links(const Growth& g) {
    std::vector<std::uint8_t> links(g.normals.size(), 0);
    for_each_index(links.size(), 4096, [&](std::size_t f) {
        for (int k = 0; k < 3; ++k) {
            const Index twin = g.c.twin[3 * f + k];
            if (twin != kNoIndex && g.normals[f].dot(g.normals[face_of(twin)]) > g.min_cosine) {
                links[f] |= static_cast<std::uint8_t>(1u << k);
            }
        }
    });
    return links;
}

/// grow_from() without a limit, on the links: the component `id` of `seed`, its faces in
/// `taken` in the order grow_from() takes them (half-edges 0, 1, 2 of each face in turn).
void take_component(const Connectivity& c, const std::vector<std::uint8_t>& links, Index seed,
                    Index id, std::vector<Index>& region, std::vector<Index>& taken) {
    taken.assign(1, seed);
    region[seed] = id;
    // Bound: a face joins the component, and `taken`, once.
    for (std::size_t head = 0; head < taken.size(); ++head) {
        const Index u = taken[head];
        for (int k = 0; k < 3; ++k) {
            if (!(links[u] >> k & 1u)) continue;
            const Index v = face_of(c.twin[3 * u + k]);
            if (region[v] != kNoIndex) continue;
            region[v] = id;
            taken.push_back(v);
        }
    }
}

/// A component grown again (regrow_in_sweep_order()): its number among all components, its
/// faces, and how many regions it became.
struct Regrown {
    Index component;
    std::vector<Index> faces;
    Index regions = 0;
};

/// §4 steps 1-3: breadth-first growth across manifold edges while neighbouring face normals
/// differ by less than the angle. A region holding curved_region_faces faces (0: no limit) only
/// takes faces within the seed's reach (curved_seed_reach angles) of its seed's normal, so it
/// depends on where it starts. Every component of the growth relation is grown once without
/// the limit; one of more than curved_region_faces faces whose normals the limit could
/// refuse (normals_within_angle()) is grown again with seeds and neighbours in geometric order,
/// so which faces share a region does not depend on the face order, the corners' rotation or
/// the orientation (issue 12). Ids follow the face order of the components' first faces; they
/// are never compared where a tie must not depend on it (wins_tie()). The components grown
/// again are independent (no growth crosses from one to another), so they grow in parallel,
/// each numbering its regions from 0 in an array of its own, and take their ids after.
std::vector<Index> grow_regions(const Mesh& mesh, const Connectivity& c,
                                const std::vector<Vec3>& normals,
                                const FeatureSegmentationOptions& o, std::size_t& region_count) {
    const std::size_t curved_limit = o.curved_region_faces;
    const double seed_reach_deg = o.curved_seed_reach * o.max_normal_angle_deg;
    const double min_cosine = std::cos(o.max_normal_angle_deg * kDegree);
    const Growth unlimited{mesh, c, normals, min_cosine, 0, -1.0};
    const Growth limited{
        mesh, c, normals, min_cosine, curved_limit, std::cos(seed_reach_deg * kDegree)};
    std::vector<Index> region(normals.size(), kNoIndex);  // first the component of each face
    std::vector<Index> component;
    std::vector<Regrown> regrown;
    Index components = 0;
    const std::vector<std::uint8_t> links = growth_links(unlimited);
    // Bound: each seed takes at least itself, so at most #F components.
    for (Index seed = 0; seed < normals.size(); ++seed) {
        if (region[seed] != kNoIndex) continue;
        take_component(c, links, seed, components, region, component);
        if (curved_limit != 0 && component.size() > curved_limit &&
            !normals_within_angle(normals, component, seed_reach_deg)) {
            regrown.push_back({components, component});
        }
        ++components;
    }
    region_count = components;
    if (regrown.empty()) return region;  // the components are the regions
    // Per face, its region's number within its component (0 where that is not grown again).
    std::vector<Index> local(normals.size(), 0);
    for_each_index(regrown.size(), 1, [&](std::size_t i) {
        Regrown& r = regrown[i];
        r.regions = regrow_in_sweep_order(limited, links, r.faces, local);
    });
    std::vector<Index> first_id(components + 1, 1);  // per component, as prefix sums
    first_id[0] = 0;
    for (const Regrown& r : regrown) first_id[r.component + 1] = r.regions;
    for (std::size_t k = 1; k < first_id.size(); ++k) first_id[k] += first_id[k - 1];
    for (Index f = 0; f < region.size(); ++f) region[f] = first_id[region[f]] + local[f];
    region_count = first_id.back();
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

/// The value of face_patch shared by every face around v, or kMixedRing when they differ.
/// Most vertices are inside one patch; this lets the loops below skip them cheaply.
constexpr Index kMixedRing = kNoIndex - 1;
Index ring_patch_if_single(const Connectivity& c, const std::vector<Index>& face_patch, Index v) {
    const auto ring = c.faces_around(v);
    if (ring.empty()) return kMixedRing;
    const Index first = face_patch[ring[0]];
    for (Index f : ring) {
        if (face_patch[f] != first) return kMixedRing;
    }
    return first;
}

/// Per vertex (#V): ring_patch_if_single() over face_patch. Taken once for the loops that read
/// the same ids.
std::vector<Index> single_ring_patches(const Connectivity& c, const std::vector<Index>& face_patch,
                                       std::size_t vertex_count) {
    std::vector<Index> single(vertex_count);
    for_each_index(vertex_count, 4096, [&](std::size_t v) {
        single[v] = ring_patch_if_single(c, face_patch, static_cast<Index>(v));
    });
    return single;
}

/// single_ring_patches() of face_patch, given those (`before`) of ids that face_patch maps to one
/// id each, keeping kNoIndex (merged and renumbered). A ring of one id before has one after,
/// that of any of its faces; only the mixed rings are looked at again.
std::vector<Index> carry_single_patches(const Connectivity& c, const std::vector<Index>& face_patch,
                                        std::vector<Index> before) {
    for_each_index(before.size(), 4096, [&](std::size_t i) {
        const Index v = static_cast<Index>(i);
        Index& single = before[v];
        if (single == kMixedRing) {
            single = ring_patch_if_single(c, face_patch, v);
        } else if (single != kNoIndex) {
            single = face_patch[c.faces_around(v)[0]];
        }
    });
    return before;
}

struct PatchCensus {
    std::vector<std::size_t> faces, vertices, interior_vertices, edge_vertices;
};

/// `single`: single_ring_patches() of region.
PatchCensus take_census(const Mesh& mesh, const Connectivity& c, const std::vector<Index>& region,
                        const std::vector<Index>& single, std::size_t count,
                        const std::vector<std::uint8_t>& is_edge) {
    PatchCensus census{std::vector<std::size_t>(count, 0), std::vector<std::size_t>(count, 0),
                       std::vector<std::size_t>(count, 0), std::vector<std::size_t>(count, 0)};
    for (Index r : region) ++census.faces[r];
    std::vector<Index> patches;
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
        if (single[v] != kMixedRing) {
            ++census.vertices[single[v]];
            census.edge_vertices[single[v]] += is_edge[v];
            ++census.interior_vertices[single[v]];
            continue;
        }
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
        const bool on_edge_vertices =
            static_cast<double>(census.edge_vertices[p]) >= o.band_edge_fraction * vertices;
        if (one_triangle_wide && on_edge_vertices) {
            role[p] = PatchRole::Band;
        } else if (census.faces[p] < o.tiny_patch_faces) {
            role[p] = PatchRole::Tiny;
        }
    }
    return role;
}

std::vector<Index> faces_of_tiny_patches(const std::vector<Index>& region,
                                         const std::vector<PatchRole>& role) {
    std::vector<Index> faces;
    for (Index f = 0; f < region.size(); ++f) {
        if (role[region[f]] == PatchRole::Tiny) faces.push_back(f);
    }
    return faces;
}

/// How a tiny patch touches one feature patch: shared edges and the summed cosine of the angle
/// between the face normals across them.
struct Contact {
    Index patch = kNoIndex;
    std::size_t edges = 0;
    double cosine_sum = 0.0;
};

/// For every tiny patch, its contacts with feature patches. Only the faces of tiny patches are
/// visited: they are few, and the loop runs once per round of absorption.
std::vector<std::vector<Contact>> tiny_contacts(const Connectivity& c,
                                                const std::vector<Vec3>& normals,
                                                const std::vector<Index>& region,
                                                const std::vector<PatchRole>& role,
                                                const std::vector<Index>& tiny_faces) {
    std::vector<std::vector<Contact>> contacts(role.size());
    for (Index f : tiny_faces) {
        const Index mine = region[f];
        if (role[mine] != PatchRole::Tiny) continue;
        for (Index k = 0; k < 3; ++k) {
            const Index twin = c.twin[3 * f + k];
            if (twin == kNoIndex) continue;
            const Index theirs = region[face_of(twin)];
            if (role[theirs] != PatchRole::Feature) continue;
            auto& list = contacts[mine];
            auto it =
                std::find_if(list.begin(), list.end(), [&](auto& e) { return e.patch == theirs; });
            if (it == list.end()) it = list.insert(list.end(), Contact{theirs});
            ++it->edges;
            it->cosine_sum += normals[f].dot(normals[face_of(twin)]);
        }
    }
    return contacts;
}

/// The contact a tiny patch joins: the one with most shared edges among those whose normals
/// agree across the border on average (same surface); kNoIndex if none does.
Index absorbing_patch(const std::vector<Contact>& contacts, double min_mean_cosine) {
    Index best = kNoIndex;
    std::size_t best_edges = 0;
    for (const Contact& contact : contacts) {
        const double mean = contact.cosine_sum / static_cast<double>(contact.edges);
        const bool better =
            contact.edges > best_edges || (contact.edges == best_edges && contact.patch < best);
        if (mean > min_mean_cosine && better) {
            best = contact.patch;
            best_edges = contact.edges;
        }
    }
    return best;
}

/// §4: a tiny patch moves into the neighbouring feature patch of the same surface (the one it
/// shares most edges with among those whose normals agree across the border); a tiny patch with
/// no such neighbour is left tiny (join_tiny_leftovers() decides it). Without the agreement test a
/// tiny piece of a curved wall would join the flat face above it through a corner of the band,
/// and merging would then pour the whole wall into that face. Repeated so that clusters of tiny
/// patches drain into their feature neighbour from the outside in.
/// Passes of absorb_tiny at most: clusters of tiny patches on real parts drain in a few.
constexpr int kMaxAbsorbPasses = 64;

/// `tiny_faces`: faces_of_tiny_patches() of region and role as given.
std::size_t absorb_tiny(const Connectivity& c, const std::vector<Vec3>& normals,
                        double max_angle_deg, const std::vector<Index>& tiny_faces,
                        std::vector<Index>& region, std::vector<PatchRole>& role) {
    const double min_mean_cosine = std::cos(max_angle_deg * kDegree);
    std::size_t absorbed = 0;
    bool changed = true;
    // Bound: each pass that changes anything empties at least one tiny patch for good, and at
    // most kMaxAbsorbPasses passes run, each linear in the tiny faces; patches deeper inside a
    // cluster than that are left over, as patches with no feature neighbour are.
    for (int pass = 0; changed && pass < kMaxAbsorbPasses; ++pass) {
        changed = false;
        const auto contacts = tiny_contacts(c, normals, region, role, tiny_faces);
        std::vector<Index> target(role.size(), kNoIndex);
        for (Index p = 0; p < role.size(); ++p) {
            target[p] = absorbing_patch(contacts[p], min_mean_cosine);
        }
        for (Index f : tiny_faces) {
            if (target[region[f]] != kNoIndex) region[f] = target[region[f]];
        }
        for (Index p = 0; p < role.size(); ++p) {
            if (target[p] == kNoIndex) continue;
            role[p] = PatchRole::Band;  // emptied: its faces now carry the target's id
            ++absorbed;
            changed = true;
        }
    }
    return absorbed;
}

/// Sets of the tiny patches absorb_tiny() left (no feature neighbour of their surface), joined
/// across edges whose faces' normals agree within the merge angle.
struct TinySets {
    DisjointSets sets;
    std::vector<std::size_t> faces;  ///< per set root: its faces
    /// per set root: 1 where unite_large_sets_across_smooth_borders() made it
    std::vector<std::uint8_t> united;
};

/// Calls visit(f, g) for each face f of `tiny_faces` and each face g of a tiny patch across one
/// of f's edges (each such edge once from either side).
template <class Visit>
void for_each_tiny_neighbour(const Connectivity& c, const std::vector<Index>& region,
                             const std::vector<PatchRole>& role,
                             const std::vector<Index>& tiny_faces, Visit&& visit) {
    for (Index f : tiny_faces) {
        for (Index k = 0; k < 3; ++k) {
            const Index twin = c.twin[3 * f + k];
            if (twin != kNoIndex && role[region[face_of(twin)]] == PatchRole::Tiny) {
                visit(f, face_of(twin));
            }
        }
    }
}

TinySets join_across_smooth_edges(const Connectivity& c, const std::vector<Vec3>& normals,
                                  double max_angle_deg, const std::vector<Index>& region,
                                  const std::vector<PatchRole>& role,
                                  const std::vector<Index>& tiny_faces) {
    TinySets t{DisjointSets(role.size()), std::vector<std::size_t>(role.size(), 0),
               std::vector<std::uint8_t>(role.size(), 0)};
    const double min_cosine = std::cos(max_angle_deg * kDegree);
    for_each_tiny_neighbour(c, region, role, tiny_faces, [&](Index f, Index g) {
        if (normals[f].dot(normals[g]) > min_cosine) t.sets.unite(region[f], region[g]);
    });
    for (Index f : tiny_faces) ++t.faces[t.sets.find(region[f])];
    return t;
}

/// Two large sets of leftover tiny patches whose shared edges' faces part by less than this on
/// average (degrees; the sharp angle theta_s) are facets of one smooth surface.
constexpr double kSmoothSetBorderDeg = 30.0;

/// The edges between pairs of things (sets, patches), and the summed cosines of the angles
/// between their faces' normals: which pairs meet smoothly on average.
class BorderAngles {
public:
    void add(Index a, Index b, const Vec3& normal_a, const Vec3& normal_b) {
        auto& [edges, cosines] = borders_[{a, b}];
        ++edges;
        cosines += normal_a.dot(normal_b);
    }
    /// Calls visit(a, b) for each pair whose faces part by less than kSmoothSetBorderDeg on
    /// average across their edges.
    template <class Visit>
    void for_each_smooth(Visit&& visit) const {
        const double min_cosine = std::cos(kSmoothSetBorderDeg * kDegree);
        for (const auto& [pair, border] : borders_) {
            const auto& [edges, cosines] = border;
            if (cosines > min_cosine * static_cast<double>(edges)) visit(pair.first, pair.second);
        }
    }

private:
    std::map<std::pair<Index, Index>, std::pair<std::size_t, double>> borders_;
};

/// Unites the sets of at least `min_faces` faces that meet across edges whose faces' normals
/// part by less than kSmoothSetBorderDeg on average, marks the sets so made in `t.united`, and
/// counts the sets' faces again. A half cylinder of 3.3 h turned off the grid axes
/// (fillet_boss's rib at 100 cells) comes out of region growing as pieces that join into a few
/// large sets, whose facets turn by about 19 degrees where they meet: each set met another and
/// the whole rib stayed edge region, its feet on the plate with no crossing edge. Bound: each
/// tiny face's edges once, then each border once.
void unite_large_sets_across_smooth_borders(const Connectivity& c, const std::vector<Vec3>& normals,
                                            const std::vector<Index>& region,
                                            const std::vector<PatchRole>& role,
                                            const std::vector<Index>& tiny_faces,
                                            std::size_t min_faces, TinySets& t) {
    BorderAngles borders;
    for_each_tiny_neighbour(c, region, role, tiny_faces, [&](Index f, Index g) {
        const Index a = t.sets.find(region[f]), b = t.sets.find(region[g]);
        if (a < b && t.faces[a] >= min_faces && t.faces[b] >= min_faces)
            borders.add(a, b, normals[f], normals[g]);
    });
    std::vector<Index> united;
    borders.for_each_smooth([&](Index a, Index b) {
        t.sets.unite(a, b);
        united.push_back(a);
    });
    if (united.empty()) return;
    for (Index a : united) t.united[t.sets.find(a)] = 1;
    std::fill(t.faces.begin(), t.faces.end(), 0);
    for (Index f : tiny_faces) ++t.faces[t.sets.find(region[f])];
}

/// Per set root: whether the set meets another set of at least `min_faces` faces, or, for a set
/// that unite_large_sets_across_smooth_borders() made, a feature patch across edges whose faces'
/// normals part by less than kSmoothSetBorderDeg on average: then it is a piece of that patch's
/// smooth surface, not a surface of its own (on the torus of 3 h aligned two sets united so
/// meet two patches of the tube at 18 and 20 degrees, and as a patch had five phantom points
/// put beside them). A set that no union made keeps the rule before (taking it for every set
/// cost rounded_pocket aligned at 50 cells 0.866 -> 0.798 of its Edge F-score).
std::vector<std::uint8_t> crowded_sets(const Connectivity& c, const std::vector<Vec3>& normals,
                                       const std::vector<Index>& region,
                                       const std::vector<PatchRole>& role,
                                       const std::vector<Index>& tiny_faces, std::size_t min_faces,
                                       TinySets& t) {
    std::vector<std::uint8_t> crowded(role.size(), 0);
    for_each_tiny_neighbour(c, region, role, tiny_faces, [&](Index f, Index g) {
        const Index mine = t.sets.find(region[f]);
        const Index theirs = t.sets.find(region[g]);
        if (mine != theirs && t.faces[theirs] >= min_faces) crowded[mine] = 1;
    });
    BorderAngles borders;
    for (Index f : tiny_faces) {
        const Index mine = t.sets.find(region[f]);
        if (!t.united[mine]) continue;
        for (Index k = 0; k < 3; ++k) {
            const Index twin = c.twin[3 * f + k];
            if (twin == kNoIndex || role[region[face_of(twin)]] != PatchRole::Feature) continue;
            borders.add(mine, region[face_of(twin)], normals[f], normals[face_of(twin)]);
        }
    }
    borders.for_each_smooth([&](Index set, Index) { crowded[set] = 1; });
    return crowded;
}

/// The tiny patches absorb_tiny() left lie within edge regions and become band, but for a small
/// surface of its own that region growing cut into pieces: a counterbore's wall a few cells
/// high and a few in radius, whose columns of facets turn by more than the growth angle and each
/// hold fewer faces than a tiny patch, between faces it meets at a sharp edge (plate_holes_bosses
/// at 100 cells: the counterbore was one band with no crossing edge). Such pieces join, across
/// edges whose normals agree within the merge angle, into a set of at least `min_faces` faces
/// that meets no other such set, and the set becomes one feature patch. Large sets that meet at
/// under the sharp angle on average are one surface and unite first
/// (unite_large_sets_across_smooth_borders()); where large sets still meet, they are one smooth
/// surface whose facets turn too sharply in places to join (the torus of 3 h aligned: its tube
/// in sets, with crossing edges and five phantom points between them), and stay band, as does
/// a union that meets a feature patch smoothly (crowded_sets()). Returns the sets made feature
/// patches. `tiny_faces`: the faces of the tiny
/// patches before absorb_tiny(); those it moved into feature patches are left out here.
std::size_t join_tiny_leftovers(const Connectivity& c, const std::vector<Vec3>& normals,
                                double max_angle_deg, std::size_t min_faces,
                                std::vector<Index> tiny_faces, std::vector<Index>& region,
                                std::vector<PatchRole>& role) {
    std::erase_if(tiny_faces, [&](Index f) { return role[region[f]] != PatchRole::Tiny; });
    TinySets t = join_across_smooth_edges(c, normals, max_angle_deg, region, role, tiny_faces);
    unite_large_sets_across_smooth_borders(c, normals, region, role, tiny_faces, min_faces, t);
    const std::vector<std::uint8_t> crowded =
        crowded_sets(c, normals, region, role, tiny_faces, min_faces, t);
    auto own_surface = [&](Index root) { return t.faces[root] >= min_faces && !crowded[root]; };
    for (Index f : tiny_faces) {
        const Index root = t.sets.find(region[f]);
        if (own_surface(root)) region[f] = root;
    }
    std::size_t joined = 0;
    for (Index p = 0; p < role.size(); ++p) {
        if (role[p] != PatchRole::Tiny) continue;
        const Index root = t.sets.find(p);
        const bool feature = root == p && own_surface(root);
        role[p] = feature ? PatchRole::Feature : PatchRole::Band;  // emptied, or an edge region
        joined += feature;
    }
    return joined;
}

/// Border of two patches: (median -cosine of the angle between them, lower id, higher id).
using Border = std::tuple<double, Index, Index>;

/// Unites the patches of `borders` (sorted by ascending angle) while the angle stays below the
/// one whose -cosine is `sharp`. With keep_apart, borders at or above it are sharp, and two sets
/// are not united when a patch of one has a sharp border with a patch of the other: each set
/// keeps the patches it is sharp against, and the shorter of the two lists is checked.
std::size_t unite_smooth_borders(const std::vector<Border>& borders, double sharp, bool keep_apart,
                                 std::size_t patch_count, DisjointSets& sets) {
    std::vector<std::vector<Index>> sharp_against(keep_apart ? patch_count : 0);
    if (keep_apart) {
        for (const auto& [negative_cosine, a, b] : borders) {
            if (negative_cosine < sharp) continue;
            sharp_against[a].push_back(b);
            sharp_against[b].push_back(a);
        }
    }
    auto kept_apart = [&](Index root_a, Index root_b) {
        if (!keep_apart) return false;
        if (sharp_against[root_a].size() > sharp_against[root_b].size()) std::swap(root_a, root_b);
        return std::any_of(sharp_against[root_a].begin(), sharp_against[root_a].end(),
                           [&](Index p) { return sets.find(p) == root_b; });
    };
    std::size_t merges = 0;
    for (const auto& [negative_cosine, a, b] : borders) {
        if (negative_cosine >= sharp) break;
        const Index root_a = sets.find(a), root_b = sets.find(b);
        if (root_a == root_b || kept_apart(root_a, root_b)) continue;
        sets.unite(root_a, root_b);
        ++merges;
        if (!keep_apart) continue;
        const Index root = sets.find(root_a), absorbed = root == root_a ? root_b : root_a;
        auto& into = sharp_against[root];
        into.insert(into.end(), sharp_against[absorbed].begin(), sharp_against[absorbed].end());
        sharp_against[absorbed] = {};
    }
    return merges;
}

/// A vertex's vote on a border of two patches: (lower id, higher id, -cosine of their angle).
using Vote = std::tuple<Index, Index, double>;

/// Greedy merging of over-segmented patches (§4, Fig. 5): every vertex shared by two patches
/// votes the angle between the two patches' normals there (as its cosine); pairs are merged in
/// order of increasing median angle while it stays below the merge angle, keeping patches with
/// a sharp border apart if asked (unite_smooth_borders). `single`: single_ring_patches() of
/// face_patch as given.
std::size_t merge_patches(const Mesh& mesh, const Connectivity& c, const std::vector<Vec3>& normals,
                          double merge_angle_deg, bool keep_apart, std::vector<Index>& face_patch,
                          const std::vector<Index>& single, std::size_t patch_count) {
    // Each vertex votes on its own, in parallel; the votes are then sorted, which leaves them in
    // one order whatever order the threads gave them in.
    struct Voting {
        std::vector<Vote> votes;
        std::vector<Index> patches;
        std::vector<Vec3> patch_normals;
    };
    tbb::enumerable_thread_specific<Voting> voting;
    auto vote_at = [&](Index v, Voting& local) {
        ring_patches(c, face_patch, v, local.patches);
        std::sort(local.patches.begin(), local.patches.end());
        local.patch_normals.clear();
        for (Index p : local.patches) {
            local.patch_normals.push_back(patch_mean_normal(mesh, c, normals, face_patch, v, p));
        }
        for (std::size_t a = 0; a < local.patches.size(); ++a) {
            for (std::size_t b = a + 1; b < local.patches.size(); ++b) {
                local.votes.emplace_back(local.patches[a], local.patches[b],
                                         -local.patch_normals[a].dot(local.patch_normals[b]));
            }
        }
    };
    using Range = tbb::blocked_range<Index>;
    tbb::parallel_for(Range(0, static_cast<Index>(mesh.vertex_count()), 4096), [&](const Range& r) {
        Voting& local = voting.local();
        for (Index v = r.begin(); v != r.end(); ++v) {
            if (single[v] == kMixedRing) vote_at(v, local);  // else no border here
        }
    });
    std::vector<Vote> votes;  // ascending: by pair, then by angle
    for (const Voting& local : voting)
        votes.insert(votes.end(), local.votes.begin(), local.votes.end());
    std::sort(votes.begin(), votes.end());
    std::vector<Border> pairs;
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
    const std::size_t merges = unite_smooth_borders(pairs, -std::cos(merge_angle_deg * kDegree),
                                                    keep_apart, patch_count, sets);
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

/// Whether patch p wins a tie of votes at v against patch q: the patch reaching lower in z
/// (`lowest`: per patch, the least z of its vertices), as it went to the lower id when ids followed
/// a mesher's face order, which sweeps the grid slab by slab; patches reaching as low by the first
/// face around v in geometric order (face_swept_before()).
bool wins_tie(const Mesh& mesh, const Connectivity& c, const std::vector<Index>& face_patch,
              const std::vector<double>& lowest, Index v, Index p, Index q) {
    if (lowest[p] != lowest[q]) return lowest[p] < lowest[q];
    Index first = kNoIndex;
    std::array<Index, 3> first_corners{};
    for (Index f : c.faces_around(v)) {
        if (face_patch[f] != p && face_patch[f] != q) continue;
        const std::array<Index, 3> corners = corners_in_sweep_order(mesh, f);
        if (first == kNoIndex || face_swept_before(mesh, corners, first_corners, f, first)) {
            first = f;
            first_corners = corners;
        }
    }
    return face_patch[first] == p;
}

/// §4 step 4: each vertex joins the patch with the most faces in its one-ring (ties:
/// wins_tie(), not ids, which follow the face order). `single`: single_ring_patches() of
/// face_patch; `count`: the number of patches.
std::vector<Index> label_vertices(const Mesh& mesh, const Connectivity& c,
                                  const std::vector<Index>& face_patch,
                                  const std::vector<Index>& single, std::size_t count) {
    std::vector<Index> label(mesh.vertex_count(), kNoIndex);
    // Per patch, the least z of its vertices (exact: a least value, not a sum, so a scaled or
    // moved part keeps its order and its ties), gathered on the way; ties wait for it.
    std::vector<double> lowest(count, std::numeric_limits<double>::infinity());
    std::vector<Index> tied;
    std::vector<std::pair<Index, int>> counts;
    auto count_votes = [&](Index v) { count_ring_patches(c, face_patch, v, counts); };
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
        const double z = mesh.positions[v].z();
        if (single[v] != kMixedRing) {
            label[v] = single[v];  // kNoIndex too: all faces in bands
            if (single[v] != kNoIndex) lowest[single[v]] = std::min(lowest[single[v]], z);
            continue;
        }
        count_votes(v);
        int best = 0;
        bool tie = false;
        for (const auto& [p, n] : counts) {
            lowest[p] = std::min(lowest[p], z);
            tie = n == best || (tie && n < best);
            if (n > best) {
                best = n;
                label[v] = p;
            }
        }
        if (tie) tied.push_back(v);
    }
    // Bound: the tied vertices, each counted again.
    for (Index v : tied) {
        count_votes(v);
        int best = 0;
        for (const auto& [p, n] : counts) {
            if (n > best || (n == best && wins_tie(mesh, c, face_patch, lowest, v, p, label[v]))) {
                best = n;
                label[v] = p;
            }
        }
    }
    return label;
}

/// How far v rises out of the tangent plane of patch p at its neighbours labelled p: the
/// smallest sine of the elevation of v seen from such a neighbour (`any`), and from such a
/// neighbour inside p (`inside`: its faces all in p, `single`); infinity where none can tell.
struct Elevation {
    double any = std::numeric_limits<double>::infinity();
    double inside = std::numeric_limits<double>::infinity();
};

Elevation elevation_from_patch(const Mesh& mesh, const Connectivity& c,
                               const std::vector<Vec3>& normals,
                               const std::vector<Index>& face_patch,
                               const std::vector<Index>& label, const std::vector<Index>& single,
                               Index v, Index p) {
    Elevation elevation;
    for_each_ring_vertex(mesh, c, v, [&](Index q) {
        if (label[q] != p) return;
        const Vec3 n = patch_mean_normal(mesh, c, normals, face_patch, q, p, v);
        const Vec3 d = mesh.positions[v] - mesh.positions[q];
        if (n.isZero(0.0) || d.isZero(0.0)) return;
        const double e = std::abs(n.dot(d)) / d.norm();
        elevation.any = std::min(elevation.any, e);
        if (single[q] == p) elevation.inside = std::min(elevation.inside, e);
    });
    return elevation;
}

/// Below this sine of elevation a vertex lies on a patch's tangent planes: 0.2 is about 11.5
/// degrees, far above what the curvature of a machined surface gives between grid neighbours
/// (h / 2r) and far below the dihedral angle of an edge worth restoring.
constexpr double kOnPlaneSine = 0.2;

/// Sines of elevation this close are equal: a vertex on two patches' planes at once is at 0 from
/// both, and rounding, which the part's scale and position change, must not choose between
/// them. Ties go to the view from inside the patches, then to the vote (beats()).
constexpr double kElevationTie = 1e-9;

bool elevations_tie(double a, double b) { return a == b || std::abs(a - b) <= kElevationTie; }

/// Whether patch elevation e beats `best` (the least so far): lower as seen from any neighbour;
/// where those tie, lower as seen from inside the patches; where those tie too, the vote's
/// (`voted`: e is the patch the vote gave). A row of band faces that grew into a patch holds
/// vertices beyond the true edge, labelled with it and seeing each other in the row's plane, at
/// elevation 0 as from the surface they lie on: seen from inside the patch they rise off it.
/// `inside_first`: FeatureSegmentationOptions::inside_view_breaks_ties.
bool beats(const Elevation& e, const Elevation& best, bool voted, bool inside_first) {
    if (!elevations_tie(e.any, best.any)) return e.any < best.any;
    if (inside_first && !elevations_tie(e.inside, best.inside)) return e.inside < best.inside;
    return voted;
}

/// The patches a vertex could lie on: those of its faces, or, for a vertex whose faces all lie
/// in bands, those of its labelled neighbours. A vertex with faces of a single patch (and band
/// faces) keeps its vote: on a chamfer that follows the grid no band face grows into a feature,
/// and the test below would only cost time.
void candidate_patches(const Mesh& mesh, const Connectivity& c,
                       const std::vector<Index>& face_patch, const std::vector<Index>& label,
                       Index v, std::vector<Index>& out) {
    ring_patches(c, face_patch, v, out);
    if (!out.empty()) return;
    for_each_ring_vertex(mesh, c, v, [&](Index q) {
        if (label[q] != kNoIndex && std::find(out.begin(), out.end(), label[q]) == out.end()) {
            out.push_back(label[q]);
        }
    });
    std::sort(out.begin(), out.end());
}

/// Corrects the majority vote at vertices on the border of two or more patches, and labels
/// vertices all of whose faces lie in bands. Along a chamfer that does not follow the grid, band
/// faces nearly parallel to one feature grow into it, and a vertex of the other feature can
/// then count more faces of the wrong patch. Every vertex lies exactly on its surface, so the
/// patch whose tangent planes, seen from its neighbours, pass through the vertex is the right
/// one. `single`: single_ring_patches() of face_patch.
std::vector<Index> refine_border_labels(const Mesh& mesh, const Connectivity& c,
                                        const std::vector<Vec3>& normals,
                                        const std::vector<Index>& face_patch,
                                        const std::vector<Index>& single,
                                        const std::vector<Index>& label, bool inside_first) {
    std::vector<Index> refined = label;
    // Each vertex reads the labels of the vote and writes only its own refined label.
    for_each_index_with<std::vector<Index>>(
        mesh.vertex_count(), 4096, [&](std::size_t i, std::vector<Index>& candidates) {
            const Index v = static_cast<Index>(i);
            if (single[v] != kMixedRing && single[v] != kNoIndex) return;  // inside one patch
            candidate_patches(mesh, c, face_patch, label, v, candidates);
            if (candidates.size() < 2 && label[v] != kNoIndex) return;  // nothing to decide
            Elevation best;
            Index best_patch = label[v];
            for (Index p : candidates) {
                const Elevation e =
                    elevation_from_patch(mesh, c, normals, face_patch, label, single, v, p);
                if (beats(e, best, p == label[v], inside_first)) {
                    best = e;
                    best_patch = p;
                }
            }
            const bool decided = label[v] != kNoIndex
                                     ? best.any < std::numeric_limits<double>::infinity()
                                     : best.any < kOnPlaneSine;
            if (decided) refined[v] = best_patch;
        });
    return refined;
}

}  // namespace

void count_ring_patches(const Connectivity& connectivity, const std::vector<Index>& face_patch,
                        Index v, std::vector<std::pair<Index, int>>& counts) {
    counts.clear();
    for (Index f : connectivity.faces_around(v)) {
        const Index p = face_patch[f];
        if (p == kNoIndex) continue;
        auto it = std::find_if(counts.begin(), counts.end(), [&](auto& e) { return e.first == p; });
        if (it == counts.end())
            counts.emplace_back(p, 1);
        else
            ++it->second;
    }
}

Vec3 patch_mean_normal(const Mesh& mesh, const Connectivity& c, const std::vector<Vec3>& normals,
                       const std::vector<Index>& face_patch, Index v, Index p, Index away) {
    Vec3 sum = Vec3::Zero();
    for (Index f : c.faces_around(v)) {
        const Triangle& t = mesh.triangles[f];
        if (face_patch[f] != p || t[0] == away || t[1] == away || t[2] == away) continue;
        sum += normals[f];
    }
    const double length = sum.norm();
    return length > 0.0 ? Vec3(sum / length) : Vec3::Zero();
}

FeatureSegmentationOptions near_surface_settings(FeatureSegmentationOptions options) {
    if (options.curved_region_faces != 0) {
        options.curved_region_faces = kNearRegionFaces;
        options.curved_seed_reach = kNearSeedReach;
        options.band_edge_fraction = kNearBandEdgeFraction;
    }
    return options;
}

GrownRegions grow_feature_regions(const Mesh& mesh, const Connectivity& connectivity,
                                  const std::vector<Vec3>& face_normals,
                                  const FeatureSegmentationOptions& options) {
    validate(options);
    GrownRegions grown;
    grown.face_region = grow_regions(mesh, connectivity, face_normals, options, grown.count);
    return grown;
}

FeatureSegmentation segment_features(const Mesh& mesh, const Connectivity& connectivity,
                                     const std::vector<Vec3>& face_normals,
                                     const std::vector<std::uint8_t>& is_edge_vertex,
                                     const FeatureSegmentationOptions& options) {
    return segment_features(mesh, connectivity, face_normals,
                            grow_feature_regions(mesh, connectivity, face_normals, options),
                            is_edge_vertex, options);
}

FeatureSegmentation segment_features(const Mesh& mesh, const Connectivity& connectivity,
                                     const std::vector<Vec3>& face_normals, GrownRegions regions,
                                     const std::vector<std::uint8_t>& is_edge_vertex,
                                     const FeatureSegmentationOptions& options) {
    validate(options);
    if (regions.face_region.size() != mesh.face_count()) {
        throw InvalidInput("feature segmentation: " + std::to_string(regions.face_region.size()) +
                           " grown regions' faces for " + std::to_string(mesh.face_count()) +
                           " faces");
    }
    const auto beyond = std::find_if(regions.face_region.begin(), regions.face_region.end(),
                                     [&](Index r) { return r >= regions.count; });
    if (beyond != regions.face_region.end()) {
        throw InvalidInput("feature segmentation: face " +
                           std::to_string(beyond - regions.face_region.begin()) + " in region " +
                           std::to_string(*beyond) + " of " + std::to_string(regions.count));
    }
    FeatureSegmentation s;
    s.grown_patches = regions.count;
    std::vector<Index> region = std::move(regions.face_region);
    // The rings of one region, taken once (in parallel): absorbing tiny patches, making bands,
    // merging and renumbering map each id to one, which keeps them so.
    std::vector<Index> single = single_ring_patches(connectivity, region, mesh.vertex_count());
    const PatchCensus census =
        take_census(mesh, connectivity, region, single, s.grown_patches, is_edge_vertex);
    std::vector<PatchRole> role = assign_roles(census, options);
    s.band_patches =
        static_cast<std::size_t>(std::count(role.begin(), role.end(), PatchRole::Band));
    std::vector<Index> tiny_faces = faces_of_tiny_patches(region, role);
    s.tiny_absorbed =
        absorb_tiny(connectivity, face_normals, options.merge_angle_deg, tiny_faces, region, role);
    s.tiny_joined =
        join_tiny_leftovers(connectivity, face_normals, options.merge_angle_deg,
                            options.tiny_patch_faces, std::move(tiny_faces), region, role);

    for (Index& r : region) {
        if (role[r] == PatchRole::Band) r = kNoIndex;
    }
    single = carry_single_patches(connectivity, region, std::move(single));
    s.merges = merge_patches(mesh, connectivity, face_normals, options.merge_angle_deg,
                             options.keep_sharp_borders_apart, region, single, s.grown_patches);
    s.patch_count = compact_ids(region, s.grown_patches);
    single = carry_single_patches(connectivity, region, std::move(single));
    s.face_patch = std::move(region);
    s.vertex_patch = refine_border_labels(
        mesh, connectivity, face_normals, s.face_patch, single,
        label_vertices(mesh, connectivity, s.face_patch, single, s.patch_count),
        options.inside_view_breaks_ties);
    return s;
}

}  // namespace resharp
