#include "resharp/near/vertex_placement.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <complex>
#include <cstdint>
#include <numbers>
#include <optional>
#include <span>
#include <sstream>
#include <vector>

#include "resharp/core/errors.h"
#include "resharp/core/rounding.h"
#include "resharp/core/turn_phasor.h"

namespace resharp {
namespace {

// The shares that decide. A grid-edge mesher (mc, bisection, midpoint) puts every vertex on a
// grid edge. A surface-nets mesh fits a grid on its flat axis-aligned faces too (vertices at cell
// centres, on the lines of the grid shifted by h/2; where such faces lie on grid planes, at the
// midpoints of that shifted grid's edges): only its band vertices are off those edges, 0.2 % of
// them on a plane-only part at 60 cells. Hence a share this close to 1; a grid-edge mesh with
// more stray vertices than this takes the exact path, the safe one.
constexpr double kOnEdgeShare = 0.9999;
constexpr double kMidpointShare = 0.9;  // of the vertices on grid edges, at their edge's middle
constexpr double kDualShare = 0.9;      // triangles on the four cells around one grid edge
/// Dual grids whose shares come within this of the best one's fit as well (a pitch a little off
/// still fits most triangles of a small part).
constexpr double kDualShareSlack = 0.005;
/// Cell means lie off the edges of the grid they are dual to (a cell's centre is on none of its
/// edges), but a grid-edge mesh with a few stray vertices (a fin, a patch from another mesher)
/// has a share of its vertices on the edges of the grid it is dual to (those on edges along the
/// axis it is shifted across): more than this, and it is not taken for near.
constexpr double kDualOnEdgeShare = 0.05;
/// A lattice's strength (the mean resultant of its values' phases) below which the shared
/// coordinate values show no common spacing.
constexpr double kMinStrength = 0.25;
constexpr std::size_t kMinShared = 3;    // vertices sharing a coordinate value: a candidate line
constexpr double kCoordinateUlps = 8.0;  // the coordinate noise, in units in the last place
constexpr std::size_t kSampledTriangles = 20000;  // triangles the structure tests look at
constexpr double kWindowSpacings = 12.0;  // half-width of the pitch search's window, in spacings
constexpr std::size_t kCandidates = 6;    // pitches tried, from the strongest peaks
constexpr int kStarts = 6;                // refinements from pitches each side of a peak

/// A coordinate value held by n vertices, with weight log2(n): a grid line holds the vertices
/// of one slice of the surface; a large flat face, as many vertices as all the lines crossing it,
/// at one value off the grid; weighed by count it would outweigh them.
struct SharedValue {
    double value = 0.0;
    double weight = 0.0;
};
using AxisValues = std::array<std::vector<SharedValue>, 3>;

/// Lines at phase[a] + k * pitch on axis a.
struct Lattice {
    double pitch = 0.0;
    Vec3 phase = Vec3::Zero();
};

/// The coordinate noise of the mesh, kCoordinateUlps units in the last place of its largest
/// coordinate: of double, and of float when every coordinate is a float (as in an STL file;
/// exact multiples of a power of two, as on a dyadic grid, are floats too), else none.
std::pair<double, std::optional<double>> coordinate_tolerances(const Mesh& mesh) {
    double largest = 0.0;
    bool all_float = true;
    for (const Vec3& p : mesh.positions) {
        for (int a = 0; a < 3; ++a) {
            largest = std::max(largest, std::abs(p[a]));
            all_float = all_float && static_cast<double>(static_cast<float>(p[a])) == p[a];
        }
    }
    const double ulps = kCoordinateUlps * std::max(largest, 1.0e-300);
    return {ulps * DBL_EPSILON, all_float ? std::optional(ulps * FLT_EPSILON) : std::nullopt};
}

/// Per axis, every vertex's coordinate, sorted: what shared_values() groups, at either tolerance.
using SortedCoordinates = std::array<std::vector<double>, 3>;

SortedCoordinates sorted_coordinates(const Mesh& mesh) {
    SortedCoordinates out;
    for (int a = 0; a < 3; ++a) {
        out[a].resize(mesh.vertex_count());
        for (std::size_t v = 0; v < out[a].size(); ++v) out[a][v] = mesh.positions[v][a];
        std::sort(out[a].begin(), out[a].end());
    }
    return out;
}

/// Per axis, the coordinate values at least kMinShared vertices hold (within `tol`), sorted.
AxisValues shared_values(const SortedCoordinates& sorted, double tol) {
    AxisValues out;
    for (int a = 0; a < 3; ++a) {
        const std::vector<double>& xs = sorted[a];
        for (std::size_t i = 0; i < xs.size();) {
            std::size_t j = i + 1;
            while (j < xs.size() && xs[j] - xs[i] <= 2.0 * tol) ++j;
            if (j - i >= kMinShared) {
                out[a].push_back({xs[(i + j) / 2], std::log2(static_cast<double>(j - i))});
            }
            i = j;
        }
    }
    return out;
}

/// The median length of the edges of (at most kSampledTriangles evenly spread) triangles.
double median_edge_length(const Mesh& mesh) {
    const std::size_t stride = std::max<std::size_t>(1, mesh.face_count() / kSampledTriangles);
    std::vector<double> lengths;
    for (std::size_t f = 0; f < mesh.face_count(); f += stride) {
        const Triangle& t = mesh.triangles[f];
        for (int k = 0; k < 3; ++k) {
            lengths.push_back((mesh.positions[t[k]] - mesh.positions[t[(k + 1) % 3]]).norm());
        }
    }
    if (lengths.empty()) return 0.0;
    auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
    std::nth_element(lengths.begin(), middle, lengths.end());
    return *middle;
}

/// e^(2 pi i value / pitch), the term phasor() adds for a value of weight 1.
std::complex<double> unit_phasor(double value, double pitch) {
    return std::polar(1.0, 2.0 * std::numbers::pi * value / pitch);
}

/// Sum of weight * e^(2 pi i value / pitch): its length over the total weight is 1 when every
/// value lies on one lattice of this pitch, and its angle gives the lattice's phase.
std::complex<double> phasor(std::span<const SharedValue> values, double pitch) {
    std::complex<double> sum = 0.0;
    for (const SharedValue& s : values) {
        sum += s.weight * unit_phasor(s.value, pitch);
    }
    return sum;
}

double total_weight(const AxisValues& values) {
    double w = 0.0;
    for (const auto& axis : values) {
        for (const SharedValue& s : axis) w += s.weight;
    }
    return w;
}

/// The pitches coarse_lattices() scans: from spacing / 3 to 3 spacing, a constant factor apart.
std::vector<double> scan_pitches(double spacing) {
    constexpr double kReach = 2.0 * kWindowSpacings;  // the window's width, in spacings
    const int steps = static_cast<int>(std::log(9.0) * 20.0 * kReach);
    const double factor = std::pow(9.0, 1.0 / steps);
    std::vector<double> pitches(steps + 1);
    for (int i = 0; i <= steps; ++i) pitches[i] = spacing / 3.0 * std::pow(factor, i);
    return pitches;
}

/// How well one lattice per axis, all of the pitch, holds the values (0..1), as the scan
/// compares it: the sums run as phasor()'s do (axis by axis, value by value), so that a peak
/// found with approximate_strengths() is confirmed with the same bits wherever it is looked at.
/// `near` must have a positive total weight.
double exact_strength(const AxisValues& near, double pitch) {
    double length = 0.0;
    for (const auto& axis : near) length += std::abs(phasor(axis, pitch));
    return length / total_weight(near);
}

/// exact_strength() at each of the scan's pitches from approximate phasors, and a bound on how
/// far any of them may be from it: each term is off by at most turn_phasor_error() of the
/// largest value over the finest pitch per component (its length by sqrt 2 of that), and the
/// sums' own rounding differs by at most n units in the last place of the total weight for n
/// values (doubled, with room, in `error`).
struct ApproximateStrengths {
    std::vector<double> strength;
    double error = 0.0;
};

ApproximateStrengths approximate_strengths(const AxisValues& near,
                                           const std::vector<double>& pitches) {
    const std::size_t count = pitches.size();
    const double w = total_weight(near);
    ApproximateStrengths out{std::vector<double>(count, 0.0), 0.0};
    std::vector<std::complex<double>> sum(count);
    double largest = 0.0;
    std::size_t most = 0;
    for (const auto& axis : near) {
        std::fill(sum.begin(), sum.end(), 0.0);
        for (const SharedValue& s : axis) {
            // Each term made where it is added: kept per value for the rounded reading, which
            // shares most values with the exact one, they took 16 kB a value of fresh memory,
            // whose page faults cost more than the terms (mech by surface nets: 230 values,
            // 3.7 MB, about 8 ms of a 20 ms estimate on one thread).
            for (std::size_t i = 0; i < count; ++i) {
                sum[i] += s.weight * approximate_turn_phasor(s.value / pitches[i]);
            }
            largest = std::max(largest, std::abs(s.value));
        }
        for (std::size_t i = 0; i < count; ++i) out.strength[i] += std::abs(sum[i]);
        most = std::max(most, axis.size());
    }
    for (double& x : out.strength) x /= w;
    const double term = turn_phasor_error(largest / pitches.front());
    out.error = 4.0 * (term + static_cast<double>(most + 8) * DBL_EPSILON);
    return out;
}

/// The pitches at which exact_strength() has a local peak of at least kMinStrength, with that
/// strength: (strength, pitch). exact_strength() is taken only where the approximate strengths,
/// within their error, could make a peak; elsewhere none can be.
std::vector<std::pair<double, double>> strength_peaks(const AxisValues& near,
                                                      const std::vector<double>& pitches) {
    std::vector<std::pair<double, double>> peaks;
    if (total_weight(near) <= 0.0) return peaks;
    const ApproximateStrengths approximate = approximate_strengths(near, pitches);
    const std::vector<double>& s = approximate.strength;
    const double e = approximate.error;
    std::vector<std::optional<double>> exact(pitches.size());
    const auto exact_at = [&](std::size_t i) {
        if (!exact[i]) exact[i] = exact_strength(near, pitches[i]);
        return *exact[i];
    };
    for (std::size_t i = 1; i + 1 < pitches.size(); ++i) {
        if (s[i] < s[i - 1] - 2.0 * e || s[i] <= s[i + 1] - 2.0 * e || s[i] < kMinStrength - e) {
            continue;  // exact_strength() cannot peak here
        }
        const double here = exact_at(i);
        if (here >= exact_at(i - 1) && here > exact_at(i + 1) && here >= kMinStrength) {
            peaks.emplace_back(here, pitches[i]);
        }
    }
    return peaks;
}

/// Per axis, the weighted median value.
Vec3 median_values(const AxisValues& values) {
    Vec3 centre = Vec3::Zero();
    for (int a = 0; a < 3; ++a) {
        double half = 0.0, w = 0.0;
        for (const SharedValue& s : values[a]) half += 0.5 * s.weight;
        for (const SharedValue& s : values[a]) {
            w += s.weight;
            centre[a] = s.value;
            if (w >= half) break;
        }
    }
    return centre;
}

/// The values within `reach` of centre on each axis.
AxisValues window(const AxisValues& values, const Vec3& centre, double reach) {
    AxisValues out;
    for (int a = 0; a < 3; ++a) {
        for (const SharedValue& s : values[a]) {
            if (std::abs(s.value - centre[a]) <= reach) out[a].push_back(s);
        }
    }
    return out;
}

/// The lattice of the pitch whose lines, per axis, lie at the mean phase of the values (the
/// angle of their phasor): lines that hold the values in step outweigh those off them.
Lattice phased_lattice(const AxisValues& near, double pitch) {
    Lattice l{pitch, Vec3::Zero()};
    for (int a = 0; a < 3; ++a) {
        l.phase[a] = std::arg(phasor(near[a], pitch)) / (2.0 * std::numbers::pi) * pitch;
    }
    return l;
}

/// First lattices: the pitches in [spacing / 3, 3 spacing] at which the values near the centre
/// (a window, so that the search steps can be coarse) peak, at most kCandidates of them. A
/// lattice of pitch h also holds at h/2, h/3, ..., as strongly: the peaks nearly as strong as
/// the strongest come first, coarsest first, then the others by strength.
std::vector<Lattice> coarse_lattices(const AxisValues& near, const std::vector<double>& pitches) {
    std::vector<std::pair<double, double>> peaks =
        strength_peaks(near, pitches);  // (strength, pitch)
    std::sort(peaks.rbegin(), peaks.rend());
    if (peaks.size() > kCandidates) peaks.resize(kCandidates);
    const double strongest = peaks.empty() ? 0.0 : peaks.front().first;
    std::stable_sort(peaks.begin(), peaks.end(), [&](const auto& x, const auto& y) {
        const bool x_strong = x.first >= 0.8 * strongest, y_strong = y.first >= 0.8 * strongest;
        if (x_strong != y_strong) return x_strong;
        return x_strong && x.second > y.second;
    });
    std::vector<Lattice> out;
    for (const auto& [unused, pitch] : peaks) out.push_back(phased_lattice(near, pitch));
    return out;
}

/// A fit_lattice() pass: the lattice fitted, and the largest distance from its line of a value
/// the fit used (negative when it used none).
struct LatticeFit {
    Lattice lattice;
    double widest = -1.0;
};

/// One least-squares pass: values within `reach` of the centre and within `band` of a line of
/// `l` give the line number k; fits value = phase[a] + k * pitch (one pitch, a phase per axis).
LatticeFit fit_lattice(const AxisValues& values, const Lattice& l, const Vec3& centre, double reach,
                       double band) {
    std::array<double, 3> sw{}, sk{}, sd{}, skk{}, skd{};
    Vec3 anchor;
    double widest = -1.0;
    for (int a = 0; a < 3; ++a) {
        anchor[a] = l.phase[a] + round_half_away((centre[a] - l.phase[a]) / l.pitch) * l.pitch;
        for (const SharedValue& s : values[a]) {
            if (std::abs(s.value - centre[a]) > reach) continue;
            const double d = s.value - anchor[a];  // relative to the anchor: no cancellation
            const double k = round_half_away(d / l.pitch);
            const double off = std::abs(d - k * l.pitch);
            if (off > band) continue;
            widest = std::max(widest, off);
            sw[a] += s.weight, sk[a] += s.weight * k, sd[a] += s.weight * d;
            skk[a] += s.weight * k * k, skd[a] += s.weight * k * d;
        }
    }
    double num = 0.0, den = 0.0;
    for (int a = 0; a < 3; ++a) {
        if (sw[a] <= 0.0) continue;
        num += skd[a] - sk[a] * sd[a] / sw[a];
        den += skk[a] - sk[a] * sk[a] / sw[a];
    }
    LatticeFit out{l, widest};
    if (den > 0.0) out.lattice.pitch = num / den;  // else every axis has one line: keep the pitch
    for (int a = 0; a < 3; ++a) {
        out.lattice.phase[a] =
            sw[a] > 0.0 ? anchor[a] + (sd[a] - out.lattice.pitch * sk[a]) / sw[a] : l.phase[a];
    }
    return out;
}

/// A fit_lattice() pass: the lattice it was given, and what it gave.
struct FitPass {
    Lattice given;
    LatticeFit fit;
};

/// Whether two lattices are the same bits (a fit of either computes the same).
bool same_bits(const Lattice& x, const Lattice& y) {
    const auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v); };
    return bits(x.pitch) == bits(y.pitch) && bits(x.phase[0]) == bits(y.phase[0]) &&
           bits(x.phase[1]) == bits(y.phase[1]) && bits(x.phase[2]) == bits(y.phase[2]);
}

/// The lattice refined over all values: the window doubles while the band around the lines stays
/// wide (the line numbers stay right while the pitch error times the lines in reach is well
/// below the band), then the band narrows to the coordinate noise, dropping values off the lines
/// (a flat face's height). Bounded: the reach doubles at most 64 times from the first window to
/// the values' extent, the band quarters at most 64 times down to the noise.
Lattice refine_lattice(const AxisValues& values, Lattice l, const Vec3& centre, double reach,
                       double tol) {
    double extent = 0.0;
    for (int a = 0; a < 3; ++a) {
        for (const SharedValue& s : values[a]) {
            extent = std::max(extent, std::abs(s.value - centre[a]));
        }
    }
    double band = 0.05 * l.pitch;
    // Once the reach holds every value, a pass given the lattice an earlier pass was given
    // computes what that one did (same lattice, same values, same sums) while the band, which
    // only narrows, still keeps every value that one used. Rounding leaves the refinement on one
    // lattice or alternating between two: such passes are taken from the last two computed.
    std::array<std::optional<FitPass>, 2> recent;  // the last two passes over all values
    for (int pass = 0; pass < 128; ++pass) {
        const double used = std::max(band, 2.0 * tol);
        const FitPass* again = nullptr;
        for (const std::optional<FitPass>& r : recent) {
            if (r && same_bits(r->given, l) && r->fit.widest <= used) again = &*r;
        }
        if (again) {
            l = again->fit.lattice;
        } else {
            const LatticeFit fit = fit_lattice(values, l, centre, reach, used);
            if (reach >= extent) recent = {FitPass{l, fit}, recent[0]};
            l = fit.lattice;
        }
        if (!(l.pitch > 0.0) || !std::isfinite(l.pitch)) break;
        if (reach < extent) {
            reach *= 2.0;
        } else if (band > 2.0 * tol) {
            band *= 0.25;
        } else {
            break;
        }
    }
    return l;
}

/// The weight of the values within 2 `tol` of a line of the lattice.
double weight_on_lines(const AxisValues& values, const Lattice& l, double tol) {
    double w = 0.0;
    for (int a = 0; a < 3; ++a) {
        for (const SharedValue& s : values[a]) {
            const double u = (s.value - l.phase[a]) / l.pitch;
            if (std::abs(u - round_half_away(u)) * l.pitch <= 2.0 * tol) w += s.weight;
        }
    }
    return w;
}

/// Where the lattice search starts: the values' weighted median, the first window's reach around
/// it, and the coarse lattices found in that window, strongest first (coarse_lattices; none if
/// the values show no common spacing).
struct LatticeSeeds {
    Vec3 centre = Vec3::Zero();
    double reach = 0.0;
    std::vector<Lattice> coarse;
};

/// What the two readings of one mesh (at the exact and at the rounded tolerance) share: its
/// coordinates sorted per axis, its median edge length (the spacing the pitch search scales
/// with) and the pitches the scan tries.
struct SharedWork {
    SortedCoordinates sorted;
    double spacing = 0.0;
    std::vector<double> pitches;
};

SharedWork shared_work(const Mesh& mesh) {
    SharedWork work{sorted_coordinates(mesh), median_edge_length(mesh), {}};
    work.pitches = scan_pitches(work.spacing);
    return work;
}

/// The first window of the lattice search: the values within its reach of their weighted median.
struct FirstWindow {
    Vec3 centre = Vec3::Zero();
    double reach = 0.0;
    AxisValues values;
};

/// Nothing where no value is shared or the mesh shows no spacing.
std::optional<FirstWindow> first_window(const AxisValues& values, const SharedWork& work) {
    if (total_weight(values) <= 0.0 || !(work.spacing > 0.0)) return std::nullopt;
    FirstWindow w;
    w.centre = median_values(values);
    w.reach = kWindowSpacings * work.spacing;
    w.values = window(values, w.centre, w.reach);
    return w;
}

/// One reading of the sample's coordinates at a tolerance: the values shared within it and the
/// first window of the lattice search over them, read by the quick test of an exact mesh and by
/// the search alike.
struct Reading {
    double tol = 0.0;
    AxisValues values;
    std::optional<FirstWindow> first;
};

Reading read_at(double tol, const SharedWork& work) {
    Reading r{tol, shared_values(work.sorted, tol), std::nullopt};
    r.first = first_window(r.values, work);
    return r;
}

LatticeSeeds lattice_seeds(const std::optional<FirstWindow>& w, const SharedWork& work) {
    if (!w) return {};
    return {w->centre, w->reach, coarse_lattices(w->values, work.pitches)};
}

/// Whether a refinement stayed a lattice within 5 % of the pitch it started from.
bool stays_near(const Lattice& fine, double from_pitch) {
    return fine.pitch > 0.0 && std::abs(fine.pitch / from_pitch - 1.0) <= 0.05;
}

/// One coarse lattice refined over all values, or nothing if no refinement stays within 5 % of
/// its pitch. The peak of a small part is broad, and values off the lattice pull it aside: the
/// refinement starts from pitches around it too (kStarts each side, 0.5 % apart) and keeps the
/// lattice whose lines hold the most values. The caller refines one coarse lattice at a time,
/// so that a search that stops at the first grid found refines no more.
std::optional<Lattice> refined_lattice(const AxisValues& values, const LatticeSeeds& seeds,
                                       const Lattice& coarse, double tol) {
    std::optional<Lattice> best;
    double best_weight = 0.0;
    for (int start = -kStarts; start <= kStarts; ++start) {
        Lattice from = coarse;
        from.pitch *= 1.0 + 0.005 * start;
        const Lattice fine = refine_lattice(values, from, seeds.centre, seeds.reach, tol);
        if (!stays_near(fine, coarse.pitch)) continue;
        const double weight = weight_on_lines(values, fine, tol);
        if (weight > best_weight) best = fine, best_weight = weight;
    }
    return best;
}

/// Signed offset of x from the nearest grid line, in pitches: (-0.5, 0.5].
double line_offset(double x, double origin, double pitch) {
    const double u = (x - origin) / pitch;
    return u - round_half_away(u);
}

/// How the vertices sit on the edges of `grid` (shares of #V; midpoint of those on edges).
struct EdgeStats {
    double on_edge = 0.0;   ///< two or three coordinates on lines
    double on_node = 0.0;   ///< three
    double midpoint = 0.0;  ///< of those on edges, two on lines and the third at the middle
};

/// How many coordinates of p lie on a line of `grid` (within `within` pitches), and the last axis
/// whose coordinate does not.
std::pair<int, int> lines_through(const Vec3& p, const Grid& grid, double within) {
    int on_lines = 0, free_axis = 0;
    for (int a = 0; a < 3; ++a) {
        if (std::abs(line_offset(p[a], grid.origin[a], grid.pitch)) <= within) {
            ++on_lines;
        } else {
            free_axis = a;
        }
    }
    return {on_lines, free_axis};
}

EdgeStats edge_stats(const Mesh& mesh, const Grid& grid, double tol) {
    const double within = 2.0 * tol / grid.pitch;  // in pitches
    std::size_t on_edge = 0, on_node = 0, midpoint = 0;
    for (const Vec3& p : mesh.positions) {
        const auto [on_lines, free_axis] = lines_through(p, grid, within);
        if (on_lines < 2) continue;
        ++on_edge;
        if (on_lines == 3) {
            ++on_node;
        } else if (std::abs(
                       std::abs(line_offset(p[free_axis], grid.origin[free_axis], grid.pitch)) -
                       0.5) <= within) {
            ++midpoint;
        }
    }
    const double n = static_cast<double>(mesh.vertex_count());
    return {static_cast<double>(on_edge) / n, static_cast<double>(on_node) / n,
            on_edge > 0 ? static_cast<double>(midpoint) / static_cast<double>(on_edge) : 0.0};
}

/// edge_stats().on_edge when it is at least `at_least`, else nothing. Stops as soon as the
/// vertices not yet looked at, were all of them on edges, could no longer lift the share to
/// `at_least`: on a mesh whose vertices are off this grid's edges that is after a few hundred.
/// The share it gives is edge_stats()'s to the bit (same count, same division).
std::optional<double> on_edge_share_reaching(const Mesh& mesh, const Grid& grid, double tol,
                                             double at_least) {
    const double within = 2.0 * tol / grid.pitch;
    const std::size_t nv = mesh.vertex_count();
    const double n = static_cast<double>(nv);
    std::size_t on_edge = 0;
    for (std::size_t v = 0; v < nv; ++v) {
        on_edge += lines_through(mesh.positions[v], grid, within).first >= 2 ? 1 : 0;
        // On the largest share still possible: every vertex after v on an edge.
        if (v % 64 == 63 && static_cast<double>(on_edge + (nv - 1 - v)) / n < at_least) {
            return std::nullopt;
        }
    }
    const double share = static_cast<double>(on_edge) / n;
    return share >= at_least ? std::optional(share) : std::nullopt;
}

/// The coarsest grid whose edges still hold nearly every vertex, from `fine` (which must): a
/// lattice of pitch h also fits at h/2 (where flat faces happen to lie on the half lines, or a
/// midpoint mesh's vertices are all on the nodes of the half grid). Each doubling keeps the
/// every-other lines of each axis that hold the most vertices; at most 8 doublings.
Grid coarsest_edge_grid(const Mesh& mesh, Grid fine, double tol) {
    for (int doubling = 0; doubling < 8; ++doubling) {
        std::optional<Grid> best;
        double best_share = kOnEdgeShare;
        for (int parity = 0; parity < 8; ++parity) {
            Grid g{2.0 * fine.pitch, fine.origin};
            for (int a = 0; a < 3; ++a) {
                if ((parity >> a) & 1) g.origin[a] += fine.pitch;
            }
            if (const auto share = on_edge_share_reaching(mesh, g, tol, best_share)) {
                best = g, best_share = *share;
            }
        }
        if (!best) break;
        fine = *best;
    }
    return fine;
}

/// True when three cells are distinct, at most one apart along every axis and equal along one:
/// three of the four cells around one grid edge.
bool around_one_edge(const std::array<std::array<double, 3>, 3>& cell) {
    if (cell[0] == cell[1] || cell[1] == cell[2] || cell[0] == cell[2]) return false;
    bool adjacent = true, one_slab = false;
    for (int a = 0; a < 3; ++a) {
        const double lo = std::min({cell[0][a], cell[1][a], cell[2][a]});
        const double hi = std::max({cell[0][a], cell[1][a], cell[2][a]});
        adjacent = adjacent && hi - lo <= 1.0;
        one_slab = one_slab || hi == lo;
    }
    return adjacent && one_slab;
}

/// Whether the vertices of `t` lie in three of the four cells of `grid` around one grid edge, as
/// every triangle of a surface-nets mesh does (half of the quad dual to a crossed edge). A
/// coordinate on a grid line (within `within` pitches: a mean of crossings all on one face of its
/// cell, as on a flat face lying on a grid plane) may be in the cell on either side; the triangle
/// counts if one choice fits (at most 2^9 choices).
bool is_dual(const Mesh& mesh, const Triangle& t, const Grid& grid, double within) {
    std::array<std::array<double, 3>, 3> cell;
    unsigned on_line = 0;  // bit 3k + a: coordinate a of vertex k lies on a line
    for (int k = 0; k < 3; ++k) {
        const Vec3& p = mesh.positions[t[k]];
        for (int a = 0; a < 3; ++a) {
            const double u = (p[a] - grid.origin[a]) / grid.pitch;
            const double nearest = round_half_away(u);
            const bool on = std::abs(u - nearest) <= within;
            // std::floor(u) to the bit, without a second rounding: u lies within half of the
            // integer `nearest`, or is that integer (|u| of 2^52 or more, or not finite).
            cell[k][a] = on || u >= nearest ? nearest : nearest - 1.0;
            on_line |= on ? 1u << (3 * k + a) : 0u;
        }
    }
    // Each subset of the on-line coordinates moved to the cell below.
    for (unsigned below = on_line;; below = (below - 1) & on_line) {
        std::array<std::array<double, 3>, 3> choice = cell;
        for (unsigned bits = below; bits != 0; bits &= bits - 1) {
            const int bit = std::countr_zero(bits);
            choice[bit / 3][bit % 3] -= 1.0;
        }
        if (around_one_edge(choice)) return true;
        if (below == 0) return false;
    }
}

/// The step between the triangles dual_share() tests: at most about kSampledTriangles, evenly
/// spread.
std::size_t dual_stride(const Mesh& mesh) {
    return std::max<std::size_t>(1, mesh.face_count() / kSampledTriangles);
}

/// The share of every `stride`-th triangle (from the first) that is_dual() on `grid`, when it
/// is at least `at_least`, else nothing. Stops as soon as the triangles not yet looked at, were
/// all of them dual, could no longer lift the share to `at_least`. Same count, same division,
/// whether it stops or not: the share it gives is the same bits.
std::optional<double> dual_share_reaching(const Mesh& mesh, const Grid& grid, double tol,
                                          std::size_t stride, double at_least) {
    const double within = 2.0 * tol / grid.pitch;
    const std::size_t tested = (mesh.face_count() + stride - 1) / stride;
    const double n = static_cast<double>(tested);
    std::size_t dual = 0;
    for (std::size_t i = 0; i < tested; ++i) {
        dual += is_dual(mesh, mesh.triangles[i * stride], grid, within) ? 1 : 0;
        // On the largest share still possible: every triangle after i dual.
        if (i % 64 == 63 && static_cast<double>(dual + (tested - 1 - i)) / n < at_least) {
            return std::nullopt;
        }
    }
    const double share = tested > 0 ? static_cast<double>(dual) / n : 0.0;
    return share >= at_least ? std::optional(share) : std::nullopt;
}

/// The share of the triangles dual_stride() spreads that is_dual() on `grid`.
double dual_share(const Mesh& mesh, const Grid& grid, double tol) {
    return *dual_share_reaching(mesh, grid, tol, dual_stride(mesh), 0.0);
}

std::string describe(const Grid& g) {
    std::ostringstream s;
    s.precision(9);
    s << "pitch " << g.pitch << ", origin (" << g.origin.x() << ", " << g.origin.y() << ", "
      << g.origin.z() << ")";
    return s.str();
}

std::string percent(double share) {
    std::ostringstream s;
    s.precision(3);
    s << 100.0 * share << " %";
    return s.str();
}

/// The estimate on a known grid: on its edges (midpoint or exact), dual to it (near), or exact.
/// `dual`: the grid's dual_share() where the caller has it.
PlacementEstimate classify_on(const Mesh& mesh, const Grid& grid, double tol,
                              const std::string& source, std::optional<double> dual = {}) {
    PlacementEstimate e;
    e.grid = grid;
    e.pitch = grid.pitch;
    const EdgeStats s = edge_stats(mesh, grid, tol);
    e.on_grid_edge_share = s.on_edge;
    e.midpoint_share = s.midpoint;
    const std::string where = source + " (" + describe(grid) + "): ";
    if (s.on_edge >= kOnEdgeShare) {
        e.placement =
            s.midpoint >= kMidpointShare ? VertexPlacement::Midpoint : VertexPlacement::Exact;
        e.reason = where + percent(s.on_edge) + " of the vertices on grid edges, " +
                   percent(s.midpoint) + " of those at the middle: " +
                   (e.placement == VertexPlacement::Midpoint
                        ? "midpoint"
                        : "exact (crossings or bisection along the edges)");
        return e;
    }
    e.dual_triangle_share = dual ? *dual : dual_share(mesh, grid, tol);
    e.placement = e.dual_triangle_share >= kDualShare && s.on_edge <= kDualOnEdgeShare
                      ? VertexPlacement::Near
                      : VertexPlacement::Exact;
    e.reason = where + percent(s.on_edge) + " of the vertices on grid edges, " +
               percent(e.dual_triangle_share) + " of the triangles on the cells around one edge: " +
               (e.placement == VertexPlacement::Near ? "near (cell means)" : "cannot tell, exact");
    return e;
}

/// The grids a mesh may have been built on, given a lattice of its shared coordinates: a line
/// value may be a grid line or lie halfway between two (a surface-nets vertex at a cell centre
/// where its face is flat and axis-aligned; a midpoint vertex), on each axis; and the lattice
/// may show half the pitch. The eight half-pitch shifts of the lattice's pitch and of twice it.
constexpr std::size_t kShifts = 16;  // shifted_grids() per lattice

std::vector<Grid> shifted_grids(const Lattice& l) {
    std::vector<Grid> out;
    for (double pitch : {l.pitch, 2.0 * l.pitch}) {
        for (int shift = 0; shift < 8; ++shift) {
            Grid g{pitch, l.phase};
            for (int a = 0; a < 3; ++a) {
                if ((shift >> a) & 1) g.origin[a] += 0.5 * pitch;
            }
            out.push_back(g);
        }
    }
    return out;
}

/// Per vertex, the sum of its faces' area-weighted normals.
std::vector<Vec3> vertex_normals(const Mesh& mesh) {
    std::vector<Vec3> normals(mesh.vertex_count(), Vec3::Zero());
    for (const Triangle& t : mesh.triangles) {
        const auto& x = mesh.positions;
        const Vec3 n = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]);
        for (Index v : t) normals[v] += n;
    }
    return normals;
}

/// The share of vertex coordinates on a line of `grid` whose vertex does not face along that
/// axis. A cell mean lies on a grid plane only where all its crossings do, on a flat face lying
/// in that plane: its normal points along the axis.
double stray_on_lines(const Mesh& mesh, const std::vector<Vec3>& normals, const Grid& grid,
                      double tol) {
    const double within = 2.0 * tol / grid.pitch;
    std::size_t stray = 0;
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        for (int a = 0; a < 3; ++a) {
            const bool on =
                std::abs(line_offset(mesh.positions[v][a], grid.origin[a], grid.pitch)) <= within;
            stray += on && std::abs(normals[v][a]) < 0.9 * normals[v].norm() ? 1 : 0;
        }
    }
    return static_cast<double>(stray) / (3.0 * static_cast<double>(mesh.vertex_count()));
}

/// Per candidate, its dual_share(), or nothing where best_dual_grid() need not know it: where
/// it is below the best share less kDualShareSlack, or, once a share of 1 (every triangle dual,
/// the most there is) makes the best known, in a lattice after one that holds a grid near the
/// best (the first such lattice is the one taken). Each share on every 64th of the triangles
/// first orders the full counts, best first: the first then sets a bar that most candidates
/// (shares of 0.8 to 0.99 on a surface-nets mesh) fall below within a few hundred triangles.
std::vector<std::optional<double>> dual_shares_near_best(const Mesh& mesh,
                                                         const std::vector<Grid>& candidates,
                                                         double tol) {
    const std::size_t stride = dual_stride(mesh);
    std::vector<double> rough;
    for (const Grid& g : candidates)
        rough.push_back(*dual_share_reaching(mesh, g, tol, 64 * stride, 0.0));
    std::vector<std::size_t> order(candidates.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return rough[a] > rough[b]; });
    std::vector<std::optional<double>> shares(candidates.size());
    double highest = 0.0;  // at most the best share: the bar below it holds for the best too
    std::size_t first_full_lattice = candidates.size();  // of a share within the slack of 1
    for (std::size_t i : order) {
        if (highest == 1.0 && i / kShifts > first_full_lattice) continue;
        shares[i] =
            dual_share_reaching(mesh, candidates[i], tol, stride, highest - kDualShareSlack);
        if (!shares[i]) continue;
        highest = std::max(highest, *shares[i]);
        if (*shares[i] >= 1.0 - kDualShareSlack)
            first_full_lattice = std::min(first_full_lattice, i / kShifts);
    }
    return shares;
}

/// The candidate with the most dual triangles, and its share. A pitch a little off still fits
/// most triangles of a small part: the first lattice within kDualShareSlack of the best share is
/// taken. Where flat faces lie on grid planes, the grid shifted by half a cell across them fits
/// as well: of that lattice's shifts, the one with the fewest stray coordinates on grid lines
/// (stray_on_lines).
std::pair<Grid, double> best_dual_grid(const Mesh& mesh, const std::vector<Grid>& candidates,
                                       double tol) {
    const std::vector<std::optional<double>> shares = dual_shares_near_best(mesh, candidates, tol);
    const double best = **std::max_element(shares.begin(), shares.end());
    const auto near_best = [&](std::size_t i) {
        return shares[i] && *shares[i] >= best - kDualShareSlack;
    };
    const std::vector<Vec3> normals = vertex_normals(mesh);
    // The candidates come in lattice order, kShifts per lattice: the first lattice that
    // reaches the best share, its shift with the fewest stray coordinates.
    std::size_t first = 0;
    while (!near_best(first)) ++first;
    const std::size_t lattice_end = (first / kShifts + 1) * kShifts;
    std::size_t chosen = first;
    double fewest_stray = 2.0;
    for (std::size_t i = first; i < lattice_end && i < candidates.size(); ++i) {
        if (!near_best(i)) continue;
        const double stray = stray_on_lines(mesh, normals, candidates[i], tol);
        if (stray < fewest_stray) chosen = i, fewest_stray = stray;
    }
    return {candidates[chosen], *shares[chosen]};
}

/// Where the grid of an estimate came from, as its reason says.
constexpr const char* kSharedCoordinates = "the grid of the shared coordinates";

/// Per axis, the values held by at least the square root of the most vertices any value of the
/// axis holds (weight half the largest). On a grid-edge mesh these are the grid lines, each
/// holding a slice of the surface; the others are the few vertices that share a free coordinate
/// by chance (on impeller 109 of the first window's 181 values), or by rounding at a float
/// tolerance, in no step with the lines.
AxisValues heavy_values(const AxisValues& near) {
    AxisValues out;
    for (int a = 0; a < 3; ++a) {
        double heaviest = 0.0;
        for (const SharedValue& s : near[a]) heaviest = std::max(heaviest, s.weight);
        for (const SharedValue& s : near[a]) {
            if (s.weight >= 0.5 * heaviest) out[a].push_back(s);
        }
    }
    return out;
}

/// Per axis, the median gap between neighbouring values, once each: for heavy_values() of a
/// grid-edge mesh, the pitch on an axis whose lines outnumber the faces off them (a flat face
/// off the lines splits a gap, a missing line doubles one; cavity's scallop floors, levels of
/// the tool's passes, split most of the gaps along the tool axis). At most three.
std::vector<double> median_gaps(const AxisValues& values) {
    std::vector<double> out;
    for (const auto& axis : values) {
        if (axis.size() < 2) continue;
        std::vector<double> gaps;
        for (std::size_t i = 1; i < axis.size(); ++i)
            gaps.push_back(axis[i].value - axis[i - 1].value);
        const auto middle = gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2);
        std::nth_element(gaps.begin(), middle, gaps.end());
        if (std::find(out.begin(), out.end(), *middle) == out.end()) out.push_back(*middle);
    }
    return out;
}

/// The estimate of an exact-crossing (or bisection) mesh without the pitch scan, which costs
/// most of the estimate on such a mesh (on impeller 51 of 93 M instructions, the refinement of
/// its peaks 32 M more): for each median gap of the first window's heavy values, the lattice of
/// that pitch in step with them, refined over all values as a coarse lattice is, and its grids
/// tested as the scan's are. Taken only where a grid's edges hold the vertices and they are
/// placed exactly: a grid-edge mesh is what that share says, and a grid found this way
/// classifies as the scan's would (both are made coarsest by coarsest_edge_grid()); Midpoint
/// and the rest are left to the scan, whose grid their moves use. Nothing otherwise.
std::optional<PlacementEstimate> exact_on_gap_lattice(const Mesh& mesh, const Reading& reading) {
    const double tol = reading.tol;
    const AxisValues& values = reading.values;
    const std::optional<FirstWindow>& first = reading.first;
    if (!first) return std::nullopt;
    const AxisValues lines = heavy_values(first->values);
    for (double gap : median_gaps(lines)) {  // Bound: three gaps
        if (!(gap >= 64.0 * tol)) continue;  // rounded too coarsely to tell
        const Lattice l =
            refine_lattice(values, phased_lattice(lines, gap), first->centre, first->reach, tol);
        if (!stays_near(l, gap) || l.pitch < 64.0 * tol) continue;
        for (const Grid& g : shifted_grids(l)) {  // Bound: kShifts grids
            if (!on_edge_share_reaching(mesh, g, tol, kOnEdgeShare)) continue;
            PlacementEstimate e =
                classify_on(mesh, coarsest_edge_grid(mesh, g, tol), tol, kSharedCoordinates);
            if (e.placement == VertexPlacement::Exact) return e;
            return std::nullopt;
        }
    }
    return std::nullopt;
}

/// What estimate_within() looks for: a grid whose edges hold the vertices, or one the mesh is
/// dual to as well.
enum class Search { EdgeGridOnly, Any };

/// The estimate from the mesh alone, coordinates compared within the reading's tolerance. With
/// Search::EdgeGridOnly, where no grid's edges hold the vertices it says so and stops there
/// (an on-edge share of 0).
PlacementEstimate estimate_within(const Mesh& mesh, const Reading& reading, Search search,
                                  const SharedWork& work) {
    PlacementEstimate e;
    const double tol = reading.tol;
    const AxisValues& values = reading.values;
    const LatticeSeeds seeds = lattice_seeds(reading.first, work);
    // A grid-edge mesh takes the first grid whose edges hold its vertices. Only then may a mesh
    // be dual: a grid-edge mesh is dual to its grid shifted by half a cell on every axis (its
    // triangles span the eighths of a cell), so the dual test alone cannot tell them apart. A
    // dual mesh takes the grid with the most dual triangles over all lattices (a pitch a little
    // off still holds most of them).
    const std::string source = kSharedCoordinates;
    std::optional<double> first_pitch;  // of the first lattice refined
    std::vector<Grid> candidates;
    for (const Lattice& coarse : seeds.coarse) {  // Bound: kCandidates lattices
        const std::optional<Lattice> lattice = refined_lattice(values, seeds, coarse, tol);
        if (!lattice) continue;
        if (!first_pitch) first_pitch = lattice->pitch;
        if (lattice->pitch < 64.0 * tol) continue;  // rounded too coarsely to tell
        for (const Grid& g : shifted_grids(*lattice)) {
            if (on_edge_share_reaching(mesh, g, tol, kOnEdgeShare)) {
                return classify_on(mesh, coarsest_edge_grid(mesh, g, tol), tol, source);
            }
            candidates.push_back(g);
        }
    }
    if (!first_pitch) {
        e.reason =
            "no coordinate values shared by many vertices at a common spacing: no grid, "
            "exact";
        return e;
    }
    if (search == Search::EdgeGridOnly) {
        e.reason = "no grid's edges hold the vertices";
        return e;
    }
    std::ostringstream r;
    r.precision(9);
    r << "the spacings of the shared coordinates (first " << *first_pitch << ") ";
    if (candidates.empty()) {
        r << "are below the coordinates' rounding: cannot tell, exact";
        e.reason = r.str();
        return e;
    }
    const auto [dual, share] = best_dual_grid(mesh, candidates, tol);
    if (share >= kDualShare) return classify_on(mesh, dual, tol, source, share);
    e.pitch = dual.pitch;
    e.on_grid_edge_share = edge_stats(mesh, dual, tol).on_edge;
    e.dual_triangle_share = share;
    r << "fit no grid: on the best, " << percent(e.on_grid_edge_share)
      << " of the vertices on grid edges, " << percent(share)
      << " of the triangles on the cells around one edge: cannot tell, exact";
    e.reason = r.str();
    return e;
}

}  // namespace

std::string_view to_string(VertexPlacement placement) {
    switch (placement) {
        case VertexPlacement::Exact:
            return "exact";
        case VertexPlacement::Near:
            return "near";
        case VertexPlacement::Midpoint:
            return "midpoint";
    }
    return "exact";
}

std::optional<VertexPlacement> vertex_placement_from_string(std::string_view name) {
    for (VertexPlacement p :
         {VertexPlacement::Exact, VertexPlacement::Near, VertexPlacement::Midpoint}) {
        if (name == to_string(p)) return p;
    }
    return std::nullopt;
}

namespace {

/// At most about kSampleFaces faces, evenly spaced in face order, with their vertices: how a
/// mesher placed its vertices shows as well on a few thousand faces as on all, and restore()
/// asks on every mesh. (The whole mesh where it is smaller.)
constexpr std::size_t kSampleFaces = 12000;

Mesh sample_of(const Mesh& mesh) {
    if (mesh.face_count() <= kSampleFaces) return mesh;
    const std::size_t stride = (mesh.face_count() + kSampleFaces - 1) / kSampleFaces;
    std::vector<Index> renumbered(mesh.vertex_count(), kNoIndex);
    Mesh sample;
    for (std::size_t f = 0; f < mesh.face_count(); f += stride) {
        Triangle t = mesh.triangles[f];
        for (Index& v : t) {
            if (renumbered[v] == kNoIndex) {
                renumbered[v] = static_cast<Index>(sample.positions.size());
                sample.positions.push_back(mesh.positions[v]);
            }
            v = renumbered[v];
        }
        sample.triangles.push_back(t);
    }
    return sample;
}

}  // namespace

PlacementEstimate estimate_vertex_placement(const Mesh& full, const std::optional<Grid>& given) {
    const Mesh mesh = sample_of(full);
    if (given && (!(given->pitch > 0.0) || !std::isfinite(given->pitch))) {
        throw InvalidInput("grid pitch must be positive and finite");
    }
    if (given && !given->origin.allFinite()) throw InvalidInput("grid origin must be finite");
    if (mesh.vertex_count() < 4 || mesh.face_count() == 0) {
        PlacementEstimate e;
        e.grid = given;
        e.reason = "too few vertices to show how they were placed: exact";
        return e;
    }
    // Float coordinates may be exact (a dyadic grid: then only double's noise lets a bisection
    // vertex h/512 off a line be told from it) or rounded: the first where nearly every vertex
    // lies on grid edges, else the rounded reading.
    const auto [exact_tol, float_tol] = coordinate_tolerances(mesh);
    std::optional<SharedWork> work;
    std::vector<Reading> readings;  // at exact_tol, then at float_tol if there is one
    if (!given) {
        work = shared_work(mesh);
        readings.push_back(read_at(exact_tol, *work));
        if (float_tol) readings.push_back(read_at(*float_tol, *work));
        // A mesh with every vertex on a grid's edges at either tolerance, and placed exactly,
        // needs no search (exact_on_gap_lattice()).
        for (const Reading& r : readings) {
            if (auto e = exact_on_gap_lattice(mesh, r)) return *e;
        }
    }
    const auto estimate = [&](std::size_t reading, double tol, Search search) {
        return given ? classify_on(mesh, *given, tol, "the given grid")
                     : estimate_within(mesh, readings[reading], search, *work);
    };
    // The first reading stands only where a grid's edges hold the vertices (a share of
    // kOnEdgeShare or more, which no dual grid reaches: estimate_within() tests every grid for
    // that first); with a rounded reading to follow, it need not look for a dual grid.
    PlacementEstimate e = estimate(0, exact_tol, float_tol ? Search::EdgeGridOnly : Search::Any);
    if (float_tol && e.on_grid_edge_share < kOnEdgeShare) e = estimate(1, *float_tol, Search::Any);
    return e;
}

}  // namespace resharp
