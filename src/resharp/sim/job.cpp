#include "resharp/sim/job.h"

#include <filesystem>

#include "resharp/core/errors.h"
#include "resharp/sim/detail/json_fields.h"

namespace resharp::sim {
namespace {

using detail::json;

class JobReader {
public:
    explicit JobReader(const std::string& source) : fields_(source) {}

    Job read(const json& root, const std::string& folder) const {
        fields_.expect_keys(root, "", {"stock", "pitch", "program", "start", "tools"});
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
        return job;
    }

private:
    void read_tool(const json& entry, std::size_t index, Job& job) const {
        const std::string where = "tools[" + std::to_string(index) + "]";
        fields_.expect_keys(entry, where,
                            {"number", "type", "diameter", "corner_radius", "flute_length"});
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
        } else {
            fields_.bad(where + ".type", "must be \"flat\", \"ball\" or \"bullnose\"");
        }
        const double corner = entry.contains("corner_radius")
                                  ? fields_.number(entry["corner_radius"], where + ".corner_radius")
                                  : 0.0;
        try {
            const Tool tool = Tool::make(
                shape,
                fields_.positive(fields_.member(entry, where, "diameter"), where + ".diameter"),
                corner,
                fields_.positive(fields_.member(entry, where, "flute_length"),
                                 where + ".flute_length"));
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
