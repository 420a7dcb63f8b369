#include "tehl/gear/path_of_contact.hpp"

#include <cmath>

#include "base/number_text.hpp"
#include "tehl/error.hpp"

namespace tehl {

PathOfContact::PathOfContact(const GearPair& pair, double pinion_speed_rad_s, Flank flank)
    : line_(pair.line(flank)), internal_(pair.spec().internal), w1_(pinion_speed_rad_s) {
  if (!(pinion_speed_rad_s > 0) || !std::isfinite(pinion_speed_rad_s))
    throw InputError(InputProblem{"", 0, "operating.pinion_speed_rad_s",
                                  internal::FormatReal(pinion_speed_rad_s),
                                  "must be finite and > 0 [rad/s]", "a pinion speed > 0 [rad/s]"});
  w2_ = w1_ / pair.gear_ratio();
}

ContactPoint PathOfContact::At(double s) const {
  ContactPoint p;
  p.s_m = s;
  p.position_m = line_.a_m + s;
  p.time_s = s / contact_speed_m_s();
  p.rho1_m = p.position_m;
  p.rho2_m =
      internal_ ? line_.tangent_length_m + p.position_m : line_.tangent_length_m - p.position_m;
  p.reduced_radius_m = internal_ ? p.rho1_m * p.rho2_m / (p.rho2_m - p.rho1_m)
                                 : p.rho1_m * p.rho2_m / (p.rho1_m + p.rho2_m);
  p.r1_m = std::hypot(line_.pinion_base_radius_m, p.rho1_m);
  p.r2_m = std::hypot(line_.wheel_base_radius_m, p.rho2_m);
  p.u1_m_s = w1_ * p.rho1_m;
  p.u2_m_s = w2_ * p.rho2_m;
  p.um_m_s = 0.5 * (p.u1_m_s + p.u2_m_s);
  p.sliding_m_s = p.u1_m_s - p.u2_m_s;
  p.srr = p.sliding_m_s / p.um_m_s;
  p.pairs_in_contact = static_cast<int>(SimultaneousContacts(s).size());
  return p;
}

std::vector<double> PathOfContact::SimultaneousContacts(double s) const {
  const double pb = base_pitch_m();
  const double g = length_m();
  // Round-off guard: a pair exactly at A or E counts as in contact.
  const double eps = 1e-12 * pb;
  std::vector<double> out;
  const long j_min = static_cast<long>(std::ceil((-eps - s) / pb));
  const long j_max = static_cast<long>(std::floor((g + eps - s) / pb));
  for (long j = j_min; j <= j_max; ++j) out.push_back(j == 0 ? s : s + j * pb);
  return out;
}

}  // namespace tehl
