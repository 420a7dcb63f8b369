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
// edge and get the smallest grid. Private to src/.
#pragma once

#include <limits>
#include <string>

#include "scene/film_case.hpp"
#include "tehl/ehl/grid.hpp"

namespace tehl::internal {

// The smallest automatic grid: the resolution of the default grid, whose Richardson error at
// M = 20, L = 10 is under 1 % (docs/validation.md section 4) [-].
inline constexpr int kAutomaticGridMinNodes = 513;
// The largest: a 16385-node film takes about 0.3 s cold and 40 MB (docs/performance.md) [-].
inline constexpr int kAutomaticGridMaxNodes = 16385;

class GridChoice {
 public:
  GridChoice(const FilmCase& film, double e_prime_pa);
  // One film the grid must carry: reduced radius [m], entrainment speed (u1 + u2)/2 [m/s] and
  // load per unit width [N/m].
  void Add(double reduced_radius_m, double um_m_s, double load_n_per_m);
  // The grid over `units`: [numerics] grid_points when the case gives it, else automatic.
  UniformGrid Grid(const GridUnits& units) const;
  // How the node count was chosen, for the run's report and the result file.
  std::string Rule(const GridUnits& units) const;

 private:
  int Nodes(const GridUnits& units) const;
  const FilmCase& film_;
  double e_prime_pa_;
  double eta0_pa_s_, alpha_per_pa_;  // inlet viscosity and pressure-viscosity coefficient
  double edge_m_ = std::numeric_limits<double>::infinity();  // narrowest estimated edge [m]
};

}  // namespace tehl::internal
