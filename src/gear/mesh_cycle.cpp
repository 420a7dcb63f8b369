#include "tehl/gear/mesh_cycle.hpp"

#include <algorithm>
#include <limits>

#include "tehl/error.hpp"

namespace tehl {

std::vector<std::string> MeshCycleOptions::Validate() const {
  std::vector<std::string> bad;
  if (points < 2)
    bad.push_back("MeshCycleOptions::points = " + std::to_string(points) + " violates >= 2");
  return bad;
}

std::vector<MeshCycleRow> MeshCycle(const PathOfContact& path,
                                    const ToothLoad& load,
                                    const MeshCycleOptions& options,
                                    const PairStiffnessFn& stiffness) {
  ProblemList problems;
  for (const auto& m : options.Validate()) problems.Add({"", 0, "mesh_cycle", "", m, ""});
  const bool by_stiffness = options.load_sharing != LoadSharing::kLinear;
  if (by_stiffness && !stiffness)
    problems.Add({"", 0, "gear.load_sharing",
                  std::string(1, '"').append(ToString(options.load_sharing)).append(1, '"'),
                  "stiffness load sharing needs a mesh stiffness model", "\"linear\""});
  if (options.relief.Active() && !by_stiffness)
    problems.Add({"", 0, "gear.load_sharing", ToString(options.load_sharing),
                  "tip relief needs the stiffness load sharing", "\"stiffness\" or \"loaded\""});
  if (options.load_sharing == LoadSharing::kLoaded && !options.corner)
    problems.Add({"", 0, "gear.load_sharing", "\"loaded\"",
                  "the loaded sharing needs the pair's corner contact", "a CornerContact"});
  problems.ThrowIfAny();

  const double g = path.length_m();
  std::vector<double> s;
  for (int i = 0; i < options.points; ++i) s.push_back(g * i / (options.points - 1));
  // Switch points on both sides: one-sided limits of the load at B and D.
  const double nudge = 1e-9 * g;
  for (double sw : {path.s_b_m(), path.s_d_m()})
    if (sw > nudge && sw < g - nudge) {
      s.push_back(sw - nudge);
      s.push_back(sw + nudge);
    }
  std::sort(s.begin(), s.end());
  s.erase(std::unique(s.begin(), s.end()), s.end());

  std::vector<MeshCycleRow> rows;
  rows.reserve(s.size());
  for (double q : s) {
    MeshCycleRow r;
    r.contact = path.At(q);
    if (stiffness) {
      r.pair_stiffness_n_per_m = stiffness(r.contact.r1_m, r.contact.r2_m);
      r.mesh_stiffness_n_per_m = MeshStiffnessAt(path, q, stiffness);
    }
    if (options.load_sharing == LoadSharing::kLinear) {
      r.share = LinearLoadShare(path, q);
    } else if (options.relief.Active() || options.load_sharing == LoadSharing::kLoaded) {
      const RelievedShare rs = RelievedLoadShare(path, q, stiffness, options.relief,
                                                 load.normal_force_n, options.corner);
      r.share = rs.share;
      r.transmission_error_m = rs.approach_m;
    } else if (r.mesh_stiffness_n_per_m > 0) {
      r.share = r.pair_stiffness_n_per_m / r.mesh_stiffness_n_per_m;
      r.transmission_error_m = load.normal_force_n / r.mesh_stiffness_n_per_m;
    }
    r.load_n_per_m = r.share * load.load_per_width_n_per_m;
    rows.push_back(r);
  }
  return rows;
}

MeshStiffnessSummary SummarizeMeshStiffness(const PathOfContact& path,
                                            const PairStiffnessFn& stiffness,
                                            int samples) {
  MeshStiffnessSummary out;
  out.min_n_per_m = std::numeric_limits<double>::infinity();
  const double pb = path.base_pitch_m();
  double sum = 0;
  // Midpoint samples of the period, so that no sample sits on a switch point.
  for (int i = 0; i < samples; ++i) {
    const double k = MeshStiffnessAt(path, pb * (i + 0.5) / samples, stiffness);
    sum += k;
    out.min_n_per_m = std::min(out.min_n_per_m, k);
    out.max_n_per_m = std::max(out.max_n_per_m, k);
  }
  out.mean_n_per_m = sum / samples;
  const double g = path.length_m();
  for (int i = 0; i <= samples; ++i) {
    const ContactPoint c = path.At(g * i / samples);
    out.single_pair_max_n_per_m = std::max(out.single_pair_max_n_per_m, stiffness(c.r1_m, c.r2_m));
  }
  return out;
}

}  // namespace tehl
