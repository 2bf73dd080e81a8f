#pragma once
/// Internal to resharp::sim: reading the simulator's JSON files (the job, the CSG solid) with
/// every key checked, each error naming the file and the key's place ("solid.union[2].radius").

#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "resharp/core/types.h"

namespace resharp::sim::detail {

using nlohmann::json;

/// Parses `text` (comments allowed). \throws ParseError(source, line) for malformed JSON.
json parse_json(const std::string& text, const std::string& source);

/// The bytes of the file at `path`. \throws ReadError if it cannot be opened or read.
std::string read_text_file(const std::string& path);

/// Typed access to the members of a parsed JSON document; every failure throws InvalidInput
/// reading "SOURCE: PLACE: REASON", where PLACE is the dotted key path.
class JsonFields {
public:
    explicit JsonFields(std::string source) : source_(std::move(source)) {}

    [[noreturn]] void bad(const std::string& place, const std::string& reason) const;
    /// `where` joined to `key` as a place: "key" at the top, "where.key" below it.
    static std::string place(const std::string& where, const std::string& key) {
        return where.empty() ? key : where + "." + key;
    }
    /// object[key]; \throws if it is missing.
    const json& member(const json& object, const std::string& where, const char* key) const;
    /// \throws unless `object` is an object whose keys are all in `allowed`.
    void expect_keys(const json& object, const std::string& where,
                     const std::set<std::string>& allowed) const;
    double number(const json& value, const std::string& place) const;
    double positive(const json& value, const std::string& place) const;
    /// [x, y, z] of finite numbers.
    Vec3 point(const json& value, const std::string& place) const;
    const std::string& source() const { return source_; }

private:
    std::string source_;
};

}  // namespace resharp::sim::detail
