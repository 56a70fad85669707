#include "geometry/pattern/crease_pattern.h"

namespace sdog {

const char* fold_name(Fold fold) {
  switch (fold) {
    case Fold::kMountain:
      return "mountain";
    case Fold::kValley:
      return "valley";
    case Fold::kFlat:
      return "flat";
    case Fold::kUnassigned:
      break;
  }
  return "unassigned";
}

std::optional<Fold> find_fold(const std::string& name) {
  for (const Fold fold : {Fold::kUnassigned, Fold::kMountain, Fold::kValley, Fold::kFlat})
    if (name == fold_name(fold)) return fold;
  return std::nullopt;
}

double fold_sign(Fold fold) { return fold == Fold::kValley ? 1.0 : fold == Fold::kMountain ? -1.0 : 0.0; }

}  // namespace sdog
