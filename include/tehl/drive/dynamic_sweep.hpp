// The dynamic load factor against speed (seed 000 Fig. 5.49; docs/dynamics.md "Speed sweeps").
//
// Each speed's periodic response (dynamic_response.hpp) starts either from the static
// deflection (the default: every speed on its own, in parallel) or, by continuation, from the
// periodic response of the speed before it in the order given (a speed whose response is not
// periodic hands on nothing: the next starts from the static deflection): (x, x') at phase 0
// with x' scaled by the speed ratio (the orbit keeps its shape in the phase, dx/dphi, as the speed
// changes a little). Where the response has two stable branches (a mesh that strikes its back
// flanks or separates is a hardening or softening spring; the resonance jumps) continuation
// follows the branch it is on through the jump, upwards or downwards, and the static start
// lands on whichever branch attracts it.
#pragma once

#include <vector>

#include "tehl/drive/dynamic_response.hpp"

namespace tehl {

// One point of a speed sweep.
struct SweepPoint {
  double pinion_speed_rpm = 0;     // [rpm]
  double mesh_frequency_hz = 0;    // [Hz]
  double dynamic_load_factor = 0;  // peak F / F_s [-]
  double pair_load_factor = 0;     // peak tracked-pair load / peak static pair load [-]
  double min_force_n = 0;          // [N]
  double separated_fraction = 0;   // [-]
  double back_flank_fraction = 0;  // [-]
  bool periodic = false;
  bool diverged = false;  // the response grows without bound (dynamic_response.hpp)
  int periods = 0;
};

enum class SweepStart {
  kStatic,        // each speed from the static deflection (threads run speeds in parallel)
  kContinuation,  // each speed from the response of the one before (sequential)
};

// Every speed with the parameters of `p` otherwise, in the order given. Runs the speeds on
// `threads` threads (kStatic only).
std::vector<SweepPoint> SweepSpeeds(const TorsionalMesh& mesh,
                                    const TorsionalParameters& p,
                                    const std::vector<double>& speeds_rpm,
                                    const DynamicResponseOptions& o,
                                    int threads = 1,
                                    SweepStart start = SweepStart::kStatic);

}  // namespace tehl
