// A plain line contact of two discs or rollers ([contact] case, no gears): a steady solve,
// or time stepping through tables of load and surface speeds. Writes CSV files of the film.
#pragma once

#include <string>
#include <vector>

#include "tehl/ehl/line_contact_solver.hpp"

namespace tehl {

struct ContactRunOptions {
  bool quiet = false;          // no progress line on stderr
  std::string output_dir;      // overrides [output] directory when not empty
};

struct ContactStepRecord {
  double time_s = 0;           // [s]
  double load_n_per_m = 0;     // w [N/m]
  double u1_m_s = 0, u2_m_s = 0;  // surface speeds [m/s]
  double h_min_m = 0, h_c_m = 0;  // minimum and central film [m]
  double p_max_pa = 0;         // [Pa]
  LineContactSolver::Summary summary;
};

struct ContactRunResult {
  std::vector<ContactStepRecord> steps;  // one for a steady run; steady start + steps else
  std::string profile_csv;     // x, p, h of the last level
  std::string history_csv;     // per-step table (transient runs), else empty
  bool converged() const;      // every step usable
};

// Reads and runs a [contact] case. Throws InputError (with file:line) for bad input.
ContactRunResult RunContactCase(const std::string& case_path, const ContactRunOptions& options);

}  // namespace tehl
