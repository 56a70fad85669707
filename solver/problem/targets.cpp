#include "solver/problem/targets.h"

#include <algorithm>

namespace sdog {

Targets Targets::of(const DogProblem& problem) {
  Targets t;
  for (int b = 0; b < problem.positions.block_count(); ++b) t.positions.push_back(problem.positions.target(b));
  for (int b = 0; b < problem.angles.block_count(); ++b) t.cosines.push_back(problem.angles.cos_target(b));
  return t;
}

Targets Targets::met_by(const DogProblem& problem, const Dofs& x) {
  Targets t = of(problem);
  Eigen::Vector3d p[LinearPointTerm::kMaxVertices];
  for (int b = 0; b < problem.positions.block_count(); ++b) {
    gather_block(problem.positions, b, x, p);
    Eigen::Vector3d r;
    problem.positions.evaluate(b, p, r.data(), nullptr);
    t.positions[b] += r;
  }
  for (int b = 0; b < problem.angles.block_count(); ++b) {
    gather_block(problem.angles, b, x, p);
    double r = 0;
    problem.angles.evaluate(b, p, &r, nullptr);
    t.cosines[b] += r;
  }
  return t;
}

void Targets::install(DogProblem& problem) const {
  for (size_t b = 0; b < positions.size(); ++b) problem.positions.set_target(static_cast<int>(b), positions[b]);
  for (size_t b = 0; b < cosines.size(); ++b) problem.angles.set_cos(static_cast<int>(b), cosines[b]);
}

bool Targets::matches(const Targets& other) const {
  return positions.size() == other.positions.size() && cosines.size() == other.cosines.size();
}

Targets Targets::towards(const Targets& other, double s) const {
  if (s >= 1) return other;  // exactly: a reached target is not "moved" by a rounding error
  Targets t = *this;
  for (size_t b = 0; b < positions.size(); ++b) t.positions[b] += s * (other.positions[b] - positions[b]);
  for (size_t b = 0; b < cosines.size(); ++b) t.cosines[b] += s * (other.cosines[b] - cosines[b]);
  return t;
}

double Targets::distance(const Targets& other) const {
  double d = 0;
  for (size_t b = 0; b < positions.size(); ++b) d = std::max(d, (other.positions[b] - positions[b]).norm());
  for (size_t b = 0; b < cosines.size(); ++b) d = std::max(d, std::abs(other.cosines[b] - cosines[b]));
  return d;
}

}  // namespace sdog
