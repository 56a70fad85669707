// sdog mesh: pattern -> fine and coarse DOG, map, counts, VTK files.
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/cli_common.h"
#include "app/commands.h"
#include "base/atomic_output.h"
#include "base/errors.h"
#include "base/text_format.h"
#include "geometry/input/fold_writer.h"
#include "ui/vis/model_files.h"

namespace sdog::cli {
namespace {

struct MeshArgs {
  PatternOptions pattern;
  std::string out;
  bool json = false;
  bool verbose = false;
  std::string coarse = "standard";
};

nlohmann::json classes_json(const QuadTopology& t) {
  return {{"star", t.count(VertexClass::kStar)},
          {"bnd3", t.count(VertexClass::kBnd3)},
          {"bnd2", t.count(VertexClass::kBnd2)},
          {"bnd4", t.count(VertexClass::kBnd4)}};
}

nlohmann::json mesh_json(const DogMesh& m, const QuadTopology& t, const Resolution& r) {
  return {{"resolution", r.str()},
          {"vertices", m.vertex_count()},
          {"quads", m.quad_count()},
          {"patches", m.patch_count()},
          {"crease_points", m.stitching.points.size()},
          {"stitch_pairs", m.stitching.pairs.size()},
          {"junctions", m.stitching.junctions.size()},
          {"vertex_classes", classes_json(t)}};
}

nlohmann::json summary_json(const DogModel& m, double seconds,
                            const std::vector<std::string>& files) {
  const Box2& b = m.pattern.sheet.bbox;
  nlohmann::json creases = nlohmann::json::array();
  for (size_t k = 0; k < m.clean.creases.size(); ++k) {
    const Crease& c = m.clean.creases[k];
    creases.push_back({{"index", k},
                       {"element", c.origin},
                       {"id", c.id},
                       {"assignment", enum_name(c.fold)},
                       {"kind", enum_name(c.kind)},
                       {"angle", c.angle ? nlohmann::json(*c.angle) : nlohmann::json(nullptr)}});
  }
  nlohmann::json j = {
      {"pattern", m.pattern.source},
      {"sheet",
       {{"width", b.width()},
        {"height", b.height()},
        {"holes", m.pattern.sheet.holes.size()},
        {"from_viewbox", m.pattern.sheet.from_viewbox}}},
      {"creases",
       {{"drawn", m.pattern.creases.size()},
        {"cleaned", m.clean.creases.size()},
        {"junctions", m.clean.junctions.size()},
        {"list", creases}}},
      {"warnings", model_warnings(m)},
      {"cleaning", m.clean.changes},
      {"mesh_units",
       {{"scale", m.fine.scale}, {"origin", {m.fine.sheet_origin.x(), m.fine.sheet_origin.y()}}}},
      {"fine", mesh_json(m.fine, m.fine_topology, m.fine_res)},
      {"seconds", seconds},
      {"outputs", files}};
  if (m.has_coarse) {
    j["coarse"] = mesh_json(m.coarse, m.coarse_topology, m.coarse_res);
    j["coarse"]["kind"] = enum_name(m.coarse_kind);
    const CurveCoverage cover = curve_coverage(m.map);
    j["map"] = {{"link", m.map.link_count},
                {"I", m.map.i_count},
                {"X", m.map.x_count},
                {"coarse_only", m.map.coarse_only_count},
                {"coarse_cover_cells", m.coarse_cover_cells},
                {"uncovered", m.map.uncovered_count},
                {"crease_points",
                 {{"kept", cover.kept},
                  {"interpolated", cover.interpolated},
                  {"uninterpolable", cover.uninterpolable}}}};
  }
  return j;
}

void print_mesh(std::ostream& os, const char* label, const DogMesh& m, const QuadTopology& t,
                const Resolution& r) {
  os << label << r.str() << ": " << m.vertex_count() << " vertices, " << m.quad_count()
     << " quads, " << m.patch_count() << " patches\n"
     << "              crease points " << m.stitching.points.size() << ", stitching pairs "
     << m.stitching.pairs.size() << ", junctions of >2 patches " << m.stitching.junctions.size()
     << "\n"
     << "              vertex classes: star " << t.count(VertexClass::kStar) << ", bnd3 "
     << t.count(VertexClass::kBnd3) << ", bnd2 " << t.count(VertexClass::kBnd2) << ", bnd4 "
     << t.count(VertexClass::kBnd4) << "\n";
}

void print_summary(std::ostream& os, const DogModel& m, double seconds,
                   const std::vector<std::string>& files, bool verbose) {
  const Box2& b = m.pattern.sheet.bbox;
  os << "pattern       " << m.pattern.source << "\n"
     << "sheet         " << format_number(b.width()) << " x " << format_number(b.height())
     << " sheet units" << (m.pattern.sheet.from_viewbox ? " (viewBox)" : "") << ", "
     << m.pattern.sheet.holes.size() << " hole(s); mesh units = sheet units x "
     << format_number(m.fine.scale) << "\n"
     << "creases       " << m.pattern.creases.size() << " drawn, " << m.clean.creases.size()
     << " after cleaning, " << m.clean.junctions.size() << " junction(s)\n";
  for (size_t k = 0; k < m.clean.creases.size(); ++k) {
    const Crease& c = m.clean.creases[k];
    os << "  crease " << k << "  " << c.origin << "  "
       << (c.kind == CurveKind::kCrease ? enum_name(c.fold) : enum_name(c.kind));
    if (c.angle) os << ", " << format_number(*c.angle) << " degrees";
    if (!c.layer.empty()) os << " (layer \"" << c.layer << "\")";
    os << "\n";
  }
  for (const auto& w : model_warnings(m)) os << "  warning:    " << w << "\n";
  if (verbose)
    for (const auto& c : m.clean.changes) os << "  cleaning:   " << c << "\n";
  print_mesh(os, "fine          ", m.fine, m.fine_topology, m.fine_res);
  if (m.has_coarse) {
    const bool alt = m.coarse_kind == CoarseKind::kAlt;
    print_mesh(os, alt ? "coarse alt    " : "coarse        ", m.coarse, m.coarse_topology,
               m.coarse_res);
    os << "map           link " << m.map.link_count << ", I " << m.map.i_count << ", X "
       << m.map.x_count << ", coarse-only " << m.map.coarse_only_count;
    if (m.coarse_cover_cells > 0)
      os << " (" << m.coarse_cover_cells
         << " coarse cells added so coarse patches cover fine ones)";
    if (alt) os << "; fine vertices the coarse mesh does not reach " << m.map.uncovered_count;
    os << "\n";
    const CurveCoverage cover = curve_coverage(m.map);
    os << "crease points kept by the coarse mesh " << cover.kept << ", interpolated between kept "
       << "ones " << cover.interpolated << ", not interpolable " << cover.uninterpolable;
    if (cover.uninterpolable > 0) os << " (before a crease's first or after its last kept point)";
    os << "\n";
  }
  os << "time          " << format_number(seconds) << " s\n";
  for (const auto& f : files) os << "wrote         " << f << "\n";
}

}  // namespace

void register_mesh_command(CLI::App& app, Runner& run) {
  auto args = std::make_shared<MeshArgs>();
  CLI::App* cmd = app.add_subcommand(
      "mesh",
      "Build the fine DOG, its coarse twin and the map between them; print the counts and "
      "optionally write VTK files");
  add_pattern_options(*cmd, args->pattern);
  cmd->add_option("--coarse", args->coarse,
                  "the coarse DOG: standard (meshed from the crease pattern on the coarse grid) "
                  "or alt (the fine DOG without every second grid row and column: every coarse "
                  "vertex a link, crease ends not kept)")
      ->check(CLI::IsMember(enum_names<CoarseKind>()))
      ->capture_default_str();
  cmd->add_option(
      "--out", args->out,
      "directory for fine.vtu, coarse.vtu, creases.vtp, pattern.vtp (created if needed)");
  cmd->add_flag("--json", args->json, "print the summary as one JSON object");
  cmd->add_flag("-v,--verbose", args->verbose, "also list what pattern cleaning changed");
  cmd->callback([args, &run]() {
    run = [args]() {
      const auto start = std::chrono::steady_clock::now();
      args->pattern.coarse = parse_enum<CoarseKind>(args->coarse, "--coarse: ");
      if (args->pattern.coarse == CoarseKind::kAlt && args->pattern.fine_only)
        throw UsageError("--coarse alt builds a coarse DOG and --fine-only builds none; give one");
      const DogModel model = build_model(args->pattern, false);  // the summary lists the warnings
      const double seconds = seconds_since(start);
      std::vector<std::string> files;
      if (!args->out.empty()) {
        OutputSet out(args->out);
        vis::write_model_files(model, out);
        out.write_text("pattern.fold", fold_text(model.clean));
        files = out.commit();
      }
      if (args->json)
        std::cout << summary_json(model, seconds, files).dump(2) << "\n";
      else
        print_summary(std::cout, model, seconds, files, args->verbose);
    };
  });
}

}  // namespace sdog::cli
