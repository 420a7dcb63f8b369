// Tip relief: the profile modification that removes material towards the tooth tips so that
// a pair takes up its load gradually where it enters and leaves the mesh (ISO 21771:2007,
// section 7.2, "tip relief": amount C_a and length L_Ca along the line of action). The
// quasi-static load sharing with relief (docs/gear.md "Tip relief"): the pairs in contact
// close by one common approach delta along the line of action (rigid gear bodies), the pair
// at s first touches once delta exceeds the separation e(s) the relief opens there, and then
// carries k(s) (delta - e(s)); delta makes the pair loads sum to the normal force F_bt.
//
// Orientation (the pinion drives): the wheel's tip meets the pinion's root at A (s = 0) and
// the pinion's tip meets the wheel's root at E (s = g_alpha). So the wheel's relief opens
// e(s) = C_a,2 shape_2((L_2 - s) / L_2) on [0, L_2] and the pinion's e(s) = C_a,1 shape_1((s -
// g_alpha + L_1) / L_1) on [g_alpha - L_1, g_alpha]; shape(x) = x (linear) or x^2 (parabolic),
// each gear its own.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tehl/gear/corner_contact.hpp"
#include "tehl/gear/load_sharing.hpp"
#include "tehl/gear/path_of_contact.hpp"

namespace tehl {

enum class ReliefShape { kLinear, kParabolic };
std::string ToString(ReliefShape shape);  // "linear" | "parabolic"
std::optional<ReliefShape> ReliefShapeFromString(const std::string& name);

struct TipRelief {
  double pinion_amount_m = 0;  // C_a,1 at the pinion tip [m], >= 0
  double pinion_length_m = 0;  // L_Ca,1 along the line of action from E [m], > 0 with an amount
  double wheel_amount_m = 0;   // C_a,2 at the wheel tip [m], >= 0
  double wheel_length_m = 0;   // L_Ca,2 along the line of action from A [m]
  ReliefShape pinion_shape = ReliefShape::kLinear;
  ReliefShape wheel_shape = ReliefShape::kLinear;

  bool Active() const { return pinion_amount_m > 0 || wheel_amount_m > 0; }
  // Separation the relief opens between the flanks of the pair at s in [0, g_alpha] [m].
  double GapAt(double s_m, double path_length_m) const;
};

// The common approach delta of pairs of stiffness k_j [N/m] and relief gaps e_j [m] under the
// force F [N] > 0: sum_j k_j max(0, delta - e_j) = F [m]. Infinite with no stiffness.
double CommonApproach(const std::vector<double>& k_n_per_m,
                      const std::vector<double>& gap_m,
                      double force_n);

struct RelievedShare {
  double share = 0;       // load share of the pair at s [-], in [0, 1]
  double approach_m = 0;  // the common approach delta of the pairs in contact [m]
};

// Load share of the pair at s in [0, g_alpha] with tip relief, under the normal force
// F_bt [N] > 0 and the pair stiffness k [N/m] (per the full face width). Without relief it
// equals StiffnessLoadShare.
// With `corner` the pairs beyond A and E take part by corner contact (load_sharing kLoaded):
// separation corner->GapAt(q) plus the relief at the tip, stiffness of the pair at the end.
RelievedShare RelievedLoadShare(const PathOfContact& path,
                                double s_m,
                                const PairStiffnessFn& k,
                                const TipRelief& relief,
                                double normal_force_n,
                                const CornerContact* corner = nullptr);

// The approach the pairs other than the one at s need to carry F_bt on their own [m]: the
// pair at s is loaded exactly when its relief gap is below this (the largest relief amount
// that keeps it loaded at the end of the path). Infinite when s is the only pair in contact.
double ApproachWithoutPair(const PathOfContact& path,
                           double s_m,
                           const PairStiffnessFn& k,
                           const TipRelief& relief,
                           double normal_force_n,
                           const CornerContact* corner = nullptr);

// The part of the path where the tracked pair carries at least `min_share` of F_bt [m]:
// [0, g_alpha] without relief; with relief a relief can lift the pair off near A (the wheel's
// tip) and near E (the pinion's), and the ends are where the share reaches min_share
// (bisection to 1e-9 g_alpha on a sampling of 400 intervals). Empty (begin >= end) when the
// pair never carries min_share, or when it drops below it between the two ends.
struct LoadedPath {
  double begin_m = 0, end_m = 0;  // A' and E' [m]
  bool empty() const { return !(end_m > begin_m); }
};
LoadedPath LoadedPathOf(const PathOfContact& path,
                        const PairStiffnessFn& k,
                        const TipRelief& relief,
                        double normal_force_n,
                        double min_share,
                        const CornerContact* corner = nullptr);

}  // namespace tehl
