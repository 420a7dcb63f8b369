#include "tehl/ehl/grid.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "base/number_text.hpp"
#include "tehl/ehl/film_effects.hpp"
#include "tehl/error.hpp"

namespace tehl {

UniformGrid::UniformGrid(double x_start_m, double x_end_m, int n) {
  ProblemList bad;
  if (n < 5)
    bad.Add({"", 0, "UniformGrid::n", std::to_string(n), "too few nodes", "n >= 5"});
  if (!(x_end_m > x_start_m) || !std::isfinite(x_start_m) || !std::isfinite(x_end_m))
    bad.Add({"", 0, "UniformGrid::x_end_m", internal::FormatReal(x_end_m),
             "must exceed x_start_m = " + internal::FormatReal(x_start_m), "x_end_m > x_start_m"});
  bad.ThrowIfAny();
  n_ = n;
  x0_ = x_start_m;
  dx_ = (x_end_m - x_start_m) / (n - 1);
}

UniformGrid UniformGrid::AroundHertz(double b, int n, double start_b, double end_b) {
  ProblemList bad;
  if (!(b > 0) || !std::isfinite(b))
    bad.Add({"", 0, "UniformGrid::AroundHertz half_width_m", internal::FormatReal(b),
             "must be finite and > 0 [m]", "the Hertz half-width b of the largest load"});
  if (!(end_b > start_b) || !std::isfinite(start_b) || !std::isfinite(end_b))
    bad.Add({"", 0, "UniformGrid::AroundHertz end_b", internal::FormatReal(end_b),
             "must exceed start_b = " + internal::FormatReal(start_b), "start_b < end_b"});
  bad.ThrowIfAny();
  return UniformGrid(start_b * b, end_b * b, n);
}

std::vector<double> UniformGrid::Nodes() const {
  std::vector<double> x(n_);
  for (int i = 0; i < n_; ++i) x[i] = this->x(i);
  return x;
}

int UniformGrid::NodesFromStart(double x_start_m) const {
  long cells = std::lround(std::ceil((x_end_m() - x_start_m) / dx_ - 1e-9));
  if (cells % 2) ++cells;
  return static_cast<int>(std::max(cells, 4L) + 1);
}

int UniformGrid::NearestNode(double x_m) const {
  const long i = std::lround((x_m - x0_) / dx_);
  return static_cast<int>(std::clamp<long>(i, 0, n_ - 1));
}

std::string FilmEffects::ToString() const {
  std::string s;
  auto add = [&](bool on, const char* name) {
    if (!on) return;
    if (!s.empty()) s += ' ';
    s += name;
  };
  add(elastic, "elastic");
  add(piezoviscous, "piezoviscous");
  add(compressible, "compressible");
  add(transient, "transient");
  add(roughness, "roughness");
  add(thermal, "thermal");
  add(non_newtonian, "non_newtonian");
  add(finite_peclet, "finite_peclet");
  return s.empty() ? "rigid isoviscous incompressible steady" : s;
}

}  // namespace tehl
