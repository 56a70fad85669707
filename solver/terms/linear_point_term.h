#pragma once
// Linear residuals r = sum_j a_j p_j - target (3 rows per block). One definition for every term
// of that form: position constraints (a = 1), edge points (t, 1 - t), stitching pairs
// (t, 1 - t, -t, -(1 - t), target 0), link constraints, and bending (see bending.h).
#include <utility>
#include <vector>

#include "solver/terms/term.h"

namespace sdog {

class LinearPointTerm : public Term {
 public:
  static constexpr size_t kMaxVertices = 16;
  explicit LinearPointTerm(const char* name) : name_(name) {}
  const char* name() const override { return name_; }

  /// Adds the block sum_j a_j p_{v_j} - target; coefficients of a repeated vertex are merged and
  /// zero coefficients dropped. Returns the block index.
  int add(const std::vector<std::pair<int, double>>& weighted_vertices,
          const Eigen::Vector3d& target = Eigen::Vector3d::Zero());
  void set_target(int b, const Eigen::Vector3d& target) { targets_[b] = target; }
  const Eigen::Vector3d& target(int b) const { return targets_[b]; }
  double coefficient(int b, int j) const { return coefficients_[offsets_[b] + j]; }
  /// Removes every block.
  void clear();

  template <class T>
  void residual(int b, const T* const* p, T* r) const {
    for (int c = 0; c < 3; ++c) r[c] = T(-targets_[b][c]);
    for (int j = 0; j < block_size(b); ++j) {
      const double a = coefficient(b, j);
      for (int c = 0; c < 3; ++c) r[c] += a * p[j][c];
    }
  }

  void evaluate(int b, const Eigen::Vector3d* p, double* r, double* J) const override;
  bool is_linear() const override { return true; }

 private:
  const char* name_;
  std::vector<double> coefficients_;
  std::vector<int> offsets_{0};
  std::vector<Eigen::Vector3d> targets_;
};

}  // namespace sdog
