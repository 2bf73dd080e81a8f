#include "support/simple_meshes.h"

namespace resharp::test {

Mesh box_mesh(double sx, double sy, double sz) {
    Mesh m;
    for (int i = 0; i < 8; ++i) {
        m.positions.emplace_back((i & 1) ? sx : 0.0, (i & 2) ? sy : 0.0, (i & 4) ? sz : 0.0);
    }
    // Two triangles per face, counter-clockwise seen from outside.
    m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6},   // z = 0, z = sz
                   {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7},   // y = 0, y = sy
                   {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};  // x = 0, x = sx
    return m;
}

TriangleSoup box_soup(double sx, double sy, double sz) {
    const Mesh m = box_mesh(sx, sy, sz);
    TriangleSoup soup;
    for (const Triangle& t : m.triangles) {
        const Index base = static_cast<Index>(soup.points.size());
        for (Index v : t) soup.points.push_back(m.positions[v]);
        soup.triangles.push_back({base, base + 1, base + 2});
    }
    return soup;
}

}  // namespace resharp::test
