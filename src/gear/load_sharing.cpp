#include "tehl/gear/load_sharing.hpp"

#include <algorithm>
#include <sstream>

#include "tehl/error.hpp"

namespace tehl {

std::string ToString(LoadSharing sharing) {
  switch (sharing) {
    case LoadSharing::kLinear:
      return "linear";
    case LoadSharing::kLoaded:
      return "loaded";
    case LoadSharing::kStiffness:
      break;
  }
  return "stiffness";
}

std::optional<LoadSharing> LoadSharingFromString(const std::string& name) {
  if (name == "linear") return LoadSharing::kLinear;
  if (name == "stiffness") return LoadSharing::kStiffness;
  if (name == "loaded") return LoadSharing::kLoaded;
  return std::nullopt;
}

double LinearLoadShare(const PathOfContact& path, double s) {
  const double eps = path.contact_ratio();
  if (!(eps >= 1.0 && eps < 2.0)) {
    std::ostringstream m;
    m << "the linear load-sharing ramp needs 1 <= eps_alpha < 2; eps_alpha = " << eps;
    throw InputError(InputProblem{"", 0, "gear.load_sharing", "\"linear\"", m.str(),
                                  "load_sharing = \"stiffness\""});
  }
  // Double contact on the closed intervals [A, B] and [D, E]: at B the partner pair is at E,
  // at D it is at A, and both count as in contact (PathOfContact::SimultaneousContacts).
  const double sb = path.s_b_m(), sd = path.s_d_m(), g = path.length_m();
  const double tol = 1e-12 * path.base_pitch_m();
  if (s <= sb + tol) return sb > 0 ? 1.0 / 3.0 + (std::min(s, sb) / sb) / 3.0 : 2.0 / 3.0;
  if (s < sd - tol) return 1.0;
  return g > sd ? 2.0 / 3.0 - ((std::max(s, sd) - sd) / (g - sd)) / 3.0 : 1.0 / 3.0;
}

double MeshStiffnessAt(const PathOfContact& path, double s, const PairStiffnessFn& k) {
  double sum = 0;
  for (double q : path.SimultaneousContacts(s)) {
    const ContactPoint c = path.At(q);
    sum += k(c.r1_m, c.r2_m);
  }
  return sum;
}

double StiffnessLoadShare(const PathOfContact& path, double s, const PairStiffnessFn& k) {
  // The pair at s is one of the simultaneous contacts (returned as s itself): its stiffness
  // enters the sum and the share, evaluated once (each is a numerical integration).
  double own = 0, total = 0;
  bool found = false;
  for (double q : path.SimultaneousContacts(s)) {
    const ContactPoint c = path.At(q);
    const double kq = k(c.r1_m, c.r2_m);
    total += kq;
    if (q == s && !found) {
      own = kq;
      found = true;
    }
  }
  if (!found) {  // s off the path (beyond the round-off guard of A and E)
    const ContactPoint c = path.At(s);
    own = k(c.r1_m, c.r2_m);
  }
  return total > 0 ? own / total : 0.0;
}

}  // namespace tehl
