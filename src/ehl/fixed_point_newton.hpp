// Newton-Krylov on a fixed point x = G(x) whose plain iteration x <- G(x) diverges: the
// coupling of a thermal line contact, G = temperature of the energy equation at the pressure
// solved with the film at x. Where G has an eigenvalue above 1 (a loop of positive gain, as
// the film expanding with the heat of its own pressure peak, docs/thermal.md) no relaxation
// of the plain iteration converges; Newton on F(x) = G(x) - x does. Private to src/ehl.
//
// Each Newton step solves (G'(x) - I) d = -F(x) by GMRES without preconditioner (G' has few
// eigenvalues far from 0, so few Krylov steps), the products by one-sided finite differences
// G'(x) v ~ (G(x + s v/|v|) - G(x)) |v| / s, |v| the max-norm and s = fd_step (backward where
// the probe would leave the bounds); then a
// backtracking line search on ||F||_2 (Armijo, halving the step; Kelley 2003, "Solving
// Nonlinear Equations with Newton's Method", SIAM, sections 3.2 and 1.6; Knoll & Keyes 2004,
// "Jacobian-free Newton-Krylov methods", J. Comput. Phys. 193:357).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

namespace tehl::internal {

struct FixedPointNewtonOptions {
  double tolerance = 1e-2;         // converged when max |G(x) - x| < this [unit of x]
  double fd_step = 1e-2;           // max-norm of the finite-difference perturbation [unit of x]
  int max_newton_iterations = 30;  // [-]
  int max_krylov_iterations = 40;  // per Newton step [-]
  double krylov_tolerance = 1e-2;  // relative residual of each linear solve [-]
  int max_step_halvings = 12;      // line search [-]
  int max_map_evaluations = 250;   // budget of G calls over the whole solve [-]
  // Stalled when this many Newton steps in a row each lower ||G(x) - x||_2 by less than
  // the fraction stall_decrease [-].
  int stall_steps = 2;
  double stall_decrease = 1e-3;
  // The first step tried is at most this long in the max-norm (near a fold of the solution
  // curve G' has an eigenvalue close to 1 and the Newton step is far too long) [unit of x].
  double max_step = 50.0;
  // Each iterate is clamped to [lower, upper] (the range where G is defined) [unit of x];
  // per component where lower_bounds / upper_bounds have the size of x.
  double lower = -1e300, upper = 1e300;
  Eigen::VectorXd lower_bounds, upper_bounds;
};

struct FixedPointNewtonResult {
  bool converged = false;
  int newton_iterations = 0;      // [-]
  int krylov_iterations = 0;      // over all Newton steps [-]
  int map_evaluations = 0;        // calls of G [-]
  double residual = -1;           // max |G(x) - x| at the returned x [unit of x]
  std::vector<double> history;    // max |G(x) - x| after each Newton step [unit of x]
  std::string message;
};

// G(x) -> *g; false when G cannot be evaluated at x (the step is then shortened).
using FixedPointMap = std::function<bool(const Eigen::VectorXd& x, Eigen::VectorXd* g)>;

// x: the start on entry, the last accepted iterate on exit (G was last evaluated there
// unless the result says otherwise: callers re-evaluate G at x to restore their state).
FixedPointNewtonResult SolveFixedPoint(const FixedPointMap& map,
                                       const FixedPointNewtonOptions& options,
                                       Eigen::VectorXd* x);

}  // namespace tehl::internal
