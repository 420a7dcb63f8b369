// The index of a study: one row per scene with its varied values, a summary of its result
// and its status (docs/studies.md "The index"). Written as <output>/index.h5 and
// <output>/index.csv, atomically, once every scene has finished. A row is built from the
// scene's result file, so a row rebuilt by `tehl sweep --resume` equals the row of the run
// that wrote the file.
#pragma once

#include <string>
#include <vector>

#include "tehl/scene/study.hpp"

namespace tehl {

struct SceneRow {
  int scene = 0;                  // scene id [-]
  std::string status;             // "ok", "not_converged", or "failed: <message>"
  std::string message;            // solver message of the last step ("" when ok)
  std::string result_path;        // the scene's result file ("" when it failed)
  bool computed = true;           // false: rebuilt from an existing result (--resume)
  // The summaries below are over the converged films (a scene that stopped keeps its failed
  // film as its last row; with none converged they stay 0).
  double h_min_min_m = 0;         // min over the cycle of h_min [m]
  double h_c_pitch_m = 0;         // h_c at the step nearest the pitch point C [m]
                                  //   (contact cases: at the last step)
  double h_c_min_m = 0;           // min over the cycle of h_c [m]
  double p_max_max_pa = 0;        // max over the cycle of p_max [Pa]
  double t_max_max_k = 0;         // max over the cycle of T_max [K] (0: not in the file)
  double mu_mean = 0;             // mean over the steps of mu [-] (0: not in the file)
  double mu_max = 0;              // max over the steps of mu [-] (0: not in the file)
  double t_surface_max_k = 0;     // max over the cycle of both surfaces' hottest temperature
                                  //   [K] (0: not in the file)
  double flash_blok_max_k = 0;    // max over the cycle of Blok's flash temperature rise [K]
                                  //   (0: not in the file)
  double wall_time_s = 0;         // the scene's run time [s]
  double steady_restarts = 0;     // time steps replaced by the steady film at their time
                                  //   ([numerics] failed_step = "steady_restart") [-]
  double edge_cells_min = -1;     // fewest grid cells across a film's Hertzian edge
                                  //   (hertz_edge.hpp); -1: rigid solids, or a result of an
                                  //   earlier version [-]
  double grid_points = 0;         // nodes of the film grid (docs/case_format.md; 0: not in the
                                  //   result) [-]
  double inlet_deficit_max = -1;  // largest estimated film deficit of the truncated inlet
                                  //   over the films (docs/results.md "The inlet note"); -1:
                                  //   no estimate, or a result of an earlier version [-]
  double unphysical_mu_films = 0;  // converged Newtonian films whose mu exceeds
                                   //   kPhysicalFrictionLimit (flash_temperature.hpp): their
                                   //   flash rises are left out of flash_blok_max_k [-]
  int steps = 0;                   // rows of the cycle table, failed films included [-]
};

// The row of a finished scene, read from its result file (HDF5 /cycle of a mesh cycle, or the
// _steps.csv of a contact case). Throws std::runtime_error when the file cannot be read.
SceneRow ReadSceneRow(const Study& study, const StudyScene& scene);

// A row for a scene that ended by an exception.
SceneRow FailedSceneRow(const StudyScene& scene, const std::string& what);

// Rows as text and back (exact: %.17g), to move them between MPI ranks.
std::string SceneRowsToText(const std::vector<SceneRow>& rows);
std::vector<SceneRow> SceneRowsFromText(const std::string& text);

// Writes <output>/index.h5 and <output>/index.csv (rows sorted by scene id), each through a
// .part file renamed when complete. Returns the two paths.
std::vector<std::string> WriteStudyIndex(const Study& study, std::vector<SceneRow> rows);

// Whether `name` is a column (CSV) or dataset (HDF5) the index writes itself: scene, steps,
// status, computed, result or a summary column. A [[vary]] label must not be one.
bool IsIndexColumnName(const std::string& name);

}  // namespace tehl
