// Overlay names (layers.h).
#include <gtest/gtest.h>

#include "base/errors.h"
#include "ui/vis/layers.h"
#include "ui/vis/scene.h"

namespace sdog {
namespace {

TEST(Layers, NamesParseAndUnknownOnesListTheKnown) {
  EXPECT_EQ(vis::all_layers().size(), 11u);
  for (vis::Layer l : vis::all_layers()) EXPECT_EQ(vis::parse_layers(vis::layer_name(l)), std::vector<vis::Layer>{l});
  EXPECT_EQ(vis::parse_layers("dog-residual,handles,links"),
            (std::vector<vis::Layer>{vis::Layer::DogResidual, vis::Layer::Handles, vis::Layer::Links}));
  try {
    vis::parse_layers("vertex-types,residual");
    FAIL() << "no exception";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown overlay 'residual'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(vis::known_layers()), std::string::npos) << e.what();
  }
  EXPECT_THROW(vis::parse_layers("bending,patches"), UsageError);  // two colour layers
  EXPECT_THROW(vis::parse_layers("links,links"), UsageError);
  EXPECT_THROW(vis::parse_layers(""), UsageError);
  EXPECT_EQ(vis::parse_view("side-by-side"), vis::View::SideBySide);
  EXPECT_THROW(vis::parse_view("top"), UsageError);
}

}  // namespace
}  // namespace sdog
