// The paper style's render effects as the command line spells them.
#include "ui/vis/paper_style.h"

#include <gtest/gtest.h>

#include "base/errors.h"

namespace sdog {
namespace {

TEST(PaperStyle, EffectsParseOneAtATime) {
  const vis::PaperEffects occlusion = vis::parse_paper_effects("ambient-occlusion");
  EXPECT_TRUE(occlusion.ambient_occlusion);
  EXPECT_FALSE(occlusion.shadows);
  const vis::PaperEffects shadows = vis::parse_paper_effects("shadows");
  EXPECT_FALSE(shadows.ambient_occlusion);
  EXPECT_TRUE(shadows.shadows);
  const vis::PaperEffects none = vis::parse_paper_effects("none");
  EXPECT_FALSE(none.ambient_occlusion || none.shadows);
  try {
    vis::parse_paper_effects("ambient-occlusion,shadows");
    FAIL() << "no exception";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("not both"), std::string::npos) << e.what();
  }
  try {
    vis::parse_paper_effects("glow");
    FAIL() << "no exception";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown render effect 'glow'"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace sdog
