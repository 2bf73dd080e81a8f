#pragma once
/// The true sharp edges of the cube [0, side]^3, sampled as the evaluation samples a solid's
/// creases: the reference of the crease measures' tests.

#include "resharp/eval/cad_metrics.h"
#include "resharp/eval/exact_creases.h"

namespace resharp::test {

inline eval::CurveSamples cube_creases(double side) {
    sim::CsgNode node;
    node.shape = sim::BoxShape{Vec3::Zero(), Vec3::Constant(side)};
    const sim::CsgSolid cube(node);
    return eval::sample_exact_creases(
        cube, sim::sample_solid(sim::phased_grid(cube.bounds(), 0.05, 0.4142), cube));
}

}  // namespace resharp::test
