#include "solver/problem/diagnostics.h"

#include <algorithm>
#include <cmath>

#include "base/statistics.h"
#include "geometry/pattern/fold_tips.h"

namespace sdog {
namespace {

template <class F>
void for_each_block(const Term& t, const Dofs& x, F&& f) {
  std::vector<Eigen::Vector3d> p(t.max_block_size());
  std::vector<double> r(t.max_residual_count());
  for (int b = 0; b < t.block_count(); ++b) {
    gather_block(t, b, x, p.data());
    t.evaluate(b, p.data(), r.data(), nullptr);
    f(b, r.data(), t.residual_count(b));
  }
}

double sum_of_squares(const Term& t, const Dofs& x) {
  double s = 0;
  for_each_block(t, x, [&](int, const double* r, int m) {
    for (int i = 0; i < m; ++i) s += r[i] * r[i];
  });
  return s;
}

}  // namespace

double angle_difference(double angle, double target) {
  double d = std::fmod(angle - target, 360.0);
  if (d > 180) d -= 360;
  if (d <= -180) d += 360;
  return d;
}

bool near_fold_tip(const DogMesh& mesh, int point) {
  const Eigen::Vector2d& p = mesh.stitching.points[point].flat;
  return std::any_of(mesh.fold_tips.begin(), mesh.fold_tips.end(), [&](const Eigen::Vector2d& tip) {
    return (p - tip).norm() <= kFoldTipRadius;
  });
}

bool bent_against(double angle, double target) {
  return std::abs(angle) > kBentDegrees && angle * target < 0;
}

AngleAgreement angle_agreement(const DogProblem& problem, const Dofs& x) {
  AngleAgreement a;
  std::vector<double> errors;
  for (int b = 0; b < problem.angles.block_count(); ++b) {
    const int point = problem.angles.point(b), k = problem.fold_angles.site_of(point);
    if (k < 0) continue;
    const double target = problem.angles.target(b) * 180 / M_PI,
                 angle = problem.fold_angles.at(k, x);
    errors.push_back(std::abs(angle_difference(angle, target)));
    if (target == 0) continue;
    if (near_fold_tip(problem.mesh(), point)) {
      ++a.tip_sites;
      if (bent_against(angle, target)) ++a.tip_against;
      continue;
    }
    ++a.targeted_sites;
    if (std::abs(angle) <= kBentDegrees) continue;
    ++a.bent_sites;
    if (!bent_against(angle, target)) ++a.bent_as_targeted;
  }
  a.median_error = median(errors);
  return a;
}

double weighted_objective(const DogProblem& problem, const Dofs& x) {
  double f = 0;
  for (const auto& wt : problem.objective_terms())
    if (wt.weight != 0) f += wt.weight * sum_of_squares(*wt.term, x);
  return f;
}

Diagnostics diagnose(const DogProblem& problem, const Dofs& x) {
  Diagnostics d;
  const auto terms = problem.objective_terms();
  for (int k = 0; k < kTermCount; ++k) {
    d.terms[k] = sum_of_squares(*terms[k].term, x);
    d.objective += terms[k].weight * d.terms[k];
  }
  double l2 = 0;
  for_each_block(problem.dog, x, [&](int, const double* r, int m) {
    for (int i = 0; i < m; ++i) {
      d.dog_max = std::max(d.dog_max, std::abs(r[i]));
      l2 += r[i] * r[i];
    }
  });
  d.dog_l2 = std::sqrt(l2);
  for_each_block(problem.stitching, x, [&](int, const double* r, int) {
    d.stitch_gap_max =
        std::max(d.stitch_gap_max, std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]));
  });
  d.angles_met = angle_agreement(problem, x);
  for (int b = 0; b < problem.isometry.block_count(); ++b) {
    const int* v = problem.isometry.block_vertices(b);
    const double len = (vertex_of(x, v[0]) - vertex_of(x, v[1])).norm();
    const double strain = len / problem.isometry.rest_length(b) - 1;
    d.edge_strain_max = std::max(d.edge_strain_max, std::abs(strain));
    if (problem.sheet_edges[b] &&
        (std::abs(strain) > d.sheet_strain_max || d.sheet_strain_patch < 0)) {
      d.sheet_strain_max = std::abs(strain);
      d.sheet_strain_worst = strain;
      d.sheet_strain_patch = problem.mesh().vertex_patch[v[0]];
    }
  }
  return d;
}

Fields fields(const DogProblem& problem, const Dofs& x) {
  const DogMesh& mesh = problem.mesh();
  const int n = mesh.vertex_count();
  Fields out;
  out.dog_residual.assign(n, 0.0);
  out.bending.assign(n, 0.0);
  out.position_residual.assign(n, 0.0);
  for_each_block(problem.dog, x, [&](int b, const double* r, int m) {
    double worst = 0;
    for (int i = 0; i < m; ++i) worst = std::max(worst, std::abs(r[i]));
    out.dog_residual[problem.dog.block_vertices(b)[0]] = worst;
  });
  // A bending block belongs to its centre: the vertex with the largest coefficient.
  for_each_block(problem.bending, x, [&](int b, const double* r, int) {
    int centre = 0;
    for (int j = 1; j < problem.bending.block_size(b); ++j)
      if (problem.bending.coefficient(b, j) > problem.bending.coefficient(b, centre)) centre = j;
    out.bending[problem.bending.block_vertices(b)[centre]] =
        r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  });
  for_each_block(problem.positions, x, [&](int b, const double* r, int) {
    out.position_residual[problem.positions.block_vertices(b)[0]] =
        std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
  });
  out.edge_strain.assign(mesh.quad_count(), 0.0);
  const Dofs& rest = problem.rest();
  for (int q = 0; q < mesh.quad_count(); ++q)
    for (int k = 0; k < 4; ++k) {
      const int a = mesh.F(q, k), b = mesh.F(q, (k + 1) % 4);
      const double len = (vertex_of(x, a) - vertex_of(x, b)).norm();
      const double len0 = (vertex_of(rest, a) - vertex_of(rest, b)).norm();
      out.edge_strain[q] = std::max(out.edge_strain[q], std::abs(len / len0 - 1));
    }
  const CreaseStitching& st = mesh.stitching;
  out.stitch_gap.assign(st.points.size(), 0.0);
  const Eigen::MatrixX3d X = to_positions(x);
  for (const auto& pair : st.pairs) {
    const auto& copies = st.points[pair.point].copies;
    const double gap =
        (DogMesh::position(X, copies[pair.a]) - DogMesh::position(X, copies[pair.b])).norm();
    out.stitch_gap[pair.point] = std::max(out.stitch_gap[pair.point], gap);
  }
  return out;
}

}  // namespace sdog
