// Which physics a film solve includes (DESIGN.md section 5: effects are data). An effect that
// is off is not assembled and allocates nothing.
#pragma once

#include <string>

namespace tehl {

struct FilmEffects {
  bool elastic = true;       // elastic deflection v(x) of the surfaces (DC-FFT); false = rigid
  bool piezoviscous = true;  // eta(p); false = eta(0, T)
  bool compressible = true;  // rho(p); false = rho(0, T)
  bool transient = true;     // squeeze term d(rho h)/dt in time steps; false = quasi-steady
  bool roughness = false;    // surface shapes move with their surfaces (needs a surface shape:
                             // InputError from the solver without one)
  bool thermal = false;      // energy equation across the film, surface temperatures, eta(T),
                             // rho(T) and the generalized Reynolds equation. A film that
                             // slides needs non_newtonian in practice: the Newtonian one often
                             // does not settle and overestimates friction (docs/thermal.md)
  bool non_newtonian = false;  // Ree-Eyring shear thinning (needs the lubricant's Eyring data)
  bool finite_peclet = false;  // surface temperatures with conduction along the solids
                               // (Jaeger's moving line source at any Peclet number; with
                               // thermal only: InputError otherwise)
  std::string ToString() const;  // e.g. "elastic piezoviscous compressible transient"
};

}  // namespace tehl
