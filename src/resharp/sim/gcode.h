#pragma once
/// G-code: the subset 3-axis CAM post-processors emit.
///
/// Accepted words (case-insensitive, one of each letter per block):
/// - G0 rapid, G1 line, G2/G3 clockwise/counter-clockwise arc in XY with centre offsets I, J
///   (incremental from the start) or radius R (R < 0: the arc over 180°); a Z change on an arc
///   makes a helix. Motion modes are modal; a block with only coordinates repeats the last one.
/// - G17 (XY plane), G20/G21 (inch/mm), G90/G91 (absolute/incremental X Y Z); G40, G49, G54,
///   G80, G94 are accepted and change nothing (cutter compensation off, length compensation
///   off, work offset 1, canned cycles off, feed per minute: what a safe-start block sets).
/// - T n selects a tool, M6 loads it; M3, M4, M5, M8, M9 are accepted and ignored; M2 and M30
///   end the program (later lines are not read).
/// - F, S (feed, speed) and N (block numbers), O (program number) are accepted and ignored.
/// - comments in parentheses and after ';'; lines holding only '%'.
/// Anything else is an error naming the line. An arc whose end does not lie on its circle
/// (start and end radius differ by more than the tolerance) is an error too, never bent.

#include <cstdint>
#include <istream>
#include <string>
#include <vector>

#include "resharp/core/types.h"

namespace resharp::sim {

enum class MoveKind { Rapid, Line, ArcClockwise, ArcCounterClockwise };

/// One motion of the tool tip, in mm, absolute coordinates.
struct Move {
    MoveKind kind = MoveKind::Line;
    Vec3 start = Vec3::Zero();
    Vec3 end = Vec3::Zero();
    Eigen::Vector2d center{0.0, 0.0};  ///< arcs: centre in XY
    double radius = 0.0;               ///< arcs: distance from the centre to the start
    double sweep = 0.0;                ///< arcs: signed angle, rad, positive counter-clockwise
    int tool = 0;                      ///< number of the loaded tool, 0 when none is loaded
    std::uint64_t line = 0;            ///< 1-based source line

    bool is_arc() const {
        return kind == MoveKind::ArcClockwise || kind == MoveKind::ArcCounterClockwise;
    }
};

struct GcodeOptions {
    Vec3 start_position = Vec3::Zero();  ///< tool tip position before the first move, mm
    double arc_tolerance = 0.002;        ///< largest start/end radius difference of an arc, mm
};

/// The moves of a program, in order.
struct ToolPath {
    std::vector<Move> moves;
    std::string source;  ///< the program's name in errors (parse_gcode's `source`)
};

/// Parses a program from a stream; `source` names it in errors.
/// \throws ParseError(source, line, reason) on an unknown or malformed word, a repeated letter,
/// an arc whose radius does not fit its ends, an arc in another plane, M6 without T.
ToolPath parse_gcode(std::istream& in, const std::string& source, const GcodeOptions& options = {});

/// Reads and parses a program file.
/// \throws ReadError if the file cannot be opened; ParseError as parse_gcode().
ToolPath read_gcode(const std::string& path, const GcodeOptions& options = {});

}  // namespace resharp::sim
