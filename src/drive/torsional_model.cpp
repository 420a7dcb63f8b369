#include "tehl/drive/torsional_model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "tehl/units.hpp"

namespace tehl {

std::string ToString(ContactState s) {
  switch (s) {
    case ContactState::kDriveFlank:
      return "drive_flank";
    case ContactState::kSeparated:
      return "separated";
    case ContactState::kBackFlank:
      return "back_flank";
  }
  return "unknown";
}

std::string ToString(FrictionLaw f) {
  switch (f) {
    case FrictionLaw::kNone:
      return "none";
    case FrictionLaw::kConstant:
      return "constant";
    case FrictionLaw::kBuckingham:
      return "buckingham";
  }
  return "unknown";
}

std::optional<FrictionLaw> FrictionLawFromString(const std::string& name) {
  if (name == "none") return FrictionLaw::kNone;
  if (name == "constant") return FrictionLaw::kConstant;
  if (name == "buckingham") return FrictionLaw::kBuckingham;
  return std::nullopt;
}

double BuckinghamFriction(double v) {
  // Seed 000 eq. 4.10, V converted from m/s to in/s.
  const double v_in_s = std::abs(v) / 0.0254;
  return 0.05 * std::exp(-0.125 * v_in_s) + 0.002 * std::sqrt(v_in_s);
}

double DiscInertia(double rho, double b, double r) { return 0.5 * kPi * rho * b * std::pow(r, 4); }

std::vector<std::string> TorsionalParameters::Validate() const {
  std::vector<std::string> bad;
  auto rule = [&](bool ok, const char* field, double value, const char* constraint) {
    if (ok) return;
    std::ostringstream m;
    m << "TorsionalParameters::" << field << " = " << value << " violates " << constraint;
    bad.push_back(m.str());
  };
  rule(pinion_inertia_kg_m2 > 0, "pinion_inertia_kg_m2", pinion_inertia_kg_m2, "> 0 [kg m^2]");
  rule(wheel_inertia_kg_m2 > 0, "wheel_inertia_kg_m2", wheel_inertia_kg_m2, "> 0 [kg m^2]");
  rule(pinion_torque_nm > 0, "pinion_torque_nm", pinion_torque_nm, "> 0 [N m]");
  rule(pinion_speed_rad_s > 0, "pinion_speed_rad_s", pinion_speed_rad_s, "> 0 [rad/s]");
  rule(damping_ratio >= 0 && damping_ratio < 1, "damping_ratio", damping_ratio, "in [0, 1)");
  rule(backlash_m >= 0, "backlash_m", backlash_m, ">= 0 [m]");
  rule(friction_coefficient >= 0 && friction_coefficient < 1, "friction_coefficient",
       friction_coefficient, "in [0, 1)");
  return bad;
}

TorsionalModel::TorsionalModel(const TorsionalMesh& mesh, const TorsionalParameters& p)
    : mesh_(mesh), p_(p) {
  const double rb1 = mesh.pinion_base_radius_m(), rb2 = mesh.wheel_base_radius_m();
  const double j1 = p.pinion_inertia_kg_m2, j2 = p.wheel_inertia_kg_m2;
  m_e_ = j1 * j2 / (rb1 * rb1 * j2 + rb2 * rb2 * j1);
  c_ = 2.0 * p.damping_ratio * std::sqrt(mesh.mean_stiffness_n_per_m() * m_e_);
  // The back flanks' damper acts on their own closure K (-(x + b)), whose equivalent mass is
  // m_e / K^2, with their own mean stiffness (the same damping ratio).
  const double k_ratio = mesh.back_ratio();
  const TorsionalMesh& back = mesh.back_flanks() ? *mesh.back_flanks() : mesh;
  c_back_ =
      2.0 * p.damping_ratio * std::sqrt(back.mean_stiffness_n_per_m() * m_e_ / (k_ratio * k_ratio));
  f_static_ = p.pinion_torque_nm / rb1;
  torque_load_nm_ = p.pinion_torque_nm * rb2 / rb1;
}

double TorsionalModel::natural_frequency_hz() const {
  return std::sqrt(mesh_.mean_stiffness_n_per_m() / m_e_) / (2.0 * kPi);
}
double TorsionalModel::mesh_frequency_hz() const {
  return mesh_.pinion_teeth() * p_.pinion_speed_rad_s / (2.0 * kPi);
}
double TorsionalModel::mesh_period_s() const { return mesh_.base_pitch_m() / contact_speed_m_s(); }

double TorsionalModel::PhaseAt(long period, double t) const {
  return contact_speed_m_s() * t - period * mesh_.base_pitch_m();
}

double TorsionalModel::BackFlankForce(
    const TorsionalMesh& m, int seg, double phase, double x, double v) const {
  // The back flanks close by d = K (-(x + b)) at the rate -K x' along their own line of
  // action; they push and never pull, as the drive flanks (below). The force is returned
  // with the sign of x: -F_c.
  const double k_ratio = mesh_.back_ratio();
  const double d = -k_ratio * (x + p_.backlash_m);
  const double f = m.ElasticForce(seg, phase, d) - c_back_ * k_ratio * v;
  return d > 0 ? -std::max(0.0, f) : -f;
}

double TorsionalModel::MeshForce(
    ContactState s, int seg, int back_seg, double phase, double x, double v) const {
  const TorsionalMesh* back = mesh_.back_flanks();
  if (s != ContactState::kBackFlank || !back || back_seg < 0) return MeshForce(s, seg, phase, x, v);
  const MeshSegment& b = back->segments()[back_seg];
  // The reduced back phase may sit across the period wrap from the segment (a step ending at
  // the wrap): take it on the segment's side before clamping.
  const double pbc = back->base_pitch_m();
  double q = mesh_.BackPhase(phase);
  if (q > b.end_m + 0.5 * pbc) q -= pbc;
  if (q < b.begin_m - 0.5 * pbc) q += pbc;
  return BackFlankForce(*back, back_seg, std::clamp(q, b.begin_m, b.end_m), x, v);
}

double TorsionalModel::ContactForce(
    ContactState s, int seg, int back_seg, double phase, double x, double v) const {
  const double f = MeshForce(s, seg, back_seg, phase, x, v);
  if (s == ContactState::kDriveFlank) return std::max(0.0, f);
  if (s == ContactState::kBackFlank) return std::min(0.0, f);
  return 0.0;
}

double TorsionalModel::MeshForce(ContactState s, int seg, double phase, double x, double v) const {
  switch (s) {
    // Flanks in contact push and never pull: when the flanks part faster than the teeth
    // spring back, the damper's share would make the force pull (k x + c x' < 0 at x > 0);
    // the contact force is then zero until the flanks separate at x = 0. Past the guard
    // (x <= 0, before the integrator has located the separation) the force continues
    // smoothly, as the event location needs.
    case ContactState::kDriveFlank: {
      const double f = mesh_.ElasticForce(seg, phase, x) + c_ * v;
      return x > 0 ? std::max(0.0, f) : f;
    }
    case ContactState::kSeparated:
      return 0.0;
    case ContactState::kBackFlank: {
      const TorsionalMesh* back = mesh_.back_flanks();
      if (!back) return BackFlankForce(mesh_, seg, phase, x, v);
      const double q = mesh_.BackPhase(phase);
      return BackFlankForce(*back, back->SegmentAt(q), q, x, v);
    }
  }
  return 0.0;
}

double TorsionalModel::Acceleration(
    ContactState s, int seg, double phase, double x, double v) const {
  const TorsionalMesh* back = mesh_.back_flanks();
  if (s == ContactState::kBackFlank && back) {
    const double q = mesh_.BackPhase(phase);
    const int bseg = back->SegmentAt(q);
    return AccelerationWith(s, seg, phase, x, BackFlankForce(*back, bseg, q, x, v), bseg, q);
  }
  return AccelerationWith(s, seg, phase, x, MeshForce(s, seg, phase, x, v));
}

void TorsionalModel::FrictionTorques(const TorsionalMesh& m,
                                     int seg,
                                     double phase,
                                     double approach,
                                     double force,
                                     double* tf1,
                                     double* tf2) const {
  const MeshSegment& ms = m.segments()[seg];
  const double w1 = p_.pinion_speed_rad_s;
  const double w2 = w1 * m.pinion_teeth() / m.wheel_teeth();
  for (size_t i = 0; i < ms.pairs.size(); ++i) {
    const double sj = phase + ms.pairs[i] * m.base_pitch_m();
    const double rho1 = m.Rho1(sj), rho2 = m.Rho2(sj);
    const double mu = p_.friction == FrictionLaw::kConstant
                          ? p_.friction_coefficient
                          : BuckinghamFriction(w1 * rho1 - w2 * rho2);
    const double fj = force * m.PairShare(seg, static_cast<int>(i), phase, approach);
    *tf1 += mu * fj * ms.sliding[i] * rho1;
    *tf2 += mu * fj * ms.sliding[i] * rho2;
  }
}

double TorsionalModel::AccelerationWith(ContactState s,
                                        int seg,
                                        double phase,
                                        double x,
                                        double f,
                                        int back_seg,
                                        double back_phase) const {
  const double rb1 = mesh_.pinion_base_radius_m(), rb2 = mesh_.wheel_base_radius_m();
  const double j1 = p_.pinion_inertia_kg_m2, j2 = p_.wheel_inertia_kg_m2;
  double tf1 = 0, tf2 = 0;
  if (p_.friction != FrictionLaw::kNone) {
    if (s == ContactState::kDriveFlank && f > 0)
      FrictionTorques(mesh_, seg, phase, x, f, &tf1, &tf2);
    // The back flanks rub as the drive flanks do, on their own mesh: mirrored they are a
    // drive mesh loaded forwards and turning backwards, and the two flips (mirror and
    // reversed sliding) leave the drive flanks' torques T_f1, T_f2 with the back flanks' own
    // pair loads, roll distances rho_1c, rho_2c and sliding signs (docs/dynamics.md).
    if (s == ContactState::kBackFlank && f < 0 && back_seg >= 0 && mesh_.back_flanks())
      FrictionTorques(*mesh_.back_flanks(), back_seg, back_phase,
                      -mesh_.back_ratio() * (x + p_.backlash_m), -f, &tf1, &tf2);
  }
  // A back-flank force acts on x through the coast base circles: K times.
  const double arm = s == ContactState::kBackFlank ? mesh_.back_ratio() : 1.0;
  return rb1 * (p_.pinion_torque_nm - tf1) / j1 + rb2 * (torque_load_nm_ - tf2) / j2 -
         arm * f / m_e_;
}

void TorsionalModel::Reset(double t, double x, double v) {
  const double pb = mesh_.base_pitch_m();
  period_ = static_cast<long>(std::floor(contact_speed_m_s() * t / pb));
  double phase = PhaseAt(period_, t);
  if (phase >= pb) {
    ++period_;
    phase -= pb;
  }
  segment_ = mesh_.SegmentAt(std::max(phase, 0.0));
  state_ = x > 0 ? ContactState::kDriveFlank
                 : (x >= -p_.backlash_m ? ContactState::kSeparated : ContactState::kBackFlank);
  if (x == 0 && v > 0) state_ = ContactState::kDriveFlank;
  if (state_ == ContactState::kBackFlank) EnterBackFlanks(t);
  events_.clear();
}

// The back flanks' phase runs backwards: in periods, delta - c t / p_b, reduced by the
// period count back_period_ (which grows as time goes on).
double TorsionalModel::BackPhaseAt(double t) const {
  const double q = mesh_.back_phase_offset() - contact_speed_m_s() * t / mesh_.base_pitch_m();
  return mesh_.back_flanks()->base_pitch_m() * (q + back_period_);
}

void TorsionalModel::EnterBackFlanks(double t) {
  const TorsionalMesh* back = mesh_.back_flanks();
  if (!back) return;
  const double pbc = back->base_pitch_m();
  back_period_ = 0;
  back_period_ = static_cast<long>(-std::floor(BackPhaseAt(t) / pbc));
  double q = BackPhaseAt(t);
  if (q <= 0) {  // on a period boundary, running backwards: the end of the next period
    ++back_period_;
    q += pbc;
  }
  // The segment begin < q <= end: the phase leaves it at its begin.
  const auto& segs = back->segments();
  back_segment_ = static_cast<int>(segs.size()) - 1;
  for (int i = 0; i < static_cast<int>(segs.size()); ++i)
    if (q <= segs[i].end_m) {
      back_segment_ = i;
      break;
    }
}

double TorsionalModel::BackSegmentEndTime() const {
  const TorsionalMesh& back = *mesh_.back_flanks();
  const double begin = back.segments()[back_segment_].begin_m;
  return mesh_.base_pitch_m() *
         (mesh_.back_phase_offset() + back_period_ - begin / back.base_pitch_m()) /
         contact_speed_m_s();
}

double TorsionalModel::ForceNow(double t, const double* y) const {
  return MeshForce(state_, segment_, PhaseAt(period_, t), y[0], y[1]);
}

void TorsionalModel::Derivative(double t, const double* y, double* dydt) const {
  const MeshSegment& seg = mesh_.segments()[segment_];
  const double phase = std::clamp(PhaseAt(period_, t), seg.begin_m, seg.end_m);
  dydt[0] = y[1];
  const TorsionalMesh* back = mesh_.back_flanks();
  if (state_ == ContactState::kBackFlank && back) {
    // In the mode's own segment of the back flanks' mesh, as the drive flanks' above.
    const MeshSegment& b = back->segments()[back_segment_];
    const double q = std::clamp(BackPhaseAt(t), b.begin_m, b.end_m);
    const double f = BackFlankForce(*back, back_segment_, q, y[0], y[1]);
    dydt[1] = AccelerationWith(state_, segment_, phase, y[0], f, back_segment_, q);
    return;
  }
  dydt[1] = Acceleration(state_, segment_, phase, y[0], y[1]);
}

int TorsionalModel::GuardCount() const { return state_ == ContactState::kSeparated ? 2 : 1; }

double TorsionalModel::Guard(int i, double, const double* y) const {
  // Valid while >= 0. Drive flank: x >= 0. Separated: -x >= 0 and x + b >= 0. Back: -(x+b).
  switch (state_) {
    case ContactState::kDriveFlank:
      return y[0];
    case ContactState::kSeparated:
      return i == 0 ? -y[0] : y[0] + p_.backlash_m;
    case ContactState::kBackFlank:
      return -(y[0] + p_.backlash_m);
  }
  return 1.0;
}

double TorsionalModel::DriveSegmentEndTime() const {
  const double end = period_ * mesh_.base_pitch_m() + mesh_.segments()[segment_].end_m;
  return end / contact_speed_m_s();
}

bool TorsionalModel::TracksBackFlanks() const {
  return state_ == ContactState::kBackFlank && mesh_.back_flanks();
}

double TorsionalModel::NextScheduledTime(double) const {
  const double drive = DriveSegmentEndTime();
  return TracksBackFlanks() ? std::min(drive, BackSegmentEndTime()) : drive;
}

void TorsionalModel::Switch(int guard, double t, double* y) {
  if (guard < 0) {
    // The drive flanks' segment ends, or (on the back flanks) the back flanks' one, or both.
    const double tol = 1e-9 * mesh_period_s();
    const double drive = DriveSegmentEndTime();
    const bool back = TracksBackFlanks() && t >= BackSegmentEndTime() - tol;
    if (!back || t >= drive - tol) {
      if (++segment_ == static_cast<int>(mesh_.segments().size())) {
        segment_ = 0;
        ++period_;
      }
    }
    if (back && --back_segment_ < 0) {
      back_segment_ = static_cast<int>(mesh_.back_flanks()->segments().size()) - 1;
      ++back_period_;
    }
    return;
  }
  const ContactState from = state_;
  if (state_ == ContactState::kDriveFlank) {
    state_ = p_.backlash_m > 0 ? ContactState::kSeparated : ContactState::kBackFlank;
    y[0] = 0.0;  // on the guard surface (located to the event tolerance)
  } else if (state_ == ContactState::kBackFlank) {
    state_ = p_.backlash_m > 0 ? ContactState::kSeparated : ContactState::kDriveFlank;
    y[0] = -p_.backlash_m;
  } else if (guard == 0) {
    state_ = ContactState::kDriveFlank;
    y[0] = 0.0;
  } else {
    state_ = ContactState::kBackFlank;
    y[0] = -p_.backlash_m;
  }
  if (state_ == ContactState::kBackFlank) EnterBackFlanks(t);
  events_.push_back({t, from, state_});
}

}  // namespace tehl
