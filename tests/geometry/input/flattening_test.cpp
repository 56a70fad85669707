// The mesh must not depend on how finely curves are flattened.
#include <gtest/gtest.h>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

void expect_same_mesh(const std::string& path, Resolution res) {
  SvgReadOptions coarse_flat, fine_flat;
  coarse_flat.flatness = 1e-5;  // the default
  fine_flat.flatness = 1e-8;
  const DogModel a = build_dog_model(read_crease_pattern(path, coarse_flat), res);
  const DogModel b = build_dog_model(read_crease_pattern(path, fine_flat), res);
  EXPECT_EQ(a.fine.vertex_count(), b.fine.vertex_count()) << path;
  EXPECT_EQ(a.fine.quad_count(), b.fine.quad_count()) << path;
  EXPECT_EQ(a.fine.stitching.points.size(), b.fine.stitching.points.size()) << path;
  EXPECT_EQ(a.coarse.vertex_count(), b.coarse.vertex_count()) << path;
  EXPECT_EQ(a.map.coarse_only_count, b.map.coarse_only_count) << path;
  if (a.fine.vertex_count() == b.fine.vertex_count()) {
    EXPECT_TRUE(a.fine.grid == b.fine.grid) << path;
  }
}

TEST(Flattening, DatasetsMeshTheSameAtAnyFlatness) {
  for (const auto& p : test::all_datasets())
    for (Resolution r : {Resolution{21, 21}, Resolution{41, 41}, Resolution{61, 45}})
      expect_same_mesh(p, r);
}

TEST(Flattening, ThesisPatternsMeshTheSameAtAnyFlatness) {
  SDOG_REQUIRE_SHARED();
  const std::string dir = test::reference_patterns_dir();
  for (const char* name : {"1_curve", "4_corners", "valley", "parallel_curves_4"})
    expect_same_mesh(dir + "/" + name + ".svg", {61, 61});
}

}  // namespace
}  // namespace sdog
