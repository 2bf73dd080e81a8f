#include "resharp/sim/gcode.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>

#include "resharp/core/errors.h"

namespace resharp::sim {
namespace {

constexpr double kMillimetresPerInch = 25.4;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

std::string format_number(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

/// The words of one block: G and M may repeat, every other letter at most once.
struct Block {
    std::vector<double> g, m;
    std::array<std::optional<double>, 26> word;

    const std::optional<double>& operator[](char letter) const { return word[letter - 'A']; }
    bool has(char letter) const { return word[letter - 'A'].has_value(); }
};

class GcodeParser {
public:
    GcodeParser(const std::string& source, const GcodeOptions& options)
        : source_(source), options_(options), position_(options.start_position) {}

    ToolPath run(std::istream& in) {
        std::string text;
        while (!ended_ && std::getline(in, text)) {
            ++line_;
            execute(tokenize(strip_comments(text)));
        }
        if (in.bad()) throw ReadError(source_, "read failed");
        path_.source = source_;
        return std::move(path_);
    }

private:
    [[noreturn]] void fail(const std::string& reason) const {
        throw ParseError(source_, FileLocation::line(line_), reason);
    }

    std::string strip_comments(const std::string& text) const {
        std::string kept;
        bool in_parentheses = false;
        for (char c : text) {
            if (in_parentheses) {
                if (c == ')') in_parentheses = false;
            } else if (c == '(') {
                in_parentheses = true;
            } else if (c == ';') {
                break;
            } else {
                kept += c;
            }
        }
        if (in_parentheses) fail("comment '(' is not closed on its line");
        const auto first = kept.find_first_not_of(" \t\r");
        if (first != std::string::npos && kept[first] == '%' &&
            kept.find_first_not_of(" \t\r", first + 1) == std::string::npos) {
            return {};  // program start/end marker
        }
        return kept;
    }

    Block tokenize(const std::string& text) const {
        Block block;
        std::size_t i = 0;
        while (i < text.size()) {
            const char raw = text[i];
            if (std::isspace(static_cast<unsigned char>(raw))) {
                ++i;
                continue;
            }
            if (!std::isalpha(static_cast<unsigned char>(raw))) {
                fail(std::string("unexpected character '") + raw + "'");
            }
            const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(raw)));
            ++i;
            while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
            const double value = parse_number(text, i, letter);
            if (letter == 'G') {
                block.g.push_back(value);
            } else if (letter == 'M') {
                block.m.push_back(value);
            } else {
                if (std::strchr("TXYZIJKRFSNO", letter) == nullptr) {
                    fail(std::string("unknown word '") + letter + format_number(value) + "'");
                }
                if (block.has(letter)) fail(std::string("word ") + letter + " appears twice");
                block.word[letter - 'A'] = value;
            }
        }
        return block;
    }

    double parse_number(const std::string& text, std::size_t& i, char letter) const {
        std::size_t begin = i;
        if (begin < text.size() && text[begin] == '+') ++begin;
        const char* first = text.data() + begin;
        const char* last = text.data() + text.size();
        const bool starts_number =
            first < last &&
            (std::isdigit(static_cast<unsigned char>(*first)) || *first == '.' || *first == '-');
        double value = 0.0;
        const auto result = std::from_chars(first, last, value);
        if (!starts_number || result.ec != std::errc() || !std::isfinite(value)) {
            fail(std::string("word ") + letter + " needs a number");
        }
        i = static_cast<std::size_t>(result.ptr - text.data());
        return value;
    }

    int integer_code(double value, char letter) const {
        if (value != std::floor(value) || value < 0 || value > 1e6) {
            fail(std::string("unsupported ") + letter + format_number(value));
        }
        return static_cast<int>(value);
    }

    void execute(const Block& block) {
        for (double g : block.g) apply_g(g);
        if (block.has('T')) selected_tool_ = integer_code(*block['T'], 'T');
        bool ends = false;
        for (double m : block.m) {
            switch (integer_code(m, 'M')) {
                case 6:
                    if (!selected_tool_) fail("M6 tool change with no tool selected by T");
                    loaded_tool_ = *selected_tool_;
                    break;
                case 2:
                case 30:
                    ends = true;
                    break;
                case 3:
                case 4:
                case 5:
                case 8:
                case 9:
                    break;  // spindle and coolant
                default:
                    fail("unsupported M" + format_number(m));
            }
        }
        if (block.has('K')) fail("word K has no use for arcs in the XY plane (G17)");
        const bool has_axes = block.has('X') || block.has('Y') || block.has('Z');
        const bool has_arc_words = block.has('I') || block.has('J') || block.has('R');
        if (has_axes || has_arc_words) move(block);
        ended_ = ends;
    }

    void apply_g(double g) {
        switch (integer_code(g, 'G')) {
            case 0:
                motion_ = MoveKind::Rapid;
                break;
            case 1:
                motion_ = MoveKind::Line;
                break;
            case 2:
                motion_ = MoveKind::ArcClockwise;
                break;
            case 3:
                motion_ = MoveKind::ArcCounterClockwise;
                break;
            case 17:
                break;
            case 18:
            case 19:
                fail("only arcs in the XY plane (G17) are supported");
            case 20:
                scale_ = kMillimetresPerInch;
                break;
            case 21:
                scale_ = 1.0;
                break;
            case 90:
                incremental_ = false;
                break;
            case 91:
                incremental_ = true;
                break;
            case 40:
            case 49:
            case 54:
            case 80:
            case 94:
                break;  // safe-start modes
            default:
                fail("unsupported G" + format_number(g));
        }
    }

    void move(const Block& block) {
        if (!motion_) fail("coordinates given before any motion mode (G0, G1, G2, G3)");
        Move m;
        m.kind = *motion_;
        m.start = position_;
        m.end = position_;
        m.tool = loaded_tool_;
        m.line = line_;
        for (int a = 0; a < 3; ++a) {
            const auto& value = block["XYZ"[a]];
            if (value) m.end[a] = (incremental_ ? position_[a] : 0.0) + *value * scale_;
        }
        position_ = m.end;
        if (m.is_arc()) {
            make_arc(block, m);
        } else {
            if (block.has('I') || block.has('J') || block.has('R')) {
                fail("words I, J and R belong to arcs (G2, G3)");
            }
            if (m.end == m.start) return;
        }
        path_.moves.push_back(m);
    }

    void make_arc(const Block& block, Move& m) const {
        const Eigen::Vector2d from = m.start.head<2>(), to = m.end.head<2>();
        const bool clockwise = m.kind == MoveKind::ArcClockwise;
        if (block.has('R')) {
            if (block.has('I') || block.has('J')) fail("an arc takes either R or I/J, not both");
            m.center = center_from_radius(from, to, *block['R'] * scale_, clockwise);
        } else if (block.has('I') || block.has('J')) {
            m.center =
                from + scale_ * Eigen::Vector2d(block['I'].value_or(0.0), block['J'].value_or(0.0));
        } else {
            fail("an arc needs its centre (I, J) or radius (R)");
        }
        m.radius = (from - m.center).norm();
        const double end_radius = (to - m.center).norm();
        if (!(m.radius > 0.0)) fail("arc centre coincides with its start");
        if (std::abs(m.radius - end_radius) > options_.arc_tolerance) {
            fail("arc radius mismatch: start radius " + format_number(m.radius) +
                 " mm, end radius " + format_number(end_radius) + " mm (tolerance " +
                 format_number(options_.arc_tolerance) + " mm)");
        }
        const double a0 = std::atan2(from.y() - m.center.y(), from.x() - m.center.x());
        const double a1 = std::atan2(to.y() - m.center.y(), to.x() - m.center.x());
        double sweep = a1 - a0;
        if (clockwise) {
            while (sweep >= 0.0) sweep -= kTwoPi;  // equal ends: a full circle
        } else {
            while (sweep <= 0.0) sweep += kTwoPi;
        }
        m.sweep = sweep;
    }

    Eigen::Vector2d center_from_radius(const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                                       double r, bool clockwise) const {
        const Eigen::Vector2d chord = to - from;
        const double half = chord.norm() / 2;
        if (!(half > 0.0)) fail("an R-format arc needs distinct start and end points");
        double radius = std::abs(r);
        if (radius < half) {
            if (half - radius > options_.arc_tolerance) {
                fail("arc radius " + format_number(radius) +
                     " mm is smaller than half the distance between its ends (" +
                     format_number(half) + " mm)");
            }
            radius = half;
        }
        const double offset = std::sqrt(std::max(radius * radius - half * half, 0.0));
        const Eigen::Vector2d left(-chord.y() / (2 * half), chord.x() / (2 * half));
        // Counter-clockwise arcs under 180° have their centre left of the chord; clockwise ones
        // right; R < 0 asks for the arc over 180°, centre on the other side.
        const double side = (clockwise ? -1.0 : 1.0) * (r < 0.0 ? -1.0 : 1.0);
        return (from + to) / 2 + side * offset * left;
    }

    const std::string& source_;
    GcodeOptions options_;
    ToolPath path_;
    Vec3 position_;
    std::optional<MoveKind> motion_;
    std::optional<int> selected_tool_;
    int loaded_tool_ = 0;
    double scale_ = 1.0;
    bool incremental_ = false;
    bool ended_ = false;
    std::uint64_t line_ = 0;
};

}  // namespace

ToolPath parse_gcode(std::istream& in, const std::string& source, const GcodeOptions& options) {
    return GcodeParser(source, options).run(in);
}

ToolPath read_gcode(const std::string& path, const GcodeOptions& options) {
    std::ifstream in(path);
    if (!in) throw ReadError(path, std::string("cannot open: ") + std::strerror(errno));
    return parse_gcode(in, path, options);
}

}  // namespace resharp::sim
