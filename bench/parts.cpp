#include "parts.h"

#include <cstdlib>
#include <map>
#include <memory>

namespace resharp::bench {

const Part& part(const std::string& name) {
    static std::map<std::string, std::unique_ptr<Part>> parts;
    auto& slot = parts[name];
    if (!slot) {
        const char* root = std::getenv("RESHARP_EXAMPLES");
        const std::string folder = std::string(root ? root : "examples") + "/" + name;
        slot = std::make_unique<Part>();
        slot->job = sim::read_job(folder + "/job.json");
        slot->path =
            sim::read_gcode(slot->job.program, {.start_position = slot->job.start_position});
        slot->options.pitch = slot->job.pitch;
    }
    return *slot;
}

const sim::OracleMesh& part_mesh(const std::string& name) {
    static std::map<std::string, std::unique_ptr<sim::OracleMesh>> meshes;
    auto& slot = meshes[name];
    if (!slot) {
        const Part& p = part(name);
        const sim::Simulation s = sim::simulate(p.job.stock, p.job.tools, p.path, p.options);
        slot = std::make_unique<sim::OracleMesh>(sim::mesh_dexels(s.grid));
    }
    return *slot;
}

}  // namespace resharp::bench
