#include "solver/modes/mode_kind.h"

#include <algorithm>

#include "base/errors.h"
#include "base/text_format.h"

namespace sdog {
namespace {

struct ModeInfo {
  ModeKind mode;
  bool needs_coarse;
  const char* description;
};

const ModeInfo kModes[] = {
    {ModeKind::kStandard, false, "one iteration of the global SQP solver on the whole fine DOG"},
    {ModeKind::kSubsolvers, false,
     "block Jacobi over the patches: every patch takes one SQP step on its own problem, in "
     "parallel"},
    {ModeKind::kVsAdmm, false, "variable-splitting ADMM over the patches' stitching constraints"},
    {ModeKind::kJAdmm, false, "Jacobian ADMM over the patches' stitching constraints"},
    {ModeKind::kProxJAdmm, false, "proximal Jacobian ADMM over the patches' stitching constraints"},
    {ModeKind::kCoarse, true,
     "the thesis's coarse method: a coarse standard iteration, its crease curves as targets of the "
     "fine patches"},
    {ModeKind::kTwoLevel, true,
     "a coarse standard iteration moves the fine sheet, then a subsolvers round; standard "
     "iterations finish a run"},
};

const ModeInfo& info(ModeKind mode) {
  return kModes[static_cast<int>(mode)];
}

}  // namespace

const char* mode_description(ModeKind mode) {
  return info(mode).description;
}
bool mode_needs_coarse(ModeKind mode) {
  return info(mode).needs_coarse;
}

}  // namespace sdog
