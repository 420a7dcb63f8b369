// The periodic (steady-state) response of the torsional gear model at one speed, the
// tracked pair's dynamic load along the path of contact, and the dynamic load factor against
// speed (seed 000 section 4.2.7 and Fig. 5.49; docs/dynamics.md).
//
// The model starts at t = 0 (tracked pair at A) from the static deflection x = F_s / k(0+),
// x' = 0 (or a given state), and is integrated one mesh period T at a time by DormandPrince54
// (events at contact loss and regain, scheduled switches at the stiffness jumps and the pitch
// point) until the state at the start of a period repeats the previous one:
//   |x_n - x_(n-1)| <= tol x_s  and  |x'_n - x'_(n-1)| <= tol w_n x_s,
// x_s = F_s / k_mean the static deflection, w_n = sqrt(k_mean / m_e). The last period is then
// the periodic response; every step of it is kept with its dense output, so the mesh force
// can be evaluated at any phase on either side of a jump.
// Responses that are not periodic in one mesh period (sub-harmonic or chaotic motion with
// backlash) end after max_periods with periodic = false; their last period is reported.
// Responses that grow without bound end once a period start lies beyond divergence_factor
// static deflections, with diverged = true.
#pragma once

#include <string>
#include <vector>

#include "tehl/drive/integrator.hpp"
#include "tehl/drive/torsional_model.hpp"

namespace tehl {

struct DynamicResponseOptions {
  double relative_tolerance = 1e-8;           // integrator rtol; atol = rtol (x_s, w_n x_s) [-]
  double periodic_tolerance = 1e-6;           // tol of the periodicity test above [-]
  int min_periods = 2;                        // periods integrated at least [-], >= 2
  int max_periods = 5000;                     // periods integrated at most [-], >= min_periods
  int output_samples = 400;                   // uniform samples of the periodic response [-], >= 8
  int peak_samples_per_step = 8;              // dense-output points per step for the extremes [-]
  // A period start with |x| or |x'| / w_n beyond this many x_s: the response grows without
  // bound (a mesh pumped by its own stiffness variation, docs/dynamics.md "Back flanks") and
  // the integration stops there [-], > 1.
  double divergence_factor = 1e3;
  // The state at t = 0 (phase 0): empty, the static deflection x = F_s / k(0+), x' = 0; or
  // (x [m], x' [m/s]), e.g. the periodic response of a neighbouring speed (continuation).
  std::vector<double> initial_state;
  std::vector<std::string> Validate() const;  // every violated rule; empty = valid
};

struct DynamicSample {
  double phase_m = 0;            // mesh phase phi in [0, p_b] [m]
  double time_s = 0;             // from the start of the period [s]
  double x_m = 0;                // dynamic transmission error [m]
  double v_m_s = 0;              // its rate [m/s]
  double force_n = 0;            // dynamic mesh force F [N]
  double stiffness_n_per_m = 0;  // k_mesh at this phase [N/m]
  ContactState state = ContactState::kDriveFlank;
};

struct DynamicResponse {
  bool periodic = false;  // the periodicity test passed
  bool diverged = false;  // stopped: the response grows without bound (divergence_factor)
  int periods = 0;        // mesh periods integrated [-]
  std::string message;
  double pinion_speed_rad_s = 0;             // w1 [rad/s]
  double mesh_frequency_hz = 0;              // f_m = z1 w1 / (2 pi) [Hz]
  double natural_frequency_hz = 0;           // f_n = sqrt(k_mean / m_e) / (2 pi) [Hz]
  double mesh_period_s = 0;                  // T = p_b / (r_b1 w1) [s]
  double static_force_n = 0;                 // F_s = T_m / r_b1 [N]
  double peak_force_n = 0;                   // max F over the periodic period [N]
  double min_force_n = 0;                    // min F [N]
  double dynamic_load_factor = 0;            // peak_force_n / static_force_n [-]
  double separated_fraction = 0;             // fraction of the period with F = 0 (separated) [-]
  double back_flank_fraction = 0;            // fraction of the period on the back flank [-]
  std::vector<double> contact_loss_times_s;  // drive-flank contact lost, from period start [s]
  double periodicity_error = 0;              // last value of the test above, relative [-]
  double end_x_m = 0, end_v_m_s = 0;         // state at the end of the last period (phase 0)
  IntegratorSummary integrator;              // totals over all periods
  std::vector<DynamicSample> samples;        // output_samples + both sides of each segment end

  // Mesh force at phase phi in [0, p_b] of the periodic period; `left` takes the limit from
  // below at a jump [N].
  double ForceAt(double phase_m, bool left) const;
  // The state there.
  DynamicSample SampleAt(double phase_m, bool left) const;

  // Kept for ForceAt: the steps of the periodic period with their mode.
  struct Step {
    DenseStep dense;
    ContactState state = ContactState::kDriveFlank;
    int segment = 0;
    int back_segment = -1;  // on the back flanks with their own mesh: its segment
  };
  std::vector<Step> steps;
  double period_start_s = 0;              // absolute time of the periodic period's start [s]
  double contact_speed_m_s = 0;           // r_b1 w1 [m/s]
  const TorsionalModel* model = nullptr;  // for forces; valid while the model lives
};

// The periodic response of `model` (its parameters fix the speed). The model is reset.
DynamicResponse SolvePeriodicResponse(TorsionalModel& model, const DynamicResponseOptions& o);

// Tracked pair along the path of contact: the dynamic load per unit face width at s,
// w_dyn(s) = F(phi(s)) share(s, x(phi)) / b, phi(s) = s mod p_b. The share is the pair's part
// of the mesh force by the stiffness split; with tip relief or corner contact it depends on
// the approach x (a relieved flank clears, a corner beyond A or E closes): at the static
// approach of F_s for the static load, at the dynamic x(phi) for the dynamic one.
struct PairLoadPoint {
  double s_m = 0;              // from A [m]
  double share = 0;            // static share of the tracked pair [-]
  double static_n_per_m = 0;   // F_s share / b [N/m]
  double dynamic_n_per_m = 0;  // F(phi) share(x(phi)) / b [N/m]
};
// `points` >= 2 samples from A to E, the switch points B and D on both sides.
std::vector<PairLoadPoint> TrackedPairLoad(const DynamicResponse& r,
                                           double face_width_m,
                                           int points);

}  // namespace tehl
