#include "resharp/sim/cone_ramp.h"

#include <array>
#include <cmath>
#include <utility>

namespace resharp::sim {
namespace {

/// The tool surfaces a point of the swept boundary lies on, as bits.
enum SurfaceBit : unsigned { kBottom = 1, kTop = 2, kCone = 4, kSide = 8 };

/// The line alpha t + beta s = gamma of the (t, s) plane and the tool surfaces along it.
struct Line {
    double alpha = 0.0, beta = 0.0, gamma = 0.0;
    unsigned surfaces = 0;
};

/// A circle |u| = r0 + m w of the tool swept into a conic of the (t, s) plane.
struct Conic {
    double r0 = 0.0, m = 0.0;
    unsigned surface = 0;
};

/// A boundary point of the swept region in the (t, s) plane.
struct Candidate {
    double t = 0.0, s = 0.0;
    unsigned surfaces = 0;
};

/// The member of the normal cone spanned by n1 and n2 (a rim) that is orthogonal to the motion
/// d: a n1 + b n2 with a = n2·d, b = -n1·d, both of one sign. When they differ the rim does not
/// bound the sweep there (rounding at a tangency): the normal nearer orthogonal to d is kept.
Vec3 envelope_normal(const Vec3& n1, const Vec3& n2, const Vec3& d) {
    double a = n2.dot(d), b = -n1.dot(d);
    if (a * b < 0.0) return std::abs(n1.dot(d)) <= std::abs(n2.dot(d)) ? n1 : n2;
    if (a + b < 0.0) a = -a, b = -b;
    if (a + b == 0.0) return n1;
    return (a * n1 + b * n2).normalized();
}

class ConeRampCut {
public:
    ConeRampCut(const Tool& tool, const Vec3& start, const Vec3& end, const Ray& ray)
        : tool_(tool),
          slope_(std::tan(tool.half_angle)),
          d_(end - start),
          x0_(ray.origin - start),
          xt_(Vec3::Unit(ray.axis)),
          xs_(start - end),
          eps_(1e-10 * (tool.radius + tool.flute_length + d_.norm())) {}

    std::optional<Interval> run(std::size_t move) {
        collect_candidates();
        const Candidate* enter = nullptr;
        const Candidate* exit = nullptr;
        for (int i = 0; i < count_; ++i) {
            const Candidate& c = candidates_[i];
            if (!feasible(c)) continue;
            if (enter == nullptr || c.t < enter->t) enter = &c;
            if (exit == nullptr || c.t > exit->t) exit = &c;
        }
        if (enter == nullptr || !(enter->t < exit->t)) return std::nullopt;
        return Interval{crossing(*enter, move), crossing(*exit, move)};
    }

private:
    /// The point of the ray at t relative to the tip at s: x = x0 + t e_k - s d.
    Vec3 at(double t, double s) const { return x0_ + t * xt_ + s * xs_; }

    Line height_line(double w, unsigned surfaces) const {
        return {xt_.z(), xs_.z(), w - x0_.z(), surfaces};
    }

    /// Where the conic's t is stationary along s (its tangent is a line t = const): the
    /// derivative of |u|² - (r0 + m w)² in s vanishes, which is linear in (t, s).
    Line stationary_line(const Conic& q) const {
        const double m2 = q.m * q.m;
        return {xt_.head<2>().dot(xs_.head<2>()) - m2 * xt_.z() * xs_.z(),
                xs_.head<2>().squaredNorm() - m2 * xs_.z() * xs_.z(),
                -x0_.head<2>().dot(xs_.head<2>()) + q.m * q.r0 * xs_.z() + m2 * x0_.z() * xs_.z(),
                0};
    }

    void collect_candidates() {
        const double h = tool_.flute_length, cone_top = tool_.cone_height();
        const Line bottom = height_line(0.0, kBottom), top = height_line(h, kTop);
        const Line first{0.0, 1.0, 0.0, 0}, last{0.0, 1.0, 1.0, 0};
        for (const Line& w : {bottom, top}) {
            for (const Line& s : {first, last}) add_crossing(w, s);
        }
        const Conic cone{tool_.tip_radius, slope_, kCone};
        for (const Line& l : {bottom, top, first, last, stationary_line(cone)}) {
            add_on_conic(cone, l);
        }
        if (h > cone_top) {  // the cylinder above the cone, and the rim between them
            const Conic side{tool_.radius, 0.0, kSide};
            for (const Line& l :
                 {top, first, last, stationary_line(side), height_line(cone_top, kCone)}) {
                add_on_conic(side, l);
            }
        }
    }

    void add_crossing(const Line& a, const Line& b) {
        const double det = a.alpha * b.beta - a.beta * b.alpha;
        if (det == 0.0) return;
        candidates_[count_++] = {(a.gamma * b.beta - a.beta * b.gamma) / det,
                                 (a.alpha * b.gamma - a.gamma * b.alpha) / det,
                                 a.surfaces | b.surfaces};
    }

    /// The points of line l on conic q: along (t, s) = p + λ v the conic is a quadratic in λ.
    void add_on_conic(const Conic& q, const Line& l) {
        double pt, ps, vt, vs;
        if (l.beta != 0.0 && std::abs(l.beta) >= std::abs(l.alpha)) {
            pt = 0.0, ps = l.gamma / l.beta, vt = 1.0, vs = -l.alpha / l.beta;
        } else if (l.alpha != 0.0) {
            pt = l.gamma / l.alpha, ps = 0.0, vt = -l.beta / l.alpha, vs = 1.0;
        } else {
            return;
        }
        const Vec3 x0 = at(pt, ps), x1 = vt * xt_ + vs * xs_;
        const double r0 = q.r0 + q.m * x0.z(), r1 = q.m * x1.z();
        const double a = x1.head<2>().squaredNorm() - r1 * r1;
        const double b = 2.0 * (x0.head<2>().dot(x1.head<2>()) - r0 * r1);
        const double c = x0.head<2>().squaredNorm() - r0 * r0;
        const unsigned surfaces = q.surface | l.surfaces;
        const auto push = [&](double lambda) {
            candidates_[count_++] = {pt + lambda * vt, ps + lambda * vs, surfaces};
        };
        if (a == 0.0) {
            if (b != 0.0) push(-c / b);
            return;
        }
        const double disc = b * b - 4.0 * a * c;
        if (disc < 0.0) return;
        // The root formula without cancellation.
        const double half = -0.5 * (b + std::copysign(std::sqrt(disc), b));
        if (half == 0.0) {
            push(0.0);
            return;
        }
        push(half / a);
        push(c / half);
    }

    bool feasible(const Candidate& c) const {
        if (c.s < -1e-12 || c.s > 1.0 + 1e-12) return false;
        const Vec3 x = at(c.t, c.s);
        const double r = x.head<2>().norm();
        return x.z() >= -eps_ && x.z() <= tool_.flute_length + eps_ &&
               r <= tool_.tip_radius + slope_ * x.z() + eps_ && r <= tool_.radius + eps_;
    }

    Crossing crossing(const Candidate& c, std::size_t move) const {
        const Vec3 x = at(c.t, c.s);
        const double r = x.head<2>().norm();
        const Vec3 radial = r > 0.0 ? Vec3(x.x() / r, x.y() / r, 0.0) : Vec3::UnitX();
        const double beta = tool_.half_angle;
        std::array<Vec3, 2> normals;
        int count = 0;
        for (const auto& [bit, n] :
             {std::pair{kBottom, Vec3(-Vec3::UnitZ())}, std::pair{kTop, Vec3(Vec3::UnitZ())},
              std::pair{kCone, Vec3(std::cos(beta) * radial - std::sin(beta) * Vec3::UnitZ())},
              std::pair{kSide, radial}}) {
            if ((c.surfaces & bit) != 0 && count < 2) normals[count++] = n;
        }
        return {c.t, count == 1 ? normals[0] : envelope_normal(normals[0], normals[1], d_),
                tool_surface_id(move, part_of(c.surfaces))};
    }

    static ToolPart part_of(unsigned surfaces) {
        switch (surfaces) {
            case kBottom:
                return ToolPart::Bottom;
            case kTop:
                return ToolPart::Top;
            case kCone:
                return ToolPart::Cone;
            case kSide:
                return ToolPart::Side;
            case kCone | kSide:
                return ToolPart::ConeRim;
            default:
                return (surfaces & kBottom) != 0 ? ToolPart::BottomRim : ToolPart::TopRim;
        }
    }

    const Tool& tool_;
    double slope_;  // tan β
    Vec3 d_;        // the motion
    Vec3 x0_, xt_, xs_;
    double eps_;  // feasibility slack, mm
    // 4 corners, 2 roots on each of 5 lines per conic: 24 at most.
    std::array<Candidate, 24> candidates_{};
    int count_ = 0;
};

}  // namespace

std::optional<Interval> cut_cone_ramp(const Tool& tool, const Vec3& start, const Vec3& end,
                                      const Ray& ray, std::size_t move) {
    return ConeRampCut(tool, start, end, ray).run(move);
}

}  // namespace resharp::sim
