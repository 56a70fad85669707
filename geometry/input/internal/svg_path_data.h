#pragma once
// Internal to the SVG reader: number scanning and the parsers of SVG path data (the `d`
// attribute) and of number lists (`points`, `viewBox`).
//
// Numbers follow the SVG 1.1 path grammar, not strtod:
//   number   ::= sign? (digits ('.' digits?)? | '.' digits) (('e'|'E') sign? digits)?
// so "1.5.5" is 1.5 then .5, "10-5" is 10 then -5, and "nan"/"inf" are never numbers (they are
// reported as "coordinate is not a finite number", as is an overflow such as 1e999).
//
// Path data is reduced to absolute segments (relative commands add their offsets to the current
// point in double, as renderers do, so that an endpoint is bit-identical to what a renderer
// computes), with S/T control points reflected, H/V turned into lines and arcs with a zero radius
// turned into lines (SVG 1.1 F.6.2). A closepath followed by a drawing command starts a new
// subpath at the closed subpath's start point (SVG 1.1 8.3.3).
#include <Eigen/Core>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "base/errors.h"

namespace sdog::svg {

using Point = Eigen::Vector2d;

/// A problem with one element's attribute or geometry. The message has no file/element prefix:
/// the reader adds "FILE:LINE: <path id=\"x\">: path data: " and rethrows it as an InputError of
/// its own.
struct ElementError : InputError {
  using InputError::InputError;
};

/// SVG white space: space, tab, CR, LF (and form feed, which some tools emit).
bool is_wsp(char c);
void skip_wsp(std::string_view text, std::size_t& pos);
/// Skips `wsp* ','? wsp*`; returns whether a comma was consumed.
bool skip_comma_wsp(std::string_view text, std::size_t& pos);

enum class NumberScan {
  kOk,         ///< value set, pos advanced past the number
  kAbsent,     ///< no number at pos (pos unchanged)
  kNotFinite,  ///< "nan", "inf", "infinity" (any case, optional sign) or an overflow (1e999)
};

/// Scans one number at `pos` (no leading white space is skipped). Underflow gives a signed 0.
NumberScan scan_number(std::string_view text, std::size_t& pos, double& value);

/// `at character N ("…context…")` for messages; N is 1-based, the excerpt is one line.
std::string position_note(std::string_view text, std::size_t pos);

/// Numbers separated by white space and/or single commas ("0,0 10 20, 5").
/// Throws ElementError for anything else; empty or blank text gives an empty list.
std::vector<double> parse_number_list(std::string_view text);

/// The `points` attribute of <polyline>/<polygon>: an even number of coordinates.
std::vector<Point> parse_points(std::string_view text);

enum class SegmentKind { kLine, kQuadratic, kCubic, kArc };

/// One drawing command in absolute SVG user coordinates (y down, before transforms).
struct PathSegment {
  SegmentKind kind = SegmentKind::kLine;
  Point from = Point::Zero();  ///< current point before the command
  Point c1 = Point::Zero();    ///< quadratic control point / first cubic control point
  Point c2 = Point::Zero();    ///< second cubic control point
  Point to = Point::Zero();    ///< end point, exactly as computed from the path data
  // Elliptical arc, SVG endpoint parameterisation (radii are already non-negative).
  double rx = 0, ry = 0, rotation_deg = 0;
  bool large_arc = false, sweep = false;
};

struct PathSubpath {
  Point start = Point::Zero();
  std::vector<PathSegment> segments;  ///< empty for a lone moveto
  bool closed = false;                ///< ended by Z/z
  std::size_t offset = 0;             ///< index of the command that started it in the data
};

/// Parses a `d` attribute. Blank data gives no subpaths (the element renders nothing).
/// Throws ElementError, e.g. `expected a number after 'C' at character 27 ("M 0 0 C 10 …")`.
std::vector<PathSubpath> parse_path_data(std::string_view d);

}  // namespace sdog::svg
