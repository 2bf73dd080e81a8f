#include "resharp/sim/job.h"

#include <filesystem>
#include <optional>

#include "resharp/core/errors.h"
#include "resharp/sim/detail/json_fields.h"

namespace resharp::sim {
namespace {

using detail::json;

class JobReader {
public:
    explicit JobReader(const std::string& source) : fields_(source) {}

    Job read(const json& root, const std::string& folder) const {
        fields_.expect_keys(
            root, "", {"stock", "pitch", "program", "start", "tools", "mesher", "seam_duplicates"});
        Job job;
        const json& stock = fields_.member(root, "", "stock");
        fields_.expect_keys(stock, "stock", {"min", "max"});
        job.stock = Box3(fields_.point(fields_.member(stock, "stock", "min"), "stock.min"),
                         fields_.point(fields_.member(stock, "stock", "max"), "stock.max"));
        if (!(job.stock.min().array() < job.stock.max().array()).all()) {
            fields_.bad("stock", "min must be below max on every axis");
        }
        if (root.contains("pitch")) job.pitch = fields_.positive(root["pitch"], "pitch");
        const json& program = fields_.member(root, "", "program");
        if (!program.is_string() || program.get<std::string>().empty()) {
            fields_.bad("program", "must be a file name");
        }
        job.program = (std::filesystem::path(folder) / program.get<std::string>()).string();
        job.start_position =
            root.contains("start")
                ? fields_.point(root["start"], "start")
                : Vec3(job.stock.center().x(), job.stock.center().y(), job.stock.max().z() + 50.0);
        const json& tools = fields_.member(root, "", "tools");
        if (!tools.is_array() || tools.empty()) fields_.bad("tools", "must be a non-empty array");
        for (std::size_t i = 0; i < tools.size(); ++i) read_tool(tools[i], i, job);
        read_meshing(root, job.meshing);
        return job;
    }

private:
    void read_meshing(const json& root, MeshingOptions& meshing) const {
        if (root.contains("mesher")) {
            const json& name = root["mesher"];
            const auto mesher =
                name.is_string() ? mesher_from_string(name.get<std::string>()) : std::nullopt;
            if (!mesher)
                fields_.bad("mesher",
                            "must be \"mc\", \"bisect\", \"midpoint\" or \"surface-nets\"");
            meshing.mesher = *mesher;
        }
        if (root.contains("seam_duplicates")) {
            const json& seams = root["seam_duplicates"];
            if (!seams.is_number_integer() || seams.get<long long>() < 0 ||
                seams.get<long long>() > 100000) {
                fields_.bad("seam_duplicates", "must be an integer in 0..100000");
            }
            meshing.seam_duplicates = seams.get<int>();
        }
    }

    void read_tool(const json& entry, std::size_t index, Job& job) const {
        const std::string where = "tools[" + std::to_string(index) + "]";
        fields_.expect_keys(entry, where,
                            {"number", "type", "diameter", "corner_radius", "flute_length",
                             "tip_angle", "tip_diameter"});
        const json& number_value = fields_.member(entry, where, "number");
        if (!number_value.is_number_integer() || number_value.get<long long>() < 1) {
            fields_.bad(where + ".number", "must be a positive integer");
        }
        const int number_of_tool = number_value.get<int>();
        const json& type = fields_.member(entry, where, "type");
        const std::string name = type.is_string() ? type.get<std::string>() : "";
        ToolShape shape;
        if (name == "flat") {
            shape = ToolShape::FlatEnd;
        } else if (name == "ball") {
            shape = ToolShape::BallEnd;
        } else if (name == "bullnose") {
            shape = ToolShape::BullNose;
        } else if (name == "vbit") {
            shape = ToolShape::Cone;
        } else {
            fields_.bad(where + ".type", "must be \"flat\", \"ball\", \"bullnose\" or \"vbit\"");
        }
        const auto optional = [&](const char* key) {
            return entry.contains(key) ? fields_.number(entry[key], where + "." + key) : 0.0;
        };
        // Keys of the other family are refused rather than ignored.
        for (const char* key : {"tip_angle", "tip_diameter", "corner_radius"}) {
            const bool for_cones = std::string(key) != "corner_radius";
            if (entry.contains(key) && for_cones != (shape == ToolShape::Cone)) {
                fields_.bad(where + "." + key,
                            std::string("does not apply to a \"") + name + "\" tool");
            }
        }
        if (shape == ToolShape::Cone) {
            const double angle =
                fields_.number(fields_.member(entry, where, "tip_angle"), where + ".tip_angle");
            if (!(angle > 0.0 && angle < 180.0)) {
                fields_.bad(where + ".tip_angle", "must lie strictly between 0 and 180 degrees");
            }
            if (optional("tip_diameter") < 0.0)
                fields_.bad(where + ".tip_diameter", "must not be negative");
        }
        try {
            const double diameter =
                fields_.positive(fields_.member(entry, where, "diameter"), where + ".diameter");
            const double flute = fields_.positive(fields_.member(entry, where, "flute_length"),
                                                  where + ".flute_length");
            const Tool tool = shape == ToolShape::Cone
                                  ? Tool::make_cone(diameter, optional("tip_angle"),
                                                    optional("tip_diameter"), flute)
                                  : Tool::make(shape, diameter, optional("corner_radius"), flute);
            if (!job.tools.emplace(number_of_tool, tool).second) {
                fields_.bad(where + ".number",
                            "tool " + std::to_string(number_of_tool) + " is listed twice");
            }
        } catch (const InvalidInput& e) {
            if (std::string(e.what()).rfind(fields_.source(), 0) == 0) throw;
            fields_.bad(where, e.what());
        }
    }

    detail::JsonFields fields_;
};

}  // namespace

Job parse_job(const std::string& text, const std::string& source, const std::string& folder) {
    return JobReader(source).read(detail::parse_json(text, source), folder);
}

Job read_job(const std::string& path) {
    return parse_job(detail::read_text_file(path), path,
                     std::filesystem::path(path).parent_path().string());
}

}  // namespace resharp::sim
