#include "tehl/drive/torsional_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tehl/gear/path_of_contact.hpp"
#include "tehl/units.hpp"

namespace tehl {

TorsionalMesh::TorsionalMesh(const GearPair& pair,
                             const PairStiffnessFn& k,
                             int n,
                             const TipRelief& relief,
                             double corner_max_gap_m)
    : relief_(relief) {
  if (corner_max_gap_m > 0) {
    corner_.emplace(pair, Flank::kDrive, corner_max_gap_m);
    corner_before_m_ = corner_->before_m();
    corner_after_m_ = corner_->after_m();
  }
  const PathOfContact path(pair, 1.0, Flank::kDrive);
  const LineOfAction& l = path.line();
  base_pitch_m_ = path.base_pitch_m();
  length_m_ = path.length_m();
  rb1_m_ = l.pinion_base_radius_m;
  rb2_m_ = l.wheel_base_radius_m;
  start_from_t1_m_ = l.a_m;
  tangent_length_m_ = l.tangent_length_m;
  internal_ = path.internal();
  z1_ = pair.pinion().teeth;
  z2_ = pair.wheel().teeth;
  n = std::max(n, 3);
  // Chebyshev-Lobatto points s_i = g (1 - cos(pi i / (n-1))) / 2 and the barycentric weights
  // (-1)^i, halved at both ends.
  nodes_m_.resize(n);
  values_n_per_m_.resize(n);
  weights_.resize(n);
  for (int i = 0; i < n; ++i) {
    nodes_m_[i] = 0.5 * length_m_ * (1.0 - std::cos(kPi * i / (n - 1)));
    const ContactPoint c = path.At(nodes_m_[i]);
    values_n_per_m_[i] = k(c.r1_m, c.r2_m);
    weights_[i] = ((i % 2) ? -1.0 : 1.0) * ((i == 0 || i == n - 1) ? 0.5 : 1.0);
  }
  BuildSegments(path.s_c_m());
  Summarize();
}

TorsionalMesh TorsionalMesh::Constant(const GearPair& pair, double k_mesh) {
  TorsionalMesh m(
      pair, [](double, double) { return 1.0; }, 3);
  m.constant_mesh_n_per_m_ = k_mesh;
  m.Summarize();
  return m;
}

double TorsionalMesh::Rho2(double s_m) const {
  return internal_ ? tangent_length_m_ + Rho1(s_m) : tangent_length_m_ - Rho1(s_m);
}

void TorsionalMesh::BuildSegments(double s_pitch) {
  s_pitch_m_ = s_pitch;
  const double pb = base_pitch_m_, g = length_m_;
  const double tol = 1e-12 * pb;
  std::vector<double> cuts = {0.0, pb};
  const double lo = -corner_before_m_, hi = g + corner_after_m_;  // where pairs may touch
  const auto wrap = [pb](double q) { return q - std::floor(q / pb) * pb; };
  for (double q : {std::fmod(g, pb), std::fmod(s_pitch, pb), wrap(lo), wrap(hi)})
    if (q > tol && q < pb - tol) cuts.push_back(q);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end(),
                         [&](double a, double b) { return std::abs(a - b) <= tol; }),
             cuts.end());
  segments_.clear();
  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    MeshSegment seg;
    seg.begin_m = cuts[i];
    seg.end_m = cuts[i + 1];
    const double mid = 0.5 * (seg.begin_m + seg.end_m);
    for (int j = static_cast<int>(std::ceil((lo - mid) / pb)); mid + j * pb <= hi; ++j) {
      const double s = mid + j * pb;
      seg.pairs.push_back(j);
      seg.sliding.push_back(s > s_pitch ? +1 : -1);
      seg.corner.push_back(s < 0 || s > g ? 1 : 0);
    }
    segments_.push_back(std::move(seg));
  }
}

void TorsionalMesh::Summarize() {
  // Mean: composite Simpson on k(s) over [0, g] (each s is visited once per period).
  const int m = 2000;
  double integral = 0;
  for (int i = 0; i <= m; ++i) {
    const double w = (i == 0 || i == m) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    integral += w * PairStiffness(length_m_ * i / m);
  }
  integral *= length_m_ / m / 3.0;
  mean_n_per_m_ = constant_mesh_n_per_m_ > 0 ? constant_mesh_n_per_m_ : integral / base_pitch_m_;
  min_n_per_m_ = 1e300;
  max_n_per_m_ = 0;
  for (int si = 0; si < static_cast<int>(segments_.size()); ++si) {
    const MeshSegment& seg = segments_[si];
    for (int i = 0; i <= 50; ++i) {
      const double k = MeshStiffness(si, seg.begin_m + (seg.end_m - seg.begin_m) * i / 50);
      min_n_per_m_ = std::min(min_n_per_m_, k);
      max_n_per_m_ = std::max(max_n_per_m_, k);
    }
  }
}

void TorsionalMesh::SetBackFlanks(std::shared_ptr<const TorsionalMesh> back, double offset) {
  back_ = std::move(back);
  back_offset_ = offset - std::floor(offset);
}

double TorsionalMesh::BackPhase(double phase) const {
  if (!back_) return phase;
  const double q = back_offset_ - phase / base_pitch_m_;
  return back_->base_pitch_m() * (q - std::floor(q));
}

double TorsionalMesh::back_ratio() const {
  return back_ ? back_->pinion_base_radius_m() / rb1_m_ : 1.0;
}

int TorsionalMesh::SegmentAt(double phase) const {
  for (int i = 0; i < static_cast<int>(segments_.size()); ++i)
    if (phase < segments_[i].end_m) return i;
  return static_cast<int>(segments_.size()) - 1;
}

double TorsionalMesh::PairStiffness(double s) const {
  if (constant_mesh_n_per_m_ > 0) return constant_mesh_n_per_m_;
  s = std::clamp(s, 0.0, length_m_);
  double num = 0, den = 0;
  for (size_t i = 0; i < nodes_m_.size(); ++i) {
    const double d = s - nodes_m_[i];
    if (d == 0) return values_n_per_m_[i];
    const double w = weights_[i] / d;
    num += w * values_n_per_m_[i];
    den += w;
  }
  return num / den;
}

double TorsionalMesh::MeshStiffness(int segment, double phase) const {
  const MeshSegment& seg = segments_[segment];
  if (constant_mesh_n_per_m_ > 0) return constant_mesh_n_per_m_;
  double sum = 0;
  for (size_t i = 0; i < seg.pairs.size(); ++i)
    if (!seg.corner[i]) sum += PairStiffness(phase + seg.pairs[i] * base_pitch_m_);
  return sum;
}

double TorsionalMesh::PairShare(int segment, int index, double phase) const {
  const MeshSegment& seg = segments_[segment];
  if (seg.corner[index]) return 0.0;
  if (constant_mesh_n_per_m_ > 0) return 1.0 / seg.pairs.size();
  return PairStiffness(phase + seg.pairs[index] * base_pitch_m_) / MeshStiffness(segment, phase);
}

double TorsionalMesh::GapAt(double s) const {
  const double inside =
      relief_.Active() ? relief_.GapAt(std::clamp(s, 0.0, length_m_), length_m_) : 0.0;
  if (s >= 0 && s <= length_m_) return inside;
  return corner_ ? corner_->GapAt(s) + inside : std::numeric_limits<double>::infinity();
}

void TorsionalMesh::Locate(double s, bool left, int* seg_out, double* phase_out, int* index) const {
  s = std::clamp(s, 0.0, length_m_);
  const double pb = base_pitch_m_;
  const int j =
      std::min(static_cast<int>(std::floor(s / pb)), static_cast<int>(std::floor(length_m_ / pb)));
  double phase = s - j * pb;
  // The segment on the requested side of a switch.
  const double nudge = 1e-9 * pb;
  int seg = SegmentAt(std::clamp(left ? phase - nudge : phase + nudge, 0.0, pb * (1 - 1e-15)));
  if (left && phase - nudge < 0) {  // at phase 0 from below: the end of the previous period
    seg = static_cast<int>(segments_.size()) - 1;
    phase = pb;
  }
  const int jj = static_cast<int>(std::lround((s - phase) / pb));
  const auto& pairs = segments_[seg].pairs;
  const auto it = std::find(pairs.begin(), pairs.end(), jj);
  *seg_out = seg;
  *phase_out = phase;
  *index = it == pairs.end() ? -1 : static_cast<int>(it - pairs.begin());
}

double TorsionalMesh::ShareAt(double s, bool left) const {
  int seg = 0, index = -1;
  double phase = 0;
  Locate(s, left, &seg, &phase, &index);
  return index < 0 ? 0.0 : PairShare(seg, index, phase);
}

double TorsionalMesh::ShareAt(double s, bool left, double x) const {
  int seg = 0, index = -1;
  double phase = 0;
  Locate(s, left, &seg, &phase, &index);
  return index < 0 ? 0.0 : PairShare(seg, index, phase, x);
}

double TorsionalMesh::ElasticForce(int segment, double phase, double x) const {
  if (!gapped()) return MeshStiffness(segment, phase) * x;
  const MeshSegment& seg = segments_[segment];
  double f = 0;
  for (size_t i = 0; i < seg.pairs.size(); ++i) {
    const double s = phase + seg.pairs[i] * base_pitch_m_;
    const double k =
        constant_mesh_n_per_m_ > 0 ? constant_mesh_n_per_m_ / seg.pairs.size() : PairStiffness(s);
    f += k * std::max(0.0, x - GapAt(s));
  }
  return f;
}

double TorsionalMesh::PairShare(int segment, int index, double phase, double x) const {
  if (!gapped()) return PairShare(segment, index, phase);
  const MeshSegment& seg = segments_[segment];
  const double total = ElasticForce(segment, phase, x);
  if (!(total > 0)) return 0.0;
  const double s = phase + seg.pairs[index] * base_pitch_m_;
  const double k =
      constant_mesh_n_per_m_ > 0 ? constant_mesh_n_per_m_ / seg.pairs.size() : PairStiffness(s);
  return k * std::max(0.0, x - GapAt(s)) / total;
}

double TorsionalMesh::StaticApproachAt(double s, bool left, double force) const {
  int seg = 0, index = -1;
  double phase = 0;
  Locate(s, left, &seg, &phase, &index);
  const MeshSegment& m = segments_[seg];
  std::vector<double> k, gap;
  for (int j : m.pairs) {
    const double q = phase + j * base_pitch_m_;
    k.push_back(constant_mesh_n_per_m_ > 0 ? constant_mesh_n_per_m_ / m.pairs.size()
                                           : PairStiffness(q));
    gap.push_back(GapAt(q));
  }
  return CommonApproach(k, gap, force);
}

}  // namespace tehl
