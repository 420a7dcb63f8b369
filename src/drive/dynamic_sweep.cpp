#include "tehl/drive/dynamic_sweep.hpp"

#include <algorithm>
#include <thread>
#include <vector>

#include "tehl/units.hpp"

namespace tehl {

std::vector<SweepPoint> SweepSpeeds(const TorsionalMesh& mesh,
                                    const TorsionalParameters& p,
                                    const std::vector<double>& speeds_rpm,
                                    const DynamicResponseOptions& o,
                                    int threads,
                                    SweepStart start) {
  std::vector<SweepPoint> out(speeds_rpm.size());
  std::vector<double> carried;  // continuation: (x, x') at phase 0 of the speed before
  double carried_rpm = 0;
  auto run = [&](size_t i) {
    TorsionalParameters q = p;
    q.pinion_speed_rad_s = RpmToRadPerS(speeds_rpm[i]);
    TorsionalModel model(mesh, q);
    DynamicResponseOptions oi = o;
    if (start == SweepStart::kContinuation && !carried.empty())
      oi.initial_state = {carried[0], carried[1] * speeds_rpm[i] / carried_rpm};
    const DynamicResponse r = SolvePeriodicResponse(model, oi);
    // A speed without a periodic response hands on nothing: the next starts from the static
    // deflection again (not from an orbit further back).
    if (start == SweepStart::kContinuation) carried.clear();
    if (start == SweepStart::kContinuation && r.periodic) {
      carried = {r.end_x_m, r.end_v_m_s};
      carried_rpm = speeds_rpm[i];
    }
    SweepPoint& s = out[i];
    s.pinion_speed_rpm = speeds_rpm[i];
    s.mesh_frequency_hz = r.mesh_frequency_hz;
    s.dynamic_load_factor = r.dynamic_load_factor;
    s.min_force_n = r.min_force_n;
    s.separated_fraction = r.separated_fraction;
    s.back_flank_fraction = r.back_flank_fraction;
    s.periodic = r.periodic;
    s.diverged = r.diverged;
    s.periods = r.periods;
    double peak_dyn = 0, peak_static = 0;
    for (const PairLoadPoint& l : TrackedPairLoad(r, 1.0, 201)) {
      peak_dyn = std::max(peak_dyn, l.dynamic_n_per_m);
      peak_static = std::max(peak_static, l.static_n_per_m);
    }
    s.pair_load_factor = peak_static > 0 ? peak_dyn / peak_static : 0.0;
  };
  threads = std::max(1, threads);
  if (threads == 1 || start == SweepStart::kContinuation) {
    for (size_t i = 0; i < speeds_rpm.size(); ++i) run(i);
    return out;
  }
  std::vector<std::thread> pool;
  for (int w = 0; w < threads; ++w)
    pool.emplace_back([&, w]() {
      for (size_t i = w; i < speeds_rpm.size(); i += threads) run(i);
    });
  for (auto& t : pool) t.join();
  return out;
}

}  // namespace tehl
