// Restores a chamfered cube built here, through nothing but the installed resharp: the consumer
// lane's proof that find_package(resharp) gives a library that links and works. Exits 0 when
// points were put back on the cube's edges, each on an exact edge, and every input vertex stayed
// where it was; 1 otherwise.

#include <array>
#include <cmath>
#include <cstdio>
#include <exception>

#include "resharp/resharp.h"

namespace {

using resharp::Vec3;

constexpr int kCells = 24;             // grid cells along each face of the cube [-1, 1]^3
constexpr double kInset = 1.0 - 0.06;  // each chamfer band is 0.06 wide on either face
constexpr double kOnEdge = 1e-9;       // how far a restored point may be from the exact edge

/// Grid coordinate i of kCells along [-kInset, kInset], computed one way everywhere so that
/// shared vertices come out bit-identical and weld() joins them.
double coordinate(int i) { return kInset * (2.0 * i / kCells - 1.0); }

/// The point with coordinate `u` on axis k, `v` on axis m and `w` on the third axis.
Vec3 at(int k, double u, int m, double v, double w) {
    Vec3 p = Vec3::Constant(w);
    p[k] = u;
    p[m] = v;
    return p;
}

/// Appends triangle (p, q, r) to the soup, turned to face away from the origin (the cube is
/// convex around it).
void add_triangle(resharp::TriangleSoup& soup, const Vec3& p, const Vec3& q, const Vec3& r) {
    const auto first = static_cast<resharp::Index>(soup.points.size());
    soup.points.insert(soup.points.end(), {p, q, r});
    const bool outward = (q - p).cross(r - p).dot(p + q + r) > 0.0;
    soup.triangles.push_back(outward ? resharp::Triangle{first, first + 1, first + 2}
                                     : resharp::Triangle{first, first + 2, first + 1});
}

void add_quad(resharp::TriangleSoup& soup, const std::array<Vec3, 4>& p) {
    add_triangle(soup, p[0], p[1], p[2]);
    add_triangle(soup, p[0], p[2], p[3]);
}

/// The cube as a grid mesher leaves it: each face a kCells x kCells grid inset from the edges,
/// each edge a band of kCells quads between two faces, each corner one chamfer triangle.
resharp::Mesh chamfered_cube() {
    resharp::TriangleSoup soup;
    for (int k = 0; k < 3; ++k) {
        const int m = (k + 1) % 3;
        for (double s : {-1.0, 1.0}) {
            for (int i = 0; i < kCells; ++i) {
                const double u = coordinate(i), u1 = coordinate(i + 1);
                for (int j = 0; j < kCells; ++j) {  // face k = s
                    const double v = coordinate(j), v1 = coordinate(j + 1);
                    add_quad(soup, {at(k, s, m, u, v), at(k, s, m, u1, v), at(k, s, m, u1, v1),
                                    at(k, s, m, u, v1)});
                }
                for (double t : {-1.0, 1.0}) {  // the band between faces k = s and m = t
                    add_quad(soup, {at(k, s, m, t * kInset, u), at(k, s, m, t * kInset, u1),
                                    at(k, s * kInset, m, t, u1), at(k, s * kInset, m, t, u)});
                }
            }
        }
    }
    for (double x : {-1.0, 1.0}) {
        for (double y : {-1.0, 1.0}) {
            for (double z : {-1.0, 1.0}) {
                add_triangle(soup, {x, y * kInset, z * kInset}, {x * kInset, y, z * kInset},
                             {x * kInset, y * kInset, z});
            }
        }
    }
    return resharp::weld(soup);
}

/// Whether p lies on an edge of the cube: two of its coordinates at +-1.
bool on_cube_edge(const Vec3& p) {
    int at_face = 0;
    for (int k = 0; k < 3; ++k) at_face += std::abs(std::abs(p[k]) - 1.0) <= kOnEdge;
    return at_face >= 2;
}

int run() {
    const resharp::Mesh input = chamfered_cube();
    const resharp::RestoreResult result = resharp::restore(input);
    const resharp::Mesh& output = result.mesh;
    std::size_t moved = 0, off_edge = 0;
    for (std::size_t v = 0; v < input.positions.size(); ++v) {
        moved += output.positions[v] != input.positions[v];
    }
    for (std::size_t v = input.positions.size(); v < output.positions.size(); ++v) {
        off_edge += !on_cube_edge(output.positions[v]);
    }
    const resharp::RestoreReport& report = result.report;
    std::printf(
        "resharp_consumer: %zu -> %zu triangles, %zu edge and %zu corner points, "
        "%zu input vertices moved, %zu points off the cube's edges\n",
        input.triangles.size(), output.triangles.size(), report.edge_points_inserted,
        report.corner_points_inserted, moved, off_edge);
    const bool ok = report.edge_points_inserted > 0 && moved == 0 && off_edge == 0;
    return ok ? 0 : 1;
}

}  // namespace

int main() {
    try {
        return run();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "resharp_consumer: %s\n", e.what());
        return 1;
    }
}
