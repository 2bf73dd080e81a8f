#pragma once
/// Internal to resharp::io: a line-aware tokenizer over a whole text file held in memory, shared
/// by every ASCII reader (STL, OBJ, OFF, the PLY header and ASCII body). Numbers are parsed with
/// std::from_chars; every failure throws ParseError naming the file and the current line.

#include <cstdint>
#include <string>
#include <string_view>

namespace resharp::io::detail {

class TextCursor {
public:
    /// `text` must outlive the cursor. `comment` starts a comment that runs to the end of the
    /// line ('\0' for formats without comments). `first_line` numbers the first line of `text`
    /// (a PLY body starts after its header).
    TextCursor(std::string_view text, const std::string& name, char comment = '\0',
               std::uint64_t first_line = 1);

    /// The next token on the current line, or "" at the end of the line, a comment or the file.
    std::string_view token_in_line();
    /// The next token, crossing line ends and comments; "" at the end of the file.
    std::string_view token();
    /// Moves past the rest of the current line. Returns false if no further line has content.
    bool next_line();
    /// True when only whitespace (and comments) remain.
    bool only_space_left();

    /// The next token on the current line as a finite double. \throws ParseError if missing,
    /// malformed, out of range, NaN or infinite; `what` names the value in the message.
    double double_in_line(std::string_view what);
    /// The next token (crossing lines) as a finite double. \throws ParseError as double_in_line.
    double next_double(std::string_view what);
    /// The next token (crossing lines) as an integer. \throws ParseError if missing or malformed.
    std::int64_t next_integer(std::string_view what);
    /// Consumes the next token (crossing lines), which must equal `keyword` in any letter case.
    void expect(std::string_view keyword);

    /// `token` as a finite double. \throws ParseError at the current line.
    double to_double(std::string_view token, std::string_view what) const;
    /// `token` as an integer. \throws ParseError at the current line.
    std::int64_t to_integer(std::string_view token, std::string_view what) const;

    /// Throws ParseError at the current line.
    [[noreturn]] void fail(const std::string& reason) const;

    std::uint64_t line() const { return line_; }
    std::size_t offset() const { return pos_; }
    const std::string& name() const { return name_; }

private:
    bool is_comment(char c) const { return comment_ != '\0' && c == comment_; }
    void skip_to_line_end();
    /// Steps over a '\n' at pos_; counts a line only if text follows it, so errors at the end
    /// of a file name its last line.
    void step_over_newline();
    std::string_view scan_token();
    std::string_view require(std::string_view token, std::string_view what) const;

    std::string_view text_;
    const std::string& name_;
    char comment_;
    std::size_t pos_ = 0;
    std::uint64_t line_ = 1;
};

/// True if `a` and `b` are equal ignoring ASCII letter case.
bool equals_ignoring_case(std::string_view a, std::string_view b);

/// `token` quoted for an error message: at most 40 characters, unprintable bytes as '?'.
std::string quoted(std::string_view token);

}  // namespace resharp::io::detail
