#include "solver/problem/targets.h"

#include <algorithm>
#include <cmath>

namespace sdog {

Targets Targets::of(const DogProblem& problem) {
  Targets t;
  for (int b = 0; b < problem.positions.block_count(); ++b)
    t.positions.push_back(problem.positions.target(b));
  for (int b = 0; b < problem.angles.block_count(); ++b) {
    t.angles.push_back(problem.angles.target(b));
    t.angle_scales.push_back(std::pow(std::sin(problem.angles.alpha(b)), 2));
  }
  return t;
}

Targets Targets::met_by(const DogProblem& problem, const Dofs& x) {
  Targets t = of(problem);
  std::vector<Eigen::Vector3d> p(
      std::max(problem.positions.max_block_size(), problem.angles.max_block_size()));
  for (int b = 0; b < problem.positions.block_count(); ++b) {
    gather_block(problem.positions, b, x, p.data());
    Eigen::Vector3d r;
    problem.positions.evaluate(b, p.data(), r.data(), nullptr);
    t.positions[b] += r;
  }
  for (int b = 0; b < problem.angles.block_count(); ++b) {
    gather_block(problem.angles, b, x, p.data());
    t.angles[b] = problem.angles.measure(b, p.data());
  }
  return t;
}

void Targets::install(DogProblem& problem) const {
  for (size_t b = 0; b < positions.size(); ++b)
    problem.positions.set_target(static_cast<int>(b), positions[b]);
  for (size_t b = 0; b < angles.size(); ++b)
    problem.angles.set_target(static_cast<int>(b), angles[b]);
}

bool Targets::matches(const Targets& other) const {
  return positions.size() == other.positions.size() && angles.size() == other.angles.size();
}

Targets Targets::towards(const Targets& other, double s) const {
  if (s >= 1) return other;  // exactly: a reached target is not "moved" by a rounding error
  Targets t = *this;
  for (size_t b = 0; b < positions.size(); ++b)
    t.positions[b] += s * (other.positions[b] - positions[b]);
  for (size_t b = 0; b < angles.size(); ++b) t.angles[b] += s * (other.angles[b] - angles[b]);
  return t;
}

double Targets::distance(const Targets& other, const TargetSteps& steps) const {
  double d = 0;
  for (size_t b = 0; b < positions.size(); ++b)
    d = std::max(d, (other.positions[b] - positions[b]).norm() / steps.length);
  for (size_t b = 0; b < angles.size(); ++b)
    d = std::max(d, angle_scales[b] * std::abs(other.angles[b] - angles[b]) / steps.angle);
  return d;
}

}  // namespace sdog
