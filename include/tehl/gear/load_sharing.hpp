// How the normal load is shared between the tooth pairs in contact, for the pair tracked
// along the path of contact (DESIGN.md section 2; docs/gear.md "Load sharing").
//
// kLinear: the linear ramp common in spur-gear EHL studies, for 1 <= eps_alpha < 2:
//   share = 1/3 + (1/3)(s - s_A)/(s_B - s_A) on [A, B] (entering pair, double contact),
//   share = 1 on (B, D) (single contact),
//   share = 2/3 - (1/3)(s - s_D)/(s_E - s_D) on [D, E] (leaving pair, double contact).
// Since D = A + p_b and AB = DE, the two pairs in contact always share 1 in total.
// kStiffness: share(s) = k(s) / sum_j k(s + j p_b) over the pairs in contact at that
// instant, k the pair stiffness at the contact radii (equal deflection of parallel pairs,
// no profile errors or modifications).
// kLoaded: the stiffness sharing of the loaded teeth: the pairs close one common approach
// under F_bt, and pairs beyond A and E join by corner contact where the approach exceeds the
// separation of their tip corner (corner_contact.hpp; tip_relief.hpp RelievedLoadShare), so
// the share changes smoothly where the stepped kStiffness share jumps at B and D.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "tehl/gear/path_of_contact.hpp"

namespace tehl {

enum class LoadSharing { kStiffness, kLinear, kLoaded };
std::string ToString(LoadSharing sharing);  // "stiffness" | "linear" | "loaded"
std::optional<LoadSharing> LoadSharingFromString(const std::string& name);

// Stiffness of one tooth pair in contact at radius r1 on the pinion and r2 on the wheel,
// per the full face width [N/m]. Wraps a PairStiffnessModel (mesh_stiffness.hpp).
using PairStiffnessFn = std::function<double(double r1_m, double r2_m)>;

// Linear share at s in [0, g_alpha] [-]. Throws InputError (key gear.load_sharing) unless
// 1 <= eps_alpha < 2.
double LinearLoadShare(const PathOfContact& path, double s_m);

// Stiffness share at s in [0, g_alpha] [-].
double StiffnessLoadShare(const PathOfContact& path, double s_m, const PairStiffnessFn& k);

// Mesh stiffness at the instant the tracked pair is at s: the parallel sum of the pair
// stiffnesses of all pairs in contact [N/m].
double MeshStiffnessAt(const PathOfContact& path, double s_m, const PairStiffnessFn& k);

}  // namespace tehl
