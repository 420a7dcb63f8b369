// Kuang & Yang (1992) empirical tooth stiffness, as quoted in seed 000 eqs. 4.3-4.5:
// J.H. Kuang, Y.T. Yang, "An estimate of mesh stiffness and load sharing ratio of a spur gear
// pair", Proc. ASME Int. Power Transmission and Gearing Conf., DE-Vol. 43-1, 1992, pp. 1-9.
//
// Single tooth, per unit face width [N/(um mm)], contact at radius r (seed 000 eq. 4.3):
//   K(r) = (A0 + A1 x) + (A2 + A3 x) (r - r_p) / ((1 + x) m)
//   A0 =  3.867 + 1.612 z - 0.02916 z^2 + 0.0001553 z^3                 (4.4a)
//   A1 = 17.060 + 0.72896 z - 0.01728 z^2 + 0.00009993 z^3             (4.4b)
//   A2 =  2.637 - 1.222 z + 0.02217 z^2 - 0.0001179 z^3                (4.4c, corrected)
//   A3 = -6.330 - 1.033 z + 0.02068 z^2 - 0.0001130 z^3                (4.4d, corrected)
// The thesis prints 0.0221 in A2 and "+1.033 z ... +0.0001130 z^3" in A3. The original paper
// could not be consulted; the corrected signs of A2/A3 suggested by the seed 000 extraction
// are used. They are the ones that keep dK/dr < 0 (the tooth softens towards its tip) over
// the whole validity range: with the printed A3, a z = 36, x = 0.5 tooth would get stiffer
// towards its tip. A1 and A3 do not enter when x = 0.
// Pair: the two teeth in series (4.5), K = K1 K2 / (K1 + K2), times the common face width.
//
// Validity (seed 000 section 1.5): symmetric steel teeth, 12 < z < 100, |x| < 0.6; external
// gears; and, as the fit has no parameter for them, the 20 deg full-depth tooth (h_aP = 1) of
// its use in seed 000. Enforced by MakePairStiffnessModel("kuang_yang", ...) and Validate().
#pragma once

#include <string>
#include <vector>

#include "tehl/error.hpp"
#include "tehl/gear/mesh_stiffness.hpp"

namespace tehl {

class KuangYangStiffness : public PairStiffnessModel {
 public:
  // Throws InputError (key "gear.mesh_stiffness") outside the validity range.
  KuangYangStiffness(const ToothBlank& pinion, const ToothBlank& wheel);

  // Every violated rule for one blank; which = "pinion" | "wheel". Empty = usable.
  static std::vector<InputProblem> Validate(const ToothBlank& blank, const std::string& which);

  // Single-tooth stiffness per unit face width (4.3) at contact radius r [N/(um mm)].
  static double SingleToothPerWidth(const ToothBlank& blank, double r_m);

  double PairStiffness(double r1_m, double r2_m) const override;  // [N/m]
  std::string Name() const override { return "kuang_yang"; }

 private:
  ToothBlank pinion_, wheel_;
  double face_width_m_ = 0;  // common face width min(b1, b2) [m]
};

}  // namespace tehl
