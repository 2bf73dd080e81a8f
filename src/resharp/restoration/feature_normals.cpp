#include "resharp/restoration/feature_normals.h"

#include <tbb/parallel_for.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <span>

#include "resharp/core/assert.h"
#include "resharp/core/errors.h"
#include "resharp/mesh/geometry.h"

namespace resharp {
namespace {

/// A vertex with fewer faces wholly on its feature around it (and around its neighbours on it)
/// has its continuation field from the faces off the bands within kContinuationRings rings.
/// Measured on grid-sampled cylinders, cones and tori of 3 to 5 h (tests/pipeline/
/// smooth_solids_test.cpp): 8 faces left phantom points that 10 do not; 3 rings, where 2 see
/// too few faces off the phantom bands of a small torus.
constexpr std::size_t kFewOwnFaces = 10;
constexpr int kContinuationRings = 3;

void validate(const FeatureNormalOptions& o) {
    if (!(o.max_fit_correction_deg >= 0.0 && o.max_fit_correction_deg <= 180.0)) {
        throw InvalidInput("largest fit correction must lie in [0, 180] degrees");
    }
    if (!(o.max_fit_residual_deg >= 0.0 && o.max_fit_residual_deg <= 180.0)) {
        throw InvalidInput("largest fit residual must lie in [0, 180] degrees");
    }
    if (!(o.near_face_angle_deg >= 0.0 && o.near_face_angle_deg <= 180.0)) {
        throw InvalidInput("near-face angle must lie in [0, 180] degrees");
    }
}

bool lies_on_patch(const Triangle& t, const std::vector<Index>& vertex_patch, Index patch) {
    return vertex_patch[t[0]] == patch && vertex_patch[t[1]] == patch &&
           vertex_patch[t[2]] == patch;
}

Vec3 patch_normal(const Mesh& mesh, const Connectivity& c, const std::vector<Vec3>& normals,
                  const std::vector<Index>& face_patch, const std::vector<Index>& vertex_patch,
                  Index v, bool whole_faces_only) {
    const Index patch = vertex_patch[v];
    Vec3 sum = Vec3::Zero();
    for (Index f : c.faces_around(v)) {
        if (face_patch[f] != patch) continue;
        if (whole_faces_only && !lies_on_patch(mesh.triangles[f], vertex_patch, patch)) continue;
        sum += corner_angle(mesh, f, corner_of(mesh.triangles[f], v)) * normals[f];
    }
    const double length = sum.norm();
    return length > 0.0 ? Vec3(sum / length) : Vec3::Zero();
}

/// Eq. 5.1 at v over its own patch, preferring faces that lie wholly on it.
Vec3 own_patch_normal(const Mesh& mesh, const Connectivity& c, const std::vector<Vec3>& normals,
                      const std::vector<Index>& face_patch, const std::vector<Index>& vertex_patch,
                      Index v) {
    const Vec3 n = patch_normal(mesh, c, normals, face_patch, vertex_patch, v, true);
    return n.isZero(0.0) ? patch_normal(mesh, c, normals, face_patch, vertex_patch, v, false) : n;
}

/// For a vertex with no face on its own patch (all its faces lie in bands): the mean of the
/// own-patch normals of its neighbours on the same patch.
Vec3 neighbours_patch_normal(const Mesh& mesh, const Connectivity& c,
                             const std::vector<Vec3>& normals, const std::vector<Index>& face_patch,
                             const std::vector<Index>& vertex_patch, Index v) {
    Vec3 sum = Vec3::Zero();
    for_each_ring_vertex(mesh, c, v, [&](Index q) {
        if (vertex_patch[q] == vertex_patch[v]) {
            sum += own_patch_normal(mesh, c, normals, face_patch, vertex_patch, q);
        }
    });
    const double length = sum.norm();
    return length > 0.0 ? Vec3(sum / length) : Vec3::Zero();
}

/// The faces around v and around those of its neighbours that `follow` admits, each once, in
/// the order first met, that `accept` admits. A face met again contains v or a neighbour
/// already taken, which is cheaper to test than searching the list.
template <class Follow, class Accept>
void gather_faces(const Mesh& mesh, const Connectivity& c, Index v, Follow&& follow,
                  Accept&& accept, std::vector<Index>& out, std::vector<Index>& taken) {
    out.clear();
    taken.assign(1, v);
    auto met_before = [&](const Triangle& t) {
        return std::any_of(taken.begin(), taken.end(),
                           [&](Index q) { return t[0] == q || t[1] == q || t[2] == q; });
    };
    auto take_ring = [&](Index q) {
        for (Index f : c.faces_around(q)) {
            if (accept(f) && (q == v || !met_before(mesh.triangles[f]))) out.push_back(f);
        }
        if (q != v) taken.push_back(q);
    };
    take_ring(v);
    for_each_ring_vertex(mesh, c, v, [&](Index q) {
        if (follow(q) && std::find(taken.begin(), taken.end(), q) == taken.end()) take_ring(q);
    });
}

/// The faces wholly on v's patch around v and around its same-patch neighbours.
void fit_faces(const Mesh& mesh, const Connectivity& c, const std::vector<Index>& face_patch,
               const std::vector<Index>& vertex_patch, Index v, std::vector<Index>& out,
               std::vector<Index>& taken) {
    const Index patch = vertex_patch[v];
    gather_faces(
        mesh, c, v, [&](Index q) { return vertex_patch[q] == patch; },
        [&](Index f) {
            return face_patch[f] == patch && lies_on_patch(mesh.triangles[f], vertex_patch, patch);
        },
        out, taken);
}

/// The faces of any patch around v and its neighbours whose normals lie within the angle of
/// `min_cosine` of n.
void near_faces(const Mesh& mesh, const Connectivity& c, const std::vector<Vec3>& normals, Index v,
                const Vec3& n, double min_cosine, std::vector<Index>& out,
                std::vector<Index>& taken) {
    gather_faces(
        mesh, c, v, [](Index) { return true; },
        [&](Index f) { return normals[f].dot(n) > min_cosine; }, out, taken);
}

/// The faces within kContinuationRings rings of vertices around v (one ring: v's own faces) that
/// lie in no band and whose normals lie within the angle of `min_cosine` of n. Bound: the rings'
/// vertices and faces, a few dozen; the vertices sorted once per ring, the faces once.
void faces_off_bands_near(const Mesh& mesh, const Connectivity& c, const std::vector<Vec3>& normals,
                          const std::vector<BandRole>& face_role, Index v, const Vec3& n,
                          double min_cosine, std::vector<Index>& out, std::vector<Index>& ring) {
    ring.assign(1, v);  // sorted, unique: the vertices within the rings walked so far
    for (int depth = 1; depth < kContinuationRings; ++depth) {
        const std::size_t walked = ring.size();
        for (std::size_t i = 0; i < walked; ++i) {
            for_each_ring_vertex(mesh, c, ring[i], [&](Index q) { ring.push_back(q); });
        }
        std::sort(ring.begin(), ring.end());
        ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    }
    out.clear();
    for (Index q : ring) {
        for (Index f : c.faces_around(q)) {
            if (face_role[f] == BandRole::None && normals[f].dot(n) > min_cosine) out.push_back(f);
        }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

/// The linear model of fit_normal_at: per face the row (1, u, w) of its centroid's offset from
/// the vertex in a tangent frame, beside the face's normal.
/// Kept by each worker and refilled per vertex, so that no vertex allocates.
struct FitSamples {
    std::vector<Eigen::Vector3d> rows;
    std::vector<Vec3> normals;
    std::vector<std::uint8_t> use;  ///< per sample: 1 while it takes part in the fit
    double largest_offset2 = 0.0;   ///< squared length of the longest centroid offset
};

void fill_samples(const Mesh& mesh, const std::vector<Vec3>& normals, std::span<const Index> faces,
                  Index v, const Vec3& guess, FitSamples& samples) {
    const Vec3 t1 = guess.unitOrthogonal();
    const Vec3 t2 = guess.cross(t1);
    samples.rows.clear();
    samples.normals.clear();
    samples.use.assign(faces.size(), 1);
    samples.largest_offset2 = 0.0;
    for (Index f : faces) {
        const Triangle& t = mesh.triangles[f];
        const Vec3 d = (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0 -
                       mesh.positions[v];
        samples.rows.emplace_back(1.0, d.dot(t1), d.dot(t2));
        samples.normals.push_back(normals[f]);
        samples.largest_offset2 = std::max(samples.largest_offset2, d.squaredNorm());
    }
}

/// Least squares over the samples in use: the 3x3 coefficients (rows: 1, u, w; columns: x, y,
/// z), or nullopt when the used centroids do not span the plane.
std::optional<Eigen::Matrix3d> solve_fit(const FitSamples& s) {
    Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
    Eigen::Matrix3d atb = Eigen::Matrix3d::Zero();
    double count = 0.0;
    for (std::size_t i = 0; i < s.rows.size(); ++i) {
        if (!s.use[i]) continue;
        ata += s.rows[i] * s.rows[i].transpose();
        atb += s.rows[i] * s.normals[i].transpose();
        count += 1.0;
    }
    // The determinant scales as count^3 * length^4; below this share of that bound the
    // centroids lie nearly on a line and the slope across it is a guess.
    const double bound = count * count * count * s.largest_offset2 * s.largest_offset2;
    if (count < 4.0 || ata.determinant() < 1e-6 * bound) return std::nullopt;
    return Eigen::Matrix3d(ata.ldlt().solve(atb));
}

/// The field of solve_fit()'s coefficients in the tangent frame of `guess`, n0 made unit;
/// nullopt where they are not finite or n0 is zero.
std::optional<NormalField> field_of_fit(const Eigen::Matrix3d& fit, const Vec3& guess) {
    const Vec3 n0 = fit.row(0).transpose();
    if (!n0.allFinite() || n0.isZero(0.0) || !fit.allFinite()) return std::nullopt;
    const Vec3 t1 = guess.unitOrthogonal();  // the tangent frame of fill_samples
    const Vec3 t2 = guess.cross(t1);
    const double length = n0.norm();
    return NormalField{n0 / length, (fit.row(1).transpose() * t1.transpose() +
                                     fit.row(2).transpose() * t2.transpose()) /
                                        length};
}

/// Least-squares fit n(x) = n0 + a u + b w of the face normals over the faces' centroids, with
/// (u, w) the centroid's offset from v in the tangent plane of `guess`, refitted once without
/// the faces whose residual exceeds `max_residual` (radians, as a chord of unit normals);
/// returns the field with n0, the fitted normal at v, made unit, or nullopt when the centroids
/// do not span the plane. `all_faces` (if given) gets the first fit's field, of all the faces
/// (nullopt likewise): what a fit without trimming would return.
std::optional<NormalField> fit_normal_at(const Mesh& mesh, const std::vector<Vec3>& normals,
                                         std::span<const Index> faces, Index v, const Vec3& guess,
                                         double max_residual, FitSamples& samples,
                                         std::optional<NormalField>* all_faces = nullptr) {
    fill_samples(mesh, normals, faces, v, guess, samples);
    const double max_residual2 = max_residual * max_residual;
    std::optional<Eigen::Matrix3d> fit = solve_fit(samples);
    if (!fit) return std::nullopt;
    if (all_faces) *all_faces = field_of_fit(*fit, guess);
    bool trimmed = false;
    for (std::size_t i = 0; i < faces.size(); ++i) {
        const Vec3 predicted = fit->transpose() * samples.rows[i];
        samples.use[i] = (predicted - samples.normals[i]).squaredNorm() <= max_residual2;
        trimmed = trimmed || !samples.use[i];
    }
    if (!trimmed) return all_faces ? *all_faces : field_of_fit(*fit, guess);
    fit = solve_fit(samples);
    if (!fit) return std::nullopt;
    return field_of_fit(*fit, guess);
}

struct FitLimits {
    double min_cosine;      ///< of the largest correction of eq. 5.1's normal
    double max_residual;    ///< chord between a face normal and the first fit
    double near_cosine;     ///< of the widest angle to eq. 5.1's normal of near_faces()
    bool surface_vertices;  ///< FeatureNormalOptions::vertices_on_surface
};

/// What the fits read: the mesh, its face normals and the feature segmentation.
struct FitSource {
    const Mesh& mesh;
    const Connectivity& connectivity;
    const std::vector<Vec3>& normals;  ///< per face
    const std::vector<Index>& face_patch;
    const std::vector<Index>& vertex_patch;
    const std::vector<BandRole>& face_role;
};

/// Buffers one worker reuses for every vertex.
struct FitScratch {
    std::vector<Index> faces, taken;
    FitSamples samples;
};

/// True when the faces' normals all lie within about 1e-6 degrees of the first: the fit would
/// return that plane's normal, which eq. 5.1 already is.
bool coplanar(const std::vector<Vec3>& normals, std::span<const Index> faces) {
    return std::all_of(faces.begin(), faces.end(), [&](Index f) {
        return (normals[f] - normals[faces[0]]).squaredNorm() < 1e-16;
    });
}

/// Whether the faces' centroids lie along one strip: across it, in the tangent plane of n,
/// their spread (standard deviation) is under a fifth of their spread along it.
bool along_one_strip(const Mesh& mesh, std::span<const Index> faces, const Vec3& n) {
    const Vec3 t1 = n.unitOrthogonal();
    const Vec3 t2 = n.cross(t1);
    const Vec3& origin = mesh.positions[mesh.triangles[faces[0]][0]];  // small offsets: rounding
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    Eigen::Matrix2d products = Eigen::Matrix2d::Zero();
    for (Index f : faces) {
        const Triangle& t = mesh.triangles[f];
        const Vec3 c =
            (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0 - origin;
        const Eigen::Vector2d p(c.dot(t1), c.dot(t2));
        sum += p;
        products += p * p.transpose();
    }
    const double count = static_cast<double>(faces.size());
    const Eigen::Matrix2d spread = products / count - (sum / count) * (sum / count).transpose();
    // The eigenvalues of the 2x2 covariance: its half trace plus and minus this radius.
    const double half_trace = 0.5 * spread.trace();
    const double radius = std::hypot(0.5 * (spread(0, 0) - spread(1, 1)), spread(0, 1));
    return half_trace - radius < 0.04 * (half_trace + radius);
}

/// The field of all the faces around v and its neighbours, of any patch, whose normals lie
/// near n (limits.near_cosine); nullopt where their centroids do not span a plane.
std::optional<NormalField> field_of_near_faces(const FitSource& in, Index v, const Vec3& n,
                                               const FitLimits& limits, FitScratch& scratch) {
    near_faces(in.mesh, in.connectivity, in.normals, v, n, limits.near_cosine, scratch.faces,
               scratch.taken);
    return fit_normal_at(in.mesh, in.normals, scratch.faces, v, n,
                         std::numeric_limits<double>::infinity(), scratch.samples);
}

/// The field of the faces off the bands within kContinuationRings rings of v whose normals lie
/// near n (limits.near_cosine); nullopt where their centroids do not span a plane.
std::optional<NormalField> field_of_faces_off_bands(const FitSource& in, Index v, const Vec3& n,
                                                    const FitLimits& limits, FitScratch& scratch) {
    faces_off_bands_near(in.mesh, in.connectivity, in.normals, in.face_role, v, n,
                         limits.near_cosine, scratch.faces, scratch.taken);
    return fit_normal_at(in.mesh, in.normals, scratch.faces, v, n,
                         std::numeric_limits<double>::infinity(), scratch.samples);
}

/// Replaces eq. 5.1's normal n at v by the linear fit where the fit is well posed, not planar
/// and corrects n by less than the limit; `correction` gets the angle (degrees) it moved n by
/// and `field` the fit's field. Where the trimmed fit is taken, `continuation` (if given) gets
/// the fit of all the faces instead: the facets of a cylinder a few cells in radius turn by more
/// than the trimming allows, and it can leave a single flat strip whose zero slope would tell
/// drop_smooth_crossings() the feature is flat where it turns. Returns the number of v's own
/// faces fitted (wholly on its feature).
std::size_t refine_by_fit(const FitSource& in, Index v, const FitLimits& limits, Vec3& n,
                          float& correction, NormalField& field, NormalField* continuation,
                          FitScratch& scratch) {
    const Mesh& mesh = in.mesh;
    const std::vector<Vec3>& normals = in.normals;
    fit_faces(mesh, in.connectivity, in.face_patch, in.vertex_patch, v, scratch.faces,
              scratch.taken);
    const std::size_t own_faces = scratch.faces.size();
    if (scratch.faces.empty()) {
        // No face around v lies wholly on its feature (a strip narrower than a face): only the
        // faces beside it can tell how the surface turns.
        if (auto near = field_of_near_faces(in, v, n, limits, scratch)) field = *near;
        return own_faces;
    }
    if (coplanar(normals, scratch.faces)) {
        // The feature is flat around v, but a strip of facets of a small cylinder is flat too:
        // the faces beside it tell how the surface turns (drop_smooth_crossings).
        if (limits.surface_vertices && along_one_strip(mesh, scratch.faces, n)) {
            if (auto near = field_of_near_faces(in, v, n, limits, scratch)) field = *near;
        }
        return own_faces;
    }
    std::optional<NormalField> untrimmed;
    const auto fitted = fit_normal_at(mesh, normals, scratch.faces, v, n, limits.max_residual,
                                      scratch.samples, &untrimmed);
    if (fitted && fitted->n0.dot(n) > limits.min_cosine) {
        correction = static_cast<float>(angle_deg(fitted->n0, n));
        n = fitted->n0;
        field = *fitted;
        // (the field itself where the trimming left no face out)
        if (continuation && untrimmed) *continuation = *untrimmed;
        return own_faces;
    }
    // Eq. 5.1's normal stays, but how the feature turns still tells one smooth surface from
    // two (drop_smooth_crossings): on coarse facets of a small radius the faces stray from any
    // linear field by more than the trimming allows, so that field comes from all of them.
    if (!untrimmed) {
        // A patch one strip of facets wide (a cylinder a few cells in radius, along a grid
        // axis) cannot tell the slope across it: the faces near v that lie near its normal can.
        untrimmed = field_of_near_faces(in, v, n, limits, scratch);
    }
    if (untrimmed) field = *untrimmed;
    return own_faces;
}

/// v's feature normal in `result`: eq. 5.1's over its own patch (over its same-patch
/// neighbours' where that has none), replaced by the linear fit (`linear_fit`) as
/// refine_by_fit() decides, with the fit's correction and field.
void set_feature_normal(const FitSource& in, Index v, bool linear_fit, bool crossing_end,
                        const FitLimits& limits, FeatureNormals& result, FitScratch& scratch) {
    Vec3 n =
        own_patch_normal(in.mesh, in.connectivity, in.normals, in.face_patch, in.vertex_patch, v);
    if (n.isZero(0.0)) {
        n = neighbours_patch_normal(in.mesh, in.connectivity, in.normals, in.face_patch,
                                    in.vertex_patch, v);
    }
    if (linear_fit && !n.isZero(0.0)) {
        // Only drop_smooth_crossings() reads it, at the ends of crossing edges.
        NormalField* continuation =
            limits.surface_vertices && crossing_end ? &result.continuation_field_at(v) : nullptr;
        const std::size_t own_faces = refine_by_fit(in, v, limits, n, result.fit_correction_at(v),
                                                    result.field_at(v), continuation, scratch);
        if (continuation && own_faces < kFewOwnFaces) {
            // Too few to tell how the feature turns (a small cylinder's facet strips, a
            // torus's quads): the faces off the bands around v, its side of the band, tell.
            if (auto turning = field_of_faces_off_bands(in, v, n, limits, scratch)) {
                *continuation = *turning;
            }
        }
    }
    result.normal_at(v) = n;
}

}  // namespace

FeatureNormals feature_normals(const Mesh& mesh, const Connectivity& connectivity,
                               const std::vector<Vec3>& face_normals,
                               const std::vector<Index>& face_patch,
                               const std::vector<Index>& vertex_patch,
                               const BandClassification& bands,
                               const FeatureNormalOptions& options) {
    validate(options);
    RESHARP_ASSERT(bands.is_crossing.size() == 3 * mesh.face_count() &&
                   bands.face_role.size() == mesh.face_count());
    const double degree = std::numbers::pi / 180.0;
    const FitLimits fit{std::cos(options.max_fit_correction_deg * degree),
                        2.0 * std::sin(options.max_fit_residual_deg * degree / 2.0),
                        std::cos(options.near_face_angle_deg * degree),
                        options.vertices_on_surface};
    // Per vertex: kNeeded on a band face, kCrossingEnd also at an end of a crossing edge.
    constexpr std::uint8_t kNeeded = 1, kCrossingEnd = 2;
    std::vector<std::uint8_t> needed(mesh.vertex_count(), 0);
    for (Index f = 0; f < mesh.face_count(); ++f) {
        if (bands.face_role[f] == BandRole::None) continue;
        const Triangle& t = mesh.triangles[f];
        for (Index k = 0; k < 3; ++k) {
            const std::uint8_t end = bands.is_crossing[3 * f + k] ? kCrossingEnd : kNeeded;
            needed[t[k]] = std::max(needed[t[k]], end);
            needed[t[(k + 1) % 3]] = std::max(needed[t[(k + 1) % 3]], end);
        }
    }
    const FitSource source{mesh,       connectivity, face_normals,
                           face_patch, vertex_patch, bands.face_role};
    const bool linear_fit = options.estimate == NormalEstimate::LinearFit;
    FeatureNormals result(mesh.vertex_count());
    if (linear_fit) result.keep_fields();
    if (linear_fit && options.vertices_on_surface) result.keep_continuation_fields();
    std::size_t entries = 0;
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
        entries += needed[v] && vertex_patch[v] != kNoIndex;
    }
    result.reserve(entries);
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
        if (needed[v] && vertex_patch[v] != kNoIndex) result.add(v);
    }
    const tbb::blocked_range<Index> vertices(0, static_cast<Index>(mesh.vertex_count()), 4096);
    tbb::parallel_for(vertices, [&](const auto& range) {
        FitScratch scratch;
        for (Index v = range.begin(); v != range.end(); ++v) {
            if (needed[v] && vertex_patch[v] != kNoIndex) {
                set_feature_normal(source, v, linear_fit, needed[v] == kCrossingEnd, fit, result,
                                   scratch);
            }
        }
    });
    return result;
}

}  // namespace resharp
