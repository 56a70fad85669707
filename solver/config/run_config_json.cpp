#include "solver/config/run_config_json.h"

#include <fstream>

#include "base/errors.h"
#include "base/json_field.h"
#include "solver/config/option_json.h"

namespace sdog {
namespace {

using nlohmann::json;

PositionSpec position_spec(const Field& f) {
  f.expect_object({"vertex", "near", "start", "end", "move"});
  PositionSpec p;
  p.path = f.where();
  if (f.has("vertex") == f.has("near"))
    f.fail("give exactly one of \"vertex\" (an index) and \"near\" ([x, y] in sheet units)");
  if (f.has("end") == f.has("move"))
    f.fail("give exactly one of \"end\" ([x, y, z]) and \"move\" ([dx, dy, dz])");
  if (f.has("vertex")) p.vertex = f["vertex"].integer(0);
  if (f.has("near")) p.near = f["near"].vector<2>();
  if (f.has("start")) p.start = f["start"].vector<3>();
  if (f.has("end")) p.end = f["end"].vector<3>();
  if (f.has("move")) p.move = f["move"].vector<3>();
  return p;
}

AngleSpec angle_spec(const Field& f) {
  f.expect_object({"crease_point", "curve", "id", "start", "end"});
  AngleSpec a;
  a.path = f.where();
  if (f.has("crease_point") + f.has("curve") + f.has("id") != 1)
    f.fail(
        "give exactly one of \"crease_point\" (an index), \"curve\" (a crease index) and \"id\" (a "
        "crease's SVG "
        "element id)");
  if (!f.has("end")) f.fail("missing \"end\" (the final dihedral angle in degrees)");
  if (f.has("crease_point")) a.point = f["crease_point"].integer(0);
  if (f.has("curve")) a.curve = f["curve"].integer(0);
  if (f.has("id")) a.id = f["id"].text();
  if (f.has("start")) a.start_degrees = f["start"].number();
  a.end_degrees = f["end"].number();
  for (double d : {a.start_degrees, a.end_degrees})
    if (std::abs(d) > 180) f.fail("angles must be in [-180, 180] degrees");
  return a;
}

CreaseSetting crease_setting(const Field& f) {
  f.expect_object({"curve", "id", "fold", "angle"});
  CreaseSetting c;
  c.path = f.where();
  if (f.has("curve") == f.has("id"))
    f.fail(
        "give exactly one of \"curve\" (a crease index, as sdog mesh lists them) and \"id\" (its "
        "SVG element id)");
  if (!f.has("fold") && !f.has("angle"))
    f.fail("give \"fold\" (mountain, valley, flat or unassigned), \"angle\" or both");
  if (f.has("curve")) c.curve = f["curve"].integer(0);
  if (f.has("id")) c.id = f["id"].text();
  if (f.has("fold")) {
    c.fold = find_enum<Fold>(f["fold"].text());
    if (!c.fold)
      f["fold"].fail("unknown assignment \"" + f["fold"].text() +
                     "\" (mountain, valley, flat or unassigned)");
  }
  if (f.has("angle")) {
    c.angle = f["angle"].number();
    if (*c.angle < 0 || *c.angle > 180)
      f["angle"].fail(
          "the fold angle must be from 0 to 180 degrees (its direction is the assignment's)");
  }
  return c;
}

ModeSwitch mode_switch(const Field& f) {
  f.expect_object({"iteration", "mode"});
  if (!f.has("iteration") || !f.has("mode")) f.fail("give \"iteration\" (1-based) and \"mode\"");
  const int iteration = f["iteration"].integer(1);
  const std::optional<ModeKind> mode = find_enum<ModeKind>(f["mode"].text());
  if (!mode)
    f["mode"].fail("unknown mode \"" + f["mode"].text() + "\" (known: " + known_names<ModeKind>() +
                   ")");
  return {iteration, *mode};
}

template <class T>
void read_list(const Field& root, const char* key, std::vector<T>& out, T (*read)(const Field&)) {
  if (!root.has(key)) return;
  const Field list = root[key];
  out.clear();
  for (size_t i = 0; i < list.array_size(); ++i) out.push_back(read(list[i]));
}

std::vector<std::string> top_level_keys() {
  std::vector<std::string> keys = option_keys(run_option_table());
  const RunConfig defaults;
  for_each_option_section(defaults,
                          [&](const char* key, const auto&, const auto&) { keys.push_back(key); });
  for (const char* key : {"positions", "angles", "creases", "switches"}) keys.push_back(key);
  return keys;
}

json vector_json(const Eigen::Ref<const Eigen::VectorXd>& v) {
  json out = json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(v[i]);
  return out;
}

}  // namespace

void apply_run_config(const json& j, const std::string& source, RunConfig& c) {
  const Field root(j, "$", source);
  root.expect_object(top_level_keys());
  read_options(root, run_option_table(), c);
  if (root.has("preset")) apply_preset(c.preset, c);
  for_each_option_section(c, [&](const char* key, auto& options, const auto& table) {
    if (!root.has(key)) return;
    const Field section = root[key];
    section.expect_object(option_keys(table));
    read_options(section, table, options);
  });
  read_list(root, "positions", c.positions, position_spec);
  read_list(root, "angles", c.angles, angle_spec);
  read_list(root, "creases", c.creases, crease_setting);
  read_list(root, "switches", c.switches, mode_switch);
  validate_run_config(c, source);
}

json read_json_file(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the " + what);
  try {
    return json::parse(in);
  } catch (const json::exception& e) {  // also numbers out of range, such as 1e999
    throw InputError(path + ": not valid JSON (" + e.what() + ")");
  }
}

void read_run_config(const std::string& path, RunConfig& config) {
  apply_run_config(read_json_file(path, "configuration file"), path, config);
}

json to_json(const RunConfig& c) {
  json j = options_json(run_option_table(), c);
  for_each_option_section(c, [&](const char* key, const auto& options, const auto& table) {
    j[key] = options_json(table, options);
  });
  json positions = json::array(), angles = json::array(), switches = json::array();
  for (const auto& p : c.positions) {
    json e = json::object();
    if (p.vertex) e["vertex"] = *p.vertex;
    if (p.near) e["near"] = vector_json(*p.near);
    if (p.start) e["start"] = vector_json(*p.start);
    if (p.end) e["end"] = vector_json(*p.end);
    if (p.move) e["move"] = vector_json(*p.move);
    positions.push_back(e);
  }
  for (const auto& a : c.angles) {
    json e{{"start", a.start_degrees}, {"end", a.end_degrees}};
    if (a.point) e["crease_point"] = *a.point;
    if (a.curve) e["curve"] = *a.curve;
    if (a.id) e["id"] = *a.id;
    angles.push_back(e);
  }
  json creases = json::array();
  for (const auto& s : c.creases) {
    json e = json::object();
    if (s.curve) e["curve"] = *s.curve;
    if (s.id) e["id"] = *s.id;
    if (s.fold) e["fold"] = enum_name(*s.fold);
    if (s.angle) e["angle"] = *s.angle;
    creases.push_back(e);
  }
  for (const auto& s : c.switches)
    switches.push_back({{"iteration", s.iteration}, {"mode", enum_name(s.mode)}});
  j["positions"] = positions;
  j["angles"] = angles;
  j["creases"] = creases;
  j["switches"] = switches;
  return j;
}

}  // namespace sdog
