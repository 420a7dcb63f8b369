// The mesh cycle of a gear case: the gear core drives the film solver along the path of
// contact of the tracked tooth pair, from engagement A to disengagement E (DESIGN.md
// sections 2, 4 and 6; seed 004 section 2).
//
// At each step the path kinematics give R(s), u1(s), u2(s) (path_of_contact.hpp) and the
// load sharing gives w(s) = share(s) F_bt / b (load_sharing.hpp); the film solver
// (line_contact_solver.hpp) solves the transient line contact on ONE fixed grid from
// x_start_b b_max to x_end_b b_max, b_max the largest Hertz half-width on the path. The run
// starts from the steady film at A; steps land exactly on B and D, where the load share jumps:
// a step that lands on B or D uses the load arriving there (left limit), the next one the load
// after it. s and t are related by t = s / (r_b1 w1).
//
// Seed 004 (Fig. 3) plots the path quantities relative to the pitch point C:
//   C_RT = R / R0,  C_UT = um / u0,  C_WT = w / w0   with R0, u0, w0 at C.
// Results: one HDF5 file per run and a CSV of the cycle table (docs/results.md).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "tehl/ehl/flash_temperature.hpp"
#include "tehl/ehl/hertz_edge.hpp"
#include "tehl/ehl/inlet_truncation.hpp"
#include "tehl/ehl/line_contact_solver.hpp"
#include "tehl/ehl/outlet_spike.hpp"

namespace tehl {

struct MeshCycleRunOptions {
  bool quiet = false;       // no progress line on stderr
  std::string output_dir;   // overrides [output] directory when not empty
  bool write_files = true;  // false: solve only, write nothing (library use, tests)
  // Checkpoints (only when writing files): every `checkpoint_every` steps the run state goes
  // to NAME.checkpoint (0 = never). `resume`: a complete NAME.h5 is left as it is
  // (already_complete); else a checkpoint of the same case is continued.
  int checkpoint_every = 10;  // [steps]
  bool resume = false;
  // Called with the step count done once each checkpoint is on disk (empty = nothing); the
  // command line's resume tests stop the process there to kill it at a known step.
  std::function<void(int)> after_checkpoint;
};

struct MeshCycleStep {
  double s_m = 0;                       // distance from A along the line of action [m]
  double time_s = 0;                    // t = s / (r_b1 w1) since A [s]
  double reduced_radius_m = 0;          // R [m]
  double u1_m_s = 0, u2_m_s = 0;        // pinion and wheel surface speeds [m/s]
  double um_m_s = 0;                    // entrainment speed (u1 + u2)/2 [m/s]
  double srr = 0;                       // slide-to-roll ratio (u1 - u2)/um [-]
  double load_n_per_m = 0;              // w of the tracked pair (dynamic_load: dynamic) [N/m]
  double static_load_n_per_m = 0;       // w of the static load sharing [N/m]
  int pairs_in_contact = 0;             // tooth pairs sharing the load [-]
  double h_min_m = 0, h_c_m = 0;        // minimum and central (x = 0) film [m]
  double p_max_pa = 0;                  // [Pa]
  double t_max_k = 0;                   // hottest film temperature (inlet T0 when isothermal) [K]
  double t_mid_max_k = 0;               // hottest mid-film temperature (T0 when isothermal) [K]
  double t1_max_k = 0, t2_max_k = 0;    // hottest surface temperature of pinion, wheel [K]
  double friction_coefficient = 0;      // mu = integral tau dx / w (seed 004 eq. 16) [-]
  double c_rt = 0, c_ut = 0, c_wt = 0;  // R/R0, um/u0, w/w0 (seed 004 Fig. 3) [-]
  std::string zone;                     // "A-B", "B-D" or "D-E" (the segment the step ends in)
  LineContactSolver::Summary summary;
  // Non-empty when the transient step failed and its film is the steady one at this point
  // ([numerics] failed_step = "steady_restart"): the failed step's termination and message.
  std::string restart_reason;
  bool restarted() const { return !restart_reason.empty(); }
};

struct MeshCycleResult {
  std::vector<MeshCycleStep> steps;             // steps[0]: the steady film at A; then one per step
  std::vector<double> x_m;                      // grid nodes [m]
  std::vector<std::vector<double>> p_pa, h_m;   // profiles per step over x [Pa], [m]
  bool thermal = false;                         // effects.thermal of the case
  double time_tolerance = 0;  // [numerics] time_tolerance of the case (0: no time control) [-]
  bool finite_peclet = false;                   // effects.finite_peclet of the case
  bool non_newtonian = false;                   // effects.non_newtonian of the case
  int film_nodes = 0;                           // nodes across the film (thermal) [-]
  // Thermal runs only (empty otherwise), per step over x: mid-film temperature and the
  // surface temperatures of pinion and wheel [K]; the full field T(x, z) row-major (x, z)
  // per step when [output] temperature_field is true [K].
  std::vector<std::vector<double>> t_mid_k, t1_k, t2_k, t_field_k;
  double length_m = 0;                          // g_alpha, A to E [m]
  // The loaded part A'..E' whose films are solved: [0, length_m] unless a tip relief lifts
  // the tracked pair below 1 % of F_bt near A or E (docs/gear.md "Tip relief") [m].
  double begin_m = 0, end_m = 0;
  double s_b_m = 0, s_c_m = 0, s_d_m = 0;       // B, pitch point C, D from A [m]
  double r0_m = 0, u0_m_s = 0, w0_n_per_m = 0;  // R, um and w at C [m], [m/s], [N/m]
  double max_half_width_m = 0;                  // b_max, sets the grid [m]
  int planned_steps = 0;                        // steps from A to E [-]
  std::string step_rule;                        // how the step count was chosen
  std::string grid_rule;                        // how the node count was chosen
  // Notes on the inputs found before solving: a waviness on too few cells of the grid, an
  // inlet far from the lubricant law's reference temperature (case --check prints them too).
  std::vector<std::string> input_notes;
  double wall_time_s = 0;                       // whole run [s]
  std::string hdf5_path, csv_path;              // written files ("" when not written)
  int resumed_from_step = 0;                    // first step solved by this run when resumed
  bool already_complete = false;                // resume found a complete result: no steps
  bool converged() const;                       // every planned step solved and usable
  int PitchStep() const;                        // index of the step nearest to C
  int Restarts() const;                         // steps whose film is a steady restart
  // The outlet pressure spike of each step's film (p_pa; FindOutletSpike), one per row.
  std::vector<OutletSpike> OutletSpikes() const;
  // The Hertzian edge of each step's film (hertz_edge.hpp; zero width for rigid solids).
  std::vector<HertzEdge> HertzEdges() const;
  // What the truncated inlet costs each step's film (EstimateInletTruncation with the step's
  // own R, um and Hertz half-width), one per row; needs the four fields below.
  std::vector<InletTruncation> InletTruncations() const;
  double x_start_b = 0;                  // [numerics] x_start_b of the case [-]
  double e_prime_pa = 0;                 // E' of the pair [Pa]
  bool elastic = true;                   // effects.elastic of the case
  double inlet_viscosity_pa_s = 0;       // eta(p = 0, T0) [Pa s]
  double pressure_viscosity_per_pa = 0;  // d ln(eta)/dp there; 0 when not piezoviscous [1/Pa]
  ContactSolids solids;                  // thermal properties of pinion (body1) and wheel
  double inlet_temperature_k = 0;        // T0 of the oil and the bulk of both solids [K]
  // Blok's flash temperature rise of each step with its own mu, w, u1, u2 and Hertz
  // half-width (FlashTemperature with finite_peclet; docs/thermal.md "Flash temperature"), one per
  // row; -1 for rigid solids (no Hertz zone) [K].
  std::vector<double> BlokFlashRises() const;
};

// Step ends s_1..s_N in (0, g], uniform within each of the segments [0, s_b], [s_b, s_d],
// [s_d, g] (switch points outside (0, g) are skipped), `steps` in all, each segment at least
// `min_per_segment[i]` (and 1) steps; so B and D are step ends exactly. Returns s_0 = 0 first.
// With begin_m / end_m (the loaded part A'..E' of a path with tip relief) the same on
// [begin, end] (end < 0: g): s_0 = begin, s_N = end, the segments cut at B and D inside.
std::vector<double> MeshCycleStepPositions(double length_m,
                                           double s_b_m,
                                           double s_d_m,
                                           int steps,
                                           const std::vector<int>& min_per_segment = {},
                                           double begin_m = 0.0,
                                           double end_m = -1.0);

// Automatic step count: four steps per transit of the entrainment across the Hertz
// half-width, n = ceil(4 integral um / b dt) over A..E, clamped to [100, 200] (see
// docs/results.md "Step count").
int AutomaticMeshCycleSteps(double transits);

// Reads a gear case and runs its mesh cycle. Throws InputError (with file:line) for bad
// input. A time step that does not converge is replaced by the steady film at its point and
// flagged (MeshCycleStep::restart_reason; [numerics] failed_step = "steady_restart", the
// default); one that cannot be replaced (failed_step = "stop", the steady film at A, or a
// steady film that fails too) stops the run, which is then still written (the Summary of
// each step says how it ended). With failed_step = "steady_restart_or_skip" a step whose
// steady film fails too is recorded as failed and the run goes on from the last converged
// film (three failed steps in a row stop it).
MeshCycleResult RunMeshCycle(const std::string& case_path, const MeshCycleRunOptions& options);

}  // namespace tehl
