#include "solver/run/crease_settings.h"

#include "base/errors.h"

namespace sdog {

std::vector<int> named_creases(const DogMesh& mesh, const std::optional<int>& curve,
                               const std::optional<std::string>& id, const std::string& path) {
  const auto& curves = mesh.stitching.curves;
  if (curve) {
    if (*curve < 0 || *curve >= static_cast<int>(curves.size()))
      throw InputError(path + ".curve: the pattern has " + std::to_string(curves.size()) +
                       " creases (after cleaning; sdog mesh lists them), there is no crease " +
                       std::to_string(*curve));
    return {*curve};
  }
  std::vector<int> found;
  for (int k = 0; k < static_cast<int>(curves.size()); ++k)
    if (curves[k].id == *id) found.push_back(k);
  if (found.empty())
    throw InputError(path + ".id: no crease of the pattern was drawn by an element with id \"" +
                     *id + "\" (sdog mesh lists the creases with their elements)");
  return found;
}

void check_foldable(const DogMesh& mesh, int k, const std::string& path) {
  const CurveKind kind = mesh.stitching.curves[k].kind;
  if (kind == CurveKind::kCrease) return;
  throw InputError(path + ": crease " + std::to_string(k) + " is a " + enum_name(kind) +
                   (kind == CurveKind::kSlit
                        ? ", a cut that does not fold"
                        : ", the smooth continuation of an end inside the sheet, which does not "
                          "fold"));
}

void apply_crease_settings(const std::vector<CreaseSetting>& settings, DogModel& model) {
  for (const CreaseSetting& s : settings) {
    for (const int k : named_creases(model.fine, s.curve, s.id, s.path)) {
      Crease& crease = model.clean.creases[k];
      check_foldable(model.fine, k, s.path);
      if (s.fold) {
        crease.fold = *s.fold;
        if (crease.fold != Fold::kMountain && crease.fold != Fold::kValley) crease.angle.reset();
      }
      if (s.angle) crease.angle = *s.angle;
      if (crease.fold == Fold::kFlat) crease.angle = 0;
      for (DogMesh* mesh : {&model.fine, &model.coarse}) {
        if (k >= static_cast<int>(mesh->stitching.curves.size())) continue;
        mesh->stitching.curves[k].fold = crease.fold;
        mesh->stitching.curves[k].angle = crease.angle;
      }
    }
  }
}

}  // namespace sdog
