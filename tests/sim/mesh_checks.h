#pragma once
/// Checks shared by the simulator's mesh tests.

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/diagnostics.h"
#include "resharp/mesh/mesh.h"
#include "support/invariants.h"

namespace resharp::test {

/// Signed volume enclosed by a closed mesh (positive for outward orientation).
inline double signed_volume(const Mesh& mesh) {
    double six_v = 0.0;
    for (const Triangle& t : mesh.triangles) {
        six_v += mesh.positions[t[0]].dot(mesh.positions[t[1]].cross(mesh.positions[t[2]]));
    }
    return six_v / 6.0;
}

/// Closed, manifold, consistently oriented, outward, no degenerate or duplicate faces.
inline void expect_clean_closed_outward(const Mesh& mesh) {
    ASSERT_GT(mesh.face_count(), 0u);
    expect_closed_manifold(mesh);
    EXPECT_EQ(diagnose(mesh, build_connectivity(mesh)).isolated_vertices, 0u);
    EXPECT_GT(signed_volume(mesh), 0.0);
}

/// A measured value for RecordProperty, to three significant digits.
inline std::string short_number(double value) {
    std::ostringstream s;
    s.precision(3);
    s << value;
    return s.str();
}

}  // namespace resharp::test
