#include "resharp/sim/csg.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "resharp/core/errors.h"

namespace resharp::sim {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

template <class... F>
struct Overloaded : F... {
    using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

double radial(const Vec3& x) { return std::hypot(x.x(), x.y()); }

/// Gradient of rho, the distance from the z axis, scaled by `scale`, plus `dz` along z; on the
/// axis (no direction) only the z part.
Vec3 radial_gradient(const Vec3& x, double scale, double dz) {
    const double rho = radial(x);
    if (rho == 0.0) return Vec3(0.0, 0.0, dz);
    return Vec3(scale * x.x() / rho, scale * x.y() / rho, dz);
}

/// The polynomial c[0] + c[1] t + ... at t (Horner).
double evaluate(const std::vector<double>& c, double t) {
    double v = 0.0;
    for (std::size_t k = c.size(); k-- > 0;) v = v * t + c[k];
    return v;
}

/// The root of a polynomial monotone on [a, b] with a sign change there, by bisection: at most
/// 200 halvings, fewer once the midpoint equals an end (the bracket is two adjacent doubles).
double bisect(const std::vector<double>& c, double a, double b) {
    double fa = evaluate(c, a);
    for (int step = 0; step < 200; ++step) {
        const double m = 0.5 * (a + b);
        if (m <= a || m >= b) break;
        const double fm = evaluate(c, m);
        if (fm == 0.0) return m;
        if ((fm < 0.0) == (fa < 0.0)) {
            a = m;
            fa = fm;
        } else {
            b = m;
        }
    }
    return 0.5 * (a + b);
}

/// Real roots in [lo, hi] of the polynomial c[0] + c[1] t + ..., ascending. Between consecutive
/// roots of its derivative (found the same way, down to a linear polynomial) the polynomial is
/// monotone, so each piece holds at most one root, found by bisection. Double roots where the
/// polynomial only touches zero are found only when it is exactly zero there.
std::vector<double> real_roots(std::vector<double> c, double lo, double hi) {
    while (!c.empty() && c.back() == 0.0) c.pop_back();
    if (c.size() <= 1) return {};
    if (c.size() == 2) {
        const double t = -c[0] / c[1];
        return t >= lo && t <= hi ? std::vector<double>{t} : std::vector<double>{};
    }
    std::vector<double> derivative(c.size() - 1);
    for (std::size_t k = 1; k < c.size(); ++k) derivative[k - 1] = static_cast<double>(k) * c[k];
    std::vector<double> knots{lo};
    for (double t : real_roots(derivative, lo, hi)) knots.push_back(t);
    knots.push_back(hi);
    std::vector<double> roots;
    for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
        const double fa = evaluate(c, knots[k]), fb = evaluate(c, knots[k + 1]);
        if (fa == 0.0) {
            if (roots.empty() || roots.back() != knots[k]) roots.push_back(knots[k]);
        } else if ((fa < 0.0) != (fb < 0.0) && fb != 0.0) {
            roots.push_back(bisect(c, knots[k], knots[k + 1]));
        }
    }
    if (evaluate(c, hi) == 0.0 && (roots.empty() || roots.back() != hi)) roots.push_back(hi);
    return roots;
}

/// A line in a primitive's frame with the stretch of it found inside so far.
struct Clip {
    Vec3 o, d;  // origin and unit direction, primitive frame
    Crossing enter{-kInfinity, Vec3::Zero(), -1};
    Crossing exit{kInfinity, Vec3::Zero(), -1};
    bool alive = true;

    /// Keeps the part of the line with n . x <= offset; a line on the plane is kept when
    /// boundary_is_inside says so for the plane's world normal.
    void plane(const Vec3& n, double offset, const Vec3& world_normal, std::int32_t surface) {
        const double along = n.dot(d), room = offset - n.dot(o);
        if (along == 0.0) {
            if (room < 0.0 || (room == 0.0 && !boundary_is_inside(world_normal))) alive = false;
            return;
        }
        const double t = room / along;
        if (along < 0.0 && t > enter.t) enter = {t, world_normal, surface};
        if (along > 0.0 && t < exit.t) exit = {t, world_normal, surface};
    }
    /// Keeps [t0, t1] (either end infinite for none), crossing `surface` at the finite ends.
    void range(double t0, double t1, std::int32_t surface) {
        if (t0 > enter.t) enter = {t0, Vec3::Zero(), surface};
        if (t1 < exit.t) exit = {t1, Vec3::Zero(), surface};
    }
    bool empty() const { return !alive || !(enter.t < exit.t); }
};

/// The stretch [t0, t1] of the line inside the solid cone rho <= r + s z, r + s z >= 0 (one
/// nappe; a cylinder when s = 0); false if it misses or only touches it.
bool cone_range(const Vec3& o, const Vec3& d, double r, double s, double& t0, double& t1) {
    const double w0 = r + s * o.z(), dw = s * d.z();  // r + s z along the line: w0 + dw t
    const double a = d.x() * d.x() + d.y() * d.y() - dw * dw;
    const double b = 2.0 * (o.x() * d.x() + o.y() * d.y() - w0 * dw);
    const double c = o.x() * o.x() + o.y() * o.y() - w0 * w0;
    // rho^2 - w^2 = a t^2 + b t + c <= 0 on the double cone; the nappe is where w >= 0.
    if (a == 0.0) {
        if (b == 0.0) {
            t0 = -kInfinity, t1 = kInfinity;
            return c < 0.0 && w0 >= 0.0;  // along the axis of a cylinder
        }
        const double root = -c / b;
        t0 = b > 0.0 ? -kInfinity : root;
        t1 = b > 0.0 ? root : kInfinity;
    } else {
        const double disc = b * b - 4.0 * a * c;
        if (disc <= 0.0) {
            if (a > 0.0) return false;        // misses or touches
            t0 = -kInfinity, t1 = kInfinity;  // inside the double cone throughout (rounding)
        } else {
            const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
            const double r1 = std::min(q / a, c / q), r2 = std::max(q / a, c / q);
            if (a > 0.0) {
                t0 = r1, t1 = r2;
            } else if (dw > 0.0) {
                t0 = r2, t1 = kInfinity;  // the line climbs into the nappe that widens along it
            } else {
                t0 = -kInfinity, t1 = r1;
            }
        }
    }
    // Keep the nappe w >= 0.
    if (dw > 0.0) t0 = std::max(t0, -w0 / dw);
    if (dw < 0.0) t1 = std::min(t1, -w0 / dw);
    if (dw == 0.0 && w0 < 0.0) return false;
    return t0 < t1;
}

/// The pieces of the line inside the torus, at most two.
void torus_ranges(const Vec3& o_in, const Vec3& d, double major, double minor,
                  std::vector<std::array<double, 2>>& out) {
    // Measure t from the point of the line nearest the centre, so that |t| <= major + minor
    // wherever the line is inside and the quartic is well scaled.
    const double shift = o_in.dot(d);
    const Vec3 o = o_in - shift * d;
    const double reach = major + minor;
    if (o.squaredNorm() >= reach * reach) return;
    const double e = o.squaredNorm() + major * major - minor * minor;
    const double m = 4.0 * major * major;
    // (|p|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + y^2) with |p|^2 = t^2 + |o|^2.
    const std::vector<double> c{e * e - m * (o.x() * o.x() + o.y() * o.y()),
                                -2.0 * m * (o.x() * d.x() + o.y() * d.y()),
                                2.0 * e - m * (d.x() * d.x() + d.y() * d.y()), 0.0, 1.0};
    // Search a little beyond the bounding sphere, so that roots on it (a line through the
    // centre in the torus's plane) lie inside the bracket; there are none farther out.
    const std::vector<double> roots = real_roots(c, -1.01 * reach, 1.01 * reach);
    for (std::size_t k = 0; k + 1 < roots.size(); ++k) {
        if (evaluate(c, 0.5 * (roots[k] + roots[k + 1])) < 0.0) {
            out.push_back({roots[k] - shift, roots[k + 1] - shift});
        }
    }
}

/// Whether the line meets `box` (grown by `slack`), and where: [t0, t1].
bool line_meets_box(const Vec3& o, const Vec3& d, const Box3& box, double slack) {
    double t0 = -kInfinity, t1 = kInfinity;
    for (int a = 0; a < 3; ++a) {
        const double lo = box.min()[a] - slack, hi = box.max()[a] + slack;
        if (d[a] == 0.0) {
            if (o[a] < lo || o[a] > hi) return false;
            continue;
        }
        double ta = (lo - o[a]) / d[a], tb = (hi - o[a]) / d[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    return t0 <= t1;
}

/// Appends [enter, exit] to sorted `out`, closing a gap to the last interval up to `tolerance`.
void append_closing_gap(std::vector<Interval>& out, const Crossing& enter, const Crossing& exit,
                        double tolerance) {
    if (!out.empty() && enter.t - out.back().exit.t <= tolerance) {
        out.back().exit = exit;
    } else {
        out.push_back({enter, exit});
    }
}

/// `a` op `b` of two sorted, disjoint interval lists, by a sweep over their ends (at most
/// 2 (#a + #b) steps). A difference's result is bounded by b's ends with b's normals reversed.
/// Gaps and intervals up to `tolerance` long are closed and dropped.
std::vector<Interval> combine(CsgOp op, const std::vector<Interval>& a,
                              const std::vector<Interval>& b, double tolerance) {
    const auto end_of = [](const std::vector<Interval>& v, std::size_t k) -> const Crossing& {
        return k % 2 == 0 ? v[k / 2].enter : v[k / 2].exit;
    };
    const auto inside = [op](bool in_a, bool in_b) {
        switch (op) {
            case CsgOp::Union:
                return in_a || in_b;
            case CsgOp::Intersection:
                return in_a && in_b;
            default:
                return in_a && !in_b;
        }
    };
    std::vector<Interval> out;
    std::size_t ka = 0, kb = 0;
    const std::size_t na = 2 * a.size(), nb = 2 * b.size();
    bool was_inside = false;
    Crossing enter;
    while (ka < na || kb < nb) {
        const bool from_a = kb == nb || (ka < na && end_of(a, ka).t <= end_of(b, kb).t);
        Crossing c = from_a ? end_of(a, ka++) : end_of(b, kb++);
        if (!from_a && op == CsgOp::Difference) c.normal = -c.normal;
        const bool now = inside(ka % 2 == 1, kb % 2 == 1);
        if (now == was_inside) continue;
        if (now) {
            enter = c;
        } else {
            append_closing_gap(out, enter, c, tolerance);
        }
        was_inside = now;
    }
    std::erase_if(out, [&](const Interval& i) { return i.exit.t - i.enter.t <= tolerance; });
    return out;
}

bool is_rotation(const Eigen::Matrix3d& r) {
    return (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-9 &&
           r.determinant() > 0.0;
}

/// World box of a disk of radius r about centre c with unit axis a.
Box3 disk_bounds(const Vec3& c, const Vec3& a, double r) {
    const Vec3 extent = r * (Vec3::Ones() - a.cwiseAbs2()).cwiseMax(0.0).cwiseSqrt();
    return Box3(c - extent, c + extent);
}

Box3 shape_bounds(const Shape& shape, const Placement& f) {
    const Vec3 axis = f.rotation.col(2);
    return std::visit(
        Overloaded{[&](const BoxShape& b) {
                       Box3 box;
                       for (int k = 0; k < 8; ++k) {
                           box.extend(f.apply(Vec3(k & 1 ? b.max.x() : b.min.x(),
                                                   k & 2 ? b.max.y() : b.min.y(),
                                                   k & 4 ? b.max.z() : b.min.z())));
                       }
                       return box;
                   },
                   [&](const ConeShape& c) {
                       return disk_bounds(f.translation, axis, c.radius_bottom)
                           .extend(disk_bounds(f.apply(Vec3(0, 0, c.length)), axis, c.radius_top));
                   },
                   [&](const SphereShape& s) {
                       return Box3(f.translation.array() - s.radius,
                                   f.translation.array() + s.radius);
                   },
                   [&](const TorusShape& t) {
                       Box3 box = disk_bounds(f.translation, axis, t.major);
                       return Box3(box.min().array() - t.minor, box.max().array() + t.minor);
                   },
                   [&](const HalfSpaceShape&) {
                       return Box3(Vec3::Constant(-kInfinity), Vec3::Constant(kInfinity));
                   }},
        shape);
}

/// The box of the part of `box` with n . x <= offset: its corners on that side and the points
/// where its edges cross the plane.
Box3 clip_box(const Box3& box, const Vec3& n, double offset) {
    if (box.isEmpty() || !box.min().allFinite() || !box.max().allFinite()) return box;
    Box3 clipped;
    for (int k = 0; k < 8; ++k) {
        const Vec3 corner = box.corner(static_cast<Box3::CornerType>(k));
        const double side = n.dot(corner) - offset;
        if (side <= 0.0) clipped.extend(corner);
        for (int a = 0; a < 3; ++a) {
            if (k & (1 << a)) continue;  // each edge once, from its lower corner
            const Vec3 other = box.corner(static_cast<Box3::CornerType>(k | (1 << a)));
            const double other_side = n.dot(other) - offset;
            if ((side < 0.0) != (other_side < 0.0)) {
                clipped.extend(corner + side / (side - other_side) * (other - corner));
            }
        }
    }
    return clipped;
}

CsgSurface plane_surface(const Placement& frame, const Vec3& n, double offset) {
    CsgSurface s;
    s.frame = frame;
    s.plane_normal = n;
    s.offset = offset;
    return s;
}

/// The surfaces of a shape in id order (see csg.h).
std::vector<CsgSurface> shape_surfaces(const Shape& shape, const Placement& f) {
    return std::visit(
        Overloaded{[&](const BoxShape& b) {
                       std::vector<CsgSurface> s;
                       for (int a = 0; a < 3; ++a) {
                           s.push_back(plane_surface(f, -Vec3::Unit(a), -b.min[a]));
                           s.push_back(plane_surface(f, Vec3::Unit(a), b.max[a]));
                       }
                       return s;
                   },
                   [&](const ConeShape& c) {
                       CsgSurface side;
                       side.kind = SurfaceKind::Cone;
                       side.frame = f;
                       side.radius = c.radius_bottom;
                       side.slope = (c.radius_top - c.radius_bottom) / c.length;
                       return std::vector<CsgSurface>{side, plane_surface(f, -Vec3::UnitZ(), 0.0),
                                                      plane_surface(f, Vec3::UnitZ(), c.length)};
                   },
                   [&](const SphereShape& sphere) {
                       CsgSurface s;
                       s.kind = SurfaceKind::Sphere;
                       s.frame = f;
                       s.radius = sphere.radius;
                       return std::vector<CsgSurface>{s};
                   },
                   [&](const TorusShape& t) {
                       CsgSurface s;
                       s.kind = SurfaceKind::Torus;
                       s.frame = f;
                       s.radius = t.major;
                       s.tube = t.minor;
                       return std::vector<CsgSurface>{s};
                   },
                   [&](const HalfSpaceShape&) {
                       return std::vector<CsgSurface>{plane_surface(f, Vec3::UnitZ(), 0.0)};
                   }},
        shape);
}

/// The solid intervals of one shape along a line given in the shape's frame (o, d); crossings
/// carry surface ids from `first` and, for now, no normals (the caller adds them).
void shape_intervals(const Shape& shape, const Placement& f, std::int32_t first, const Vec3& o,
                     const Vec3& d, std::vector<Interval>& out) {
    Clip clip{o, d};
    const auto push = [&] {
        if (!clip.empty()) out.push_back({clip.enter, clip.exit});
    };
    std::visit(
        Overloaded{
            [&](const BoxShape& b) {
                for (int a = 0; a < 3 && clip.alive; ++a) {
                    const Vec3 e = Vec3::Unit(a);
                    clip.plane(-e, -b.min[a], -f.rotation.col(a), first + 2 * a);
                    clip.plane(e, b.max[a], f.rotation.col(a), first + 2 * a + 1);
                }
                push();
            },
            [&](const ConeShape& c) {
                const Vec3 z = f.rotation.col(2);
                clip.plane(-Vec3::UnitZ(), 0.0, -z, first + 1);
                clip.plane(Vec3::UnitZ(), c.length, z, first + 2);
                double t0, t1;
                if (clip.alive && cone_range(o, d, c.radius_bottom,
                                             (c.radius_top - c.radius_bottom) / c.length, t0, t1)) {
                    clip.range(t0, t1, first);
                    push();
                }
            },
            [&](const SphereShape& s) {
                const double along = -o.dot(d);
                const double h2 = s.radius * s.radius - (o + along * d).squaredNorm();
                if (h2 <= 0.0) return;
                clip.range(along - std::sqrt(h2), along + std::sqrt(h2), first);
                push();
            },
            [&](const TorusShape& t) {
                std::vector<std::array<double, 2>> ranges;
                torus_ranges(o, d, t.major, t.minor, ranges);
                for (const auto& r : ranges) {
                    out.push_back({{r[0], Vec3::Zero(), first}, {r[1], Vec3::Zero(), first}});
                }
            },
            [&](const HalfSpaceShape&) {
                clip.plane(Vec3::UnitZ(), 0.0, f.rotation.col(2), first);
                if (clip.alive) out.push_back({clip.enter, clip.exit});
            }},
        shape);
}

}  // namespace

void check_shape(const Shape& shape) {
    std::visit(
        Overloaded{[](const BoxShape& b) {
                       if (!(b.min.array() < b.max.array()).all()) {
                           throw InvalidInput("a box needs min below max on every axis");
                       }
                   },
                   [](const ConeShape& c) {
                       if (!(c.length > 0.0))
                           throw InvalidInput("a cone or cylinder needs a positive length");
                       if (!(c.radius_bottom >= 0.0 && c.radius_top >= 0.0) ||
                           !(c.radius_bottom > 0.0 || c.radius_top > 0.0)) {
                           throw InvalidInput("a cone's radii must not be negative nor both zero");
                       }
                   },
                   [](const SphereShape& s) {
                       if (!(s.radius > 0.0))
                           throw InvalidInput("a sphere needs a positive radius");
                   },
                   [](const TorusShape& t) {
                       if (!(t.minor > 0.0) || !(t.major > t.minor)) {
                           throw InvalidInput("a torus needs major > minor > 0");
                       }
                   },
                   [](const HalfSpaceShape&) {}},
        shape);
}

double CsgSurface::value(const Vec3& p) const {
    const Vec3 x = frame.apply_inverse(p);
    switch (kind) {
        case SurfaceKind::Plane:
            return plane_normal.dot(x) - offset;
        case SurfaceKind::Cone:
            return radial(x) - (radius + slope * x.z());
        case SurfaceKind::Sphere:
            return x.norm() - radius;
        case SurfaceKind::Torus:
            return std::hypot(radial(x) - radius, x.z()) - tube;
    }
    return 0.0;
}

Vec3 CsgSurface::gradient(const Vec3& p) const {
    const Vec3 x = frame.apply_inverse(p);
    Vec3 g = Vec3::Zero();
    switch (kind) {
        case SurfaceKind::Plane:
            g = plane_normal;
            break;
        case SurfaceKind::Cone:
            g = radial_gradient(x, 1.0, -slope);
            break;
        case SurfaceKind::Sphere:
            g = x.norm() > 0.0 ? Vec3(x / x.norm()) : Vec3::Zero();
            break;
        case SurfaceKind::Torus: {
            const double q = std::hypot(radial(x) - radius, x.z());
            if (q > 0.0) g = radial_gradient(x, (radial(x) - radius) / q, x.z() / q);
            break;
        }
    }
    return frame.rotation * g;
}

Vec3 CsgSurface::normal(const Vec3& p) const {
    const Vec3 g = gradient(p);
    const double n = g.norm();
    return n > 0.0 ? Vec3(orientation * g / n) : Vec3::Zero();
}

CsgSolid::CsgSolid(const CsgNode& root) {
    add(root, Placement{}, 1.0, 1);
    const Box3& box = nodes_.front().bounds;
    if (box.isEmpty()) throw InvalidInput("the solid is empty: its operands do not overlap");
    if (!box.min().allFinite() || !box.max().allFinite()) {
        throw InvalidInput(
            "the solid is unbounded: a half-space must be an intersection operand or a "
            "difference's subtrahend");
    }
    tolerance_ = kCoincidence * box.diagonal().norm();
}

std::size_t CsgSolid::add(const CsgNode& node, const Placement& parent, double orientation,
                          int depth) {
    if (depth > kMaxCsgDepth) {
        throw InvalidInput("the tree is nested deeper than " + std::to_string(kMaxCsgDepth));
    }
    if (!is_rotation(node.placement.rotation) || !node.placement.translation.allFinite()) {
        throw InvalidInput("a placement is not a rotation and a finite translation");
    }
    const Placement world = parent * node.placement;
    const std::size_t index = nodes_.size();
    nodes_.push_back({});
    nodes_[index].op = node.op;
    if (node.op == CsgOp::Primitive) {
        if (!node.operands.empty()) throw InvalidInput("a shape node has operands");
        check_shape(node.shape);
        nodes_[index].shape = node.shape;
        nodes_[index].world = world;
        nodes_[index].bounds = shape_bounds(node.shape, world);
        nodes_[index].first_surface = static_cast<std::int32_t>(surfaces_.size());
        for (CsgSurface s : shape_surfaces(node.shape, world)) {
            s.orientation = orientation;
            surfaces_.push_back(s);
        }
        return index;
    }
    if (node.operands.empty()) throw InvalidInput("an operation has no operands");
    for (std::size_t k = 0; k < node.operands.size(); ++k) {
        const double sign = node.op == CsgOp::Difference && k > 0 ? -orientation : orientation;
        const std::size_t child = add(node.operands[k], world, sign, depth + 1);  // grows nodes_
        nodes_[index].operands.push_back(child);
    }
    nodes_[index].bounds = operation_bounds(nodes_[index]);
    return index;
}

Box3 CsgSolid::operation_bounds(const Node& node) const {
    const auto is_half_space = [&](std::size_t child) {
        return nodes_[child].op == CsgOp::Primitive &&
               std::holds_alternative<HalfSpaceShape>(nodes_[child].shape);
    };
    // The face of a half-space operand as n . x <= offset (its complement for a subtrahend).
    const auto clip = [&](Box3 box, std::size_t child, double side) {
        const CsgSurface& face = surfaces_[nodes_[child].first_surface];
        const Vec3 n = side * face.frame.rotation.col(2);
        return clip_box(box, n, n.dot(face.frame.translation));
    };
    const std::vector<std::size_t>& operands = node.operands;
    Box3 box = nodes_[operands.front()].bounds;
    for (std::size_t k = 1; k < operands.size(); ++k) {
        const Box3& b = nodes_[operands[k]].bounds;
        if (node.op == CsgOp::Union) box.extend(b);
        if (node.op == CsgOp::Intersection) box = box.intersection(b);
    }
    // Half-spaces cut the finite box after the other operands have bounded it.
    for (std::size_t k = 0; k < operands.size(); ++k) {
        if (!is_half_space(operands[k])) continue;
        if (node.op == CsgOp::Intersection) box = clip(box, operands[k], 1.0);
        if (node.op == CsgOp::Difference && k > 0) box = clip(box, operands[k], -1.0);
    }
    return box;
}

void CsgSolid::intersect(const Ray& ray, std::vector<Interval>& out) const {
    intersect_line(ray.origin, Vec3::Unit(ray.axis), out);
}

void CsgSolid::intersect_line(const Vec3& origin, const Vec3& direction,
                              std::vector<Interval>& out) const {
    std::vector<Interval> found;
    intersect_node(0, origin, direction, found);
    out.insert(out.end(), found.begin(), found.end());
}

void CsgSolid::intersect_node(std::size_t index, const Vec3& origin, const Vec3& direction,
                              std::vector<Interval>& out) const {
    const Node& node = nodes_[index];
    out.clear();
    if (!line_meets_box(origin, direction, node.bounds, tolerance_)) return;
    if (node.op == CsgOp::Primitive) {
        const Placement& f = node.world;
        shape_intervals(node.shape, f, node.first_surface, f.apply_inverse(origin),
                        f.rotation.transpose() * direction, out);
        // One formula for every normal: the surface's own gradient at the crossing.
        for (Interval& i : out) {
            for (Crossing* c : {&i.enter, &i.exit}) {
                if (c->normal.isZero() && std::isfinite(c->t)) {
                    c->normal = surfaces_[c->surface].gradient(origin + c->t * direction);
                    c->normal.normalize();
                }
            }
        }
        return;
    }
    intersect_node(node.operands.front(), origin, direction, out);
    std::vector<Interval> other;
    for (std::size_t k = 1; k < node.operands.size(); ++k) {
        if (out.empty() && node.op != CsgOp::Union) return;
        intersect_node(node.operands[k], origin, direction, other);
        if (other.empty() && node.op == CsgOp::Difference) continue;
        out = combine(node.op, out, other, tolerance_);
    }
}

bool CsgSolid::contains(const Vec3& p) const { return contains_node(0, p); }

bool CsgSolid::contains_node(std::size_t index, const Vec3& p) const {
    const Node& node = nodes_[index];
    if (!node.bounds.contains(p)) return false;
    if (node.op == CsgOp::Primitive) {
        const Vec3 x = node.world.apply_inverse(p);
        return std::visit(
            Overloaded{[&](const BoxShape& b) {
                           return (x.array() >= b.min.array()).all() &&
                                  (x.array() <= b.max.array()).all();
                       },
                       [&](const ConeShape& c) {
                           return x.z() >= 0.0 && x.z() <= c.length &&
                                  surfaces_[node.first_surface].value(p) <= 0.0;
                       },
                       [&](const auto&) { return surfaces_[node.first_surface].value(p) <= 0.0; }},
            node.shape);
    }
    const auto inside = [&](std::size_t k) { return contains_node(node.operands[k], p); };
    switch (node.op) {
        case CsgOp::Union:
            for (std::size_t k = 0; k < node.operands.size(); ++k) {
                if (inside(k)) return true;
            }
            return false;
        case CsgOp::Intersection:
            for (std::size_t k = 0; k < node.operands.size(); ++k) {
                if (!inside(k)) return false;
            }
            return true;
        default:
            if (!inside(0)) return false;
            for (std::size_t k = 1; k < node.operands.size(); ++k) {
                if (inside(k)) return false;
            }
            return true;
    }
}

}  // namespace resharp::sim
