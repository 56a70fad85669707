// One crease pattern written in each of the drawing conventions (fold_conventions.h) and as a FOLD
// file gives the same creases, mesh and fold; the configuration overrides assignments by crease id.
#include <gtest/gtest.h>

#include "base/errors.h"
#include "geometry/input/fold_reader.h"
#include "geometry/input/svg_pattern.h"
#include "geometry/input/svg_reader.h"
#include "geometry/mesh/dog_model.h"
#include "solver/problem/crease_angles.h"
#include "solver/run/crease_settings.h"
#include "solver/run/run_setup.h"

namespace sdog {
namespace {

// Three pleats across a 100 x 100 sheet, polylines, mountain - valley - mountain; `style(k)` gives
// the attributes that draw crease k's assignment.
template <class Style>
std::string pleats_svg(Style style) {
  std::string svg =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 100 100\">"
      "<rect x=\"0\" y=\"0\" width=\"100\" height=\"100\" fill=\"none\" stroke=\"#000000\"/>";
  const char* lines[] = {"25,0 30,50 25,100", "50,0 55,50 50,100", "75,0 80,50 75,100"};
  for (int k = 0; k < 3; ++k)
    svg += "<polyline id=\"p" + std::to_string(k) + "\" points=\"" + lines[k] +
           "\" fill=\"none\" " + style(k) + "/>";
  return svg + "</svg>";
}

DogModel model_of(const std::string& svg) {
  return build_dog_model(crease_pattern_from_svg(parse_svg(svg, "pleats.svg")), {21, 21});
}

// The same pleats as a FOLD crease pattern (FOLD's y points down the page, as SVG's does).
const char* const kPleatsFold = R"({
  "frame_classes": ["creasePattern"],
  "vertices_coords": [[0, 0], [100, 0], [100, 100], [0, 100],
                      [25, 0], [30, 50], [25, 100], [50, 0], [55, 50], [50, 100], [75, 0], [80, 50], [75, 100]],
  "edges_vertices": [[0, 4], [4, 7], [7, 10], [10, 1], [1, 2], [2, 12], [12, 9], [9, 6], [6, 3], [3, 0],
                     [4, 5], [5, 6], [7, 8], [8, 9], [10, 11], [11, 12]],
  "edges_assignment": ["B", "B", "B", "B", "B", "B", "B", "B", "B", "B", "M", "M", "V", "V", "M", "M"]
})";

Dofs folded(const DogModel& model, const RunConfig& config) {
  RunSetup setup(model, ModeKind::kStandard, config);
  EXPECT_EQ(setup.run({}).termination, Termination::kCompleted);
  return setup.positions();
}

RunConfig fold_config() {
  RunConfig config;
  config.scenario = ScenarioKind::kFold;
  config.fold_angle = 50;
  config.iterations = 15;
  config.hold = 5;
  return config;
}

TEST(FoldedAsDrawn, ColoursDashesAndAttributesGiveTheSameFold) {
  const DogModel colours = model_of(pleats_svg(
      [](int k) { return std::string(k == 1 ? "stroke=\"#0000ff\"" : "stroke=\"#ff0000\""); }));
  const DogModel dashes = model_of(pleats_svg([](int k) {
    return std::string(k == 1 ? "stroke=\"#222222\" stroke-dasharray=\"4 3\""
                              : "stroke=\"#222222\" stroke-dasharray=\"8 2 1 2\"");
  }));
  const DogModel attributes = model_of(pleats_svg([](int k) {
    return std::string(k == 1 ? "stroke=\"#888888\" data-fold=\"valley\""
                              : "stroke=\"#888888\" data-fold=\"mountain\"");
  }));
  const DogModel fold_file = build_dog_model(parse_fold(kPleatsFold, "pleats.fold"), {21, 21});
  ASSERT_EQ(colours.fine.stitching.curves.size(), 3u);
  for (const DogModel* other : {&dashes, &attributes, &fold_file}) {
    EXPECT_TRUE(other->fine.V == colours.fine.V);
    EXPECT_TRUE(other->fine.F == colours.fine.F);
    for (size_t k = 0; k < 3; ++k) {
      EXPECT_EQ(other->fine.stitching.curves[k].fold, colours.fine.stitching.curves[k].fold);
      EXPECT_EQ(other->fine.stitching.curves[k].points, colours.fine.stitching.curves[k].points);
    }
  }
  EXPECT_EQ(colours.fine.stitching.curves[0].fold, Fold::kMountain);
  EXPECT_EQ(colours.fine.stitching.curves[1].fold, Fold::kValley);
  const Dofs x = folded(colours, fold_config());
  EXPECT_TRUE(folded(dashes, fold_config()) == x);
  EXPECT_TRUE(folded(attributes, fold_config()) == x);
  EXPECT_TRUE(folded(fold_file, fold_config()) == x);
  // The pleats: each fold site's angle has its crease's sign.
  const FoldAngles angles(colours.fine);
  for (size_t k = 0; k < angles.sites().size(); ++k)
    EXPECT_GT(
        angles.at(k, x) * fold_sign(colours.fine.stitching.curves[angles.sites()[k].curve].fold),
        10)
        << k;
}

TEST(FoldedAsDrawn, TheConfigurationSetsAssignmentAndAngleByIdOrIndex) {
  DogModel model = model_of(pleats_svg([](int) { return std::string("stroke=\"#ff00ff\""); }));
  RunConfig config = fold_config();
  CreaseSetting by_id;
  by_id.path = "$.creases[0]";
  by_id.id = "p1";
  by_id.fold = Fold::kValley;
  by_id.angle = 30;
  CreaseSetting by_index;
  by_index.path = "$.creases[1]";
  by_index.curve = 2;
  by_index.fold = Fold::kFlat;
  config.creases = {by_id, by_index};
  config.fold_angle = -60;  // the unassigned crease 0 folds as a mountain
  apply_crease_settings(config.creases, model);
  EXPECT_EQ(model.fine.stitching.curves[1].fold, Fold::kValley);
  EXPECT_EQ(model.coarse.stitching.curves[1].fold, Fold::kValley);
  EXPECT_EQ(model.clean.creases[2].fold, Fold::kFlat);
  const Dofs x = folded(model, config);
  const FoldAngles angles(model.fine);
  for (size_t k = 0; k < angles.sites().size(); ++k) {
    // Crease 0 unassigned, a mountain by --angle; crease 1 a 30-degree valley; crease 2 flat.
    const double expected[] = {-60, 30, 0};
    EXPECT_NEAR(angles.at(k, x), expected[angles.sites()[k].curve], 4) << k;
  }
  CreaseSetting missing;
  missing.path = "$.creases[2]";
  missing.id = "nope";
  try {
    apply_crease_settings({missing}, model);
    FAIL() << "no error for an unknown id";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("$.creases[2].id: no crease"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace sdog
