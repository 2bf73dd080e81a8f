#include "resharp/sim/sweep.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "resharp/core/errors.h"
#include "resharp/sim/cone_ramp.h"

namespace resharp::sim {
namespace {

using Vec2 = Eigen::Vector2d;
template <int D>
using VecD = Eigen::Matrix<double, D, 1>;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kTwoPi = 2.0 * std::numbers::pi;

Vec3 embed(const Vec2& v) { return Vec3(v.x(), v.y(), 0.0); }
Vec3 embed(const Vec3& v) { return v; }

/// A parameter range [t0, t1] on a ray; empty when t0 >= t1.
struct Range {
    double t0 = kInfinity, t1 = -kInfinity;
    bool empty() const { return !(t0 < t1); }
    Range meet(const Range& o) const { return {std::max(t0, o.t0), std::min(t1, o.t1)}; }
    Range hull(const Range& o) const {
        if (empty()) return o;
        if (o.empty()) return *this;
        return {std::min(t0, o.t0), std::max(t1, o.t1)};
    }
};

/// The line o + t e_k inside the ball of radius rho around c. A line touching it gets a tiny
/// chord when the touching point counts as inside (kTouchingChord).
template <int D>
Range ball_chord(const VecD<D>& o, int k, const VecD<D>& c, double rho) {
    VecD<D> off = o - c;  // from the centre to the line, across it
    off[k] = 0.0;
    const double half_squared = rho * rho - off.squaredNorm();
    const double mid = c[k] - o[k];
    if (half_squared == 0.0 && boundary_is_inside(embed(VecD<D>(off / rho)))) {
        return {mid - kTouchingChord * rho, mid + kTouchingChord * rho};
    }
    if (!(half_squared > 0.0)) return {};
    const double half = std::sqrt(half_squared);
    return {mid - half, mid + half};
}

/// The line o + t e_k inside the capsule of radius rho around the segment [a, b]: the union of
/// the two end balls and the cylinder between them (convex, so their hull). A line lying on the
/// cylinder counts as inside by the perturbation rule.
template <int D>
Range capsule_chord(const VecD<D>& o, int k, const VecD<D>& a, const VecD<D>& b, double rho) {
    Range range = ball_chord<D>(o, k, a, rho).hull(ball_chord<D>(o, k, b, rho));
    const VecD<D> d = b - a;
    const double length_squared = d.squaredNorm();
    if (length_squared == 0.0) return range;
    double d_across = 0.0;  // |d|² without its component along the line
    for (int j = 0; j < D; ++j) {
        if (j != k) d_across += d[j] * d[j];
    }
    const VecD<D> w = o - a;
    const double wd = w.dot(d);
    // Distance from the axis: |v0 + t v1| with v1 = e_k - (d_k / |d|²) d.
    const VecD<D> v0 = w - (wd / length_squared) * d;
    Range cylinder;
    if (d_across == 0.0) {
        const double gap = v0.squaredNorm() - rho * rho;
        if (gap > 0.0 || (gap == 0.0 && !boundary_is_inside(embed(VecD<D>(v0 / rho))))) {
            return range;
        }
        cylinder = {-kInfinity, kInfinity};
    } else {
        VecD<D> v1 = -(d[k] / length_squared) * d;
        v1[k] += 1.0;
        const double qa = d_across / length_squared;
        const double qb = v0.dot(v1);
        const double qc = v0.squaredNorm() - rho * rho;
        const double disc = qb * qb - qa * qc;
        const double touch = -qb / qa;
        if (disc == 0.0 && boundary_is_inside(embed(VecD<D>((v0 + touch * v1) / rho)))) {
            cylinder = {touch - kTouchingChord * rho, touch + kTouchingChord * rho};
        } else if (disc > 0.0) {
            const double root = std::sqrt(disc);
            cylinder = {(-qb - root) / qa, (-qb + root) / qa};
        } else {
            return range;
        }
    }
    // Only where the foot of the perpendicular lies on the segment: 0 <= s(t) <= 1.
    if (d[k] == 0.0) {
        if (wd < 0.0 || wd > length_squared) return range;
    } else {
        const double s0 = -wd / d[k], s1 = (length_squared - wd) / d[k];
        cylinder = cylinder.meet({std::min(s0, s1), std::max(s0, s1)});
    }
    return range.hull(cylinder);
}

template <int D>
VecD<D> nearest_on_segment(const VecD<D>& p, const VecD<D>& a, const VecD<D>& b,
                           double* s = nullptr) {
    const VecD<D> d = b - a;
    const double length_squared = d.squaredNorm();
    const double t =
        length_squared > 0.0 ? std::clamp((p - a).dot(d) / length_squared, 0.0, 1.0) : 0.0;
    if (s != nullptr) *s = t;
    return a + t * d;
}

/// A horizontal arc counter-clockwise from angle `from` through `span` >= 0 radians.
struct ArcShape {
    Vec2 center;
    double radius = 0.0;
    double from = 0.0, span = 0.0;

    Vec2 at(double angle) const { return center + radius * Vec2(std::cos(angle), std::sin(angle)); }
    Vec2 first() const { return at(from); }
    Vec2 last() const { return at(from + span); }
    bool covers(double angle) const {
        if (span >= kTwoPi) return true;
        double delta = std::fmod(angle - from, kTwoPi);
        if (delta < 0.0) delta += kTwoPi;
        return delta <= span;
    }
    Vec2 nearest(const Vec2& p) const {
        const Vec2 v = p - center;
        const double n = v.norm();
        if (n > 0.0 && covers(std::atan2(v.y(), v.x()))) return center + (radius / n) * v;
        const Vec2 a = first(), b = last();
        return (p - a).squaredNorm() <= (p - b).squaredNorm() ? a : b;
    }
};

ArcShape arc_shape(const ToolMotion& m) {
    ArcShape arc;
    arc.center = m.center;
    arc.radius = m.radius;
    arc.from = m.sweep >= 0.0 ? m.start_angle : m.start_angle + m.sweep;
    arc.span = std::abs(m.sweep);
    return arc;
}

/// Where cross(u, p(t) - c) >= 0 along the line p(t) = o + t e_k (a half-plane through c).
Range left_of(const Vec2& o, int k, const Vec2& c, const Vec2& u) {
    const Vec2 v = o - c;
    const double alpha = u.x() * v.y() - u.y() * v.x();
    const double beta = k == 0 ? -u.y() : u.x();  // cross(u, e_k)
    if (beta == 0.0) return alpha >= 0.0 ? Range{-kInfinity, kInfinity} : Range{};
    const double t = -alpha / beta;
    return beta > 0.0 ? Range{t, kInfinity} : Range{-kInfinity, t};
}

/// The line o + t e_k inside the disk of radius rho swept along the arc: its end disks, and
/// the annulus |p - c| in [R - rho, R + rho] within the arc's angular wedge. Appends pieces.
void arc_band_pieces(const Vec2& o, int k, const ArcShape& arc, double rho,
                     std::vector<Range>& pieces) {
    pieces.push_back(ball_chord<2>(o, k, arc.first(), rho));
    pieces.push_back(ball_chord<2>(o, k, arc.last(), rho));
    const Range outer = ball_chord<2>(o, k, arc.center, arc.radius + rho);
    if (outer.empty()) return;
    Range annulus[2] = {outer, {}};
    if (arc.radius > rho) {
        const Range inner = ball_chord<2>(o, k, arc.center, arc.radius - rho);
        if (!inner.empty()) annulus[0] = {outer.t0, inner.t0}, annulus[1] = {inner.t1, outer.t1};
    }
    Range wedge[2] = {{-kInfinity, kInfinity}, {}};
    if (arc.span < kTwoPi) {
        const Vec2 u_from(std::cos(arc.from), std::sin(arc.from));
        const Vec2 u_to(std::cos(arc.from + arc.span), std::sin(arc.from + arc.span));
        if (arc.span <= std::numbers::pi) {
            wedge[0] = left_of(o, k, arc.center, u_from).meet(left_of(o, k, arc.center, -u_to));
        } else {
            // The complement of a convex wedge: the line minus where it crosses that wedge.
            const Range gap =
                left_of(o, k, arc.center, u_to).meet(left_of(o, k, arc.center, -u_from));
            if (!gap.empty()) wedge[0] = {-kInfinity, gap.t0}, wedge[1] = {gap.t1, kInfinity};
        }
    }
    for (const Range& a : annulus) {
        for (const Range& w : wedge) {
            if (!a.empty() && !w.empty()) pieces.push_back(a.meet(w));
        }
    }
}

/// Sorts intervals and joins those that overlap or touch; the outer ends survive.
void merge_into(std::vector<Interval>& pieces, std::vector<Interval>& out) {
    std::sort(pieces.begin(), pieces.end(),
              [](const Interval& a, const Interval& b) { return a.enter.t < b.enter.t; });
    const std::size_t first = out.size();
    for (const Interval& piece : pieces) {
        if (!(piece.enter.t < piece.exit.t)) continue;
        if (out.size() > first && piece.enter.t <= out.back().exit.t) {
            if (piece.exit.t > out.back().exit.t) out.back().exit = piece.exit;
        } else {
            out.push_back(piece);
        }
    }
}

/// Normal of the surface a flat rim sweeps on a ramp. The rim point's normal cone is spanned by
/// g (radial) and -z or +z; the envelope normal is the member orthogonal to the motion.
Vec3 rim_normal(const Vec2& g, const Vec3& motion) {
    const double sign = motion.z() > 0.0 ? 1.0 : -1.0;
    const Vec3 n = sign * (motion.z() * embed(g) - g.dot(motion.head<2>()) * Vec3::UnitZ());
    return n.normalized();
}

Vec2 unit_or_x(const Vec2& v) {
    const double n = v.norm();
    return n > 0.0 ? Vec2(v / n) : Vec2::UnitX();
}

}  // namespace

SweptVolume::SweptVolume(const Tool& tool, const ToolMotion& motion, std::size_t move,
                         const SweepOptions& options)
    : tool_(tool), motion_(motion), move_(move), options_(options) {
    if (!(options.bullnose_step > 0.0))
        throw InvalidInput("bull-nose sampling step must be positive");
    const Vec3 delta = motion.end - motion.start;
    const double rim = tool.radius;
    if (motion.kind == ToolMotion::Kind::Arc) {
        if (motion.start.z() != motion.end.z())
            throw InvalidInput("an arc motion must be horizontal");
        if (!(motion.radius > 0.0)) throw InvalidInput("an arc motion needs a positive radius");
        method_ = Method::Horizontal;
        const ArcShape arc = arc_shape(motion);
        Eigen::AlignedBox2d xy;
        xy.extend(arc.first());
        xy.extend(arc.last());
        for (int quarter = 0; quarter < 4; ++quarter) {
            const double angle = quarter * std::numbers::pi / 2;
            if (arc.covers(angle)) xy.extend(arc.at(angle));
        }
        bounds_ = Box3(
            Vec3(xy.min().x() - rim, xy.min().y() - rim, motion.start.z()),
            Vec3(xy.max().x() + rim, xy.max().y() + rim, motion.start.z() + tool.flute_length));
        return;
    }
    if (delta.z() == 0.0) {
        method_ = Method::Horizontal;
    } else if (delta.x() == 0.0 && delta.y() == 0.0) {
        method_ = Method::Plunge;
    } else {
        method_ = tool.shape == ToolShape::FlatEnd   ? Method::FlatRamp
                  : tool.shape == ToolShape::BallEnd ? Method::BallRamp
                  : tool.shape == ToolShape::Cone    ? Method::ConeRamp
                                                     : Method::SampledRamp;
    }
    const Vec3 lo = motion.start.cwiseMin(motion.end), hi = motion.start.cwiseMax(motion.end);
    bounds_ = Box3(Vec3(lo.x() - rim, lo.y() - rim, lo.z()),
                   Vec3(hi.x() + rim, hi.y() + rim, hi.z() + tool.flute_length));
}

Eigen::Vector2d nearest_on_path(const ToolMotion& motion, const Eigen::Vector2d& p) {
    if (motion.kind == ToolMotion::Kind::Arc) return arc_shape(motion).nearest(p);
    return nearest_on_segment<2>(p, motion.start.head<2>(), motion.end.head<2>());
}

Crossing SweptVolume::crossing(const Vec3& p, const Eigen::Vector2d& nearest,
                               const ProfilePoint& profile, double t) const {
    const Vec2 g = unit_or_x(p.head<2>() - nearest);
    return {t, profile.normal_r * embed(g) + profile.normal_z * Vec3::UnitZ(),
            tool_surface_id(move_, profile.part)};
}

void SweptVolume::intersect(const Ray& ray, std::vector<Interval>& out) const {
    if (method_ == Method::SampledRamp) {
        intersect_static_copies(ray, out);
    } else if (method_ == Method::ConeRamp) {
        if (const auto cut = cut_cone_ramp(tool_, motion_.start, motion_.end, ray, move_)) {
            out.push_back(*cut);
        }
    } else if (ray.axis == 2) {
        intersect_vertical(ray, out);
    } else {
        intersect_horizontal(ray, out);
    }
}

void SweptVolume::intersect_vertical(const Ray& ray, std::vector<Interval>& out) const {
    const Vec2 xy = ray.origin.head<2>();
    const double top_rise = tool_.flute_length;
    const Crossing top_plane_at = {0.0, Vec3::UnitZ(), tool_surface_id(move_, ToolPart::Top)};
    if (method_ == Method::Horizontal || method_ == Method::Plunge) {
        // The lowest the tool reaches on this line is where the path comes nearest.
        const Vec2 q = nearest_on_path(motion_, xy);
        const double r = (xy - q).norm();
        const Vec2 g = unit_or_x(xy - q);
        if (r > tool_.radius || (r == tool_.radius && !boundary_is_inside(embed(g)))) return;
        const ProfilePoint bottom = bottom_at(tool_, r);
        const double low = std::min(motion_.start.z(), motion_.end.z());
        const double high = std::max(motion_.start.z(), motion_.end.z());
        Crossing exit = top_plane_at;
        exit.t = high + top_rise;
        out.push_back({crossing(Vec3(xy.x(), xy.y(), 0.0), q, bottom, low + bottom.value), exit});
        return;
    }
    // Ramps: the tool covers this line for s in [s_lo, s_hi] (|xy - P(s)| <= R).
    const Vec3 delta = motion_.end - motion_.start;
    const Vec2 d = delta.head<2>();
    const Vec2 w = xy - motion_.start.head<2>();
    const double qa = d.squaredNorm(), qb = w.dot(d),
                 qc = w.squaredNorm() - tool_.radius * tool_.radius;
    const double disc = qb * qb - qa * qc;
    if (!(disc > 0.0)) return;
    const double root = std::sqrt(disc);
    const double root_lo = (qb - root) / qa, root_hi = (qb + root) / qa;
    const double s_lo = std::max(root_lo, 0.0), s_hi = std::min(root_hi, 1.0);
    if (!(s_lo < s_hi)) return;
    const bool rising = delta.z() > 0.0;
    // Top of the cut: the highest position, on the top rim unless at a move end.
    const double s_top = rising ? s_hi : s_lo;
    const bool top_on_rim = rising ? root_hi < 1.0 : root_lo > 0.0;
    const Vec2 g_top = unit_or_x(xy - (motion_.start.head<2>() + s_top * d));
    Crossing exit = top_plane_at;
    exit.t = motion_.start.z() + s_top * delta.z() + top_rise;
    if (top_on_rim)
        exit = {exit.t, rim_normal(g_top, delta), tool_surface_id(move_, ToolPart::TopRim)};

    Crossing enter;
    if (method_ == Method::FlatRamp) {
        const double s_bottom = rising ? s_lo : s_hi;
        const bool bottom_on_rim = rising ? root_lo > 0.0 : root_hi < 1.0;
        const Vec2 g = unit_or_x(xy - (motion_.start.head<2>() + s_bottom * d));
        enter = {motion_.start.z() + s_bottom * delta.z(), -Vec3::UnitZ(),
                 tool_surface_id(move_, ToolPart::Bottom)};
        if (bottom_on_rim) {
            enter.normal = rim_normal(g, delta);
            enter.surface = tool_surface_id(move_, ToolPart::BottomRim);
        }
    } else {  // ball: the lowest point of the capsule around the path of the ball's centre
        const Vec3 lift = tool_.radius * Vec3::UnitZ();
        const Vec3 a = motion_.start + lift, b = motion_.end + lift;
        const Range r = capsule_chord<3>(ray.origin, 2, a, b, tool_.radius);
        if (r.empty()) return;
        const Vec3 p = ray.point(r.t0);
        enter = {r.t0, (p - nearest_on_segment<3>(p, a, b)).normalized(),
                 tool_surface_id(move_, ToolPart::Corner)};
    }
    if (enter.t < exit.t) out.push_back({enter, exit});
}

void SweptVolume::intersect_horizontal(const Ray& ray, std::vector<Interval>& out) const {
    const Vec2 o = ray.origin.head<2>();
    const int k = ray.axis;
    const double z = ray.origin.z();
    const double flute = tool_.flute_length;
    const auto band_crossings = [&](const Range& r, const ProfilePoint& profile) {
        const Vec3 p0 = ray.point(r.t0), p1 = ray.point(r.t1);
        return Interval{crossing(p0, nearest_on_path(motion_, p0.head<2>()), profile, r.t0),
                        crossing(p1, nearest_on_path(motion_, p1.head<2>()), profile, r.t1)};
    };
    if (method_ == Method::Horizontal) {
        const double height = z - motion_.start.z();
        if (height < 0.0 || height >= flute) return;  // bottom plane in, top plane out
        const ProfilePoint section = radius_at(tool_, height);
        if (!(section.value > 0.0)) return;
        if (motion_.kind == ToolMotion::Kind::Line) {
            const Range r = capsule_chord<2>(o, k, motion_.start.head<2>(), motion_.end.head<2>(),
                                             section.value);
            if (!r.empty()) out.push_back(band_crossings(r, section));
            return;
        }
        std::vector<Range> ranges;
        arc_band_pieces(o, k, arc_shape(motion_), section.value, ranges);
        std::vector<Interval> pieces;
        for (const Range& r : ranges) {
            if (!r.empty()) pieces.push_back(band_crossings(r, section));
        }
        merge_into(pieces, out);
        return;
    }
    const double low = std::min(motion_.start.z(), motion_.end.z());
    const double high = std::max(motion_.start.z(), motion_.end.z());
    if (method_ == Method::Plunge) {
        // The lowest copy reaches highest up the profile at this height.
        if (z - low < 0.0 || z - high >= flute) return;
        const ProfilePoint section = radius_at(tool_, std::min(z - low, flute));
        if (!(section.value > 0.0)) return;
        const Range r = ball_chord<2>(o, k, motion_.start.head<2>(), section.value);
        if (!r.empty()) out.push_back(band_crossings(r, section));
        return;
    }
    // Ramps. The cylindrical part of the tool (heights [from, flute) above the tip, R wide)
    // covers this height for s in a sub-range: a stadium along part of the path.
    const Vec3 delta = motion_.end - motion_.start;
    const double from = method_ == Method::BallRamp ? tool_.radius : 0.0;
    const double rel = z - motion_.start.z();
    // Height above the tip at s is rel - s dz; the s where it equals `from` and `flute`:
    const double s_at_from = (rel - from) / delta.z(), s_at_flute = (rel - flute) / delta.z();
    const double s_a = std::max(0.0, std::min(s_at_from, s_at_flute));
    const double s_b = std::min(1.0, std::max(s_at_from, s_at_flute));
    Range band;
    Vec2 a2, b2;
    if (s_a <= s_b) {
        a2 = (motion_.start + s_a * delta).head<2>();
        b2 = (motion_.start + s_b * delta).head<2>();
        band = capsule_chord<2>(o, k, a2, b2, tool_.radius);
    }
    const auto band_end = [&](double t) {
        const Vec3 p = ray.point(t);
        double s = 0.0;
        const Vec2 q = nearest_on_segment<2>(p.head<2>(), a2, b2, &s);
        const Vec2 g = unit_or_x(p.head<2>() - q);
        const double s_here = s_a + s * (s_b - s_a);
        const bool clipped = (s == 0.0 && s_a > 0.0) || (s == 1.0 && s_b < 1.0);
        if (!clipped) return Crossing{t, embed(g), tool_surface_id(move_, ToolPart::Side)};
        const bool at_flute_top = std::abs(s_here - s_at_flute) < std::abs(s_here - s_at_from);
        return Crossing{
            t, rim_normal(g, delta),
            tool_surface_id(move_, at_flute_top ? ToolPart::TopRim : ToolPart::BottomRim)};
    };
    if (method_ == Method::FlatRamp) {
        if (!band.empty()) out.push_back({band_end(band.t0), band_end(band.t1)});
        return;
    }
    // Ball: the capsule around the centre path, and the shank band above it.
    const Vec3 lift = tool_.radius * Vec3::UnitZ();
    const Vec3 a = motion_.start + lift, b = motion_.end + lift;
    const Range ball = capsule_chord<3>(ray.origin, k, a, b, tool_.radius);
    const auto ball_end = [&](double t) {
        const Vec3 p = ray.point(t);
        return Crossing{t, (p - nearest_on_segment<3>(p, a, b)).normalized(),
                        tool_surface_id(move_, ToolPart::Corner)};
    };
    const Range all = ball.hull(band);
    if (all.empty()) return;
    const bool enter_on_ball = !ball.empty() && ball.t0 <= all.t0;
    const bool exit_on_ball = !ball.empty() && ball.t1 >= all.t1;
    out.push_back({enter_on_ball ? ball_end(all.t0) : band_end(all.t0),
                   exit_on_ball ? ball_end(all.t1) : band_end(all.t1)});
}

void SweptVolume::intersect_static_copies(const Ray& ray, std::vector<Interval>& out) const {
    const Vec3 delta = motion_.end - motion_.start;
    const auto copies = static_cast<int>(std::ceil(delta.norm() / options_.bullnose_step));
    std::vector<Interval> pieces;
    for (int i = 0; i <= copies; ++i) {
        const Vec3 tip = motion_.start + (static_cast<double>(i) / copies) * delta;
        const Vec2 centre = tip.head<2>();
        if (ray.axis == 2) {
            const Vec2 xy = ray.origin.head<2>();
            const double r = (xy - centre).norm();
            const Vec2 g = unit_or_x(xy - centre);
            if (r > tool_.radius || (r == tool_.radius && !boundary_is_inside(embed(g)))) continue;
            const ProfilePoint bottom = bottom_at(tool_, r);
            pieces.push_back(
                {crossing(Vec3(xy.x(), xy.y(), 0.0), centre, bottom, tip.z() + bottom.value),
                 {tip.z() + tool_.flute_length, Vec3::UnitZ(),
                  tool_surface_id(move_, ToolPart::Top)}});
            continue;
        }
        const double height = ray.origin.z() - tip.z();
        if (height < 0.0 || height >= tool_.flute_length) continue;
        const ProfilePoint section = radius_at(tool_, height);
        const Range r = ball_chord<2>(ray.origin.head<2>(), ray.axis, centre, section.value);
        if (r.empty()) continue;
        pieces.push_back({crossing(ray.point(r.t0), centre, section, r.t0),
                          crossing(ray.point(r.t1), centre, section, r.t1)});
    }
    merge_into(pieces, out);
}

}  // namespace resharp::sim
