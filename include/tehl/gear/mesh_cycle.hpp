// The mesh cycle of the tracked tooth pair from A to E: kinematics, pair and mesh
// stiffness, load share and load per unit face width w(s) = share(s) F_bt / b. This table
// drives the film solver (scene layer) and `tehl gear --csv`.
#pragma once

#include <string>
#include <vector>

#include "tehl/gear/corner_contact.hpp"
#include "tehl/gear/load_sharing.hpp"
#include "tehl/gear/operating_point.hpp"
#include "tehl/gear/path_of_contact.hpp"
#include "tehl/gear/tip_relief.hpp"

namespace tehl {

struct MeshCycleOptions {
  int points = 201;                                 // samples from A to E inclusive [-], >= 2
  LoadSharing load_sharing = LoadSharing::kLinear;  // kStiffness, kLoaded need a PairStiffnessFn
  TipRelief relief;  // tip relief (tip_relief.hpp); needs kStiffness or kLoaded when Active()
  // kLoaded: the corner contact of the pair (corner_contact.hpp); not owned, must outlive the
  // call [-].
  const CornerContact* corner = nullptr;
  std::vector<std::string> Validate() const;        // every violated rule; empty = valid
};

struct MeshCycleRow {
  ContactPoint contact;               // kinematics at s
  double pair_stiffness_n_per_m = 0;  // k of the tracked pair; 0 without a stiffness [N/m]
  double mesh_stiffness_n_per_m = 0;  // sum of k over the pairs in contact [N/m]
  double share = 0;                   // load share of the tracked pair [-]
  double load_n_per_m = 0;            // w = share F_bt / b [N/m]
  // Static transmission error: the common approach of the pairs in contact along the line of
  // action under F_bt (F_bt / k_mesh without relief; tip_relief.hpp); 0 with kLinear [m].
  double transmission_error_m = 0;
};

// Rows at s_i = i g_alpha / (points - 1), with the switch points B and D inserted on both
// sides (so that step changes are exact). `stiffness` may be empty with kLinear; then the
// stiffness columns are 0. Throws InputError for invalid options.
std::vector<MeshCycleRow> MeshCycle(const PathOfContact& path,
                                    const ToothLoad& load,
                                    const MeshCycleOptions& options,
                                    const PairStiffnessFn& stiffness = {});

// Mesh stiffness over one mesh period (samples of the tracked pair's s in [0, p_b)).
struct MeshStiffnessSummary {
  double mean_n_per_m = 0;             // period mean of the mesh stiffness [N/m]
  double min_n_per_m = 0;              // [N/m]
  double max_n_per_m = 0;              // [N/m]
  double single_pair_max_n_per_m = 0;  // max of the pair stiffness along A..E [N/m]
};
MeshStiffnessSummary SummarizeMeshStiffness(const PathOfContact& path,
                                            const PairStiffnessFn& stiffness,
                                            int samples = 400);

}  // namespace tehl
