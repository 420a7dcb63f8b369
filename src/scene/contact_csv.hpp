// The two CSV files of a [contact] run as text (docs/results.md, "Disc and roller runs"):
// every numeric cell is checked first, like the HDF5 writer and the CSV tables of the io layer
// (docs/robustness.md, "NaN and Inf in result files"). Private to src/.
#pragma once

#include <string>
#include <vector>

#include "tehl/scene/contact_scene.hpp"

namespace tehl::internal {

// NAME_steps.csv: one row per step,
//   t_s,w_n_per_m,u1_m_s,u2_m_s,h_min_m,h_c_m,p_max_pa,t_max_k,mu,wall_time_s,spike_cells,
//   inlet_deficit,newton_iterations,coupling_iterations,t1_max_k,t2_max_k,dT_flash_blok_k,
//   termination
// Throws NonFiniteError ("... CSV <file> column <name>[<row>] = nan") at the first NaN or Inf.
std::string ContactStepsCsv(const std::string& file, const std::vector<ContactStepRecord>& steps);

// NAME_profile.csv: x_m,p_pa,h_m per node, then t_mid_k, t1_k, t2_k (mid-film and the two
// bodies' surface temperatures [K]) for those not empty (thermal runs; same size as x_m).
// Throws NonFiniteError like above.
std::string ContactProfileCsv(const std::string& file,
                              const std::vector<double>& x_m,
                              const std::vector<double>& p_pa,
                              const std::vector<double>& h_m,
                              const std::vector<double>& t_mid_k,
                              const std::vector<double>& t1_k = {},
                              const std::vector<double>& t2_k = {});

}  // namespace tehl::internal
