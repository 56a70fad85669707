#pragma once
// A crease pattern as drawn: the sheet (outer boundary with holes) and the crease curves with their
// fold assignments, in sheet units (SVG user units, y up). Built from an SvgDrawing with the
// conventions of geometry/fold_conventions.h (black curves are the sheet boundary; none: the
// viewBox rectangle), or from a FOLD file (geometry/fold_reader.h).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "geometry/svg_reader.h"

namespace sdog {

using Polyline2 = std::vector<Eigen::Vector2d>;

/// How a crease folds, as the drawing says (the FOLD format's M, V, F and U).
enum class Fold { kUnassigned, kMountain, kValley, kFlat };

/// "unassigned", "mountain", "valley", "flat".
const char* fold_name(Fold fold);
/// The Fold named by fold_name, if any.
std::optional<Fold> find_fold(const std::string& name);
/// +1 valley, -1 mountain, 0 flat or unassigned: the sign of the fold angle (FOLD's convention).
double fold_sign(Fold fold);

struct Crease {
  Polyline2 points;  ///< closed creases do not repeat the first point
  bool closed = false;
  Fold fold = Fold::kUnassigned;
  /// The fold angle the drawing gives, in degrees, 0 to 180 (its direction is `fold`'s); unset
  /// when the drawing gives none.
  std::optional<double> angle;
  std::string id;      ///< the SVG element's id (FOLD: "edge N" of its first edge), or empty
  std::string origin;  ///< where it was drawn, "FILE:LINE: <path id="c1">", for messages
  /// Same assignment and angle: creases that may be joined into one.
  bool folds_like(const Crease& other) const { return fold == other.fold && angle == other.angle; }
};

struct Sheet {
  Polyline2 outer;               ///< counter-clockwise, first point not repeated
  std::vector<Polyline2> holes;  ///< clockwise, first point not repeated
  Box2 bbox;                     ///< bounding box of the outer boundary
  bool from_viewbox = false;     ///< no black curve: the sheet is the viewBox rectangle
};

struct CreasePattern {
  std::string source;  ///< file name, for messages
  Sheet sheet;
  std::vector<Crease> creases;  ///< drawing order
  std::vector<std::string> warnings;  ///< what reading left out, one line each
  /// L = max(width, height) of the sheet: the length all tolerances are relative to.
  double size() const { return std::max(sheet.bbox.width(), sheet.bbox.height()); }
};

/// Sorts the drawing's curves into sheet boundary and creases. Boundary curves must form closed
/// loops (open black curves, in any order and direction, are chained end to end, each to the
/// nearest end within L/100; a gap becomes a straight step); the loop of
/// largest area is the outer boundary, the others are holes and must lie inside it. Creases drawn
/// as consecutive subpaths of one <path> that continue each other are joined; a crease whose ends
/// meet within `closed_fraction * L` is closed. Throws InputError for an open or
/// self-intersecting boundary, crossing boundary loops, a hole outside the sheet, a zero-area
/// sheet, or a drawing without viewBox and without boundary.
CreasePattern crease_pattern_from_svg(const SvgDrawing& drawing, double closed_fraction = 0.002);

/// A file whose name ends in .fold (in any case) is read with read_fold_file (the options do not
/// apply), any other with read_svg_file + crease_pattern_from_svg.
CreasePattern read_crease_pattern(const std::string& path, const SvgReadOptions& options = {});

}  // namespace sdog
