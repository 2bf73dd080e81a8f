#include "resharp/restoration/clearance.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace resharp {
namespace {

/// Distance between segments p1-q1 and p2-q2 (Ericson, Real-Time Collision Detection, 5.1.9).
double segment_distance(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2) {
    const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
    const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
    double s = 0.0, t = 0.0;
    if (a == 0.0 && e == 0.0) return r.norm();
    if (a == 0.0) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = d1.dot(r);
        if (e == 0.0) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = d1.dot(d2), denom = a * e - b * b;
            s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0.0) {
                t = 0.0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1.0) {
                t = 1.0;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    return ((p1 + d1 * s) - (p2 + d2 * t)).norm();
}

double height(const IdTriangle& t, const Vec3& x) { return t.n.dot(x - t.p[0]); }

/// Whether x, a point in (or within `tolerance` of) the triangle's plane, lies inside it or
/// within `tolerance` of its edges.
bool lies_in(const IdTriangle& plane, const Vec3& x, double tolerance) {
    for (int k = 0; k < 3; ++k) {
        const Vec3& a = plane.p[k];
        const Vec3 edge = plane.p[(k + 1) % 3] - a;
        const double inside = (x - a).dot(plane.n.cross(edge));  // |edge| times the distance
        if (inside < 0.0 && inside * inside > tolerance * tolerance * edge.squaredNorm())
            return false;
    }
    return true;
}

/// Whether segment a-b meets the triangle or comes within `tolerance` of it.
bool segment_meets(const Vec3& a, const Vec3& b, const IdTriangle& plane, double tolerance) {
    const double ha = height(plane, a), hb = height(plane, b);
    if ((ha > tolerance && hb > tolerance) || (ha < -tolerance && hb < -tolerance)) return false;
    if (std::abs(ha) <= tolerance && std::abs(hb) <= tolerance) {  // in the plane
        if (lies_in(plane, a, tolerance) || lies_in(plane, b, tolerance)) return true;
        for (int k = 0; k < 3; ++k) {
            if (segment_distance(a, b, plane.p[k], plane.p[(k + 1) % 3]) <= tolerance) {
                return true;
            }
        }
        return false;
    }
    // It crosses the plane, or ends at it: test where.
    const Vec3 x = std::abs(ha) <= tolerance   ? a
                   : std::abs(hb) <= tolerance ? b
                                               : Vec3(a + (b - a) * (ha / (ha - hb)));
    return lies_in(plane, x, tolerance);
}

/// Whether every vertex of t lies more than `tolerance` to one side of the plane.
bool strictly_one_side(const IdTriangle& plane, const IdTriangle& t, double tolerance) {
    int above = 0, below = 0;
    for (const Vec3& x : t.p) {
        const double h = height(plane, x);
        above += h > tolerance;
        below += h < -tolerance;
    }
    return above == 3 || below == 3;
}

/// Two triangles sharing edge a-b, with c and d their other vertices: they meet beyond the edge
/// only when flat and folded onto each other, d on c's side of the edge.
bool folded_onto(const IdTriangle& s, int a, int b, int c, const Vec3& d, double tolerance) {
    if (std::abs(height(s, d)) > tolerance) return false;
    const Vec3 across = s.n.cross(s.p[b] - s.p[a]);
    return across.dot(s.p[c] - s.p[a]) * across.dot(d - s.p[a]) > 0.0;
}

/// Two triangles in one plane (unit normal n) sharing a vertex, the others at u1, v1 and u2, v2
/// from it: they overlap exactly when their angles there do. Two angles below 180 degrees with
/// disjoint insides are parted by the line along one of their sides, so the four sides are
/// tried. A side parts them if each side of the other angle lies more than `tolerance` beyond
/// its line, or on the line but pointing the other way (touching only at the shared vertex).
bool angles_overlap(const Vec3& n, const Vec3& u1, const Vec3& v1, const Vec3& u2, const Vec3& v2,
                    double tolerance) {
    auto parts = [&](const Vec3& side, const Vec3& inner, const Vec3& w1, const Vec3& w2) {
        const Vec3 across = n.cross(side);  // across . w = |side| times w's distance from the line
        const double toward_inner = across.dot(inner) >= 0.0 ? 1.0 : -1.0;
        const double margin = tolerance * side.norm();  // across has side's length
        auto beyond = [&](const Vec3& w) {
            const double away = -toward_inner * across.dot(w);
            return away > margin || (away >= -margin && w.dot(side) < 0.0);
        };
        return beyond(w1) && beyond(w2);
    };
    return !(parts(u1, v1, u2, v2) || parts(v1, u1, u2, v2) || parts(u2, v2, u1, v1) ||
             parts(v2, u2, u1, v1));
}

/// Whether the heights of two points above a plane are both beyond `tolerance` on one side.
bool both_beyond(double h1, double h2, double tolerance) {
    return (h1 > tolerance && h2 > tolerance) || (h1 < -tolerance && h2 < -tolerance);
}

/// Two triangles sharing vertex k of s and m of t: they meet beyond it exactly when the edge
/// of one opposite it meets the other, or, lying in one plane, their angles there overlap.
bool meet_beyond_vertex(const IdTriangle& s, int k, const IdTriangle& t, int m, double tolerance) {
    const Vec3& apex = s.p[k];
    const Vec3 &b = s.p[(k + 1) % 3], &c = s.p[(k + 2) % 3];
    const Vec3 &d = t.p[(m + 1) % 3], &e = t.p[(m + 2) % 3];
    const double hd = height(s, d), he = height(s, e);
    const double hb = height(t, b), hc = height(t, c);
    if (both_beyond(hd, he, tolerance) || both_beyond(hb, hc, tolerance)) return false;
    const bool t_in_plane_of_s = std::abs(hd) <= tolerance && std::abs(he) <= tolerance;
    const bool s_in_plane_of_t = std::abs(hb) <= tolerance && std::abs(hc) <= tolerance;
    if (t_in_plane_of_s || s_in_plane_of_t) {
        return angles_overlap(s.n, b - apex, c - apex, d - apex, e - apex, tolerance);
    }
    return segment_meets(b, c, t, tolerance) || segment_meets(d, e, s, tolerance);
}

/// Whether every vertex of t lies within `tolerance` of s's plane.
bool lies_in_plane_of(const IdTriangle& s, const IdTriangle& t, double tolerance) {
    for (const Vec3& x : t.p) {
        if (std::abs(height(s, x)) > tolerance) return false;
    }
    return true;
}

/// Two triangles in one plane (s's) overlap unless the line along one of their six edges
/// parts them by more than `tolerance` (separating axes in the plane).
bool overlap_in_plane(const IdTriangle& s, const IdTriangle& t, double tolerance) {
    auto parted_along = [&](const IdTriangle& owner, int k) {
        const Vec3 edge = owner.p[(k + 1) % 3] - owner.p[k];
        const Vec3 axis = s.n.cross(edge);  // projections are |edge| times distances
        double s_min = axis.dot(s.p[0]), s_max = s_min, t_min = axis.dot(t.p[0]), t_max = t_min;
        for (int i = 1; i < 3; ++i) {
            s_min = std::min(s_min, axis.dot(s.p[i]));
            s_max = std::max(s_max, axis.dot(s.p[i]));
            t_min = std::min(t_min, axis.dot(t.p[i]));
            t_max = std::max(t_max, axis.dot(t.p[i]));
        }
        const double gap = std::max(t_min - s_max, s_min - t_max);
        return gap > 0.0 && gap * gap > tolerance * tolerance * edge.squaredNorm();
    };
    for (int k = 0; k < 3; ++k) {
        if (parted_along(s, k) || parted_along(t, k)) return false;
    }
    return true;
}

int index_of(const IdTriangle& t, Index id) {
    for (int k = 0; k < 3; ++k) {
        if (t.id[k] == id) return k;
    }
    return -1;
}

}  // namespace

IdTriangle IdTriangle::make(const Triangle& id, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = (b - a).cross(c - a);
    const double length = n.norm();
    return make(id, a, b, c, length > 0.0 ? Vec3(n / length) : Vec3::Zero());
}

IdTriangle IdTriangle::make(const Triangle& id, const Vec3& a, const Vec3& b, const Vec3& c,
                            const Vec3& unit_normal) {
    IdTriangle t{id, {a, b, c}, unit_normal, Box3(a)};
    t.box.extend(b);
    t.box.extend(c);
    return t;
}

bool triangles_meet(const IdTriangle& s, const IdTriangle& t, double tolerance) {
    if (s.box.squaredExteriorDistance(t.box) > tolerance * tolerance) return false;
    if (s.n.isZero(0.0) || t.n.isZero(0.0)) return false;
    std::array<int, 3> in_t{};  // per vertex of s, its index in t or -1
    int shared = 0;
    for (int k = 0; k < 3; ++k) {
        in_t[k] = index_of(t, s.id[k]);
        shared += in_t[k] >= 0;
    }
    if (shared == 3) return true;
    if (shared == 2) {
        const int c = in_t[0] < 0 ? 0 : in_t[1] < 0 ? 1 : 2;
        const int a = (c + 1) % 3, b = (c + 2) % 3;
        const int d = 3 - in_t[a] - in_t[b];
        return folded_onto(s, a, b, c, t.p[d], tolerance) ||
               folded_onto(t, in_t[a], in_t[b], d, s.p[c], tolerance);
    }
    if (shared == 1) {
        const int k = in_t[0] >= 0 ? 0 : in_t[1] >= 0 ? 1 : 2;
        return meet_beyond_vertex(s, k, t, in_t[k], tolerance);
    }
    if (strictly_one_side(s, t, tolerance) || strictly_one_side(t, s, tolerance)) return false;
    if (lies_in_plane_of(s, t, tolerance)) return overlap_in_plane(s, t, tolerance);
    for (int k = 0; k < 3; ++k) {
        if (segment_meets(s.p[k], s.p[(k + 1) % 3], t, tolerance) ||
            segment_meets(t.p[k], t.p[(k + 1) % 3], s, tolerance)) {
            return true;
        }
    }
    return false;
}

}  // namespace resharp
