#include "geometry/input/pattern_file.h"

#include <cctype>
#include <filesystem>

#include "geometry/input/fold_reader.h"
#include "geometry/input/svg_pattern.h"

namespace sdog {

CreasePattern read_crease_pattern(const std::string& path, const SvgReadOptions& options) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".fold") return read_fold_file(path);
  return crease_pattern_from_svg(read_svg_file(path, options));
}

}  // namespace sdog
