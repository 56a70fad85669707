#include "ui/studio/model_loader.h"

#include "geometry/input/pattern_file.h"
#include "geometry/pattern/crease_pattern.h"

namespace sdog::studio {

std::shared_ptr<const DogModel> load_model(const std::string& pattern_path,
                                           const std::string& resolution) {
  const CreasePattern pattern = read_crease_pattern(pattern_path);
  const Resolution res =
      resolve_resolution(resolution, pattern.sheet.bbox.width(), pattern.sheet.bbox.height());
  MeshOptions options;
  options.build_coarse = res.nx % 2 == 1 && res.ny % 2 == 1;
  check_resolution(res, options.build_coarse);
  return std::make_shared<const DogModel>(build_dog_model(pattern, res, options));
}

}  // namespace sdog::studio
