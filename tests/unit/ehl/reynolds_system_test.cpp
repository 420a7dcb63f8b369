// The discrete Reynolds residual's analytic local derivatives against central finite
// differences, and the Newton Jacobian's matrix-free product against its dense form.
#include "ehl/reynolds_system.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "ehl/newton_system.hpp"
#include "support/test_lubricants.hpp"
#include "tehl/ehl/elastic_deflection.hpp"

namespace tehl::internal {
namespace {

struct Fixture {
  int n = 41;
  double dx = 5e-6;
  Eigen::VectorXd p, h;
  Lubricant oil = tehl::testing::ReferenceOil();
  FluidLaws fluid;
  TimeDerivative td;
  Fixture() {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    p.resize(n);
    h.resize(n);
    for (int i = 0; i < n; ++i) {
      const double x = (i - n / 2) * dx / 1e-4;
      p[i] = (i == 0 || i == n - 1) ? 0.0 : 5e8 * std::max(0.05, 1 - x * x) * (0.9 + 0.2 * u(rng));
      h[i] = 1e-7 * (1.0 + 0.3 * u(rng) + x * x);
    }
    fluid.viscosity = &oil.viscosity();
    fluid.density = &oil.density();
    fluid.temperature_k = tehl::testing::kReferenceT0;
    td.active = true;
    td.a0 = 1.5e4;
    td.a1 = -2e4;
    td.a2 = 0.5e4;
    td.q1 = Eigen::VectorXd::Constant(n, 870 * 1e-7);
    td.q2 = Eigen::VectorXd::Constant(n, 870 * 1.1e-7);
  }
};

class ReynoldsDerivatives : public ::testing::TestWithParam<int> {};

TEST_P(ReynoldsDerivatives, MatchCentralDifferences) {
  Fixture f;
  const double um = 1.3;
  ReynoldsSystem sys(f.n, f.dx, GetParam());
  sys.Evaluate(f.fluid, um, f.p, f.h, f.td, true);
  const auto a = sys.dr_dp();
  const auto b = sys.dr_dh();
  for (int i = 2; i < f.n - 1; ++i) {
    // Errors are measured against the row's largest derivative: the residual is a sum of
    // large terms that cancel, so single small entries carry the rounding of the row.
    const double row_scale = std::max(a.row(i).cwiseAbs().maxCoeff() * 1e8,
                                      b.row(i).cwiseAbs().maxCoeff() * 1e-7);
    for (int c = 0; c < 4; ++c) {
      const int k = i - 2 + c;
      for (int which = 0; which < 2; ++which) {
        if (which == 0 && (k == 0 || k == f.n - 1)) continue;  // fixed p = 0 at the ends
        Eigen::VectorXd p = f.p, h = f.h;
        Eigen::VectorXd& v = which == 0 ? p : h;
        const double step = 1e-6 * std::abs(v[k]) + (which == 0 ? 1.0 : 1e-15);
        v[k] += step;
        sys.Evaluate(f.fluid, um, p, h, f.td, false);
        const double rp = sys.residual()[i];
        v[k] -= 2 * step;
        sys.Evaluate(f.fluid, um, p, h, f.td, false);
        const double rm = sys.residual()[i];
        const double fd = (rp - rm) / (2 * step);
        const double an = which == 0 ? a(i, c) : b(i, c);
        const double scale = row_scale / (which == 0 ? 1e8 : 1e-7);
        // Central differences carry O(step^2) truncation: 1e-6 relative is ample.
        EXPECT_NEAR(an / scale, fd / scale, 1e-6)
            << (which ? "dr/dh" : "dr/dp") << " row " << i << " node " << k;
      }
    }
  }
}
INSTANTIATE_TEST_SUITE_P(UpwindOrders, ReynoldsDerivatives, ::testing::Values(1, 2));

TEST(NewtonSystem, MatrixFreeProductEqualsDenseJacobian) {
  Fixture f;
  ReynoldsSystem sys(f.n, f.dx, 2);
  sys.Evaluate(f.fluid, 1.0, f.p, f.h, f.td, true);
  ElasticDeflection k(f.n, f.dx, 226.4e9);
  NewtonSystem ns;
  ns.n = f.n;
  ns.dx = f.dx;
  ns.p_ref = 5e8;
  ns.h_ref = 1e-7;
  const Eigen::VectorXd weights = Eigen::VectorXd::LinSpaced(f.n, -1.0, -3.0);
  ns.row_scale = &weights;
  ns.load = 1e5;
  ns.a = &sys.dr_dp();
  ns.b = &sys.dr_dh();
  ns.elastic = &k;
  ns.cavitated.assign(f.n, 0);
  ns.cavitated[f.n - 3] = 1;
  const Eigen::MatrixXd dense = ns.Dense();
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  Eigen::VectorXd x(f.n - 1), y;
  for (int i = 0; i < x.size(); ++i) x[i] = g(rng);
  ns.Apply(x, &y);
  const Eigen::VectorXd yd = dense * x;
  EXPECT_LT((y - yd).lpNorm<Eigen::Infinity>() / yd.lpNorm<Eigen::Infinity>(), 1e-12);
}

}  // namespace
}  // namespace tehl::internal
