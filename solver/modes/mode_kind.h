#pragma once
// The solver modes by name (`sdog run --mode`, `sdog bench --modes`, the studio's Mode menu), in
// the order of the documentation, with one line on what an iteration of each does.
#include <optional>
#include <string>
#include <vector>

namespace sdog {

enum class ModeKind { kStandard, kSubsolvers, kVsAdmm, kJAdmm, kProxJAdmm, kCoarse, kTwoLevel };

const std::vector<ModeKind>& all_modes();
/// "standard", "subsolvers", "vsadmm", "jadmm", "proxjadmm", "coarse", "twolevel".
const char* mode_name(ModeKind mode);
/// One line: what an iteration of the mode does.
const char* mode_description(ModeKind mode);
/// True when the mode needs the coarse mesh and the fine-coarse map.
bool mode_needs_coarse(ModeKind mode);
/// The names, in order.
std::vector<std::string> mode_names();
/// The names, comma separated (help texts and messages).
std::string known_modes();
std::optional<ModeKind> find_mode(const std::string& name);
/// Throws UsageError "`what`unknown mode 'name' (known: ...)" unless `name` is a mode.
ModeKind parse_mode(const std::string& name, const std::string& what = "");

}  // namespace sdog
