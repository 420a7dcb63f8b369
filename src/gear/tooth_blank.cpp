#include "tehl/gear/tooth_blank.hpp"

namespace tehl {
namespace {

ToothBlank Blank(const GearPair& pair, const GearGeometry& g, const GearMemberSpec& m) {
  const GearPairSpec& s = pair.spec();
  ToothBlank b;
  b.teeth = g.teeth;
  b.module_m = s.module_m;
  b.drive_pressure_angle_rad = s.drive_pressure_angle_rad;
  b.coast_pressure_angle_rad = s.coast_pressure_angle_rad;
  b.profile_shift = g.profile_shift;
  b.addendum_coefficient = s.addendum_coefficient;
  b.dedendum_coefficient = s.dedendum_coefficient;
  b.root_fillet_coefficient = s.root_fillet_coefficient;
  b.tip_radius_m = g.tip_radius_m;
  b.face_width_m = s.face_width_m;
  b.youngs_modulus_pa = m.material.youngs_modulus_pa;
  b.poisson_ratio = m.material.poisson_ratio;
  b.internal = g.internal;
  return b;
}

}  // namespace

ToothBlank PinionBlank(const GearPair& pair) {
  return Blank(pair, pair.pinion(), pair.spec().pinion);
}

ToothBlank WheelBlank(const GearPair& pair) { return Blank(pair, pair.wheel(), pair.spec().wheel); }

PairStiffnessFn AsPairStiffnessFn(const PairStiffnessModel& model) {
  return [&model](double r1, double r2) { return model.PairStiffness(r1, r2); };
}

}  // namespace tehl
