// The run configuration as JSON: the option tables drive reading, checking and writing, every key
// round-trips through run.json, and every error names the file and the JSON path.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "base/errors.h"
#include "base/json_field.h"
#include "solver/config/option_json.h"
#include "solver/config/run_config_json.h"

namespace sdog {
namespace {

using nlohmann::json;

// A valid value other than `current` for an option (twice the default, or the next choice).
template <class S>
double other_value(const Option<S>& o, const std::optional<double>& current) {
  switch (o.type) {
    case OptionType::kBoolean:
      return *current == 0 ? 1 : 0;
    case OptionType::kChoice:
      return std::fmod(*current + 1, static_cast<double>(o.choices.size()));
    case OptionType::kInteger:
      return *current > 0 ? 2 * *current : *current + 1;
    case OptionType::kReal:
      break;
  }
  if (!current) return 1.5;
  const double v = *current != 0 ? 2 * *current : *current + 1;
  return o.bounds.contains(v) ? v : 0.5 * (o.bounds.min + o.bounds.max);
}

// Every option of the table gets another value; returns how many were changed.
template <class S>
int change_every_option(const OptionTable<S>& table, S& s) {
  for (const Option<S>& o : table) {
    const double v = other_value(o, o.get(s));
    EXPECT_TRUE(o.bounds.contains(v)) << o.key << " " << v;
    o.set(s, v);
  }
  return static_cast<int>(table.size());
}

// Every option's value, as "section.key" and value.
std::vector<std::pair<std::string, std::optional<double>>> option_values(const RunConfig& c) {
  std::vector<std::pair<std::string, std::optional<double>>> out;
  for (const auto& o : run_option_table()) out.push_back({o.key, o.get(c)});
  for_each_option_section(c, [&](const char* section, const auto& options, const auto& table) {
    for (const auto& o : table) out.push_back({std::string(section) + "." + o.key, o.get(options)});
  });
  return out;
}

TEST(RunConfigJson, EveryKeyRoundTripsThroughRunJson) {
  RunConfig changed;
  int keys = change_every_option(run_option_table(), changed);
  for_each_option_section(changed, [&](const char*, auto& options, const auto& table) {
    keys += change_every_option(table, options);
  });
  EXPECT_GT(keys, 50);
  validate_run_config(changed, "test");  // the changed values are valid ones

  const json written = to_json(changed);
  RunConfig read;
  apply_run_config(json::parse(written.dump()), "run.json", read);
  EXPECT_EQ(option_values(read), option_values(changed));
  // Every value differs from its default, so the comparison above could fail.
  const auto defaults = option_values(RunConfig());
  const auto values = option_values(changed);
  for (size_t i = 0; i < values.size(); ++i)
    EXPECT_NE(values[i].second, defaults[i].second) << values[i].first;
}

TEST(RunConfigJson, ListsOfConstraintsAndSwitchesRoundTrip) {
  const json j = json::parse(R"({
    "positions": [{"vertex": 3, "move": [0, 0, 1]}, {"near": [1.5, -2], "start": [0, 0, 0], "end": [1, 2, 3]}],
    "angles": [{"curve": 1, "end": 60}, {"crease_point": 7, "start": -10, "end": -45}, {"id": "c2", "end": 30}],
    "creases": [{"id": "c2", "fold": "valley", "angle": 40}, {"curve": 0, "fold": "flat"}, {"curve": 1, "angle": 15}],
    "switches": [{"iteration": 5, "mode": "twolevel"}, {"iteration": 9, "mode": "standard"}]})");
  RunConfig c;
  apply_run_config(j, "c.json", c);
  ASSERT_EQ(c.positions.size(), 2u);
  EXPECT_EQ(*c.positions[0].vertex, 3);
  EXPECT_EQ(*c.positions[1].end, Eigen::Vector3d(1, 2, 3));
  ASSERT_EQ(c.angles.size(), 3u);
  EXPECT_EQ(*c.angles[1].point, 7);
  EXPECT_EQ(c.angles[1].start_degrees, -10);
  EXPECT_EQ(*c.angles[2].id, "c2");
  ASSERT_EQ(c.creases.size(), 3u);
  EXPECT_EQ(*c.creases[0].id, "c2");
  EXPECT_EQ(*c.creases[0].fold, Fold::kValley);
  EXPECT_EQ(*c.creases[0].angle, 40);
  EXPECT_EQ(*c.creases[1].fold, Fold::kFlat);
  EXPECT_FALSE(c.creases[2].fold);
  ASSERT_EQ(c.switches.size(), 2u);
  EXPECT_EQ(c.switches[0].mode, ModeKind::kTwoLevel);
  RunConfig again;
  apply_run_config(to_json(c), "run.json", again);
  EXPECT_EQ(to_json(again), to_json(c));
}

// "preset" sets its options first; the keys of the file then change what it set.
TEST(RunConfigJson, ThePresetIsAppliedBeforeTheOtherKeys) {
  RunConfig c;
  apply_run_config(json::parse(R"({"preset": "thesis", "solver": {"polish_factorizations": 7}})"),
                   "c.json", c);
  EXPECT_EQ(c.preset, Preset::kThesis);
  EXPECT_EQ(c.standard.stitching, Stitching::kSoft);
  EXPECT_EQ(c.standard.sqp.polish_factorizations, 7);
  EXPECT_FALSE(c.standard.converge);
  EXPECT_EQ(c.standard.max_fold_bias, 1e14);        // the reference's escalation, up to 10^14
  EXPECT_EQ(c.standard.sqp.projection_steps, 100);  // its unbudgeted last iteration as before
  RunConfig d;
  apply_run_config(json::parse(R"({"preset": "default"})"), "d.json", d);
  EXPECT_EQ(d.standard.stitching, Stitching::kExact);
  EXPECT_TRUE(d.standard.converge);
  EXPECT_EQ(d.standard.max_fold_bias, 1e6);
  EXPECT_EQ(d.standard.sqp.polish_factorizations, SqpOptions().polish_factorizations);
  EXPECT_EQ(d.standard.sqp.projection_steps, 400);
  RunConfig e;
  EXPECT_THROW(apply_run_config(json::parse(R"({"preset": "warp"})"), "e.json", e), InputError);
}

TEST(RunConfigJson, TheDefaultProximalWeightDependsOnThePatchCount) {
  RunConfig config;
  EXPECT_DOUBLE_EQ(config.admm.proximal_weight(4), 0.003);
  EXPECT_DOUBLE_EQ(config.admm.proximal_weight(11), 0.01);
  apply_run_config(json::parse(R"({"admm": {"p": 0.25}})"), "c.json", config);
  EXPECT_DOUBLE_EQ(config.admm.proximal_weight(4), 0.25);
  // Unset, it stays unset when read back.
  RunConfig unset, read;
  apply_run_config(to_json(unset), "run.json", read);
  EXPECT_DOUBLE_EQ(read.admm.proximal_weight(4), 0.003);
}

TEST(RunConfigJson, BadValuesNameTheFileAndTheJsonPath) {
  const std::pair<const char*, const char*> cases[] = {
      {R"({"admm": {"rho": -1}})", "c.json: $.admm.rho: expected a number > 0, got -1"},
      {R"({"admm": {"gamma": 0}})", "c.json: $.admm.gamma"},
      {R"({"admm": {"p": -0.5}})", "c.json: $.admm.p: expected a number >= 0"},
      {R"({"admm": {"inner": 0}})", "c.json: $.admm.inner: expected an integer >= 1, got 0"},
      {R"({"admm": {"sigma": 1}})",
       "c.json: $.admm.sigma: unknown key (known: rho, gamma, p, inner)"},
      {R"({"solver": {"armijo": 0.5}})", "c.json: $.solver.armijo: expected a number in (0, 0.5)"},
      {R"({"solver": {"max_steps": 1.5}})", "c.json: $.solver.max_steps: expected an integer"},
      {R"({"solver": {"folding": 1}})", "c.json: $.solver.folding: expected true or false"},
      {R"({"patch_solver": {"backend": "lapack"}})",
       "c.json: $.patch_solver.backend: expected one of sqp, ceres"},
      {R"({"weights": {"bending": -2}})", "c.json: $.weights.bending: expected a number >= 0"},
      {R"({"scenario": "twist"})",
       "c.json: $.scenario: expected one of corners, fold, none, flatten"},
      {R"({"angle": 200})", "c.json: $.angle: expected a number in [-180, 180]"},
      {R"({"positions": [{"vertex": 1}]})", "c.json: $.positions[0]: give exactly one of \"end\""},
      {R"({"positions": [{"vertex": 1, "end": [1, 2]}]})",
       "c.json: $.positions[0].end: expected an array of 3"},
      {R"({"switches": [{"iteration": 2, "mode": "fast"}]})",
       "c.json: $.switches[0].mode: unknown mode"},
      {R"({"angles": [{"curve": 1, "id": "a", "end": 3}]})",
       "c.json: $.angles[0]: give exactly one of"},
      {R"({"creases": [{"id": "a", "fold": "hill"}]})",
       "c.json: $.creases[0].fold: unknown assignment \"hill\""},
      {R"({"creases": [{"id": "a"}]})", "c.json: $.creases[0]: give \"fold\""},
      {R"({"creases": [{"curve": 2, "angle": -5}]})",
       "c.json: $.creases[0].angle: the fold angle must be from 0 to 180"},
      {R"({"creases": [{"fold": "valley"}]})",
       "c.json: $.creases[0]: give exactly one of \"curve\""},
      {R"({"iterations": 0, "hold": 0})", "c.json: iterations + hold must be at least 1"},
      {R"([1, 2])", "c.json: $: expected an object"}};
  for (const auto& [text, message] : cases) {
    RunConfig config;
    try {
      apply_run_config(json::parse(text), "c.json", config);
      ADD_FAILURE() << text << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << text << ": " << e.what();
    }
  }
}

TEST(RunConfigJson, ValuesSetInCodeAreCheckedByTheSameBounds) {
  RunConfig config;
  config.admm.rho = 0;
  try {
    validate_run_config(config, "c.json");
    ADD_FAILURE() << "rho 0 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("c.json: $.admm.rho must be positive"), std::string::npos)
        << e.what();
  }
  config = RunConfig();
  config.standard.sqp.rho_max = 10;  // below 1/epsilon
  EXPECT_NE(config.standard.validate().find("rho_max must be at least 1/epsilon"),
            std::string::npos);
  config = RunConfig();
  config.subsolvers.patch.max_penalty = 1;  // below the initial penalty
  EXPECT_NE(config.subsolvers.validate().find("max_penalty"), std::string::npos);
}

}  // namespace
}  // namespace sdog
