#include "geometry/input/fold_conventions.h"

#include <cctype>
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

std::string lower_case(std::string text) {
  for (char& ch : text) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return text;
}

}  // namespace

std::optional<CurveReading> layer_meaning(const std::string& group_name) {
  static const std::pair<const char*, CurveReading> kWords[] = {
      {"mountain", {CurveRole::kCrease, Fold::kMountain, std::nullopt, ""}},
      {"valley", {CurveRole::kCrease, Fold::kValley, std::nullopt, ""}},
      {"cut", {CurveRole::kCut, Fold::kUnassigned, std::nullopt, ""}},
      {"boundary", {CurveRole::kBoundary, Fold::kUnassigned, std::nullopt, ""}},
      {"outline", {CurveRole::kBoundary, Fold::kUnassigned, std::nullopt, ""}},
  };
  const std::string name = lower_case(group_name);
  std::optional<CurveReading> meaning;
  for (const auto& [word, reading] : kWords) {
    if (name.find(word) == std::string::npos) continue;
    if (meaning) return std::nullopt;
    meaning = reading;
    meaning->layer = group_name;
  }
  return meaning;
}

CurveReading read_curve(const SvgCurve& curve, const std::string& where) {
  CurveReading reading;
  // 3. and 5.: the colour.
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
  // 4.: dashes, on black and on colours without a meaning of their own.
  if (curve.dashed && !simulator_colour &&
      (reading.role == CurveRole::kBoundary || reading.role == CurveRole::kCrease)) {
    reading.role = CurveRole::kCrease;
    reading.fold = curve.dash_dot ? Fold::kMountain : Fold::kValley;
  }
  // 2.: the nearest group whose name gives a meaning.
  for (auto it = curve.groups.rbegin(); it != curve.groups.rend(); ++it) {
    const std::optional<CurveReading> layer = layer_meaning(*it);
    if (!layer) continue;
    const bool same_fold = reading.role == CurveRole::kCrease && reading.fold == layer->fold;
    const std::optional<double> angle = reading.angle;
    reading = *layer;
    if (same_fold) reading.angle = angle;
    break;
  }
  // 1.: this project's attributes.
  if (curve.data_fold || curve.data_angle) reading.role = CurveRole::kCrease;
  if (curve.data_fold) {
    reading.fold = fold_of_attribute(*curve.data_fold, where);
    reading.layer.clear();
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
