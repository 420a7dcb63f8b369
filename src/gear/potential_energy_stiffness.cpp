#include "tehl/gear/potential_energy_stiffness.hpp"

#include <algorithm>
#include <cmath>

#include "gear/stiffness_blank_check.hpp"
#include "gear/stiffness_tooth_beam.hpp"
#include "gear/stiffness_tooth_geometry.hpp"
#include "tehl/units.hpp"

namespace tehl {

std::vector<InputProblem> PotentialEnergyStiffness::Options::Validate() const {
  std::vector<InputProblem> out;
  if (quadrature_points < 4 || quadrature_points > 256) {
    out.push_back(InputProblem{"", 0, "quadrature_points", std::to_string(quadrature_points),
                               "out of range", "4 <= n <= 256"});
  }
  return out;
}

std::vector<InputProblem> PotentialEnergyStiffness::Validate(const ToothBlank& b,
                                                             const std::string& which) {
  using internal::FormatValue;
  using internal::MethodRangeProblem;
  std::vector<InputProblem> out = internal::CheckToothBlank(b, which);
  const std::string who = "potential_energy (" + which + "): ";
  if (b.internal) {
    out.push_back(MethodRangeProblem("\"potential_energy\"",
                                     who + "ring gears are not modelled (external teeth only)",
                                     "an external pair, or [gear] mesh_stiffness = \"iso\" (ISO "
                                     "6336-1 method B, which covers internal pairs)"));
  }
  if (!out.empty()) return out;
  const internal::StiffnessToothGeometry g(b);
  const double r_a = g.tip_radius_m();
  const double tip_angle =
      g.HalfAngle(internal::FlankSide::kDrive, r_a) + g.HalfAngle(internal::FlankSide::kCoast, r_a);
  if (!(tip_angle > 0)) {
    out.push_back(MethodRangeProblem(FormatValue(r_a),
                                     who + "pointed tooth: the flanks cross below the tip [m]",
                                     "a tip radius with a positive top land"));
  }
  if (!(r_a > g.base_radius_m(internal::FlankSide::kDrive))) {
    out.push_back(MethodRangeProblem(FormatValue(r_a),
                                     who + "tip inside the drive base circle: no involute [m]",
                                     "r_a > r_b of the drive flank"));
  }
  return out;
}

PotentialEnergyStiffness::PotentialEnergyStiffness(const ToothBlank& pinion,
                                                   const ToothBlank& wheel)
    : PotentialEnergyStiffness(pinion, wheel, Options()) {}

PotentialEnergyStiffness::PotentialEnergyStiffness(const ToothBlank& pinion,
                                                   const ToothBlank& wheel,
                                                   const Options& options) {
  ProblemList problems;
  problems.Append(options.Validate());
  problems.Append(Validate(pinion, "pinion"));
  problems.Append(Validate(wheel, "wheel"));
  problems.ThrowIfAny();
  const double l = std::min(pinion.face_width_m, wheel.face_width_m);
  pinion_ = std::make_unique<internal::StiffnessToothBeam>(pinion, l, options);
  wheel_ = std::make_unique<internal::StiffnessToothBeam>(wheel, l, options);
  const double e_prime = ReducedModulus(pinion.youngs_modulus_pa, pinion.poisson_ratio,
                                        wheel.youngs_modulus_pa, wheel.poisson_ratio);
  hertz_stiffness_n_per_m_ = kPi * e_prime * l / 4.0;
}

PotentialEnergyStiffness::~PotentialEnergyStiffness() = default;

PotentialEnergyStiffness::ToothCompliance PotentialEnergyStiffness::PinionCompliance(
    double r1_m) const {
  return pinion_->Compliance(r1_m);
}

PotentialEnergyStiffness::ToothCompliance PotentialEnergyStiffness::WheelCompliance(
    double r2_m) const {
  return wheel_->Compliance(r2_m);
}

double PotentialEnergyStiffness::LowestContactRadius(int gear) const {
  TEHL_ASSERT(gear == 1 || gear == 2, "gear is 1 (pinion) or 2 (wheel)");
  return gear == 1 ? pinion_->LowestContactRadius() : wheel_->LowestContactRadius();
}

double PotentialEnergyStiffness::PairStiffness(double r1_m, double r2_m) const {
  const double compliance = 1.0 / hertz_stiffness_n_per_m_ + pinion_->Compliance(r1_m).Total() +
                            wheel_->Compliance(r2_m).Total();
  return 1.0 / compliance;
}

}  // namespace tehl
