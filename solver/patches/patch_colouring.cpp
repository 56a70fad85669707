#include "solver/patches/patch_colouring.h"

#include <set>

namespace sdog {

std::vector<int> colour_patches(const DogMesh& mesh) {
  const int n = mesh.patch_count();
  std::vector<std::set<int>> neighbours(n);
  for (const auto& pair : mesh.stitching.pairs) {
    const auto& copies = mesh.stitching.points[pair.point].copies;
    const int a = mesh.vertex_patch[copies[pair.a].v1], b = mesh.vertex_patch[copies[pair.b].v1];
    if (a == b) continue;
    neighbours[a].insert(b);
    neighbours[b].insert(a);
  }
  std::vector<int> colour(n, -1);
  for (int p = 0; p < n; ++p) {
    std::set<int> taken;
    for (int q : neighbours[p])
      if (colour[q] >= 0) taken.insert(colour[q]);
    int c = 0;
    while (taken.count(c)) ++c;
    colour[p] = c;
  }
  return colour;
}

}  // namespace sdog
