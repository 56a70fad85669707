#pragma once
// The solver modes by name (`sdog run --mode`, `sdog bench --modes`, the studio's Mode menu), in
// the order of the documentation, with one line on what an iteration of each does.
#include "base/enum_names.h"

namespace sdog {

enum class ModeKind { kStandard, kSubsolvers, kVsAdmm, kJAdmm, kProxJAdmm, kCoarse, kTwoLevel };
template <>
struct EnumNames<ModeKind> {
  static constexpr const char* noun = "mode";
  static constexpr EnumName<ModeKind> rows[] = {
      {ModeKind::kStandard, "standard"},   {ModeKind::kSubsolvers, "subsolvers"},
      {ModeKind::kVsAdmm, "vsadmm"},       {ModeKind::kJAdmm, "jadmm"},
      {ModeKind::kProxJAdmm, "proxjadmm"}, {ModeKind::kCoarse, "coarse"},
      {ModeKind::kTwoLevel, "twolevel"},
  };
};

/// One line: what an iteration of the mode does.
const char* mode_description(ModeKind mode);
/// True when the mode needs the coarse mesh and the fine-coarse map.
bool mode_needs_coarse(ModeKind mode);

}  // namespace sdog
