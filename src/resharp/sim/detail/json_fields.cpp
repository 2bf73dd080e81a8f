#include "resharp/sim/detail/json_fields.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "resharp/core/errors.h"

namespace resharp::sim::detail {
namespace {

/// 1-based line of a byte offset, for JSON syntax errors.
std::uint64_t line_of(const std::string& text, std::size_t byte) {
    const auto end = text.begin() + static_cast<std::ptrdiff_t>(std::min(byte, text.size()));
    return 1 + static_cast<std::uint64_t>(std::count(text.begin(), end, '\n'));
}

}  // namespace

json parse_json(const std::string& text, const std::string& source) {
    try {
        return json::parse(text, nullptr, true, /*ignore_comments=*/true);
    } catch (const json::parse_error& e) {
        const std::size_t byte = e.byte > 0 ? e.byte - 1 : 0;
        std::string reason = e.what();
        const auto detail = reason.find("parse error");
        throw ParseError(
            source, FileLocation::line(line_of(text, byte)),
            "malformed JSON (" + reason.substr(detail == std::string::npos ? 0 : detail) + ")");
    }
}

std::string read_text_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ReadError(path, std::string("cannot open: ") + std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw ReadError(path, "read failed");
    return text.str();
}

void JsonFields::bad(const std::string& place, const std::string& reason) const {
    throw InvalidInput(source_ + ": " + place + ": " + reason);
}

const json& JsonFields::member(const json& object, const std::string& where,
                               const char* key) const {
    if (!object.contains(key)) bad(place(where, key), "missing");
    return object[key];
}

void JsonFields::expect_keys(const json& object, const std::string& where,
                             const std::set<std::string>& allowed) const {
    if (!object.is_object()) bad(where.empty() ? "top level" : where, "must be an object");
    for (const auto& item : object.items()) {
        if (!allowed.count(item.key())) bad(place(where, item.key()), "unknown key");
    }
}

double JsonFields::number(const json& value, const std::string& place) const {
    if (!value.is_number()) bad(place, "must be a number");
    const double x = value.get<double>();
    if (!std::isfinite(x)) bad(place, "must be finite");
    return x;
}

double JsonFields::positive(const json& value, const std::string& place) const {
    const double x = number(value, place);
    if (!(x > 0.0)) bad(place, "must be positive");
    return x;
}

Vec3 JsonFields::point(const json& value, const std::string& place) const {
    if (!value.is_array() || value.size() != 3) bad(place, "must be [x, y, z]");
    return Vec3(number(value[0], place), number(value[1], place), number(value[2], place));
}

}  // namespace resharp::sim::detail
