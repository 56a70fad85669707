#pragma once
// A patch stepper that does no work: its step calls `on_step` (which may record the thread, the
// order, ...) and reports a converged step. For tests of step_patches (patch_stepper.h).
#include <functional>
#include <utility>

#include "solver/patches/patch_stepper.h"

namespace sdog::test {

class ProbePatch : public PatchStepper {
 public:
  ProbePatch(int patch, int vertices, std::function<void(int patch)> on_step)
      : patch_(patch), vertices_(vertices), on_step_(std::move(on_step)) {}
  int patch() const override { return patch_; }
  int vertex_count() const override { return vertices_; }
  PatchReport step(Dofs&, bool) override {
    on_step_(patch_);
    PatchReport r;
    r.patch = patch_;
    r.converged = true;
    return r;
  }
  void set_weight(size_t, double) override {}

 private:
  int patch_, vertices_;
  std::function<void(int)> on_step_;
};

}  // namespace sdog::test
