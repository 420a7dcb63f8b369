// The seed 000 gear pair for the torsional-dynamics tests: 36/36 teeth, 8 diametral pitch
// (m = 25.4/8 mm), 20 deg, face width 1 in (seed 000 extraction sections 1.4 and 7.3),
// steel; Kuang-Yang stiffness (seed 000 eqs. 4.3-4.8); 100 lbf in on the pinion (extraction
// section 2.1, T_p = 100, read as lbf in); inertias of solid steel discs of the pitch
// diameter and the face width (seed 000 gives none).
#pragma once

#include <memory>

#include "tehl/drive/torsional_mesh.hpp"
#include "tehl/drive/torsional_model.hpp"
#include "tehl/gear/kuang_yang_stiffness.hpp"
#include "tehl/gear/tooth_blank.hpp"
#include "tehl/units.hpp"
#include "unit/gear/reference_pairs.hpp"

namespace tehl::testing {

inline GearPairSpec Seed000Symmetric() {
  GearPairSpec s = Seed000Spec(20.0, 20.0);
  s.root_fillet_coefficient = 0.38;
  return s;
}

struct Seed000Dynamics {
  Seed000Dynamics() : pair(Seed000Symmetric()) {
    model = MakePairStiffnessModel("kuang_yang", PinionBlank(pair), WheelBlank(pair));
    mesh = std::make_unique<TorsionalMesh>(pair, AsPairStiffnessFn(*model));
    const double r = pair.pinion().pitch_radius_m;
    params.pinion_inertia_kg_m2 = DiscInertia(7850.0, pair.spec().face_width_m, r);
    params.wheel_inertia_kg_m2 = params.pinion_inertia_kg_m2;
    params.pinion_torque_nm = 100.0 * 0.45359237 * 9.80665 * 0.0254;  // 100 lbf in [N m]
    params.pinion_speed_rad_s = RpmToRadPerS(1000.0);
    params.damping_ratio = 0.05;
    params.backlash_m = 50e-6;
  }
  GearPair pair;
  std::unique_ptr<PairStiffnessModel> model;
  std::unique_ptr<TorsionalMesh> mesh;
  TorsionalParameters params;
};

// Resonance speed: f_m = z1 n / 60 = f_n  ->  n = 60 f_n / z1 [rpm].
inline double ResonanceRpm(const Seed000Dynamics& d) {
  const TorsionalModel m(*d.mesh, d.params);
  return 60.0 * m.natural_frequency_hz() / d.pair.pinion().teeth;
}

}  // namespace tehl::testing
