#include "resharp/io/detail/text_cursor.h"

#include <charconv>
#include <cmath>

#include "resharp/core/errors.h"

namespace resharp::io::detail {
namespace {

bool is_line_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

bool is_space(char c) { return c == '\n' || is_line_space(c); }

// from_chars accepts no leading '+', which some writers emit ("+1.5e+01").
std::string_view without_plus(std::string_view token) {
    return token.size() > 1 && token[0] == '+' && token[1] != '-' ? token.substr(1) : token;
}

}  // namespace

bool equals_ignoring_case(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; };
        if (lower(a[i]) != lower(b[i])) return false;
    }
    return true;
}

std::string quoted(std::string_view token) {
    constexpr std::size_t kMax = 40;
    std::string out = "'";
    for (std::size_t i = 0; i < token.size() && i < kMax; ++i) {
        const unsigned char c = static_cast<unsigned char>(token[i]);
        out += (c >= 0x20 && c < 0x7f) ? static_cast<char>(c) : '?';
    }
    out += token.size() > kMax ? "...'" : "'";
    return out;
}

TextCursor::TextCursor(std::string_view text, const std::string& name, char comment,
                       std::uint64_t first_line)
    : text_(text), name_(name), comment_(comment), line_(first_line) {}

void TextCursor::fail(const std::string& reason) const {
    throw ParseError(name_, FileLocation::line(line_), reason);
}

void TextCursor::skip_to_line_end() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
}

void TextCursor::step_over_newline() {
    ++pos_;
    if (pos_ < text_.size()) ++line_;
}

std::string_view TextCursor::scan_token() {
    const std::size_t begin = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_]) && !is_comment(text_[pos_])) ++pos_;
    return text_.substr(begin, pos_ - begin);
}

std::string_view TextCursor::token_in_line() {
    while (pos_ < text_.size() && is_line_space(text_[pos_])) ++pos_;
    if (pos_ == text_.size() || text_[pos_] == '\n') return {};
    if (is_comment(text_[pos_])) {
        skip_to_line_end();
        return {};
    }
    return scan_token();
}

std::string_view TextCursor::token() {
    while (pos_ < text_.size()) {
        const char c = text_[pos_];
        if (c == '\n') {
            step_over_newline();
        } else if (is_line_space(c)) {
            ++pos_;
        } else if (is_comment(c)) {
            skip_to_line_end();
        } else {
            return scan_token();
        }
    }
    return {};
}

bool TextCursor::next_line() {
    skip_to_line_end();
    if (pos_ + 1 >= text_.size()) {
        pos_ = text_.size();
        return false;
    }
    step_over_newline();
    return true;
}

bool TextCursor::only_space_left() { return token().empty(); }

std::string_view TextCursor::require(std::string_view token, std::string_view what) const {
    if (token.empty()) {
        fail("missing " + std::string(what) +
             (pos_ == text_.size() ? " (unexpected end of file)" : ""));
    }
    return token;
}

double TextCursor::double_in_line(std::string_view what) {
    return to_double(require(token_in_line(), what), what);
}

double TextCursor::next_double(std::string_view what) {
    return to_double(require(token(), what), what);
}

std::int64_t TextCursor::next_integer(std::string_view what) {
    return to_integer(require(token(), what), what);
}

void TextCursor::expect(std::string_view keyword) {
    const std::string_view found = token();
    if (equals_ignoring_case(found, keyword)) return;
    fail("expected '" + std::string(keyword) + "', found " +
         (found.empty() ? std::string("end of file") : quoted(found)));
}

double TextCursor::to_double(std::string_view token, std::string_view what) const {
    const std::string_view digits = without_plus(token);
    double value = 0.0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec == std::errc::result_out_of_range) {
        fail(std::string(what) + " out of range: " + quoted(token));
    }
    if (ec != std::errc() || end != digits.data() + digits.size()) {
        fail("expected a number for " + std::string(what) + ", found " + quoted(token));
    }
    if (!std::isfinite(value)) fail(std::string(what) + " is NaN or infinite: " + quoted(token));
    return value;
}

std::int64_t TextCursor::to_integer(std::string_view token, std::string_view what) const {
    const std::string_view digits = without_plus(token);
    std::int64_t value = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec == std::errc::result_out_of_range) {
        fail(std::string(what) + " out of range: " + quoted(token));
    }
    if (ec != std::errc() || end != digits.data() + digits.size()) {
        fail("expected an integer for " + std::string(what) + ", found " + quoted(token));
    }
    return value;
}

}  // namespace resharp::io::detail
