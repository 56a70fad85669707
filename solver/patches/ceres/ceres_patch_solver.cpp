#include "solver/patches/ceres/ceres_patch_solver.h"

#include <ceres/version.h>

#include "solver/patches/ceres/ceres_patch.h"

#include "base/stopwatch.h"

namespace sdog {

namespace {

// Residuals of block b of a patch term at the patch positions read by `position(v)` (local v).
template <class Position>
Eigen::VectorXd block_residual(const Term& t, int b, Position position) {
  std::vector<Eigen::Vector3d> p(t.block_size(b));
  for (int j = 0; j < t.block_size(b); ++j) p[j] = position(t.block_vertices(b)[j]);
  Eigen::VectorXd r(t.residual_count(b));
  t.evaluate(b, p.data(), r.data(), nullptr);
  return r;
}

}  // namespace

CeresPatchSolver::CeresPatchSolver(const DogMesh& mesh, int patch,
                                   const std::vector<WeightedTerm>& terms, const Term& dog,
                                   const CeresPatchOptions& options, const PatchCoupling& coupling)
    : patch_(patch),
      begin_(mesh.patch_begin[patch]),
      end_(mesh.patch_begin[patch + 1]),
      options_(options),
      local_(3 * static_cast<size_t>(end_ - begin_)),
      mu_(options.initial_penalty) {
  ceres::Problem::Options po;
  po.enable_fast_removal = false;
  problem_ = std::make_unique<ceres::Problem>(po);
  for (int v = begin_; v < end_; ++v) problem_->AddParameterBlock(&local_[3 * (v - begin_)], 3);
  std::vector<double*> params;
  auto parameters = [&](const Term& t, int b) {
    params.clear();
    for (int j = 0; j < t.block_size(b); ++j) params.push_back(&local_[3 * t.block_vertices(b)[j]]);
    return params;
  };
  term_costs_.resize(terms.size());
  for (size_t k = 0; k < terms.size(); ++k) {
    terms_.push_back(std::make_unique<PatchTerm>(*terms[k].term, begin_, end_,
                                                 coupling.frozen_for(terms[k].term)));
    const Term& t = *terms_.back();
    weights_.push_back(terms[k].weight);
    for (int b = 0; b < t.block_count(); ++b) {
      auto* cost = new TermCost(t, b, terms[k].weight);
      term_costs_[k].push_back(cost);
      problem_->AddResidualBlock(cost, nullptr, parameters(t, b));
    }
  }
  dog_ = std::make_unique<PatchTerm>(dog, begin_, end_);
  int rows = 0;
  for (int b = 0; b < dog_->block_count(); ++b) rows += dog_->residual_count(b);
  lambda_ = Eigen::VectorXd::Zero(rows);
  offset_ = Eigen::VectorXd::Zero(rows);
  int row = 0;
  for (int b = 0; b < dog_->block_count(); ++b) {
    auto* cost = new TermCost(*dog_, b, mu_, offset_.data() + row);
    dog_costs_.push_back(cost);
    problem_->AddResidualBlock(cost, nullptr, parameters(*dog_, b));
    row += dog_->residual_count(b);
  }
}

void CeresPatchSolver::set_weight(size_t index, double weight) {
  weights_[index] = weight;
  for (TermCost* c : term_costs_[index]) c->set_weight(weight);
}

void CeresPatchSolver::load(const Dofs& x) {
  for (size_t i = 0; i < local_.size(); ++i)
    local_[i] = x[3 * begin_ + static_cast<Eigen::Index>(i)];
}

double CeresPatchSolver::constraint_max_local() {
  double m = 0;
  auto position = [&](int v) { return Eigen::Vector3d(&local_[3 * v]); };
  for (int b = 0; b < dog_->block_count(); ++b)
    m = std::max(m, block_residual(*dog_, b, position).lpNorm<Eigen::Infinity>());
  return m;
}

double CeresPatchSolver::dog_max(const Dofs& x) const {
  double m = 0;
  auto position = [&](int v) { return Eigen::Vector3d(vertex_of(x, v + begin_)); };
  for (int b = 0; b < dog_->block_count(); ++b)
    m = std::max(m, block_residual(*dog_, b, position).lpNorm<Eigen::Infinity>());
  return m;
}

double CeresPatchSolver::objective(const Dofs& x) const {
  double f = 0;
  auto position = [&](int v) { return Eigen::Vector3d(vertex_of(x, v + begin_)); };
  for (size_t k = 0; k < terms_.size(); ++k)
    for (int b = 0; b < terms_[k]->block_count(); ++b)
      f += weights_[k] * block_residual(*terms_[k], b, position).squaredNorm();
  return f;
}

PatchReport CeresPatchSolver::step(Dofs& x, bool last) {
  const double tolerance = options_.constraint_tolerance;
  if (last) options_.constraint_tolerance = options_.final_constraint_tolerance;
  const PatchReport r = solve(x);
  options_.constraint_tolerance = tolerance;
  return r;
}

PatchReport CeresPatchSolver::solve(Dofs& x) {
  const auto t0 = Clock::now();
  PatchReport report;
  report.patch = patch_;
  load(x);
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  so.sparse_linear_algebra_library_type = ceres::SUITE_SPARSE;
  so.num_threads = 1;
  so.max_num_iterations = options_.max_inner;
  so.logging_type = ceres::SILENT;
  so.function_tolerance = 1e-14;
  so.gradient_tolerance = 1e-14;
  so.parameter_tolerance = 1e-14;
  double cmax = constraint_max_local();
  for (int outer = 0; outer < options_.max_outer; ++outer) {
    offset_ = lambda_ / mu_;
    for (TermCost* c : dog_costs_) c->set_weight(mu_);
    ceres::Solver::Summary summary;
    ceres::Solve(so, problem_.get(), &summary);
    report.work.steps += static_cast<int>(summary.iterations.size()) - 1;
    report.work.factor_ms += 1e3 * summary.linear_solver_time_in_seconds;
    ++report.outer;
    // The multiplier update, from the constraint values at the new point.
    int row = 0;
    double new_max = 0;
    auto position = [&](int v) { return Eigen::Vector3d(&local_[3 * v]); };
    for (int b = 0; b < dog_->block_count(); ++b) {
      const Eigen::VectorXd c = block_residual(*dog_, b, position);
      lambda_.segment(row, c.size()) -= mu_ * c;
      new_max = std::max(new_max, c.lpNorm<Eigen::Infinity>());
      row += static_cast<int>(c.size());
    }
    if (new_max > options_.constraint_tolerance && new_max > 0.25 * cmax)
      mu_ = std::min(mu_ * options_.penalty_growth, options_.max_penalty);
    cmax = new_max;
    if (cmax <= options_.constraint_tolerance) break;
  }
  for (size_t i = 0; i < local_.size(); ++i)
    x[3 * begin_ + static_cast<Eigen::Index>(i)] = local_[i];
  report.dog_max = cmax;
  report.converged = cmax <= options_.constraint_tolerance;
  report.objective = objective(x);
  report.ms = ms_between(t0, Clock::now());
  return report;
}

std::string ceres_version() {
  return CERES_VERSION_STRING;
}

std::unique_ptr<PatchStepper> make_ceres_patch(const DogMesh& mesh, int patch,
                                               const std::vector<WeightedTerm>& terms,
                                               const Term& dog, const CeresPatchOptions& options,
                                               const PatchCoupling& coupling) {
  return std::make_unique<CeresPatchSolver>(mesh, patch, terms, dog, options, coupling);
}

}  // namespace sdog
