#include "resharp/sim/job.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "resharp/core/errors.h"

namespace resharp::sim {
namespace {

using nlohmann::json;

class JobReader {
public:
    explicit JobReader(const std::string& source) : source_(source) {}

    Job read(const json& root, const std::string& folder) const {
        expect_keys(root, "",
                    {"stock", "pitch", "program", "start", "tools", "mesher", "seam_duplicates"});
        Job job;
        const json& stock = member(root, "", "stock");
        expect_keys(stock, "stock", {"min", "max"});
        job.stock = Box3(point(member(stock, "stock", "min"), "stock.min"),
                         point(member(stock, "stock", "max"), "stock.max"));
        if (!(job.stock.min().array() < job.stock.max().array()).all()) {
            bad("stock", "min must be below max on every axis");
        }
        if (root.contains("pitch")) job.pitch = positive(root["pitch"], "pitch");
        const json& program = member(root, "", "program");
        if (!program.is_string() || program.get<std::string>().empty()) {
            bad("program", "must be a file name");
        }
        job.program = (std::filesystem::path(folder) / program.get<std::string>()).string();
        job.start_position =
            root.contains("start")
                ? point(root["start"], "start")
                : Vec3(job.stock.center().x(), job.stock.center().y(), job.stock.max().z() + 50.0);
        const json& tools = member(root, "", "tools");
        if (!tools.is_array() || tools.empty()) bad("tools", "must be a non-empty array");
        for (std::size_t i = 0; i < tools.size(); ++i) read_tool(tools[i], i, job);
        read_meshing(root, job.meshing);
        return job;
    }

private:
    [[noreturn]] void bad(const std::string& key, const std::string& reason) const {
        throw InvalidInput(source_ + ": " + key + ": " + reason);
    }

    const json& member(const json& object, const std::string& where, const char* key) const {
        if (!object.contains(key)) bad(where.empty() ? key : where + "." + key, "missing");
        return object[key];
    }

    void expect_keys(const json& object, const std::string& where,
                     const std::set<std::string>& allowed) const {
        if (!object.is_object()) bad(where.empty() ? "job" : where, "must be an object");
        for (const auto& item : object.items()) {
            if (!allowed.count(item.key())) {
                bad(where.empty() ? item.key() : where + "." + item.key(), "unknown key");
            }
        }
    }

    double number(const json& value, const std::string& key) const {
        if (!value.is_number()) bad(key, "must be a number");
        const double x = value.get<double>();
        if (!std::isfinite(x)) bad(key, "must be finite");
        return x;
    }

    double positive(const json& value, const std::string& key) const {
        const double x = number(value, key);
        if (!(x > 0.0)) bad(key, "must be positive");
        return x;
    }

    Vec3 point(const json& value, const std::string& key) const {
        if (!value.is_array() || value.size() != 3) bad(key, "must be [x, y, z]");
        return Vec3(number(value[0], key), number(value[1], key), number(value[2], key));
    }

    void read_meshing(const json& root, MeshingOptions& meshing) const {
        if (root.contains("mesher")) {
            const json& name = root["mesher"];
            const auto mesher =
                name.is_string() ? mesher_from_string(name.get<std::string>()) : std::nullopt;
            if (!mesher)
                bad("mesher", "must be \"mc\", \"bisect\", \"midpoint\" or \"surface-nets\"");
            meshing.mesher = *mesher;
        }
        if (root.contains("seam_duplicates")) {
            const json& seams = root["seam_duplicates"];
            if (!seams.is_number_integer() || seams.get<long long>() < 0 ||
                seams.get<long long>() > 100000) {
                bad("seam_duplicates", "must be an integer in 0..100000");
            }
            meshing.seam_duplicates = seams.get<int>();
        }
    }

    void read_tool(const json& entry, std::size_t index, Job& job) const {
        const std::string where = "tools[" + std::to_string(index) + "]";
        expect_keys(entry, where,
                    {"number", "type", "diameter", "corner_radius", "flute_length", "tip_angle",
                     "tip_diameter"});
        const json& number_value = member(entry, where, "number");
        if (!number_value.is_number_integer() || number_value.get<long long>() < 1) {
            bad(where + ".number", "must be a positive integer");
        }
        const int number_of_tool = number_value.get<int>();
        const json& type = member(entry, where, "type");
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
            bad(where + ".type", "must be \"flat\", \"ball\", \"bullnose\" or \"vbit\"");
        }
        const auto optional = [&](const char* key) {
            return entry.contains(key) ? number(entry[key], where + "." + key) : 0.0;
        };
        // Keys of the other family are refused rather than ignored.
        for (const char* key : {"tip_angle", "tip_diameter", "corner_radius"}) {
            const bool for_cones = std::string(key) != "corner_radius";
            if (entry.contains(key) && for_cones != (shape == ToolShape::Cone)) {
                bad(where + "." + key, std::string("does not apply to a \"") + name + "\" tool");
            }
        }
        if (shape == ToolShape::Cone) {
            const double angle = number(member(entry, where, "tip_angle"), where + ".tip_angle");
            if (!(angle > 0.0 && angle < 180.0)) {
                bad(where + ".tip_angle", "must lie strictly between 0 and 180 degrees");
            }
            if (optional("tip_diameter") < 0.0)
                bad(where + ".tip_diameter", "must not be negative");
        }
        try {
            const double diameter = positive(member(entry, where, "diameter"), where + ".diameter");
            const double flute =
                positive(member(entry, where, "flute_length"), where + ".flute_length");
            const Tool tool = shape == ToolShape::Cone
                                  ? Tool::make_cone(diameter, optional("tip_angle"),
                                                    optional("tip_diameter"), flute)
                                  : Tool::make(shape, diameter, optional("corner_radius"), flute);
            if (!job.tools.emplace(number_of_tool, tool).second) {
                bad(where + ".number",
                    "tool " + std::to_string(number_of_tool) + " is listed twice");
            }
        } catch (const InvalidInput& e) {
            if (std::string(e.what()).rfind(source_, 0) == 0) throw;
            bad(where, e.what());
        }
    }

    const std::string& source_;
};

/// 1-based line of a byte offset, for JSON syntax errors.
std::uint64_t line_of(const std::string& text, std::size_t byte) {
    const auto end = text.begin() + static_cast<std::ptrdiff_t>(std::min(byte, text.size()));
    return 1 + static_cast<std::uint64_t>(std::count(text.begin(), end, '\n'));
}

}  // namespace

Job parse_job(const std::string& text, const std::string& source, const std::string& folder) {
    json root;
    try {
        root = json::parse(text, nullptr, true, /*ignore_comments=*/true);
    } catch (const json::parse_error& e) {
        const std::size_t byte = e.byte > 0 ? e.byte - 1 : 0;
        std::string reason = e.what();
        const auto detail = reason.find("parse error");
        throw ParseError(
            source, FileLocation::line(line_of(text, byte)),
            "malformed JSON (" + reason.substr(detail == std::string::npos ? 0 : detail) + ")");
    }
    return JobReader(source).read(root, folder);
}

Job read_job(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ReadError(path, std::string("cannot open: ") + std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw ReadError(path, "read failed");
    return parse_job(text.str(), path, std::filesystem::path(path).parent_path().string());
}

}  // namespace resharp::sim
