// The fields across the film that make a line contact thermal and/or non-Newtonian: the film
// temperature T(x_i, xi_j) (energy equation, ehl/film_energy.hpp) and the Ree-Eyring factor
// f = eta_eff / eta(p, T) (docs/theory.md, "Thermal coupling" and "Ree-Eyring film").
//
// The pressure solve reads both as frozen fields (generalized Reynolds, ehl/cross_film.hpp);
// between pressure solves the coupling updates them from the pressure solution:
//   Eyring: at each node the wall shear stress tau_1 solves h int_0^1 gdot(tau_1 + h p' xi) dxi
//           = u2 - u1 with gdot(tau) = (tau0/eta) sinh(tau/tau0) / (1 - (tau/tauL)^2) (the last
//           factor only with a limiting shear stress tauL = tauL0 + Lambda p: the stress tends
//           to tauL as the shear rate grows), then f = tau / (eta gdot(tau)) at every xi_j;
//   thermal: the energy equation with the velocity profile and the dissipation tau^2/eta_eff.
// Private to src/ehl.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ehl/anderson_mixer.hpp"
#include "tehl/ehl/film_effects.hpp"
#include "tehl/ehl/film_energy.hpp"
#include "tehl/ehl/grid.hpp"
#include "tehl/ehl/line_contact_solver.hpp"

namespace tehl {
class Lubricant;
}

namespace tehl::internal {

class FilmField {
 public:
  FilmField(const UniformGrid& grid,
            const Lubricant& lubricant,
            const FilmEffects& effects,
            const ContactSolids& solids,
            const LineContactSolver::Options& options);

  // The frozen fields the Reynolds system reads (null when the effect is off) [K], [-].
  const Eigen::MatrixXd* temperature() const { return thermal_ ? &t_.t_k : nullptr; }
  const Eigen::MatrixXd* viscosity_factor() const { return eyring_ ? &factor_ : nullptr; }

  // Starts from the state's temperature when it has one of the right size, else T0; the
  // Eyring factor is recomputed from the state (1 for a state without pressure).
  void Begin(const ContactConditions& c, const FilmState& s);

  // The Eyring factor started again from 1 and moved `relaxation` of the way (in log) to that
  // of the state (0: Newtonian at the current temperature): the fallback of a coupled solve
  // whose first pressure solve failed with the factor of its start in full.
  void RestartRheology(const ContactConditions& c, const FilmState& s, double relaxation);

  // Recomputes the Eyring factor from a pressure solution, moving log f by `relaxation` of
  // the way to its target (1 = the factor of this state exactly); returns the largest
  // distance |log f_target - log f| before the move [-] (0 when Newtonian).
  // With `accelerate` the move is an Anderson step on log f instead (history kept from
  // Begin on): the coupling iteration of isothermal Ree-Eyring films.
  double UpdateRheology(const ContactConditions& c,
                        const FilmState& s,
                        double relaxation,
                        bool accelerate = false);
  // The under-relaxation of the coupling iteration's Eyring update without the energy
  // equation [-]. With it the factor moves all the way (relaxation 1) and the temperature
  // update's Anderson step mixes temperature and log f together.
  static constexpr double kEyringRelaxation = 0.5;
  // Weight of log f against the temperature in that joint step [K].
  static constexpr double kLogFactorWeightK = 10.0;

  struct EnergyUpdate {
    bool ok = false;
    double max_change_k = 0;    // max |T change| over the update (the coupling measure) [K]
    double inner_change_k = 0;  // last change of the fixed-pressure iteration [K]
    bool limited = false;       // the heating had to be cut (a way station, not a solution)
    FilmEnergySolver::Summary summary;
  };
  // The film temperature at the pressure of a solution: energy solves (steady when
  // dt_s <= 0, else implicit Euler from `previous`, whose p, h and temperature give dp/dt,
  // dh/dt and the old level) with the shear heating of eta(p, T) iterated to a fixed point
  // (Anderson-accelerated, damped by `relaxation`).
  EnergyUpdate UpdateTemperature(const ContactConditions& c,
                                 const FilmState& s,
                                 const FilmState* previous,
                                 double dt_s,
                                 double relaxation);

  // One evaluation of the coupling map G(T) for the Newton coupling (ehl/fixed_point_newton.hpp):
  // the film temperature the energy equation gives at the pressure of s with the shear
  // heating of the current temperature, solved to tolerance_k [K], into *image (n x nz);
  // neither relaxed nor mixed nor limited. The current temperature stays; the wall heat
  // fluxes become those of the image.
  EnergyUpdate MapTemperature(const ContactConditions& c,
                              const FilmState& s,
                              const FilmState* previous,
                              double dt_s,
                              double tolerance_k,
                              Eigen::MatrixXd* image);
  // Sets the current film temperature (n x nz; columns 0 and nz-1 are the surfaces) [K].
  void SetTemperature(const Eigen::MatrixXd& t_k);
  // The unknowns of the coupling as one vector: the film temperature [K], followed in
  // Ree-Eyring runs by w log f (w = kLogFactorWeightK [K]), column-major n x nz each; and
  // the bounds the coupling keeps them in at inlet temperature t0_k (log f <= 0).
  Eigen::VectorXd CouplingState() const;
  void SetCouplingState(const Eigen::VectorXd& x);
  void CouplingBounds(double t0_k, Eigen::VectorXd* lower, Eigen::VectorXd* upper) const;
  const Eigen::MatrixXd& film_temperature() const { return t_.t_k; }
  // Lowest and highest film temperature the coupling accepts at inlet temperature t0_k [K].
  static double MinTemperature(double t0_k) { return 0.8 * t0_k; }
  static double MaxTemperature(double t0_k) { return t0_k + kMaxRiseK; }
  static constexpr double kMaxRiseK = 400.0;  // largest film temperature rise accepted [K]

  // Writes the current temperature into the state (thermal runs).
  void Store(FilmState* s) const;

  // Friction of a state with the current fields.
  FilmFriction Friction(const ContactConditions& c, const FilmState& s) const;

 private:
  // eta_eff(x_i, xi_j) [Pa s] at the state's pressure with the current fields.
  void NodeViscosity(
      const ContactConditions& c, const FilmState& s, int i, double* eta, bool newtonian) const;
  double Slope(const Eigen::VectorXd& p, int i) const;  // dp/dx at node i [Pa/m]
  // The flow field of a pressure solution without its velocity profile and heating; the
  // old temperature level of a transient step (or null) into *prev_t.
  FilmFlowField Flow(const ContactConditions& c,
                     const FilmState& s,
                     const FilmState* previous,
                     double dt_s,
                     const FilmTemperature** prev_t) const;
  // Velocity profile, shear heating and its temperature response at the current temperature.
  void Heating(const ContactConditions& c, const FilmState& s, FilmFlowField* flow) const;
  void Energy(double t0_k);

  UniformGrid grid_;
  const Lubricant& lub_;
  FilmEffects eff_;
  ContactSolids solids_;
  LineContactSolver::Options opt_;
  int nz_;
  bool thermal_, eyring_;
  FilmTemperature t_;       // thermal only
  Eigen::MatrixXd factor_;  // Eyring only
  // Thermal Eyring runs: the factor the last UpdateRheology started from; the coupling's
  // Anderson step mixes (T, log f) together (UpdateTemperature).
  Eigen::MatrixXd factor_in_;
  std::unique_ptr<FilmEnergySolver> energy_;
  AndersonMixer outer_{5};    // the coupling iteration, reset by Begin
  int inner_iterations_ = 1;  // energy solves per coupling iteration
  // The last coupling change of the temperature [K]; sets how far each energy solve needs
  // to converge (a tenth of it, no less than the energy solver's own tolerance).
  double last_change_k_ = kFirstCouplingChangeK;
  static constexpr double kFirstCouplingChangeK = 5.0;  // [K], assumed before the first
};

// Friction of a film with eta(x_i, xi_j) given per node by `viscosity(i, eta)` over nz
// cross-film nodes (seed 004 eq. 16).
FilmFriction IntegrateFriction(const UniformGrid& grid,
                               const FilmState& s,
                               const ContactConditions& c,
                               int nz,
                               const std::function<void(int, double*)>& viscosity);

}  // namespace tehl::internal
