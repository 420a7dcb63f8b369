#include "tehl/gear/contact_ratio.hpp"

#include <cmath>

#include "tehl/gear/involute.hpp"
#include "tehl/units.hpp"

namespace tehl {

double ExternalTransverseContactRatio(
    double ra1, double rb1, double ra2, double rb2, double a, double alpha_w, double pb) {
  return (RollDistance(rb1, ra1) + RollDistance(rb2, ra2) - a * std::sin(alpha_w)) / pb;
}

double InternalTransverseContactRatio(
    double ra1, double rb1, double ra2, double rb2, double a, double alpha_w, double pb) {
  return (RollDistance(rb1, ra1) - RollDistance(rb2, ra2) + a * std::sin(alpha_w)) / pb;
}

TransverseParameters HelicalTransverse(double mn, double alpha_n, double beta) {
  TransverseParameters t;
  t.module_m = mn / std::cos(beta);
  t.pressure_angle_rad = std::atan(std::tan(alpha_n) / std::cos(beta));
  return t;
}

double FaceContactRatio(double b, double beta, double mn) {
  return b * std::sin(beta) / (kPi * mn);
}

ContactRatioAssessment AssessContactRatio(double eps, double band) {
  ContactRatioAssessment r;
  r.continuous = eps >= 1.0;
  r.below_minimum = eps < 1.2;
  const double nearest = std::round(eps);
  r.near_integer = nearest >= 1.0 && std::abs(eps - nearest) < band;
  return r;
}

}  // namespace tehl
