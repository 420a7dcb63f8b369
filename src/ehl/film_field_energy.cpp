// FilmField: the energy updates of the thermal coupling (one energy solve from a pressure
// solution, with its heating cut back while the film would run away) and the wall fluxes and
// solids' heat history they hand on (src/ehl/film_field.hpp).
#include <algorithm>
#include <cmath>
#include <string>

#include "base/number_text.hpp"
#include "ehl/film_field.hpp"

namespace tehl::internal {
namespace {

constexpr int kHeatingCuts = 8;  // heating scalings tried per energy solve [-]

// The wall fluxes of an energy solve and the solids' heat history it hands on.
void KeepWallFluxes(const FilmTemperature& from, FilmTemperature* to) {
  to->q1_w_m2 = from.q1_w_m2;
  to->q2_w_m2 = from.q2_w_m2;
  to->travel1_m = from.travel1_m;
  to->travel2_m = from.travel2_m;
  to->speed1_m_s = from.speed1_m_s;
  to->speed2_m_s = from.speed2_m_s;
  to->earlier = from.earlier;
}

}  // namespace

FilmField::EnergyUpdate FilmField::MapTemperature(const ContactConditions& c,
                                                  const FilmState& s,
                                                  const FilmState* previous,
                                                  double dt_s,
                                                  double tolerance_k,
                                                  Eigen::MatrixXd* image) {
  EnergyUpdate out;
  Energy(c.temperature_k);
  const FilmTemperature* prev_t = nullptr;
  FilmFlowField flow = Flow(c, s, previous, dt_s, &prev_t);
  Heating(c, s, &flow);
  FilmTemperature next = t_;
  out.summary = energy_->Solve(flow, prev_t, prev_t ? dt_s : 0.0, tolerance_k, &next);
  out.ok = out.summary.usable() && next.t_k.allFinite();
  if (!out.ok) return out;
  out.max_change_k = (next.t_k - t_.t_k).cwiseAbs().maxCoeff();
  KeepWallFluxes(next, &t_);
  *image = next.t_k;
  return out;
}

FilmField::EnergyUpdate FilmField::UpdateTemperature(const ContactConditions& c,
                                                     const FilmState& s,
                                                     const FilmState* previous,
                                                     double dt_s,
                                                     double relaxation) {
  EnergyUpdate out;
  if (!thermal_) {
    out.ok = true;
    return out;
  }
  Energy(c.temperature_k);
  const FilmTemperature* prev_t = nullptr;
  FilmFlowField flow = Flow(c, s, previous, dt_s, &prev_t);
  const Eigen::MatrixXd incoming = t_.t_k;
  // At fixed pressure the temperature is a fixed point of T -> T_energy(heating(eta(p, T))):
  // the shear heating falls as the film warms. Up to inner_iterations_ energy solves,
  // Anderson-accelerated (Walker & Ni 2011, "Anderson acceleration for fixed-point
  // iterations", SIAM J. Numer. Anal. 49:1715). Measured on a 40-step seed 004 cycle at 257
  // nodes: 1 energy solve per coupling iteration needed 270 energy solves in all, an inner
  // loop to convergence 1088 (with 210 instead of 270 pressure solves): one is the default.
  AndersonMixer mixer(5);
  const double inner_tolerance = 0.1 * opt_.thermal_tolerance_k;
  const int inner_max = inner_iterations_;
  double change = 0, energy_time = 0;
  int inner_done = 0;
  for (int it = 0; it < inner_max; ++it) {
    Heating(c, s, &flow);
    // Heating limiter: the first energy solve of a sliding contact sees the heating of the
    // isothermal (cold) viscosity and can heat the film by thousands of kelvin, beyond the
    // range of the density law. Such a solve is repeated with the heating scaled down (by
    // 0.3 each time) until the film stays within kMaxRiseK of T0; the limited temperature
    // is a way station only (the next iteration heats with the warmer, thinner film) and
    // the coupling cannot settle while a limit was needed.
    const Eigen::MatrixXd full_heating = flow.heating_w_m3;
    FilmTemperature next = t_;
    double scale = 1.0;
    for (int attempt = 0;; ++attempt) {
      next = t_;
      // Inexact solves: while the coupling still moves the temperature by more than ten
      // times its tolerance (the rule of the pressure solves), a tenth of the last coupling
      // change is all the next iteration can use; the final solves are to the energy
      // solver's own tolerance.
      const double tolerance = last_change_k_ > 10 * opt_.thermal_tolerance_k
                                   ? std::max(energy_->options().tolerance_k, 0.1 * last_change_k_)
                                   : energy_->options().tolerance_k;
      out.summary = energy_->Solve(flow, prev_t, prev_t ? dt_s : 0.0, tolerance, &next);
      ++inner_done;
      energy_time += out.summary.wall_time_s;
      const bool sane = next.t_k.allFinite() && out.summary.usable() &&
                        next.t_k.maxCoeff() < c.temperature_k + kMaxRiseK;
      if (sane) break;
      if (attempt >= kHeatingCuts) {
        if (!next.t_k.allFinite())
          out.summary.message = "the energy equation gave a non-finite temperature";
        else if (out.summary.usable())
          out.summary.message = "the film temperature rises more than " + FormatReal(kMaxRiseK) +
                                " K even with the heating cut";
        return out;
      }
      scale *= 0.3;
      flow.heating_w_m3 = scale * full_heating;
    }
    if (scale < 1.0) {
      out.limited = true;
      mixer = AndersonMixer(5);
      outer_ = AndersonMixer(5);
    }
    change = (next.t_k - t_.t_k).cwiseAbs().maxCoeff();
    KeepWallFluxes(next, &t_);
    if (change < inner_tolerance || out.limited) {
      t_.t_k = next.t_k.cwiseMax(MinTemperature(c.temperature_k));
    } else {
      t_.t_k = mixer.Mix(t_.t_k, next.t_k, relaxation)
                   .cwiseMax(MinTemperature(c.temperature_k))
                   .cwiseMin(c.temperature_k + kMaxRiseK);
    }
    t_.t1_k = t_.t_k.col(0);
    t_.t2_k = t_.t_k.col(nz_ - 1);
    if (change < inner_tolerance) break;
  }
  out.inner_change_k = change;
  if (std::getenv("TEHL_DEBUG_COUPLING"))
    std::fprintf(stderr, "  inner %d energy %.4f s picard %d factorizations %d\n", inner_done,
                 energy_time, out.summary.iterations, out.summary.factorizations);
  out.max_change_k = (t_.t_k - incoming).cwiseAbs().maxCoeff();
  last_change_k_ = out.max_change_k;
  // The coupling itself, T -> T(p(T)), is a fixed-point iteration too: accelerate it the same
  // way (history kept from Begin on).
  if (out.limited) out.max_change_k = std::max(out.max_change_k, 10 * opt_.thermal_tolerance_k);
  if (out.max_change_k >= opt_.thermal_tolerance_k && !out.limited) {
    const int n = grid_.size();
    if (eyring_ && factor_in_.rows() == n && factor_in_.cols() == nz_) {
      // (T, w log f) -> (T', w log f_target): one fixed point, one Anderson history (mixing
      // T alone while f moves by its own relaxation stalls the coupling of sliding films).
      const Eigen::Index m = incoming.size();
      Eigen::VectorXd x(2 * m), g(2 * m);
      x << incoming.reshaped(), kLogFactorWeightK * factor_in_.array().log().reshaped();
      g << t_.t_k.reshaped(), kLogFactorWeightK * factor_.array().log().reshaped();
      const Eigen::VectorXd mixed = outer_.Mix(x, g, 1.0);
      t_.t_k = mixed.head(m).reshaped(n, nz_);
      factor_ = (mixed.tail(m) / kLogFactorWeightK).array().exp().min(1.0).reshaped(n, nz_);
    } else {
      t_.t_k = outer_.Mix(incoming, t_.t_k, 1.0);
    }
    t_.t_k = t_.t_k.cwiseMax(MinTemperature(c.temperature_k)).cwiseMin(c.temperature_k + kMaxRiseK);
    t_.t1_k = t_.t_k.col(0);
    t_.t2_k = t_.t_k.col(nz_ - 1);
  }
  // With one energy solve per coupling iteration (the default) the coupling itself converges
  // the heating; a longer inner loop must settle on its own.
  out.ok = change < inner_tolerance || inner_max == 1;
  if (!out.ok)
    out.summary.message = "the film temperature at fixed pressure did not settle (change " +
                          FormatReal(change) + " K)";
  return out;
}

}  // namespace tehl::internal
