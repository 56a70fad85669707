// Every term's Jacobian against central finite differences (Richardson-extrapolated) and against
// Ceres automatic differentiation, at random non-flat configurations; second derivatives against
// finite differences of the analytic gradient.
#include <ceres/dynamic_autodiff_cost_function.h>
#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/patches/ceres/ceres_cost.h"
#include "solver/patches/patch_term.h"
#include "solver/terms/bending.h"
#include "solver/terms/crease_geometry.h"
#include "solver/terms/dihedral_angles.h"
#include "solver/terms/dog_constraints.h"
#include "solver/terms/fold_bias.h"
#include "solver/terms/isometry.h"
#include "solver/terms/linear_point_term.h"
#include "solver/terms/stacked_term.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

struct Fixture {
  DogModel model;
  Dofs rest;
  Fixture() {
    model = build_dog_model(read_crease_pattern(test::dataset("crossing_creases.svg")), {11, 11});
    rest = to_dofs(model.fine.V);
  }
};
const Fixture& fixture() {
  static Fixture f;
  return f;
}

// An angle constraint at every fold site, with targets of both signs.
void add_crease_angles(const Fixture& f, DihedralAngleTerm& t) {
  int k = 0;
  for (const auto& site : fold_sites(f.model.fine))
    t.add(dihedral_site(f.model.fine, site), (k++ % 2 ? 1.2 : -2.5));
}

// A random non-flat configuration: the rest state moved in plane and lifted out of it.
Dofs perturbed(const Dofs& rest, unsigned seed, double in_plane, double out_of_plane) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0, 1);
  Dofs x = rest;
  for (Eigen::Index v = 0; v < x.size() / 3; ++v) {
    x[3 * v] += in_plane * n(rng);
    x[3 * v + 1] += in_plane * n(rng);
    x[3 * v + 2] += out_of_plane * n(rng);
  }
  return x;
}

using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

Matrix analytic_jacobian(const Term& t, int b, const Dofs& x) {
  std::vector<Eigen::Vector3d> p(t.block_size(b));
  gather_block(t, b, x, p.data());
  Matrix J(t.residual_count(b), 3 * t.block_size(b));
  Eigen::VectorXd r(t.residual_count(b));
  t.evaluate(b, p.data(), r.data(), J.data());
  return J;
}

Eigen::VectorXd residuals(const Term& t, int b, const std::vector<Eigen::Vector3d>& p) {
  Eigen::VectorXd r(t.residual_count(b));
  t.evaluate(b, p.data(), r.data(), nullptr);
  return r;
}

// Central differences, Richardson-extrapolated: (4 D(h/2) - D(h)) / 3.
Matrix numeric_jacobian(const Term& t, int b, const Dofs& x, double h) {
  std::vector<Eigen::Vector3d> p(t.block_size(b));
  gather_block(t, b, x, p.data());
  Matrix J(t.residual_count(b), 3 * t.block_size(b));
  for (int j = 0; j < t.block_size(b); ++j)
    for (int c = 0; c < 3; ++c) {
      auto central = [&](double step) {
        auto plus = p, minus = p;
        plus[j][c] += step;
        minus[j][c] -= step;
        return Eigen::VectorXd((residuals(t, b, plus) - residuals(t, b, minus)) / (2 * step));
      };
      J.col(3 * j + c) = (4 * central(h / 2) - central(h)) / 3;
    }
  return J;
}

template <class TermT>
Matrix autodiff_jacobian(const TermT& t, int b, const Dofs& x) {
  auto* functor = new TermResidualFunctor<TermT>{&t, b};
  ceres::DynamicAutoDiffCostFunction<TermResidualFunctor<TermT>, 4> cost(functor);
  std::vector<Eigen::Vector3d> p(t.block_size(b));
  gather_block(t, b, x, p.data());
  std::vector<const double*> params;
  for (auto& q : p) {
    cost.AddParameterBlock(3);
    params.push_back(q.data());
  }
  cost.SetNumResiduals(t.residual_count(b));
  const int m = t.residual_count(b), k = t.block_size(b);
  std::vector<std::vector<double>> blocks(k, std::vector<double>(3 * m));
  std::vector<double*> jac;
  for (auto& bl : blocks) jac.push_back(bl.data());
  Eigen::VectorXd r(m);
  EXPECT_TRUE(cost.Evaluate(params.data(), r.data(), jac.data()));
  Matrix J(m, 3 * k);
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < m; ++i)
      for (int c = 0; c < 3; ++c) J(i, 3 * j + c) = blocks[j][3 * i + c];
  return J;
}

double relative_error(const Matrix& a, const Matrix& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(b.cwiseAbs().maxCoeff(), 1e-12);
}

template <class TermT>
void check_jacobians(const TermT& t, const Dofs& x, double h = 1e-5, int max_blocks = 200) {
  ASSERT_GT(t.block_count(), 0) << t.name();
  const int step = std::max(1, t.block_count() / max_blocks);
  for (int b = 0; b < t.block_count(); b += step) {
    const Matrix J = analytic_jacobian(t, b, x);
    EXPECT_LT(relative_error(J, numeric_jacobian(t, b, x, h)), 1e-6) << t.name() << " block " << b;
    EXPECT_LT(relative_error(J, autodiff_jacobian(t, b, x)), 1e-10) << t.name() << " block " << b;
    // Ceres' analytic wrapper gives sqrt(w) J.
    TermCost cost(t, b, 4.0);
    std::vector<Eigen::Vector3d> p(t.block_size(b));
    gather_block(t, b, x, p.data());
    std::vector<const double*> params;
    for (auto& q : p) params.push_back(q.data());
    std::vector<std::vector<double>> blocks(t.block_size(b),
                                            std::vector<double>(3 * t.residual_count(b)));
    std::vector<double*> jac;
    for (auto& bl : blocks) jac.push_back(bl.data());
    Eigen::VectorXd r(t.residual_count(b));
    ASSERT_TRUE(cost.Evaluate(params.data(), r.data(), jac.data()));
    EXPECT_NEAR(r.norm(), 2 * residuals(t, b, p).norm(), 1e-12 * (1 + r.norm()));
    for (int j = 0; j < t.block_size(b); ++j)
      for (int i = 0; i < t.residual_count(b); ++i)
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(jac[j][3 * i + c], 2 * J(i, 3 * j + c),
                      1e-12 * (1 + std::abs(J(i, 3 * j + c))));
  }
}

// sum_i y_i Hessian(r_i) against central differences of the analytic gradient J^T y.
void check_second_order(const Term& t, const Dofs& x, int max_blocks = 100) {
  ASSERT_TRUE(t.has_second_order()) << t.name();
  std::mt19937 rng(7);
  std::normal_distribution<double> n(0, 1);
  const int step = std::max(1, t.block_count() / max_blocks);
  for (int b = 0; b < t.block_count(); b += step) {
    const int k = t.block_size(b), m = t.residual_count(b);
    Eigen::VectorXd y(m);
    for (int i = 0; i < m; ++i) y[i] = n(rng);
    std::vector<Eigen::Vector3d> p(k);
    gather_block(t, b, x, p.data());
    Matrix H = Matrix::Zero(3 * k, 3 * k);
    t.add_second_order(b, p.data(), y.data(), H.data());
    auto gradient = [&](const std::vector<Eigen::Vector3d>& q) {
      Matrix J(m, 3 * k);
      Eigen::VectorXd r(m);
      t.evaluate(b, q.data(), r.data(), J.data());
      return Eigen::VectorXd(J.transpose() * y);
    };
    Matrix H_fd(3 * k, 3 * k);
    const double h = 1e-5;
    for (int j = 0; j < k; ++j)
      for (int c = 0; c < 3; ++c) {
        auto central = [&](double s) {
          auto plus = p, minus = p;
          plus[j][c] += s;
          minus[j][c] -= s;
          return Eigen::VectorXd((gradient(plus) - gradient(minus)) / (2 * s));
        };
        H_fd.col(3 * j + c) = (4 * central(h / 2) - central(h)) / 3;
      }
    EXPECT_LT(relative_error(H, H_fd), 1e-6) << t.name() << " block " << b;
    EXPECT_LT(relative_error(H, Matrix(H.transpose())), 1e-14)
        << t.name() << " block " << b << " not symmetric";
  }
}

TEST(TermDerivatives, BendingMatchesFiniteDifferencesAndAutodiff) {
  const auto& f = fixture();
  const LinearPointTerm t = make_bending_term(f.model.fine_topology, f.rest);
  for (unsigned seed : {1u, 2u}) check_jacobians(t, perturbed(f.rest, seed, 0.2, 0.5));
}

TEST(TermDerivatives, BendingVanishesAtRest) {
  const auto& f = fixture();
  const LinearPointTerm t = make_bending_term(f.model.fine_topology, f.rest);
  double worst = 0;
  for (int b = 0; b < t.block_count(); ++b) {
    std::vector<Eigen::Vector3d> p(t.block_size(b));
    gather_block(t, b, f.rest, p.data());
    worst = std::max(worst, residuals(t, b, p).norm());
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(TermDerivatives, IsometryMatchesFiniteDifferencesAndAutodiff) {
  const auto& f = fixture();
  const IsometryTerm t(f.model.fine_topology, f.rest);
  for (unsigned seed : {3u, 4u}) {
    const Dofs x = perturbed(f.rest, seed, 0.2, 0.5);
    check_jacobians(t, x);
    check_second_order(t, x);
  }
}

TEST(TermDerivatives, LinearTermsMatchFiniteDifferencesAndAutodiff) {
  const auto& f = fixture();
  const DogMesh& mesh = f.model.fine;
  LinearPointTerm positions("positions"), edge_points("edge_points"), stitching("stitching");
  positions.add({{0, 1.0}}, Eigen::Vector3d(1, 2, 3));
  positions.add({{mesh.vertex_count() - 1, 1.0}}, Eigen::Vector3d(-1, 0, 2));
  for (const auto& pair : mesh.stitching.pairs) {
    const auto& p = mesh.stitching.points[pair.point];
    const EdgePoint& a = p.copies[pair.a];
    const EdgePoint& b = p.copies[pair.b];
    stitching.add({{a.v1, a.t}, {a.v2, 1 - a.t}, {b.v1, -b.t}, {b.v2, -(1 - b.t)}});
    edge_points.add({{a.v1, a.t}, {a.v2, 1 - a.t}}, Eigen::Vector3d(0.5, 0.25, -1));
  }
  const Dofs x = perturbed(f.rest, 5, 0.2, 0.5);
  check_jacobians(positions, x);
  check_jacobians(edge_points, x);
  check_jacobians(stitching, x);
}

TEST(TermDerivatives, EdgeAnglesMatchFiniteDifferencesAndAutodiff) {
  const auto& f = fixture();
  DihedralAngleTerm t;
  add_crease_angles(f, t);
  check_jacobians(t, perturbed(f.rest, 6, 0.2, 0.5));
  check_jacobians(t, perturbed(f.rest, 16, 0.05, 1e-3));  // nearly flat
}

TEST(TermDerivatives, FoldBiasMatchesFiniteDifferencesAndAutodiff) {
  const auto& f = fixture();
  const auto sites = fold_sites(f.model.fine);
  const FoldBiasTerm t(f.model.fine, sites);
  // The bias saturates (tanh of 1000 B.e) once a site is bent more than about 1e-3, where its
  // derivatives vanish and finite differences measure noise: test where it is not saturated,
  // nearly flat and moderately bent.
  check_jacobians(t, perturbed(f.rest, 7, 0.0, 1e-4), 1e-7);
  check_jacobians(t, perturbed(f.rest, 8, 0.05, 1e-3), 1e-7);
}

// A patch's view of a cross-patch term with the other patches frozen (patch_term.h): residuals
// equal the whole term's at the frozen state, the Jacobian is the inside columns of the whole one,
// and both derivatives agree with finite differences in the patch's own unknowns.
TEST(TermDerivatives, SplitPatchBlocksMatchFiniteDifferences) {
  const auto& f = fixture();
  const DogMesh& mesh = f.model.fine;
  DihedralAngleTerm angles;
  add_crease_angles(f, angles);
  const Dofs x = perturbed(f.rest, 11, 0.2, 0.5);
  int split = 0;
  for (int patch = 0; patch < mesh.patch_count(); ++patch) {
    const int begin = mesh.patch_begin[patch], end = mesh.patch_begin[patch + 1];
    const PatchTerm view(angles, begin, end, &x);
    const PatchTerm whole_only(angles, begin, end);
    EXPECT_EQ(view.block_count() - view.split_block_count(), whole_only.block_count());
    split += view.split_block_count();
    const Dofs local = x.segment(3 * begin, 3 * (end - begin));
    for (int b = 0; b < view.block_count(); ++b) {
      const int src = view.source_block(b);
      const Matrix J = analytic_jacobian(view, b, local);
      const Matrix J_whole = analytic_jacobian(angles, src, x);
      std::vector<Eigen::Vector3d> p(view.block_size(b)), q(angles.block_size(src));
      gather_block(view, b, local, p.data());
      gather_block(angles, src, x, q.data());
      EXPECT_LT((residuals(view, b, p) - residuals(angles, src, q)).cwiseAbs().maxCoeff(), 1e-15);
      for (int j = 0; j < view.block_size(b); ++j) {
        const int v = view.block_vertices(b)[j] + begin;
        const int* whole_vertices = angles.block_vertices(src);
        const int slot = static_cast<int>(
            std::find(whole_vertices, whole_vertices + angles.block_size(src), v) - whole_vertices);
        ASSERT_LT(slot, angles.block_size(src));
        EXPECT_LT(
            relative_error(Matrix(J.middleCols(3 * j, 3)), Matrix(J_whole.middleCols(3 * slot, 3))),
            1e-15);
      }
      EXPECT_LT(relative_error(J, numeric_jacobian(view, b, local, 1e-5)), 1e-6)
          << "patch " << patch << " block " << b;
    }
    if (view.split_block_count() > 0 && view.has_second_order()) check_second_order(view, local);
  }
  EXPECT_GT(split, 0);  // the crease edges' angle blocks reach across patches
}

TEST(TermDerivatives, DogConstraintsAndTheirLagrangianHessianMatchFiniteDifferences) {
  const auto& f = fixture();
  const DogConstraints t(f.model.fine_topology);
  EXPECT_EQ(t.row_count(), 3 * f.model.fine_topology.count(VertexClass::kStar) +
                               f.model.fine_topology.count(VertexClass::kBnd3));
  for (unsigned seed : {9u, 10u}) {
    const Dofs x = perturbed(f.rest, seed, 0.15, 0.4);
    check_jacobians(t, x);
    check_second_order(t, x);
  }
}

// The stacked constraint term of exact stitching: each block is its part's block with the residuals
// and the Jacobian multiplied by the part's scale (checked against the parts and finite
// differences), and its second derivatives match finite differences of its gradient.
TEST(TermDerivatives, StackedTermScalesItsPartsAndMatchesFiniteDifferences) {
  const auto& f = fixture();
  const DogMesh& mesh = f.model.fine;
  const DogConstraints dog(f.model.fine_topology);
  LinearPointTerm stitching("stitching");
  for (const auto& pair : mesh.stitching.pairs) {
    const auto& p = mesh.stitching.points[pair.point];
    const EdgePoint& a = p.copies[pair.a];
    const EdgePoint& b = p.copies[pair.b];
    stitching.add({{a.v1, a.t}, {a.v2, 1 - a.t}, {b.v1, -b.t}, {b.v2, -(1 - b.t)}});
  }
  ASSERT_GT(stitching.block_count(), 0);
  const double scale = 1.7;
  const StackedTerm stacked({{&dog, 1.0}, {&stitching, scale}});
  ASSERT_EQ(stacked.block_count(), dog.block_count() + stitching.block_count());
  EXPECT_FALSE(stacked.is_linear());
  const Dofs x = perturbed(f.rest, 11, 0.15, 0.4);
  for (int b : {0, dog.block_count() - 1, dog.block_count(), stacked.block_count() - 1}) {
    const bool second = b >= dog.block_count();
    const Term& part = second ? static_cast<const Term&>(stitching) : dog;
    const int local = second ? b - dog.block_count() : b;
    const double s = second ? scale : 1.0;
    ASSERT_EQ(stacked.block_size(b), part.block_size(local));
    ASSERT_EQ(stacked.residual_count(b), part.residual_count(local));
    const Matrix J = analytic_jacobian(stacked, b, x);
    EXPECT_LT(relative_error(J, s * analytic_jacobian(part, local, x)), 1e-15) << "block " << b;
    EXPECT_LT(relative_error(J, numeric_jacobian(stacked, b, x, 1e-5)), 1e-6) << "block " << b;
    std::vector<Eigen::Vector3d> p(stacked.block_size(b));
    gather_block(stacked, b, x, p.data());
    Eigen::VectorXd r(stacked.residual_count(b)), q(part.residual_count(local));
    stacked.evaluate(b, p.data(), r.data(), nullptr);
    part.evaluate(local, p.data(), q.data(), nullptr);
    EXPECT_LT((r - s * q).norm(), 1e-15 * (1 + r.norm())) << "block " << b;
  }
  check_second_order(stacked, x);
}

// Constraint values alone (line searches, restoration) take a shorter path than values with the
// Jacobian; both must give the same numbers to the last bit, or results would depend on which
// path computed them.
TEST(TermDerivatives, DogConstraintValuesAloneEqualThoseComputedWithTheJacobian) {
  const auto& f = fixture();
  const DogConstraints t(f.model.fine_topology);
  const Dofs x = perturbed(f.rest, 12, 0.15, 0.4);
  int rows = 0;
  for (int b = 0; b < t.block_count(); ++b) {
    std::vector<Eigen::Vector3d> p(t.block_size(b));
    gather_block(t, b, x, p.data());
    Eigen::VectorXd with_jacobian(t.residual_count(b));
    Matrix J(t.residual_count(b), 3 * t.block_size(b));
    t.evaluate(b, p.data(), with_jacobian.data(), J.data());
    const Eigen::VectorXd alone = residuals(t, b, p);
    for (int i = 0; i < t.residual_count(b); ++i, ++rows)
      EXPECT_EQ(alone[i], with_jacobian[i]) << "block " << b;
  }
  EXPECT_EQ(rows, t.row_count());
}

TEST(TermDerivatives, DogConstraintsVanishOnAFlatGridAndOnADevelopableBend) {
  const auto& f = fixture();
  const DogConstraints t(f.model.fine_topology);
  // Bending the flat sheet into a cylinder around the y axis is a DOG motion (the grid stays
  // orthogonal and geodesic): every constraint stays zero.
  Dofs x = f.rest;
  const double R = 7;
  for (Eigen::Index v = 0; v < x.size() / 3; ++v) {
    const double u = x[3 * v];
    x[3 * v] = R * std::sin(u / R);
    x[3 * v + 2] = R * (1 - std::cos(u / R));
  }
  double worst_flat = 0, worst_bent = 0;
  for (int b = 0; b < t.block_count(); ++b) {
    std::vector<Eigen::Vector3d> p(t.block_size(b));
    gather_block(t, b, f.rest, p.data());
    worst_flat = std::max(worst_flat, residuals(t, b, p).cwiseAbs().maxCoeff());
    gather_block(t, b, x, p.data());
    worst_bent = std::max(worst_bent, residuals(t, b, p).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst_flat, 1e-14);
  EXPECT_LT(worst_bent, 1e-12);
  // A shear is not a DOG motion.
  Dofs sheared = f.rest;
  for (Eigen::Index v = 0; v < x.size() / 3; ++v) sheared[3 * v] += 0.3 * sheared[3 * v + 1];
  double worst_shear = 0;
  for (int b = 0; b < t.block_count(); ++b) {
    std::vector<Eigen::Vector3d> p(t.block_size(b));
    gather_block(t, b, sheared, p.data());
    worst_shear = std::max(worst_shear, residuals(t, b, p).cwiseAbs().maxCoeff());
  }
  EXPECT_GT(worst_shear, 0.1);
}

}  // namespace
}  // namespace sdog
