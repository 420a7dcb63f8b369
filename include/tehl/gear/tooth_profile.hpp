// Transverse tooth profile points of both gears (`tehl gear CASE --profile out.csv`).
//
// Each gear in its own frame: centre at the origin, one tooth centred on +y at the pitch
// circle, the drive flank on the +x side. An external tooth is the envelope of the basic
// rack (gear_pair.hpp): the straight rack flank generates the involute, seed 000 eqs.
// 3.1-3.3, with polar angle theta(r) = s_f / r_p + inv(alpha_t) - inv(phi(r)) from +y,
// s_f = m_t (pi/4 + x tan(alpha_n)) the flank's share of the pitch thickness; the rack's
// tip rounding rho_fP generates the trochoidal root fillet from the root circle up to the
// form circle r_F (the contact point on the rounding is where its normal passes through
// the pitch point). Helical gears: the transverse section with a circular rounding of
// radius rho_fP m_n (an approximation). A ring (shaper-cut, cutter unknown): its involute
// flanks, tip arc and root arc, centred on a tooth space; no fillet.
#pragma once

#include <string>
#include <vector>

#include "tehl/gear/gear_pair.hpp"

namespace tehl {

struct ProfilePoint {
  double x_m = 0;  // [m]
  double y_m = 0;  // [m]
};

struct ProfileCurve {
  std::string gear;                  // "pinion" | "wheel"
  std::string flank;                 // "drive" | "coast" | "tip" | "root"
  std::vector<ProfilePoint> points;  // ordered from the root towards the tip (flanks)
};

struct ToothProfileOptions {
  int involute_points = 40;  // per involute flank [-], >= 2
  int fillet_points = 20;    // per root fillet [-], >= 2
  int arc_points = 9;        // per tip or root arc [-], >= 2
};

std::vector<ProfileCurve> ToothProfile(const GearPair& pair,
                                       const ToothProfileOptions& options = {});

}  // namespace tehl
