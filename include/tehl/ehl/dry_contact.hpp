// Dry (unlubricated) line contact of two elastic cylinders, optionally rough.
//
// On the uniform grid x_i = x_0 + i dx (i = 0..n-1) of an ElasticDeflection, find the pressure
// p_i [Pa] and the rigid approach h0 [m] such that, with the gap
//   g_i = h0 + x_i^2/(2R) + v_i - s_i,   v = K p (elastic_deflection.hpp),
//   s_i = height1(x_i) + height2(x_i) (surface_roughness.hpp sign convention, 0 if smooth),
// the contact conditions hold:
//   p_i >= 0,  g_i >= 0,  p_i g_i = 0,  sum_i p_i dx = w.
// Method: the projected conjugate-gradient method of Polonsky & Keer, Wear 231 (1999) 206-219,
// with the load enforced by rescaling and h0 as the Lagrange multiplier of the load (the mean
// gap over the contact set). Each iteration costs two O(n log n) deflection evaluations.
//
// For smooth surfaces the result is the Hertz line contact (VALIDATION.md section 1):
//   b = sqrt(8 w R / (pi E')),  p(x) = p_H sqrt(1 - x^2/b^2),  p_H = sqrt(w E' / (2 pi R)).
// The grid must contain the whole contact; the summary says when the contact reaches its edge.
#pragma once

#include <string>
#include <vector>

#include "tehl/ehl/elastic_deflection.hpp"

namespace tehl {

struct DryContactProblem {
  double reduced_radius_m = 0;  // R, 1/R = 1/rho1 + 1/rho2, > 0 [m]
  double load_n_per_m = 0;      // w, load per unit face width, > 0 [N/m]
  // s_i = height1 + height2 at the grid points (positive = into the gap); empty = smooth.
  // Fill with SampleHeights() of both surfaces and add them [m].
  std::vector<double> surface_height_m;
};

struct DryContactSolution {
  std::vector<double> pressure_pa;   // p_i [Pa]
  std::vector<double> gap_m;         // g_i = h0 + x_i^2/(2R) + v_i - s_i, >= 0 [m]
  std::vector<double> deflection_m;  // v_i = (K p)_i [m]
  double approach_m = 0;             // h0 (its additive constant follows K's, see v) [m]
};

class DryContactSolver {
 public:
  struct Options {
    // Stop when dx sum|p_k - p_{k-1}| / w < this (Polonsky & Keer's criterion) [-].
    double tolerance = 1e-10;
    int max_iterations = 10000;  // conjugate-gradient iterations, >= 1 [-]
    // Every violated rule, e.g. "DryContactSolver::Options::tolerance = 0 violates > 0".
    std::vector<std::string> Validate() const;
  };

  enum class Termination {
    kConverged,          // tolerance met
    kMaxIterations,      // max_iterations reached first
    kContactAtGridEdge,  // converged, but the contact reaches the first or last grid point:
                         // the grid is too short and the pressure is truncated
    kNotSolved,          // Solve() was not called or failed
  };

  struct Summary {
    Termination termination = Termination::kNotSolved;
    std::string message = "Solve() was not called.";
    int iterations = -1;
    double relative_change = -1;       // dx sum|p_k - p_{k-1}| / w of the last iteration [-]
    double load_balance_error = -1;    // |dx sum p - w| / w [-]
    double complementarity = -1;       // max_i p_i g_i / (p_max * max|g|), 0 when exact [-]
    double max_pressure_pa = -1;       // [Pa]
    double contact_begin_m = 0;        // left edge of the first loaded cell (x - dx/2) [m]
    double contact_end_m = 0;          // right edge of the last loaded cell (x + dx/2) [m]
    double contact_half_width_m = -1;  // (contact_end - contact_begin) / 2 [m]
    double wall_time_s = -1;           // [s]
    bool usable() const { return termination == Termination::kConverged; }
    std::string BriefReport() const;
  };

  // The grid: n points from x0_m with spacing dx_m; E' the reduced modulus [Pa].
  // Throws InputError for n < 3, dx_m <= 0 or e_prime_pa <= 0. A solve takes a few hundred
  // deflection evaluations, too few to repay FFTW_MEASURE planning: kEstimate by default.
  DryContactSolver(int n,
                   double x0_m,
                   double dx_m,
                   double e_prime_pa,
                   FftPlanEffort effort = FftPlanEffort::kEstimate);

  int size() const { return deflection_.size(); }
  double x0_m() const { return x0_m_; }
  double dx_m() const { return deflection_.dx_m(); }
  double X(int i) const { return x0_m_ + i * deflection_.dx_m(); }  // x_i [m]
  const ElasticDeflection& deflection() const { return deflection_; }

  // Solves; throws InputError for invalid options or problem (non-positive R or w, wrong
  // surface_height_m size). Not converging is reported in the Summary. Not thread-safe (the
  // deflection's FFT buffers are reused): one solver per thread.
  Summary Solve(const Options& options,
                const DryContactProblem& problem,
                DryContactSolution* solution) const;

 private:
  double x0_m_;
  ElasticDeflection deflection_;
};

std::string ToString(DryContactSolver::Termination t);

}  // namespace tehl
