#include "ui/studio/model_loader.h"

#include "geometry/crease_pattern.h"

namespace sdog::studio {

std::shared_ptr<const DogModel> load_model(const std::string& pattern_path, const std::string& resolution) {
  const Resolution res = parse_resolution(resolution);
  MeshOptions options;
  options.build_coarse = res.nx % 2 == 1 && res.ny % 2 == 1;
  check_resolution(res, options.build_coarse);
  return std::make_shared<const DogModel>(build_dog_model(read_crease_pattern(pattern_path), res, options));
}

}  // namespace sdog::studio
