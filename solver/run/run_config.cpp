#include "solver/run/run_config.h"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include "base/errors.h"
#include "base/text_format.h"
#include "solver/run/flatten_scenario.h"
#include "solver/config/json_field.h"

namespace sdog {
namespace {

using nlohmann::json;

void apply_weights(const Field& f, Weights& w) {
  f.expect_object({"bending", "isometry", "stitching", "positions", "edge_points", "angles", "fold_bias", "link"});
  const std::pair<const char*, double*> all[] = {{"bending", &w.bending},       {"isometry", &w.isometry},
                                                 {"stitching", &w.stitching},   {"positions", &w.positions},
                                                 {"edge_points", &w.edge_points}, {"angles", &w.angles},
                                                 {"fold_bias", &w.fold_bias},   {"link", &w.link}};
  for (const auto& [key, target] : all)
    if (f.has(key)) *target = f[key].non_negative();
}

void apply_solver(const Field& f, StandardOptions& o) {
  f.expect_object({"kkt_tolerance", "max_steps", "epsilon", "restoration_epsilon", "polish_epsilon", "merit_penalty",
                   "trusted_backtracks", "constraint_tolerance", "final_constraint_tolerance",
                   "max_restoration_steps", "polish_steps", "local_rings", "local_fraction", "armijo",
                   "max_backtracks", "regularization", "rho_max", "second_order_correction",
                   "lagrangian_hessian", "folding", "max_fold_bias"});
  SqpOptions& s = o.sqp;
  const std::pair<const char*, double*> positive[] = {
      {"kkt_tolerance", &s.kkt_tolerance},     {"epsilon", &s.epsilon},
      {"restoration_epsilon", &s.restoration_epsilon}, {"polish_epsilon", &s.polish_epsilon},
      {"merit_penalty", &s.merit_penalty},
      {"constraint_tolerance", &s.constraint_tolerance},
      {"final_constraint_tolerance", &s.final_constraint_tolerance},
      {"armijo", &s.armijo},                   {"rho_max", &s.rho_max},
      {"max_fold_bias", &o.max_fold_bias}};
  for (const auto& [key, target] : positive)
    if (f.has(key)) *target = f[key].positive();
  const std::pair<const char*, int*> counts[] = {{"max_steps", &s.max_steps},
                                                 {"trusted_backtracks", &s.trusted_backtracks},
                                                 {"max_restoration_steps", &s.max_restoration_steps},
                                                 {"polish_steps", &s.polish_steps},
                                                 {"local_rings", &s.local_rings},
                                                 {"max_backtracks", &s.max_backtracks}};
  for (const auto& [key, target] : counts)
    if (f.has(key)) *target = f[key].integer(0);
  if (f.has("local_fraction")) s.local_fraction = f["local_fraction"].non_negative();
  if (f.has("regularization")) s.regularization = f["regularization"].non_negative();
  if (f.has("second_order_correction")) s.second_order_correction = f["second_order_correction"].boolean();
  if (f.has("lagrangian_hessian")) s.lagrangian_hessian = f["lagrangian_hessian"].boolean();
  if (f.has("folding")) o.folding = f["folding"].boolean();
}

void apply_patch_solver(const Field& f, SubsolverOptions& o) {
  f.expect_object({"backend", "sweep", "constraint_tolerance", "final_constraint_tolerance", "initial_penalty",
                   "penalty_growth", "max_penalty", "max_outer", "max_inner"});
  if (f.has("backend")) {
    o.backend = f["backend"].text();
    if (o.backend != "sqp" && o.backend != "ceres") f["backend"].fail("expected \"sqp\" or \"ceres\"");
  }
  if (f.has("sweep")) {
    o.sweep = f["sweep"].text();
    if (o.sweep != "jacobi" && o.sweep != "colours") f["sweep"].fail("expected \"jacobi\" or \"colours\"");
  }
  PatchOptions& p = o.patch;
  const std::pair<const char*, double*> positive[] = {{"constraint_tolerance", &p.constraint_tolerance},
                                                      {"final_constraint_tolerance", &p.final_constraint_tolerance},
                                                      {"initial_penalty", &p.initial_penalty},
                                                      {"penalty_growth", &p.penalty_growth},
                                                      {"max_penalty", &p.max_penalty}};
  for (const auto& [key, target] : positive)
    if (f.has(key)) *target = f[key].positive();
  if (f.has("max_outer")) p.max_outer = f["max_outer"].integer(1);
  if (f.has("max_inner")) p.max_inner = f["max_inner"].integer(1);
}

void apply_coarse(const Field& f, CoarseOptions& o) {
  f.expect_object({"link_weight", "fine_to_coarse", "prolongate", "concurrent_coarse"});
  if (f.has("prolongate")) o.prolongate = f["prolongate"].boolean();
  if (f.has("link_weight")) o.link_weight = f["link_weight"].non_negative();
  if (f.has("fine_to_coarse")) o.fine_to_coarse = f["fine_to_coarse"].boolean();
  if (f.has("concurrent_coarse")) o.concurrent_coarse = f["concurrent_coarse"].boolean();
}

void apply_twolevel(const Field& f, TwoLevelOptions& o) {
  f.expect_object({"link_weight", "fold_sharpness", "standard_finish", "finish_fold_bias_cap", "concurrent_coarse",
                   "coarse_every"});
  if (f.has("link_weight")) o.link_weight = f["link_weight"].non_negative();
  if (f.has("fold_sharpness")) o.fold_sharpness = f["fold_sharpness"].positive();
  if (f.has("standard_finish")) o.standard_finish = f["standard_finish"].integer(0);
  if (f.has("finish_fold_bias_cap")) o.finish_fold_bias_cap = f["finish_fold_bias_cap"].at_least(1);
  if (f.has("concurrent_coarse")) o.concurrent_coarse = f["concurrent_coarse"].boolean();
  if (f.has("coarse_every")) o.coarse_every = f["coarse_every"].integer(1);
}

void apply_admm(const Field& f, AdmmOptions& o) {
  f.expect_object({"rho", "gamma", "p", "inner"});
  if (f.has("rho")) o.rho = f["rho"].positive();
  if (f.has("gamma")) o.gamma = f["gamma"].positive();
  if (f.has("p")) o.p = f["p"].non_negative();
  if (f.has("inner")) o.inner = f["inner"].integer(1);
}

PositionSpec position_spec(const Field& f) {
  f.expect_object({"vertex", "near", "start", "end", "move"});
  PositionSpec p;
  p.path = f.where();
  if (f.has("vertex") == f.has("near")) f.fail("give exactly one of \"vertex\" (an index) and \"near\" ([x, y] in sheet units)");
  if (f.has("end") == f.has("move")) f.fail("give exactly one of \"end\" ([x, y, z]) and \"move\" ([dx, dy, dz])");
  if (f.has("vertex")) p.vertex = f["vertex"].integer(0);
  if (f.has("near")) p.near = f["near"].vector<2>();
  if (f.has("start")) p.start = f["start"].vector<3>();
  if (f.has("end")) p.end = f["end"].vector<3>();
  if (f.has("move")) p.move = f["move"].vector<3>();
  return p;
}

AngleSpec angle_spec(const Field& f) {
  f.expect_object({"crease_point", "curve", "start", "end"});
  AngleSpec a;
  a.path = f.where();
  if (f.has("crease_point") == f.has("curve"))
    f.fail("give exactly one of \"crease_point\" (an index) and \"curve\" (a crease curve index)");
  if (!f.has("end")) f.fail("missing \"end\" (the final dihedral angle in degrees)");
  if (f.has("crease_point")) a.point = f["crease_point"].integer(0);
  if (f.has("curve")) a.curve = f["curve"].integer(0);
  if (f.has("start")) a.start_degrees = f["start"].number();
  a.end_degrees = f["end"].number();
  for (double d : {a.start_degrees, a.end_degrees})
    if (std::abs(d) > 180) f.fail("angles must be in [-180, 180] degrees");
  return a;
}

}  // namespace

void apply_run_config(const json& j, const std::string& source, RunConfig& c) {
  const Field root(j, "$", source);
  root.expect_object(
      {"scenario", "iterations", "hold", "angle", "weights", "solver", "patch_solver", "coarse", "positions", "angles",
       "admm", "twolevel", "switches"});
  if (root.has("scenario")) {
    c.scenario = root["scenario"].text();
    const auto names = scenario_names();
    if (std::find(names.begin(), names.end(), c.scenario) == names.end())
      root["scenario"].fail("expected one of " + join(names, ", ") + ", got \"" + c.scenario + "\"");
  }
  if (root.has("iterations")) c.iterations = root["iterations"].integer(0);
  if (root.has("hold")) c.hold = root["hold"].integer(0);
  if (root.has("angle")) c.fold_angle = root["angle"].number();
  if (root.has("weights")) apply_weights(root["weights"], c.weights);
  if (root.has("solver")) apply_solver(root["solver"], c.standard);
  if (root.has("patch_solver")) apply_patch_solver(root["patch_solver"], c.subsolvers);
  if (root.has("coarse")) apply_coarse(root["coarse"], c.coarse);
  if (root.has("positions")) {
    const Field list = root["positions"];
    c.positions.clear();
    for (size_t i = 0; i < list.array_size(); ++i) c.positions.push_back(position_spec(list[i]));
  }
  if (root.has("angles")) {
    const Field list = root["angles"];
    c.angles.clear();
    for (size_t i = 0; i < list.array_size(); ++i) c.angles.push_back(angle_spec(list[i]));
  }
  if (root.has("admm")) apply_admm(root["admm"], c.admm);
  if (root.has("twolevel")) apply_twolevel(root["twolevel"], c.twolevel);
  if (root.has("switches")) {
    const Field list = root["switches"];
    c.switches.clear();
    for (size_t i = 0; i < list.array_size(); ++i) {
      const Field s = list[i];
      s.expect_object({"iteration", "mode"});
      if (!s.has("iteration") || !s.has("mode")) s.fail("give \"iteration\" (1-based) and \"mode\"");
      c.switches.push_back({s["iteration"].integer(1), s["mode"].text()});
    }
  }
  validate_run_config(c, source);
}

nlohmann::json read_json_file(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the " + what);
  try {
    return json::parse(in);
  } catch (const json::parse_error& e) {
    throw InputError(path + ": not valid JSON (" + e.what() + ")");
  }
}

void read_run_config(const std::string& path, RunConfig& config) {
  apply_run_config(read_json_file(path, "configuration file"), path, config);
}

void validate_run_config(const RunConfig& c, const std::string& source) {
  if (c.iterations + c.hold < 1) throw InputError(source + ": iterations + hold must be at least 1");
  if (!(std::abs(c.fold_angle) <= 180))
    throw InputError(source + ": $.angle: the fold angle must be in [-180, 180] degrees");
  if (const std::string m = c.weights.validate(); !m.empty()) throw InputError(source + ": $.weights: " + m);
  if (const std::string m = c.standard.validate(); !m.empty()) throw InputError(source + ": $.solver: " + m);
  if (const std::string m = c.subsolvers.validate(); !m.empty())
    throw InputError(source + ": $.patch_solver: " + m);
  if (const std::string m = c.admm.validate(); !m.empty()) throw InputError(source + ": $.admm." + m);
  if (const std::string m = c.coarse.validate(); !m.empty()) throw InputError(source + ": $.coarse." + m);
  if (const std::string m = c.twolevel.validate(); !m.empty()) throw InputError(source + ": $.twolevel." + m);
  for (size_t i = 0; i < c.switches.size(); ++i) {
    const int k = c.switches[i].iteration;
    const std::string where = source + ": $.switches[" + std::to_string(i) + "]: ";
    if (k < 1 || k > c.iterations + c.hold)
      throw InputError(where + "iteration " + std::to_string(k) + " is not in the run (1 to " +
                       std::to_string(c.iterations + c.hold) + ")");
    if (i > 0 && k <= c.switches[i - 1].iteration)
      throw InputError(where + "switches must be in ascending order of iteration");
  }
}

std::vector<std::string> scenario_names() { return {"corners", "fold", "none", "flatten"}; }

void check_scenario_name(const std::string& name, const std::string& what) {
  const auto names = scenario_names();
  if (std::find(names.begin(), names.end(), name) == names.end())
    throw UsageError(what + "unknown scenario '" + name + "' (known: " + join(names, ", ") + ")");
}

void check_scenario_targets(const Scenario& s, const RunConfig& c, const std::string& where) {
  if (!s.positions.empty() || !s.angles.empty()) return;
  if (c.scenario == "fold")
    throw UsageError("the fold scenario found no fold sites in " + where +
                     " (crease points strictly inside a grid edge between two patches; creases through grid "
                     "vertices only have none: try another resolution)");
  throw UsageError("the run has no targets: scenario '" + c.scenario +
                   "' and no position or angle constraints in the configuration");
}

Scenario make_scenario(const RunConfig& c, const DogMesh& mesh) {
  Scenario s;
  if (c.scenario == "corners") s = corners_scenario(mesh, c.iterations, c.hold);
  if (c.scenario == "fold") s = fold_scenario(mesh, c.fold_angle, c.iterations, c.hold);
  if (c.scenario == "none") s.name = "none";
  if (c.scenario == "flatten") s = flatten_scenario(mesh, c.weights, c.standard, c.fold_angle, c.iterations, c.hold);
  s.iterations = c.iterations;
  s.hold = c.hold;
  for (const auto& p : c.positions) {
    int v = -1;
    if (p.vertex) {
      if (*p.vertex >= mesh.vertex_count())
        throw InputError(p.path + ".vertex: the fine mesh has " + std::to_string(mesh.vertex_count()) +
                         " vertices, there is no vertex " + std::to_string(*p.vertex));
      v = *p.vertex;
    } else {
      const Eigen::Vector2d target = mesh.to_mesh(*p.near);
      double best = 0;
      for (int u = 0; u < mesh.vertex_count(); ++u) {
        const double d = (mesh.V.row(u).head<2>().transpose() - target).squaredNorm();
        if (v < 0 || d < best) v = u, best = d;
      }
    }
    PositionConstraint pc;
    pc.vertex = v;
    pc.start = p.start ? *p.start : Eigen::Vector3d(mesh.V.row(v).transpose());
    pc.end = p.end ? *p.end : Eigen::Vector3d(pc.start + *p.move);
    s.positions.push_back(pc);
  }
  const auto sites = fold_sites(mesh);
  s.curve_signs.resize(mesh.stitching.curves.size(), 0.0);
  auto set_sign = [&](int curve, double degrees) {
    if (degrees != 0) s.curve_signs[curve] = degrees > 0 ? 1.0 : -1.0;
  };
  for (const auto& a : c.angles) {
    if (a.point) {
      bool found = false;
      for (const auto& site : sites) found = found || site.point == *a.point;
      if (!found)
        throw InputError(a.path + ".crease_point: crease point " + std::to_string(*a.point) +
                         " is not a fold site (an interior crease point on an edge between two patches; the mesh "
                         "has " + std::to_string(sites.size()) + " of them, see `sdog mesh --out` creases.vtp)");
      s.angles.push_back(angle_constraint(mesh, *a.point, a.start_degrees, a.end_degrees));
      for (const auto& site : sites)
        if (site.point == *a.point) set_sign(site.curve, a.end_degrees);
    } else {
      if (*a.curve >= static_cast<int>(mesh.stitching.curves.size()))
        throw InputError(a.path + ".curve: the pattern has " + std::to_string(mesh.stitching.curves.size()) +
                         " crease curves, there is no curve " + std::to_string(*a.curve));
      for (const auto& site : sites)
        if (site.curve == *a.curve) s.angles.push_back(angle_constraint(mesh, site.point, a.start_degrees, a.end_degrees));
      set_sign(*a.curve, a.end_degrees);
    }
  }
  return s;
}

nlohmann::json to_json(const RunConfig& c) {
  const SqpOptions& s = c.standard.sqp;
  const Weights& w = c.weights;
  json positions = json::array(), angles = json::array(), switches = json::array();
  for (const auto& s : c.switches) switches.push_back({{"iteration", s.iteration}, {"mode", s.mode}});
  for (const auto& p : c.positions) {
    json e;
    if (p.vertex) e["vertex"] = *p.vertex;
    if (p.near) e["near"] = {p.near->x(), p.near->y()};
    if (p.start) e["start"] = {p.start->x(), p.start->y(), p.start->z()};
    if (p.end) e["end"] = {p.end->x(), p.end->y(), p.end->z()};
    if (p.move) e["move"] = {p.move->x(), p.move->y(), p.move->z()};
    positions.push_back(e);
  }
  for (const auto& a : c.angles) {
    json e{{"start", a.start_degrees}, {"end", a.end_degrees}};
    if (a.point) e["crease_point"] = *a.point;
    if (a.curve) e["curve"] = *a.curve;
    angles.push_back(e);
  }
  return {{"scenario", c.scenario},
          {"iterations", c.iterations},
          {"hold", c.hold},
          {"angle", c.fold_angle},
          {"weights",
           {{"bending", w.bending},
            {"isometry", w.isometry},
            {"stitching", w.stitching},
            {"positions", w.positions},
            {"edge_points", w.edge_points},
            {"angles", w.angles},
            {"fold_bias", w.fold_bias},
            {"link", w.link}}},
          {"solver",
           {{"kkt_tolerance", s.kkt_tolerance},
            {"max_steps", s.max_steps},
            {"epsilon", s.epsilon},
            {"restoration_epsilon", s.restoration_epsilon},
            {"polish_epsilon", s.polish_epsilon},
            {"merit_penalty", s.merit_penalty},
            {"trusted_backtracks", s.trusted_backtracks},
            {"constraint_tolerance", s.constraint_tolerance},
            {"final_constraint_tolerance", s.final_constraint_tolerance},
            {"max_restoration_steps", s.max_restoration_steps},
            {"polish_steps", s.polish_steps},
            {"local_rings", s.local_rings},
            {"local_fraction", s.local_fraction},
            {"armijo", s.armijo},
            {"max_backtracks", s.max_backtracks},
            {"regularization", s.regularization},
            {"rho_max", s.rho_max},
            {"second_order_correction", s.second_order_correction},
            {"lagrangian_hessian", s.lagrangian_hessian},
            {"folding", c.standard.folding},
            {"max_fold_bias", c.standard.max_fold_bias}}},
          {"patch_solver",
           {{"backend", c.subsolvers.backend},
            {"sweep", c.subsolvers.sweep},
            {"constraint_tolerance", c.subsolvers.patch.constraint_tolerance},
            {"final_constraint_tolerance", c.subsolvers.patch.final_constraint_tolerance},
            {"initial_penalty", c.subsolvers.patch.initial_penalty},
            {"penalty_growth", c.subsolvers.patch.penalty_growth},
            {"max_penalty", c.subsolvers.patch.max_penalty},
            {"max_outer", c.subsolvers.patch.max_outer},
            {"max_inner", c.subsolvers.patch.max_inner}}},
          {"coarse",
           {{"link_weight", c.coarse.link_weight}, {"fine_to_coarse", c.coarse.fine_to_coarse}, {"prolongate", c.coarse.prolongate},
            {"concurrent_coarse", c.coarse.concurrent_coarse}}},
          {"positions", positions},
          {"angles", angles},
          {"admm",
           {{"rho", c.admm.rho},
            {"gamma", c.admm.gamma},
            {"p", c.admm.p >= 0 ? json(c.admm.p) : json("0.001 (patches - 1)")},
            {"inner", c.admm.inner}}},
          {"twolevel", {{"link_weight", c.twolevel.link_weight}, {"fold_sharpness", c.twolevel.fold_sharpness},
                        {"standard_finish", c.twolevel.standard_finish},
                        {"finish_fold_bias_cap", c.twolevel.finish_fold_bias_cap},
                        {"concurrent_coarse", c.twolevel.concurrent_coarse},
                        {"coarse_every", c.twolevel.coarse_every}}},
          {"switches", switches}};
}

}  // namespace sdog
