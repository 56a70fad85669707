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

// The pleats as editors export them: every stroke black with the meaning in its layer
// (Illustrator's group ids, or Inkscape's layer labels), the sheet outline drawn as short lines
// whose ends overlap by a hair, and each crease as short pieces (0.5 units, half the distance
// within which crease ends merge).
std::string exported_pleats_svg(bool inkscape) {
  auto layer = [&](const std::string& name) {
    return inkscape ? "<g inkscape:groupmode=\"layer\" id=\"layer" + std::to_string(name.size()) +
                          "\" inkscape:label=\"" + name + "\">"
                    : "<g id=\"" + name + "\">";
  };
  auto line = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const char* extra) {
    return "<line x1=\"" + std::to_string(a.x()) + "\" y1=\"" + std::to_string(a.y()) + "\" x2=\"" +
           std::to_string(b.x()) + "\" y2=\"" + std::to_string(b.y()) + "\" fill=\"none\" " +
           "stroke=\"#000000\"" + extra + "/>";
  };
  std::string svg =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" "
      "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" viewBox=\"0 0 100 100\">" +
      layer(inkscape ? "Outline" : "CutLine");
  const Eigen::Vector2d corners[] = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  for (int c = 0; c < 4; ++c)
    for (int half = 0; half < 2; ++half) {
      const Eigen::Vector2d a = corners[c], b = corners[(c + 1) % 4];
      const Eigen::Vector2d hair = 0.01 * (b - a).normalized();
      svg += line(a + 0.5 * half * (b - a) - (half ? hair : Eigen::Vector2d::Zero()),
                  a + 0.5 * (half + 1) * (b - a), "");
    }
  const double xs[] = {25, 50, 75};
  for (int k = 0; k < 3; ++k) {
    svg += std::string("</g>") + layer(k == 1 ? "ValleyLine" : "Mountain_Fold");
    for (int i = 0; i < 200; ++i) {
      auto at = [&](int j) {
        const double y = 0.5 * j;
        return Eigen::Vector2d(xs[k] + 5 * (y <= 50 ? y : 100 - y) / 50, y);
      };
      svg += line(at(i), at(i + 1), k == 1 ? " stroke-dasharray=\"4,3\"" : "");
    }
  }
  return svg + "</g></svg>";
}

TEST(FoldedAsDrawn, LayersAndPiecesAsEditorsExportThemGiveTheSameFold) {
  const DogModel colours = model_of(pleats_svg(
      [](int k) { return std::string(k == 1 ? "stroke=\"#0000ff\"" : "stroke=\"#ff0000\""); }));
  const Dofs x = folded(colours, fold_config());
  for (const bool inkscape : {false, true}) {
    const DogModel exported = model_of(exported_pleats_svg(inkscape));
    ASSERT_EQ(exported.clean.creases.size(), 3u) << inkscape;
    ASSERT_EQ(exported.fine.V.rows(), colours.fine.V.rows()) << inkscape;
    EXPECT_LT((exported.fine.V - colours.fine.V).cwiseAbs().maxCoeff(), 1e-9) << inkscape;
    EXPECT_TRUE(exported.fine.F == colours.fine.F) << inkscape;
    for (size_t k = 0; k < 3; ++k)
      EXPECT_EQ(exported.fine.stitching.curves[k].fold, colours.fine.stitching.curves[k].fold);
    EXPECT_EQ(exported.clean.creases[1].layer, "ValleyLine");
    EXPECT_LT((folded(exported, fold_config()) - x).cwiseAbs().maxCoeff(), 1e-6) << inkscape;
  }
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
