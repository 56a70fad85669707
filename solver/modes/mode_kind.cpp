#include "solver/modes/mode_kind.h"

#include <algorithm>

#include "base/errors.h"
#include "base/text_format.h"

namespace sdog {
namespace {

struct ModeInfo {
  ModeKind mode;
  const char* name;
  bool needs_coarse;
  const char* description;
};

const ModeInfo kModes[] = {
    {ModeKind::kStandard, "standard", false, "one iteration of the global SQP solver on the whole fine DOG"},
    {ModeKind::kSubsolvers, "subsolvers", false,
     "block Jacobi over the patches: every patch takes one SQP step on its own problem, in parallel"},
    {ModeKind::kVsAdmm, "vsadmm", false, "variable-splitting ADMM over the patches' stitching constraints"},
    {ModeKind::kJAdmm, "jadmm", false, "Jacobian ADMM over the patches' stitching constraints"},
    {ModeKind::kProxJAdmm, "proxjadmm", false, "proximal Jacobian ADMM over the patches' stitching constraints"},
    {ModeKind::kCoarse, "coarse", true,
     "the thesis's coarse method: a coarse standard iteration, its crease curves as targets of the fine patches"},
    {ModeKind::kTwoLevel, "twolevel", true,
     "a coarse standard iteration moves the fine sheet, then a subsolvers round; standard iterations finish a run"},
};

const ModeInfo& info(ModeKind mode) { return kModes[static_cast<int>(mode)]; }

}  // namespace

const std::vector<ModeKind>& all_modes() {
  static const std::vector<ModeKind> modes = [] {
    std::vector<ModeKind> out;
    for (const auto& m : kModes) out.push_back(m.mode);
    return out;
  }();
  return modes;
}

const char* mode_name(ModeKind mode) { return info(mode).name; }
const char* mode_description(ModeKind mode) { return info(mode).description; }
bool mode_needs_coarse(ModeKind mode) { return info(mode).needs_coarse; }

std::vector<std::string> mode_names() {
  std::vector<std::string> out;
  for (const auto& m : kModes) out.push_back(m.name);
  return out;
}

std::string known_modes() { return join(mode_names(), ", "); }

std::optional<ModeKind> find_mode(const std::string& name) {
  const auto it = std::find_if(std::begin(kModes), std::end(kModes), [&](const ModeInfo& m) { return name == m.name; });
  if (it == std::end(kModes)) return std::nullopt;
  return it->mode;
}

ModeKind parse_mode(const std::string& name, const std::string& what) {
  if (const auto mode = find_mode(name)) return *mode;
  throw UsageError(what + "unknown mode '" + name + "' (known: " + known_modes() + ")");
}

}  // namespace sdog
