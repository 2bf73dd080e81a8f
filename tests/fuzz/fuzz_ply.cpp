#include "fuzz_reader.h"
#include "resharp/io/ply.h"

// Reads with properties, the larger code path, and checks every property has one value per
// vertex or per triangle.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return resharp::fuzz::run(data, size, [](std::string_view bytes) {
        resharp::io::PlyMesh mesh = resharp::io::read_ply_with_properties(bytes, "fuzz.ply");
        for (const auto& p : mesh.vertex_properties) {
            resharp::fuzz::require(p.values.size() == mesh.soup.points.size());
        }
        for (const auto& p : mesh.face_properties) {
            resharp::fuzz::require(p.values.size() == mesh.soup.triangles.size());
        }
        return std::move(mesh.soup);
    });
}
