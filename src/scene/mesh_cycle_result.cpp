// What a mesh cycle's result tells beyond its steps (mesh_cycle_scene.hpp, MeshCycleResult):
// whether it converged, its restarts and pitch step, and per step the checks of the film
// against its grid and the Blok flash temperature rise.
#include <algorithm>
#include <cmath>

#include "tehl/scene/mesh_cycle_scene.hpp"
#include "tehl/units.hpp"

namespace tehl {

bool MeshCycleResult::converged() const {
  if (static_cast<int>(steps.size()) != planned_steps + 1) return false;
  return std::all_of(steps.begin(), steps.end(),
                     [](const MeshCycleStep& s) { return s.summary.usable(); });
}

int MeshCycleResult::Restarts() const {
  return static_cast<int>(std::count_if(steps.begin(), steps.end(),
                                        [](const MeshCycleStep& s) { return s.restarted(); }));
}

int MeshCycleResult::PitchStep() const {
  int best = 0;
  for (size_t k = 1; k < steps.size(); ++k)
    if (std::abs(steps[k].s_m - s_c_m) < std::abs(steps[best].s_m - s_c_m))
      best = static_cast<int>(k);
  return best;
}

std::vector<InletTruncation> MeshCycleResult::InletTruncations() const {
  std::vector<InletTruncation> out;
  if (x_m.size() < 3) return out;
  for (size_t k = 0; k < steps.size() && k < p_pa.size() && k < h_m.size(); ++k) {
    const MeshCycleStep& st = steps[k];
    InletTruncationInputs in;
    in.x_start_m = x_m.front();
    in.dx_m = x_m[1] - x_m[0];
    in.reduced_radius_m = st.reduced_radius_m;
    in.half_width_m =
        elastic && st.load_n_per_m > 0
            ? LineContactHertz(st.load_n_per_m, st.reduced_radius_m, e_prime_pa).half_width_m
            : 0.0;
    in.um_m_s = st.um_m_s;
    in.inlet_viscosity_pa_s = inlet_viscosity_pa_s;
    in.pressure_viscosity_per_pa = pressure_viscosity_per_pa;
    in.load_n_per_m = st.load_n_per_m;
    out.push_back(EstimateInletTruncation(
        Eigen::Map<const Eigen::VectorXd>(p_pa[k].data(),
                                          static_cast<Eigen::Index>(p_pa[k].size())),
        Eigen::Map<const Eigen::VectorXd>(h_m[k].data(), static_cast<Eigen::Index>(h_m[k].size())),
        in));
  }
  return out;
}

std::vector<double> MeshCycleResult::BlokFlashRises() const {
  std::vector<double> out;
  for (const MeshCycleStep& st : steps) {
    if (!elastic || !(st.load_n_per_m > 0)) {
      out.push_back(elastic ? 0.0 : -1.0);
      continue;
    }
    FlashTemperatureInputs in;
    in.friction_coefficient = st.friction_coefficient;
    in.load_n_per_m = st.load_n_per_m;
    in.u1_m_s = st.u1_m_s;
    in.u2_m_s = st.u2_m_s;
    in.half_width_m =
        LineContactHertz(st.load_n_per_m, st.reduced_radius_m, e_prime_pa).half_width_m;
    out.push_back(FlashTemperature(in, solids.body1, solids.body2, finite_peclet));
  }
  return out;
}

std::vector<OutletSpike> MeshCycleResult::OutletSpikes() const {
  std::vector<OutletSpike> out;
  if (x_m.size() < 2) return out;
  for (const auto& row : p_pa) {
    const Eigen::Map<const Eigen::VectorXd> p(row.data(), static_cast<Eigen::Index>(row.size()));
    out.push_back(FindOutletSpike(p, x_m.front(), x_m[1] - x_m[0]));
  }
  return out;
}

std::vector<HertzEdge> MeshCycleResult::HertzEdges() const {
  std::vector<HertzEdge> out;
  if (x_m.size() < 2) return out;
  for (const MeshCycleStep& st : steps) {
    const double b =
        elastic && st.load_n_per_m > 0
            ? LineContactHertz(st.load_n_per_m, st.reduced_radius_m, e_prime_pa).half_width_m
            : 0.0;
    out.push_back(EstimateHertzEdge(st.reduced_radius_m, b, st.h_c_m, x_m[1] - x_m[0]));
  }
  return out;
}

}  // namespace tehl
