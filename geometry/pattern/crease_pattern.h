#pragma once
// A crease pattern as drawn: the sheet (outer boundary with holes) and the crease curves with their
// fold assignments, in sheet units (y up). The readers of geometry/input/ build it from SVG
// drawings and FOLD files (geometry/input/pattern_file.h loads either).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "base/enum_names.h"
#include "geometry/pattern/plane_geometry.h"

namespace sdog {

/// How a crease folds, as the drawing says (the FOLD format's M, V, F and U).
enum class Fold { kUnassigned, kMountain, kValley, kFlat };

template <>
struct EnumNames<Fold> {
  static constexpr const char* noun = "fold";
  static constexpr EnumName<Fold> rows[] = {
      {Fold::kUnassigned, "unassigned"},
      {Fold::kMountain, "mountain"},
      {Fold::kValley, "valley"},
      {Fold::kFlat, "flat"},
  };
};
/// +1 valley, -1 mountain, 0 flat or unassigned: the sign of the fold angle (FOLD's convention).
double fold_sign(Fold fold);

/// What a curve inside the sheet is. A crease folds as its assignment says. A slit is a cut that
/// ends inside the sheet (drawn as an open cut line): its two sides are free. A seam is a straight
/// line that cleaning adds from a crease or slit end inside the sheet to the nearest crease or
/// boundary, so that the curves divide the sheet into patches: the patches are stitched along it
/// and held smooth across it (fold angle zero), so the paper there stays one smooth piece.
enum class CurveKind { kCrease, kSlit, kSeam };

template <>
struct EnumNames<CurveKind> {
  static constexpr const char* noun = "curve kind";
  static constexpr EnumName<CurveKind> rows[] = {
      {CurveKind::kCrease, "crease"},
      {CurveKind::kSlit, "slit"},
      {CurveKind::kSeam, "seam"},
  };
};

struct Crease {
  Polyline2 points;  ///< closed creases do not repeat the first point
  bool closed = false;
  Fold fold = Fold::kUnassigned;
  /// The fold angle the drawing gives, in degrees, 0 to 180 (its direction is `fold`'s); unset
  /// when the drawing gives none.
  std::optional<double> angle;
  std::string id;  ///< the drawn element's id (SVG: its id attribute; FOLD: "edge N" of its first
                   ///< edge), or empty
  std::string origin;  ///< where it was drawn, "FILE:LINE: <path id="c1">", for messages
  std::string layer;   ///< the drawing's layer (group name) that gave the assignment, or empty
  CurveKind kind = CurveKind::kCrease;  ///< slits and seams are flat (fold kFlat)
  /// Same kind, assignment and angle: curves that may be joined into one.
  bool folds_like(const Crease& other) const {
    return kind == other.kind && fold == other.fold && angle == other.angle;
  }
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
  std::vector<Crease> creases;        ///< drawing order
  std::vector<std::string> warnings;  ///< what reading left out, one line each
  /// L = max(width, height) of the sheet: the length all tolerances are relative to.
  double size() const { return std::max(sheet.bbox.width(), sheet.bbox.height()); }
};

}  // namespace sdog
