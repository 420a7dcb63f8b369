// A Newton system of the EHL solver (src/ehl/newton_system.hpp) for linear-solver tests: random
// Reynolds stencils with order-one scaled entries (a Poiseuille-like (-1, 2, -1) stencil plus
// upwind-like Couette weights, perturbed; the row weights c_i make c_i (p_ref A + h_ref B) of
// order one, as the solver's row weights do, so J is well conditioned), the real elastic kernel
// of steel on steel, and the last fifth of the rows cavitated (outlet rows).
#pragma once

#include <Eigen/Core>
#include <random>

#include "ehl/newton_system.hpp"
#include "tehl/ehl/elastic_deflection.hpp"

namespace tehl::testing {

struct RandomNewtonSystem {
  // `effort`: the FFTW plans of the kernel (benchmarks measure with the solver's kMeasure).
  RandomNewtonSystem(int n, unsigned seed, FftPlanEffort effort = FftPlanEffort::kEstimate)
      : rng(seed), kernel(n, 1e-6, 226.4e9, effort), a(n, 4), b(n, 4), c(n) {
    const double p_ref = 1e9, h_ref = 1e-7;  // [Pa], [m]
    std::uniform_real_distribution<double> u(0.5, 1.5);
    for (int i = 0; i < n; ++i) {
      a.row(i) << 0.1 * u(rng), -1.0 * u(rng), 2.0 * u(rng), -1.0 * u(rng);
      b.row(i) << 0.5 * u(rng), -2.0 * u(rng), 1.5 * u(rng), 0.0;
      a.row(i) /= p_ref;
      b.row(i) /= h_ref;
      c[i] = -1.0 / (2.0 * u(rng));
    }
    sys.n = n;
    sys.dx = 1e-6;  // [m]
    sys.p_ref = p_ref;
    sys.h_ref = h_ref;
    sys.row_scale = &c;
    sys.load = 1e5;  // [N/m]
    sys.a = &a;
    sys.b = &b;
    sys.elastic = &kernel;
    sys.cavitated.assign(n, 0);
    for (int i = n - n / 5; i < n - 1; ++i) sys.cavitated[i] = 1;
  }
  RandomNewtonSystem(const RandomNewtonSystem&) = delete;  // sys points into this object
  RandomNewtonSystem& operator=(const RandomNewtonSystem&) = delete;

  // A vector of the Newton unknowns' size (n - 1) with entries uniform in [-0.5, 0.5).
  Eigen::VectorXd RandomVector() {
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    Eigen::VectorXd v(sys.n - 1);
    for (int i = 0; i < sys.n - 1; ++i) v[i] = u(rng);
    return v;
  }

  std::mt19937 rng;
  ElasticDeflection kernel;
  Eigen::Matrix<double, Eigen::Dynamic, 4> a, b;
  Eigen::VectorXd c;
  internal::NewtonSystem sys;
};

}  // namespace tehl::testing
