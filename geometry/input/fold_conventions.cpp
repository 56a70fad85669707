#include "geometry/input/fold_conventions.h"

#include <cmath>
#include <cstdlib>

#include "base/errors.h"
#include "base/text_format.h"

namespace sdog {
namespace {

constexpr double kHalfTurn = 180;

Fold fold_of_attribute(const std::string& value, const std::string& where) {
  if (const std::optional<Fold> fold = find_enum<Fold>(value)) return *fold;
  throw InputError(where + ": data-fold=\"" + value +
                   "\": expected \"mountain\", \"valley\", \"flat\" or \"unassigned\"");
}

double angle_of_attribute(const std::string& value, const std::string& where) {
  char* end = nullptr;
  const double degrees = std::strtod(value.c_str(), &end);
  while (end && (*end == ' ' || *end == '\t')) ++end;
  if (value.empty() || !end || *end != '\0' || !std::isfinite(degrees))
    throw InputError(where + ": data-angle=\"" + value + "\": expected a number of degrees");
  if (degrees < 0 || degrees > kHalfTurn)
    throw InputError(where + ": data-angle=\"" + value +
                     "\": the fold angle must be from 0 to 180 degrees (its direction is the "
                     "crease's assignment: data-fold, the colour or the dashes)");
  return degrees;
}

}  // namespace

CurveReading read_curve(const SvgCurve& curve, const std::string& where) {
  CurveReading reading;
  // 2. and 4.: the colour.
  const std::string& c = curve.colour;
  if (c == "#000000")
    reading.role = CurveRole::kBoundary;
  else if (c == "#ff0000")
    reading.fold = Fold::kMountain;
  else if (c == "#0000ff")
    reading.fold = Fold::kValley;
  else if (c == "#00ff00" || c == "#008000")
    reading.role = CurveRole::kCut;
  else if (c == "#ffff00")
    reading.role = CurveRole::kFacet;
  const bool simulator_colour = c == "#ff0000" || c == "#0000ff" || c == "#ff00ff";
  if ((c == "#ff0000" || c == "#0000ff") && curve.opacity)
    reading.angle = *curve.opacity * kHalfTurn;
  // 3.: dashes, on black and on colours without a meaning of their own.
  if (curve.dashed && !simulator_colour &&
      (reading.role == CurveRole::kBoundary || reading.role == CurveRole::kCrease)) {
    reading.role = CurveRole::kCrease;
    reading.fold = curve.dash_dot ? Fold::kMountain : Fold::kValley;
  }
  // 1.: this project's attributes.
  if (curve.data_fold || curve.data_angle) reading.role = CurveRole::kCrease;
  if (curve.data_fold) {
    reading.fold = fold_of_attribute(*curve.data_fold, where);
    if (reading.fold != Fold::kMountain && reading.fold != Fold::kValley) reading.angle.reset();
  }
  if (curve.data_angle) {
    reading.angle = angle_of_attribute(*curve.data_angle, where);
    if (reading.fold == Fold::kFlat && *reading.angle != 0)
      throw InputError(where + ": data-angle=\"" + *curve.data_angle +
                       "\" on a flat crease; a flat crease does not fold");
  }
  if (reading.fold == Fold::kFlat) reading.angle = 0;
  return reading;
}

}  // namespace sdog
