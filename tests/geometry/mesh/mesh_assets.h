#pragma once
// A pattern file at one resolution: the parameter of the tests that check meshes on every dataset
// and reference pattern.
#include <cctype>
#include <filesystem>
#include <ostream>
#include <string>

#include "geometry/mesh/grid.h"

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

}  // namespace sdog::test
