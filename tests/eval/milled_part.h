#pragma once
/// A stock milled by a G-code program given as text, with the simulator's oracle and the solid
/// rebuilt for evaluation: the evaluation tests' way to get parts with known surfaces.

#include <map>
#include <sstream>
#include <string>

#include "resharp/eval/ideal_points.h"
#include "resharp/eval/machined_solid.h"
#include "resharp/sim/marching_cubes.h"
#include "resharp/sim/simulate.h"

namespace resharp::test {

struct MilledPart {
    sim::Box3 stock;
    std::map<int, sim::Tool> tools;
    sim::ToolPath path;
    sim::SimulationOptions options;
    sim::OracleMesh meshed;
    eval::Oracle oracle;
    eval::MachinedSolid solid;

    MilledPart(const sim::Box3& stock_box, std::map<int, sim::Tool> tool_table,
               const std::string& gcode, double pitch = 0.5)
        : stock(stock_box),
          tools(std::move(tool_table)),
          path(parse(gcode, stock_box)),
          options{.pitch = pitch},
          meshed(sim::mesh_dexels(sim::simulate(stock, tools, path, options).grid)),
          oracle{meshed.normals, meshed.surface_ids},
          solid(stock, tools, path, options) {}

    const Mesh& mesh() const { return meshed.mesh; }

private:
    static sim::ToolPath parse(const std::string& gcode, const sim::Box3& stock) {
        std::istringstream in(gcode);
        const Vec3 above = stock.center() + Vec3(0, 0, stock.sizes().z() + 40.0);
        return sim::parse_gcode(in, "test.nc", {.start_position = above});
    }
};

}  // namespace resharp::test
