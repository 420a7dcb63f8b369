// [numerics] grid_points = 0 (the default): the grid chosen from the films it must carry.
//
// A film whose Hertzian edge spans few grid cells comes out too thin, by about 1.1 / N^2 with N
// cells across the edge (include/tehl/ehl/hertz_edge.hpp, docs/validation.md section 3.2), and
// the edge narrows as the load parameter M grows. The automatic grid is the fewest nodes
// 2^k + 1, from kAutomaticGridMinNodes up to kAutomaticGridMaxNodes, that put
// kEdgeResolvedCells cells across the edge of every film the run will meet, each edge estimated
// before anything is solved from the contact's R, b and an estimated central film: the thinner
// of Moes' and Pan-Hamrock's fits at the inlet viscosity (computed films lie within 0.97 x
// Pan-Hamrock ... 1.03 x Moes, docs/validation.md section 3). Rigid films have no Hertzian
// edge and get the smallest grid.
//
// The automatic grid also reaches far enough upstream: a piezoviscous film whose inlet at
// x_start_b would thin it by more than kInletTargetDeficit (PredictInletTruncation,
// include/tehl/ehl/inlet_truncation.hpp: Grubin's estimate before solving, 0.99-1.06 times
// the measured deficit on steel discs) gets the inlet that keeps it below, and a nearly
// isoviscous, nearly rigid one the isoviscous inlet length; both at most R/2. Light loads and
// high speeds need this: a gear pair at Moes' M = 0.35 lost 40 % of its film at -4.5 b. A
// case that sets grid_points keeps its inlet, and `Rule` gives the predicted deficit there.
// Private to src/.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "scene/film_case.hpp"
#include "tehl/ehl/grid.hpp"

namespace tehl::internal {

// The smallest automatic grid: the resolution of the default grid, whose Richardson error at
// M = 20, L = 10 is under 1 % (docs/validation.md section 4) [-].
inline constexpr int kAutomaticGridMinNodes = 513;
// The largest: a 16385-node film takes about 0.3 s cold and 40 MB (docs/performance.md) [-].
inline constexpr int kAutomaticGridMaxNodes = 16385;
// The most nodes [numerics] grid_points accepts (case_schema.cpp) [-].
inline constexpr int kMaxGridPoints = 1000000;

// The largest film deficit the automatic grid's inlet is sized for; below the inlet note's
// 0.5 % (docs/results.md "The inlet note") with the prediction's scatter [-].
inline constexpr double kInletTargetDeficit = 0.004;
// `tehl case --check` and `tehl run` note an inlet that thins the films by more [-].
inline constexpr double kInletNoteDeficit = 0.005;
// A mesh cycle's films that size the inlet carry at least this part of its largest load: the
// double-contact zone carries about half of the single-contact zone's [-].
inline constexpr double kInletSizingLoadFraction = 0.4;

class GridChoice {
 public:
  GridChoice(const FilmCase& film, double e_prime_pa);
  // One film the grid must carry: reduced radius [m], entrainment speed (u1 + u2)/2 [m/s] and
  // load per unit width [N/m]. `sizes_inlet`: the film also sizes the inlet (a mesh cycle
  // leaves out its lightly loaded films, which would stretch the grid of every film).
  void Add(double reduced_radius_m, double um_m_s, double load_n_per_m, bool sizes_inlet = true);
  // The grid over `units` (stretched upstream where an automatic grid's films need it):
  // [numerics] grid_points when the case gives it, else automatic.
  UniformGrid Grid(const GridUnits& units) const;
  // How the node count and the inlet were chosen, for the run's report and the result file.
  std::string Rule(const GridUnits& units) const;
  // For a grid whose inlet thins the films by more than kInletNoteDeficit (estimated before
  // solving; a case that sets grid_points or x_start_b): what it costs and what removes it.
  // "" otherwise.
  std::string InletNote(const GridUnits& units) const;

 private:
  struct InletFilm {
    double r_m, um_m_s, w_n_per_m, b_m, h_m;  // h: the estimated central film
  };
  GridUnits Stretched(const GridUnits& units) const;
  int Nodes(const GridUnits& units) const;
  // The largest predicted deficit of the inlet-sizing films with the grid starting at x0 < 0
  // [-]; 0 without estimate.
  double WorstDeficit(double x0_m) const;
  const FilmCase& film_;
  double e_prime_pa_;
  double eta0_pa_s_, alpha_per_pa_;  // inlet viscosity and pressure-viscosity coefficient
  double edge_m_ = std::numeric_limits<double>::infinity();  // narrowest estimated edge [m]
  double inlet_need_m_ = 0;  // the longest inlet Grubin's estimate asks for [m]
  GridUnits isoviscous_;     // the nearly isoviscous films' units (GridUnitsFor) [m]
  std::vector<InletFilm> inlet_films_;
};

}  // namespace tehl::internal
