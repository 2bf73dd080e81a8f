#include "resharp/eval/evaluation_files.h"

#include <sstream>

#include "resharp/core/errors.h"
#include "resharp/eval/position_index.h"
#include "resharp/io/mesh_io.h"

namespace resharp::eval {
namespace {

const std::vector<double>& vertex_property(const io::PlyMesh& ply, const char* property,
                                           const std::string& name) {
    const std::vector<double>* values = ply.vertex_property(property);
    if (!values) throw ReadError(name, std::string("no vertex property '") + property + "'");
    return *values;
}

/// PLY colour channels read back as doubles; only an exact match decodes.
bool is_color(const io::Rgb& color, double r, double g, double b) {
    return r == color.red && g == color.green && b == color.blue;
}

}  // namespace

Oracle match_oracle(const io::PlyMesh& ply, const std::string& name, const Mesh& input) {
    const auto &nx = vertex_property(ply, "nx", name), &ny = vertex_property(ply, "ny", name),
               &nz = vertex_property(ply, "nz", name),
               &surface = vertex_property(ply, "surface", name);
    const std::vector<double>*sx = ply.vertex_property("sx"), *sy = ply.vertex_property("sy"),
          *sz = ply.vertex_property("sz");
    const bool has_surface_points = sx && sy && sz;
    const PositionIndex index(ply.soup.points);
    Oracle oracle;
    oracle.normals.reserve(input.vertex_count());
    oracle.surfaces.reserve(input.vertex_count());
    for (std::size_t v = 0; v < input.vertex_count(); ++v) {
        const std::optional<Index> o = index.find(input.positions[v]);
        if (!o) {
            std::ostringstream s;
            s << "input vertex " << v << " is not in the oracle " << name
              << " (the oracle must come from the same simulation as the input)";
            throw InvalidInput(s.str());
        }
        oracle.normals.push_back(Vec3(nx[*o], ny[*o], nz[*o]).normalized());
        oracle.surfaces.push_back(static_cast<std::int32_t>(surface[*o]));
        if (has_surface_points)
            oracle.surface_points.push_back(Vec3((*sx)[*o], (*sy)[*o], (*sz)[*o]));
    }
    return oracle;
}

Oracle read_oracle(const std::filesystem::path& path, const Mesh& input) {
    return match_oracle(io::read_ply_with_properties(path), path.string(), input);
}

Mesh match_restored(const Mesh& read, const std::string& name, const Mesh& input) {
    const PositionIndex input_index(input.positions);
    std::vector<Index> renumber(read.vertex_count());
    Mesh out{input.positions, {}};
    std::vector<bool> seen(input.vertex_count(), false);
    for (std::size_t v = 0; v < read.vertex_count(); ++v) {
        if (const std::optional<Index> i = input_index.find(read.positions[v])) {
            renumber[v] = *i;
            seen[*i] = true;
        } else {
            renumber[v] = static_cast<Index>(out.positions.size());
            out.positions.push_back(read.positions[v]);
        }
    }
    for (std::size_t v = 0; v < seen.size(); ++v) {
        if (!seen[v]) {
            throw InvalidInput(name + ": input vertex " + std::to_string(v) +
                               " is missing from the restored mesh");
        }
    }
    out.triangles.reserve(read.face_count());
    for (const Triangle& t : read.triangles) {
        out.triangles.push_back({renumber[t[0]], renumber[t[1]], renumber[t[2]]});
    }
    return out;
}

bool starts_with_moved_input(const Mesh& written, const Mesh& input) {
    const std::size_t n = input.vertex_count();
    if (written.vertex_count() < n) return false;
    const PositionIndex input_index(input.positions);
    std::size_t in_place = 0;
    for (std::size_t v = 0; v < written.vertex_count(); ++v) {
        const std::optional<Index> i = input_index.find(written.positions[v]);
        if (i && *i != v) return false;
        in_place += i.has_value();
    }
    return in_place < n;
}

Mesh read_restored(const std::filesystem::path& path, const Mesh& input) {
    TriangleSoup soup = io::read_mesh(path);
    Mesh written{std::move(soup.points), std::move(soup.triangles)};
    if (starts_with_moved_input(written, input)) return written;
    return match_restored(weld(to_soup(written)), path.string(), input);
}

std::vector<BandRole> decode_segment_roles(const io::PlyMesh& ply, const std::string& name,
                                           std::size_t face_count) {
    const auto *r = ply.face_property("red"), *g = ply.face_property("green"),
               *b = ply.face_property("blue");
    if (!r || !g || !b) throw ReadError(name, "no face colours (red, green, blue)");
    if (r->size() != face_count) throw InvalidInput(name + ": face count differs from the input's");
    std::vector<BandRole> roles(face_count, BandRole::None);
    for (std::size_t f = 0; f < face_count; ++f) {
        if (is_color(kEdgeTriangleColor, (*r)[f], (*g)[f], (*b)[f])) roles[f] = BandRole::Edge;
        if (is_color(kCornerTriangleColor, (*r)[f], (*g)[f], (*b)[f])) roles[f] = BandRole::Corner;
    }
    return roles;
}

std::vector<BandRole> read_segment_roles(const std::filesystem::path& path,
                                         std::size_t face_count) {
    return decode_segment_roles(io::read_ply_with_properties(path), path.string(), face_count);
}

}  // namespace resharp::eval
