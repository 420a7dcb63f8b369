// LineContactSolver::Impl::Friction: the friction of a film, from its own field (thermal or
// Ree-Eyring: the wall shear stresses of the cross-film velocity profile) or, isothermal and
// Newtonian, from eta(p, T0) uniform across the film (seed 004 eq. 16; docs/thermal.md,
// "Friction").
#include <algorithm>
#include <limits>

#include "ehl/film_field.hpp"
#include "ehl/line_contact_impl.hpp"
#include "tehl/lubricant/lubricant.hpp"

namespace tehl {

FilmFriction LineContactSolver::Impl::Friction(const ContactConditions& c, const FilmState& st) {
  // A state that is not a film of this grid (e.g. that of a first solve that failed) has no
  // friction: NaN, never a read past its end.
  if (st.p_pa.size() != grid_.size()) {
    FilmFriction none;
    none.coefficient = std::numeric_limits<double>::quiet_NaN();
    return none;
  }
  FilmState s = st;
  Film(c, &s);
  if (field_) {
    // The film's own Eyring factor (Begin alone would leave it half-way from 1, a shear
    // stress near the geometric mean of the Newtonian and the Eyring one).
    field_->Begin(c, st);
    field_->UpdateRheology(c, s, 1.0);
    return field_->Friction(c, s);
  }
  // Newtonian, isothermal: eta(p, T0) uniform across the film (two cross-film nodes).
  return internal::IntegrateFriction(grid_, s, c, 2, [&](int i, double* eta) {
    const double p = eff_.piezoviscous ? std::max(s.p_pa[i], 0.0) : 0.0;
    eta[0] = eta[1] = lub_.viscosity().Evaluate(p, c.temperature_k).eta_pa_s;
  });
}

}  // namespace tehl
