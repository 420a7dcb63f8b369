// The uniform grid of a line contact, in a frame moving with the contact point:
// x_i = x_start + i dx, i = 0 .. n-1. Pressure nodes sit at x_i; for the elastic
// deflection each node owns the cell [x_i - dx/2, x_i + dx/2].
#pragma once

#include <vector>

namespace tehl {

class UniformGrid {
 public:
  UniformGrid() = default;
  // n >= 5 nodes from x_start_m to x_end_m > x_start_m. Throws InputError otherwise.
  UniformGrid(double x_start_m, double x_end_m, int n);
  // The grid -start_b*b .. end_b*b in units of a Hertz half-width b (default -4.5 b .. 1.5 b).
  static UniformGrid AroundHertz(double half_width_m, int n, double start_b = -4.5,
                                 double end_b = 1.5);

  int size() const { return n_; }
  double dx_m() const { return dx_; }                          // node spacing [m]
  double x_start_m() const { return x0_; }                     // first node [m]
  double x_end_m() const { return x0_ + (n_ - 1) * dx_; }      // last node [m]
  double x(int i) const { return x0_ + i * dx_; }              // node i [m]
  std::vector<double> Nodes() const;                           // all x_i [m]
  int NearestNode(double x_m) const;                           // clamped to [0, n-1]
  // The odd node count (a node stays at x = 0 on grids symmetric in their cells) of a grid
  // with this spacing from x_start_m to this grid's last node: how many nodes a longer inlet
  // needs at the same resolution [-].
  int NodesFromStart(double x_start_m) const;

 private:
  double x0_ = 0, dx_ = 0;
  int n_ = 0;
};

}  // namespace tehl
