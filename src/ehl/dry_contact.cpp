#include "tehl/ehl/dry_contact.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "tehl/error.hpp"

namespace tehl {

namespace {

std::string Num(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

// Grid rules are checked here, before ElasticDeflection repeats its own (n >= 1).
int CheckedGridSize(int n, double x0_m) {
  ProblemList problems;
  if (n < 3) {
    problems.Add({"", 0, "DryContactSolver::n", std::to_string(n), "must be >= 3",
                  "a grid of at least three points across the contact"});
  }
  if (!std::isfinite(x0_m)) {
    problems.Add({"", 0, "DryContactSolver::x0_m", Num(x0_m), "must be finite [m]",
                  "the position of the first grid point"});
  }
  problems.ThrowIfAny();
  return n;
}

}  // namespace

std::string ToString(DryContactSolver::Termination t) {
  switch (t) {
    case DryContactSolver::Termination::kConverged:
      return "converged";
    case DryContactSolver::Termination::kMaxIterations:
      return "max_iterations";
    case DryContactSolver::Termination::kContactAtGridEdge:
      return "contact_at_grid_edge";
    case DryContactSolver::Termination::kNotSolved:
      return "not_solved";
  }
  return "unknown";
}

std::vector<std::string> DryContactSolver::Options::Validate() const {
  std::vector<std::string> bad;
  auto rule = [&](bool ok, const char* field, auto value, const char* constraint) {
    if (ok) return;
    std::ostringstream m;
    m << "DryContactSolver::Options::" << field << " = " << value << " violates " << constraint;
    bad.push_back(m.str());
  };
  rule(tolerance > 0 && std::isfinite(tolerance), "tolerance", tolerance, "> 0");
  rule(max_iterations >= 1, "max_iterations", max_iterations, ">= 1");
  return bad;
}

std::string DryContactSolver::Summary::BriefReport() const {
  std::ostringstream s;
  s << "dry contact: " << ToString(termination) << " after " << iterations << " iterations, change "
    << Num(relative_change) << ", load error " << Num(load_balance_error) << ", p_max "
    << Num(max_pressure_pa) << " Pa, half-width " << Num(contact_half_width_m) << " m";
  return s.str();
}

DryContactSolver::DryContactSolver(
    int n, double x0_m, double dx_m, double e_prime_pa, FftPlanEffort effort)
    : x0_m_(x0_m), deflection_(CheckedGridSize(n, x0_m), dx_m, e_prime_pa, effort) {}

DryContactSolver::Summary DryContactSolver::Solve(const Options& options,
                                                  const DryContactProblem& problem,
                                                  DryContactSolution* solution) const {
  const auto start = std::chrono::steady_clock::now();
  const int n = size();
  const double dx = dx_m();
  {
    ProblemList problems;
    for (const std::string& m : options.Validate()) {
      problems.Add({"", 0, "DryContactSolver::Options", "", m, "see dry_contact.hpp"});
    }
    const double r = problem.reduced_radius_m, w = problem.load_n_per_m;
    if (!(r > 0) || !std::isfinite(r)) {
      problems.Add({"", 0, "DryContactProblem::reduced_radius_m", Num(r), "must be > 0 [m]",
                    "a positive reduced radius"});
    }
    if (!(w > 0) || !std::isfinite(w)) {
      problems.Add({"", 0, "DryContactProblem::load_n_per_m", Num(w), "must be > 0 [N/m]",
                    "a positive load per unit width"});
    }
    const auto& s = problem.surface_height_m;
    if (!s.empty() && static_cast<int>(s.size()) != n) {
      problems.Add({"", 0, "DryContactProblem::surface_height_m", std::to_string(s.size()),
                    "must have one value per grid point (" + std::to_string(n) + ")",
                    "empty (smooth) or n heights"});
    } else if (!std::all_of(s.begin(), s.end(), [](double z) { return std::isfinite(z); })) {
      problems.Add({"", 0, "DryContactProblem::surface_height_m", "non-finite value",
                    "must be finite [m]", "finite heights"});
    }
    problems.ThrowIfAny();
  }
  const double w = problem.load_n_per_m;

  // Rigid gap without h0: x^2/(2R) - s.
  std::vector<double> rigid(n);
  for (int i = 0; i < n; ++i) {
    const double x = X(i);
    rigid[i] = x * x / (2.0 * problem.reduced_radius_m) -
               (problem.surface_height_m.empty() ? 0.0 : problem.surface_height_m[i]);
  }

  // Polonsky & Keer (1999), section 3, steps 1-8.
  std::vector<double> p(n, w / (n * dx)), p_old(n), g(n), t(n, 0.0), r(n);
  double g_norm_old = 1.0;
  bool conjugate = false;  // PK's delta: 0 right after the contact set grew
  Summary summary;
  summary.termination = Termination::kMaxIterations;
  int it = 0;
  for (it = 1; it <= options.max_iterations; ++it) {
    deflection_.Apply(p.data(), g.data());
    double g_mean = 0.0;
    int contact = 0;
    for (int i = 0; i < n; ++i) {
      g[i] += rigid[i];
      if (p[i] > 0) {
        g_mean += g[i];
        ++contact;
      }
    }
    g_mean /= std::max(contact, 1);
    double g_norm = 0.0;
    for (int i = 0; i < n; ++i) {
      g[i] -= g_mean;  // gap relative to the current approach h0 = -g_mean
      if (p[i] > 0) g_norm += g[i] * g[i];
    }
    const double beta = conjugate ? g_norm / g_norm_old : 0.0;
    for (int i = 0; i < n; ++i) t[i] = p[i] > 0 ? g[i] + beta * t[i] : 0.0;
    g_norm_old = g_norm;

    deflection_.Apply(t.data(), r.data());
    double r_mean = 0.0;
    for (int i = 0; i < n; ++i) {
      if (p[i] > 0) r_mean += r[i];
    }
    r_mean /= std::max(contact, 1);
    double num = 0.0, den = 0.0;
    for (int i = 0; i < n; ++i) {
      if (p[i] > 0) {
        num += g[i] * t[i];
        den += (r[i] - r_mean) * t[i];
      }
    }
    const double tau = den != 0.0 ? num / den : 0.0;

    p_old = p;
    for (int i = 0; i < n; ++i) {
      if (p[i] > 0) p[i] = std::max(p[i] - tau * t[i], 0.0);
    }
    bool grew = false;  // points without pressure that penetrate get loaded (PK step 6)
    for (int i = 0; i < n; ++i) {
      if (p[i] == 0.0 && g[i] < 0) {
        p[i] = -tau * g[i];
        grew = true;
      }
    }
    conjugate = !grew;
    double load = 0.0;
    for (double pi : p) load += pi * dx;
    if (load <= 0) {  // every point released: restart from uniform pressure
      std::fill(p.begin(), p.end(), w / (n * dx));
      conjugate = false;
      continue;
    }
    double change = 0.0;
    for (int i = 0; i < n; ++i) {
      p[i] *= w / load;
      change += std::abs(p[i] - p_old[i]) * dx;
    }
    summary.relative_change = change / w;
    if (summary.relative_change < options.tolerance) {
      summary.termination = Termination::kConverged;
      break;
    }
  }
  summary.iterations = std::min(it, options.max_iterations);

  // Final state from the final pressure.
  DryContactSolution& out = *solution;
  out.pressure_pa = p;
  out.deflection_m.assign(n, 0.0);
  deflection_.Apply(p.data(), out.deflection_m.data());
  double g_mean = 0.0;
  int contact = 0;
  for (int i = 0; i < n; ++i) {
    if (p[i] > 0) {
      g_mean += out.deflection_m[i] + rigid[i];
      ++contact;
    }
  }
  g_mean /= std::max(contact, 1);
  out.approach_m = -g_mean;
  out.gap_m.resize(n);
  double load = 0.0, p_max = 0.0, g_max = 0.0;
  int first = n, last = -1;
  for (int i = 0; i < n; ++i) {
    out.gap_m[i] = out.approach_m + out.deflection_m[i] + rigid[i];
    load += p[i] * dx;
    p_max = std::max(p_max, p[i]);
    g_max = std::max(g_max, std::abs(out.gap_m[i]));
    if (p[i] > 0) {
      first = std::min(first, i);
      last = i;
    }
  }
  double pg = 0.0;
  for (int i = 0; i < n; ++i) pg = std::max(pg, p[i] * std::abs(out.gap_m[i]));
  summary.load_balance_error = std::abs(load - w) / w;
  summary.complementarity = (p_max > 0 && g_max > 0) ? pg / (p_max * g_max) : 0.0;
  summary.max_pressure_pa = p_max;
  if (last >= 0) {
    summary.contact_begin_m = X(first) - 0.5 * dx;
    summary.contact_end_m = X(last) + 0.5 * dx;
    summary.contact_half_width_m = 0.5 * (summary.contact_end_m - summary.contact_begin_m);
  }
  if (summary.termination == Termination::kConverged && (p.front() > 0 || p.back() > 0)) {
    summary.termination = Termination::kContactAtGridEdge;
  }
  switch (summary.termination) {
    case Termination::kConverged:
      summary.message = "Converged.";
      break;
    case Termination::kMaxIterations:
      summary.message =
          "No convergence in max_iterations = " + std::to_string(options.max_iterations) +
          " iterations.";
      break;
    case Termination::kContactAtGridEdge:
      summary.message = "The contact reaches the end of the grid: widen the grid.";
      break;
    case Termination::kNotSolved:
      break;
  }
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace tehl
