// One mesh period of a spur gear pair as the torsional model sees it (docs/dynamics.md
// "Mesh"): the time-varying mesh stiffness k(t) of all pairs in contact, where it jumps, and
// the kinematics the tooth friction needs.
//
// The mesh phase is the position of the tracked pair along the line of action measured from
// A, reduced modulo the base pitch: phi = (r_b1 w1 t) mod p_b in [0, p_b), so the tracked
// pair is at A at t = 0. At phase phi the pairs in contact are at s = phi + j p_b in
// [0, g_alpha] (j = 0, 1, ...). The period is cut into segments at the phases where a pair
// enters (0) or leaves (g_alpha mod p_b: single/double contact switches) and where a pair
// passes the pitch point (s_C mod p_b: the sliding and so the friction force change sign).
// Within a segment the set of pairs and the friction signs are fixed and k is smooth.
//
// The pair stiffness k(s) of the gear core (any method: Kuang-Yang fit, potential energy,
// symmetric or asymmetric flanks) is sampled once at Chebyshev-Lobatto points on [0,
// g_alpha] and evaluated by barycentric interpolation (Berrut & Trefethen 2004, SIAM Rev.
// 46:501-517), so the integrator's many evaluations cost no tooth-beam quadrature. Thread-safe
// after construction.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "tehl/gear/corner_contact.hpp"
#include "tehl/gear/gear_pair.hpp"
#include "tehl/gear/load_sharing.hpp"
#include "tehl/gear/tip_relief.hpp"

namespace tehl {

struct MeshSegment {
  double begin_m = 0;        // phase at the start [m], in [0, p_b)
  double end_m = 0;          // phase at the end [m], in (0, p_b]
  std::vector<int> pairs;    // offsets j of the pairs in contact (s = phi + j p_b), ascending
  std::vector<int> sliding;  // sign of u1 - u2 of each pair (+1 past the pitch point) [-]
  // 1 for a pair outside [0, g_alpha], which touches only by corner contact (it carries load
  // only once the approach exceeds its separation), 0 on the path of contact.
  std::vector<int> corner;
};

class TorsionalMesh {
 public:
  // The drive-flank mesh of `pair` with pair stiffness `k` [N/m] (see load_sharing.hpp);
  // chebyshev_points >= 3 samples of k on [0, g_alpha].
  // With `relief` the drive-flank pairs carry k_j max(0, x - e_j) at the approach x
  // (tip_relief.hpp); without it k_j x. With corner_max_gap_m > 0 the pairs also mesh
  // outside [0, g_alpha] by corner contact (corner_contact.hpp), up to that separation [m],
  // with the stiffness of the pair at the nearer end of the path; 0: the pairs mesh on
  // [0, g_alpha] only and the mesh stiffness steps at A and E (seed 000).
  TorsionalMesh(const GearPair& pair,
                const PairStiffnessFn& k,
                int chebyshev_points = 33,
                const TipRelief& relief = {},
                double corner_max_gap_m = 0);
  // The same geometry with a constant mesh stiffness k_mesh [N/m] shared equally between the
  // pairs in contact (for limits and tests).
  static TorsionalMesh Constant(const GearPair& pair, double mesh_stiffness_n_per_m);

  double base_pitch_m() const { return base_pitch_m_; }               // p_b [m]
  double length_m() const { return length_m_; }                       // g_alpha [m]
  double pitch_point_m() const { return s_pitch_m_; }                 // s_C [m]
  double pinion_base_radius_m() const { return rb1_m_; }              // r_b1 [m]
  double wheel_base_radius_m() const { return rb2_m_; }               // r_b2 [m]
  double contact_ratio() const { return length_m_ / base_pitch_m_; }  // eps_alpha [-]
  int pinion_teeth() const { return z1_; }
  int wheel_teeth() const { return z2_; }
  // Radii of curvature (roll distances) of the pinion and wheel flanks at s [m].
  double Rho1(double s_m) const { return start_from_t1_m_ + s_m; }
  double Rho2(double s_m) const;

  const std::vector<MeshSegment>& segments() const { return segments_; }
  // Segment holding phase phi in [0, p_b): begin <= phi < end.
  int SegmentAt(double phase_m) const;

  double PairStiffness(double s_m) const;  // k(s), s clamped to [0, g_alpha] [N/m]
  // Sum over the pairs on [0, g_alpha] (the nominal mesh stiffness; corner contacts add to
  // it only as far as the approach closes their separation, see ElasticForce) [N/m].
  double MeshStiffness(int segment, double phase_m) const;
  // Share of pair `index` (position in segments()[segment].pairs) of the mesh force: its
  // stiffness over the sum (equal deflection of parallel pairs; 0 for a corner pair) [-].
  double PairShare(int segment, int index, double phase_m) const;
  // Share of the pair at s in [0, g_alpha]; `left` takes the limit from below at a switch.
  double ShareAt(double s_m, bool left) const;

  // Tip relief (docs/gear.md "Tip relief"): the gap e(s) its relief opens [m], the elastic
  // drive-flank force sum_j k_j max(0, x - e_j) at the approach x [N], the share of pair
  // `index` at x (its stiffness share without relief) [-], and the static approach under the
  // force F at the instant the pair at s sees [m]. Without relief: k_mesh x, k_i / k_mesh
  // and F / k_mesh.
  const TipRelief& relief() const { return relief_; }
  // Corner contact: on, and how far before A and after E pairs may touch [m].
  bool corner_contact() const { return corner_before_m_ > 0 || corner_after_m_ > 0; }
  double corner_before_m() const { return corner_before_m_; }
  double corner_after_m() const { return corner_after_m_; }
  // The separation the pair at s must close before it carries load: the relief gap on
  // [0, g_alpha], the corner separation (plus the relief at the tip) outside [m].
  double GapAt(double s_m) const;
  // Whether the force needs the pair-by-pair sum (relief or corner contact).
  bool gapped() const { return relief_.Active() || corner_contact(); }
  double ElasticForce(int segment, double phase_m, double x_m) const;
  double PairShare(int segment, int index, double phase_m, double x_m) const;
  double ShareAt(double s_m, bool left, double x_m) const;
  double StaticApproachAt(double s_m, bool left, double force_n) const;

  // Over one period: mean of k_mesh = (1/p_b) integral of k(s) over [0, g_alpha], and the
  // extremes (sampled) [N/m].
  double mean_stiffness_n_per_m() const { return mean_n_per_m_; }
  double min_stiffness_n_per_m() const { return min_n_per_m_; }
  double max_stiffness_n_per_m() const { return max_n_per_m_; }

  // The back flanks (docs/dynamics.md "Back flanks"): the mesh of the pair seen from its
  // coast side (flank_phase.hpp: the drive mesh of GearPair(CoastSideSpec(spec)), same relief
  // and corner contact), whose pairs sit at s_c = BackPhase(phi) + j p_bc when this mesh's
  // sit at phi + j p_b: as phi runs forward, the back phase runs backwards. Without them the
  // back flanks mesh on this mesh at its own phase (constant-stiffness limits and tests).
  void SetBackFlanks(std::shared_ptr<const TorsionalMesh> back, double phase_offset);
  const TorsionalMesh* back_flanks() const { return back_.get(); }
  double back_phase_offset() const { return back_offset_; }  // delta [-], in [0, 1)
  // Phase of the back flanks' mesh at this mesh's phase phi [m], in [0, p_bc):
  // p_bc frac(delta - phi / p_b); this phase itself without back flanks.
  double BackPhase(double phase_m) const;
  // K = r_bc / r_bd: a back-flank force F_c acts on the drive coordinate x as K F_c, and the
  // back flanks close by K (-(x + b)) [-]; 1 without back flanks.
  double back_ratio() const;

 private:
  TorsionalMesh() = default;
  void BuildSegments(double s_pitch_m);
  // The segment, phase and pair index of the pair at s (index -1: not in contact).
  void Locate(double s_m, bool left, int* segment, double* phase_m, int* index) const;
  void Summarize();

  double base_pitch_m_ = 0, length_m_ = 0, s_pitch_m_ = 0, rb1_m_ = 0, rb2_m_ = 0;
  double start_from_t1_m_ = 0, tangent_length_m_ = 0;
  bool internal_ = false;
  int z1_ = 0, z2_ = 0;
  double constant_mesh_n_per_m_ = 0;                        // > 0: constant mode
  std::vector<double> nodes_m_, values_n_per_m_, weights_;  // Chebyshev-Lobatto interpolant
  std::vector<MeshSegment> segments_;
  TipRelief relief_;
  std::optional<CornerContact> corner_;
  double corner_before_m_ = 0, corner_after_m_ = 0;
  double mean_n_per_m_ = 0, min_n_per_m_ = 0, max_n_per_m_ = 0;
  std::shared_ptr<const TorsionalMesh> back_;
  double back_offset_ = 0;
};

}  // namespace tehl
