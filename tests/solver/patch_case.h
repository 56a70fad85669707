#pragma once
// A small case for the patch tests: a dataset's fine DOG with the corners scenario half way, and a
// bent developable state.
#include <cmath>
#include <memory>
#include <string>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/problem/dog_problem.h"
#include "solver/problem/scenario.h"
#include "tests/test_support.h"

namespace sdog::test {

struct PatchCase {
  DogModel model;
  std::unique_ptr<DogProblem> problem;
  Scenario scenario;
  explicit PatchCase(const std::string& pattern, Eigen::Vector2i res) {
    model = build_dog_model(read_crease_pattern(test::dataset(pattern)), {res[0], res[1]});
    problem = std::make_unique<DogProblem>(model.fine, model.fine_topology);
    scenario = corners_scenario(model.fine, 10, 0);
    scenario.install(*problem);
    scenario.apply(*problem, 0.5);  // the dragged corner half way
  }
  // A bent start: the flat sheet rolled around the y axis (a developable state, DOG constraints 0).
  Dofs bent() const {
    Dofs x = to_dofs(model.fine.V);
    const double radius = 3 * model.fine.nx();
    for (Eigen::Index v = 0; v < x.size() / 3; ++v) {
      const double a = x[3 * v] / radius;
      x[3 * v] = radius * std::sin(a);
      x[3 * v + 2] = radius * (1 - std::cos(a));
    }
    return x;
  }
};

}  // namespace sdog::test
