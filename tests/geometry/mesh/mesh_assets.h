#pragma once
// A pattern file at one resolution: the parameter of the tests that check meshes on every dataset
// and reference pattern, and its model built once.
#include <cctype>
#include <filesystem>
#include <ostream>
#include <string>

#include <map>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"

namespace sdog::test {

struct MeshAsset {
  std::string path;
  Resolution res;
  friend void PrintTo(const MeshAsset& a, std::ostream* os) { *os << a.path << " " << a.res.str(); }
};

/// A test name for an asset: the file's stem and the resolution, alphanumerics and underscores.
inline std::string asset_name(const MeshAsset& a) {
  std::string name = std::filesystem::path(a.path).stem().string() + "_" + a.res.str();
  for (auto& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

/// The model of an asset, built once per asset and coarse kind and shared by the tests.
inline const DogModel& cached_model(const MeshAsset& a, CoarseKind coarse = CoarseKind::kStandard) {
  static std::map<std::string, DogModel> cache;
  const std::string key = a.path + a.res.str() + enum_name(coarse);
  auto it = cache.find(key);
  if (it == cache.end()) {
    MeshOptions options;
    options.coarse = coarse;
    it = cache.emplace(key, build_dog_model(read_crease_pattern(a.path), a.res, options)).first;
  }
  return it->second;
}

}  // namespace sdog::test
