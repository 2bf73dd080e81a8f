#pragma once
/// A hand-made crossing for the evaluation's tests: the unit square on z = 0 cut along its
/// diagonal (1, 2). Vertices 0 and 1 lie on surface 0 with exact normal n1, vertices 2 and 3 on
/// surface 1 with n2, so the diagonal crosses.

#include "resharp/eval/ideal_points.h"

namespace resharp::test {

struct Square {
    Mesh mesh{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)}, {{0, 1, 2}, {1, 3, 2}}};
    eval::Oracle oracle;
    Square(const Vec3& n1, const Vec3& n2) {
        oracle.normals = {n1.normalized(), n1.normalized(), n2.normalized(), n2.normalized()};
        oracle.surfaces = {0, 0, 1, 1};
    }
};

}  // namespace resharp::test
