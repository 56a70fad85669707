// Overlay names (layers.h).
#include <gtest/gtest.h>

#include "base/errors.h"
#include "ui/vis/layers.h"
#include "ui/vis/scene.h"

namespace sdog {
namespace {

TEST(Layers, NamesParseAndUnknownOnesListTheKnown) {
  EXPECT_EQ(enum_values<vis::Layer>().size(), 11u);
  for (vis::Layer l : enum_values<vis::Layer>())
    EXPECT_EQ(vis::parse_layers(enum_name(l)), std::vector<vis::Layer>{l});
  EXPECT_EQ(vis::parse_layers("dog-residual,handles,links"),
            (std::vector<vis::Layer>{vis::Layer::kDogResidual, vis::Layer::kHandles,
                                     vis::Layer::kLinks}));
  try {
    vis::parse_layers("vertex-types,residual");
    FAIL() << "no exception";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown overlay 'residual'"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find(known_names<vis::Layer>()), std::string::npos) << e.what();
  }
  EXPECT_THROW(vis::parse_layers("bending,patches"), UsageError);  // two colour layers
  EXPECT_THROW(vis::parse_layers("links,links"), UsageError);
  EXPECT_THROW(vis::parse_layers(""), UsageError);
  EXPECT_EQ(parse_enum<vis::View>("side-by-side"), vis::View::kSideBySide);
  EXPECT_THROW(parse_enum<vis::View>("top"), UsageError);
}

}  // namespace
}  // namespace sdog
