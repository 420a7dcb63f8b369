// A plain line contact of two discs or rollers ([contact] case, no gears): a steady solve,
// or time stepping through tables of load and surface speeds. Writes CSV files of the film
// (NAME_profile.csv, NAME_steps.csv; columns in docs/results.md). Every number is checked before
// anything is written: a NaN or Inf throws NonFiniteError (tehl/io/hdf5_writer.hpp) naming the
// file, column and row, and leaves no file under the final names.
#pragma once

#include <string>
#include <vector>

#include "tehl/ehl/hertz_edge.hpp"
#include "tehl/ehl/inlet_truncation.hpp"
#include "tehl/ehl/line_contact_solver.hpp"
#include "tehl/ehl/outlet_spike.hpp"

namespace tehl {

struct ContactRunOptions {
  bool quiet = false;      // no progress line on stderr
  std::string output_dir;  // overrides [output] directory when not empty
};

struct ContactStepRecord {
  double time_s = 0;                // [s]
  double load_n_per_m = 0;          // w [N/m]
  double u1_m_s = 0, u2_m_s = 0;    // surface speeds [m/s]
  double h_min_m = 0, h_c_m = 0;    // minimum and central film [m]
  double p_max_pa = 0;              // [Pa]
  double t_max_k = 0;               // largest film temperature; the inlet temperature when the
                                    //   run is isothermal [K]
  double friction_coefficient = 0;  // mu = (|F1| + |F2|) / (2 w), seed 004 eq. 16
                                    //   (LineContactSolver::Friction, as /cycle/mu) [-]
  double t1_max_k = 0, t2_max_k = 0;  // hottest surface of body 1, 2 (inlet T when isothermal) [K]
  double flash_rise_blok_k = 0;       // Blok's flash temperature rise with this mu (as
                                      //   /cycle/dT_flash_blok); -1 for rigid solids [K]
  double half_width_m = 0;            // Hertz half-width b at this load; 0 for rigid solids [m]
  double wall_time_s = 0;           // wall time of this step's solve (substeps included) [s]
  OutletSpike outlet_spike;         // the outlet pressure spike and its width in cells
  HertzEdge hertz_edge;             // the film's Hertzian edge and its width in cells (elastic
                                    //   solids; zero width for rigid ones)
  InletTruncation inlet;            // what the truncated inlet costs the film (estimate)
  LineContactSolver::Summary summary;
  // Non-empty when the time step failed and its film is the steady one at its time
  // ([numerics] failed_step = "steady_restart"): the failed step's termination and message.
  std::string restart_reason;
  bool restarted() const { return !restart_reason.empty(); }
};

struct ContactRunResult {
  std::vector<ContactStepRecord> steps;  // one for a steady run; steady start + steps else
  std::string profile_csv;               // x, p, h (and T_mid when thermal) of the last level;
                                         // "" with [output] profiles = false
  std::string history_csv;  // NAME_steps.csv: the steady solve, then one row per time step
  double x_start_b = 0;     // [numerics] x_start_b of the case (the inlet end of the grid) [-]
  double x_start_m = 0;     // the grid's first node [m]
  double x_end_m = 0;       // the grid's last node [m]
  int grid_points = 0;      // nodes of the grid the film was solved on [-]
  std::string grid_rule;    // how that node count was chosen
  // Notes on the inputs found before solving: a waviness on too few cells of the grid, an
  // inlet far from the lubricant law's reference temperature (case --check prints them too).
  std::vector<std::string> input_notes;
  double inlet_temperature_k = 0;  // T0 of the oil and the bulk of both bodies [K]
  bool finite_peclet = false;      // effects.finite_peclet of the case
  bool thermal = false;            // effects.thermal of the case
  double time_tolerance = 0;       // [numerics] time_tolerance of the case (0: no time control) [-]
  bool non_newtonian = false;      // effects.non_newtonian of the case
  ContactSolids solids;            // thermal properties of bodies 1 and 2
  bool converged() const;   // every step usable
  int Restarts() const;     // time steps whose film is a steady restart
};

// Reads and runs a [contact] case. Throws InputError (with file:line) for bad input.
ContactRunResult RunContactCase(const std::string& case_path, const ContactRunOptions& options);

}  // namespace tehl
