// Torsional dynamics of a spur gear pair: two rigid inertias coupled by the time-varying
// mesh stiffness, with mesh damping, tooth friction and backlash (seed 000 section 4.2,
// eqs. 4.1-4.2, 4.9, 4.10, 4.37-4.42, after Lin, Huston & Coy 1988; docs/dynamics.md).
//
// Equations of motion in SI (seed 000 eqs. 4.1-4.2 with the piecewise mesh force F):
//   J1 th1'' = T_m - T_f1 - r_b1 F,      J2 th2'' = T_f2 - T_L + r_b2 F.
// With the dynamic transmission error along the line of action x = r_b1 th1 - r_b2 th2 (the
// rigid-body rotation at the nominal speeds removed), the rigid-body mode drops out:
//   x'' = r_b1 (T_m - T_f1) / J1 + r_b2 (T_L - T_f2) / J2 - F / m_e,
//   m_e = J1 J2 / (r_b1^2 J2 + r_b2^2 J1)         (equivalent mass [kg]).
// The load torque balances the input statically, T_L = T_m r_b2 / r_b1, so the static mesh
// force is F_s = T_m / r_b1 and without friction m_e x'' = F_s - F.
// Mesh force, three contact states (seed 000 eqs. 4.37-4.42), backlash b along the line of
// action:
//   drive flank (x > 0):      F = k(t) x + c x'
//   separated (-b <= x <= 0): F = 0
//   back flank (x < -b):      F = k(t) (x + b) + c x'
// With tip relief (torsional_mesh.hpp) the elastic parts are sum_j k_j max(0, x - e_j) on the
// drive flanks and -sum_j k_j max(0, -(x + b) - e_j) on the back flanks (both flanks of a
// tooth relieved alike).
// The back flanks are the coast flanks, with their own mesh when the mesh has one
// (TorsionalMesh::back_flanks, flank_phase.hpp; docs/dynamics.md "Back flanks"): base
// circles K = r_bc / r_bd times the drive flanks', closure d_c = K (-(x + b)), contact force
// F_c = sum_j k_cj max(0, d_c - e_cj) - c_c K x' >= 0 at the back phase, acting on x as
// K F_c: x'' = ... + K F_c / m_e, c_c = 2 zeta sqrt(k_c,mean m_e / K^2). MeshForce returns
// -F_c in this state. Without back flanks of its own (K = 1) this is the line above.
// Damping c = 2 zeta sqrt(k_mean m_e) (seed 000 eq. 4.9 with the period-mean stiffness and
// the equivalent mass of the x coordinate; the printed eq. 4.9 swaps J1 and J2).
// Friction: pair j carries F_j = F k_j / k_mesh; at its contact the friction force mu F_j
// opposes the sliding u1 - u2 and acts perpendicular to the line of action with arms rho1 and
// rho2 about the two axes, so T_f1 = sum mu_j F_j sign(u1 - u2)_j rho1_j and T_f2 = sum
// mu_j F_j sign(u1 - u2)_j rho2_j (seed 000 gives no arm; this is the usual one). Friction
// acts where flanks carry load: on the drive flanks for F > 0, and on the back flanks with
// their own mesh the same torques of their pairs (their F_cj, rho_1c, rho_2c, signs).
// Buckingham's friction law, seed 000 eq. 4.10 with V in in/s, in SI (V in m/s, 1 in/s =
// 0.0254 m/s): mu = 0.05 exp(-0.125 V/0.0254) + 0.002 sqrt(V/0.0254)
//                 = 0.05 exp(-4.92126 V) + 0.0125491 sqrt(V).
// The mesh runs at the nominal speed: the mesh phase is r_b1 w1 t (parametric excitation).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tehl/drive/integrator.hpp"
#include "tehl/drive/torsional_mesh.hpp"

namespace tehl {

enum class ContactState { kDriveFlank, kSeparated, kBackFlank };
std::string ToString(ContactState s);  // "drive_flank" | "separated" | "back_flank"

enum class FrictionLaw { kNone, kConstant, kBuckingham };
std::string ToString(FrictionLaw f);  // "none" | "constant" | "buckingham"
std::optional<FrictionLaw> FrictionLawFromString(const std::string& name);

// Buckingham's friction coefficient (seed 000 eq. 4.10) at sliding speed |V| [m/s] -> [-].
double BuckinghamFriction(double sliding_speed_m_s);

// Polar moment of inertia of a solid disc of radius r, width b, density rho:
// J = pi rho b r^4 / 2 [kg m^2].
double DiscInertia(double density_kg_m3, double face_width_m, double radius_m);

struct TorsionalParameters {
  double pinion_inertia_kg_m2 = 0;  // J1 [kg m^2], > 0
  double wheel_inertia_kg_m2 = 0;   // J2 [kg m^2], > 0
  double pinion_torque_nm = 0;      // T_m on the pinion [N m], > 0; T_L = T_m r_b2 / r_b1
  double pinion_speed_rad_s = 0;    // nominal w1 [rad/s], > 0
  double damping_ratio = 0.05;      // zeta [-], in [0, 1); seed 000: 0.03-0.17
  double backlash_m = 0;            // b along the line of action [m], >= 0
  FrictionLaw friction = FrictionLaw::kNone;
  double friction_coefficient = 0.05;         // mu for FrictionLaw::kConstant [-], in [0, 1)
  std::vector<std::string> Validate() const;  // every violated rule; empty = valid
};

// The hybrid ODE system y = (x [m], x' [m/s]) of the equations above. The mode is the contact
// state and the mesh segment of the current period. Holds a reference to the mesh (it must
// outlive the model). Not thread-safe (the mode changes while integrating).
class TorsionalModel : public HybridOdeSystem {
 public:
  TorsionalModel(const TorsionalMesh& mesh, const TorsionalParameters& p);

  const TorsionalMesh& mesh() const { return mesh_; }
  const TorsionalParameters& parameters() const { return p_; }
  double equivalent_mass_kg() const { return m_e_; }   // m_e [kg]
  double damping_n_s_per_m() const { return c_; }      // c [N s/m]
  // The back flanks' damper on their own closure: 2 zeta sqrt(k_c,mean m_e / K^2) [N s/m].
  double back_damping_n_s_per_m() const { return c_back_; }
  double static_force_n() const { return f_static_; }  // F_s = T_m / r_b1 [N]
  double natural_frequency_hz() const;                 // sqrt(k_mean/m_e)/(2 pi)
  double mesh_frequency_hz() const;                    // z1 w1 / (2 pi)
  double mesh_period_s() const;                        // p_b / (r_b1 w1)
  double contact_speed_m_s() const { return mesh_.pinion_base_radius_m() * p_.pinion_speed_rad_s; }

  // Mesh force (eqs. 4.37-4.42) in a given state and segment at phase phi [N]: on the back
  // flanks their contact force F_c with the sign of x (-F_c), which acts on x as K F_c.
  double MeshForce(ContactState state, int segment, double phase_m, double x_m, double v_m_s) const;
  // The contact force as the results report it: MeshForce (with the back flanks' segment)
  // held to the push of the flanks in contact, >= 0 on the drive flanks and <= 0 on the back
  // flanks (MeshForce itself continues past a guard, at x = 0 say, for the event location).
  double ContactForce(ContactState state,
                      int segment,
                      int back_segment,
                      double phase_m,
                      double x_m,
                      double v_m_s) const;
  // The same with the back flanks' segment given (a step's own mode, so that a step ending on
  // one of their switches sees its own side of it; -1: the segment holding the back phase).
  double MeshForce(ContactState state,
                   int segment,
                   int back_segment,
                   double phase_m,
                   double x_m,
                   double v_m_s) const;
  // x'' in a given state and segment [m/s^2].
  double Acceleration(
      ContactState state, int segment, double phase_m, double x_m, double v_m_s) const;
  // Phase of time t within period `period` [m] (not reduced).
  double PhaseAt(long period, double t_s) const;

  // Puts the model at time t (on a period boundary or inside) with state (x, v): the mode
  // follows from x and the phase.
  void Reset(double t_s, double x_m, double v_m_s);
  ContactState state() const { return state_; }
  int segment() const { return segment_; }
  long period() const { return period_; }
  // On the back flanks with their own mesh: its segment (the phase runs through them
  // backwards, flank_phase.hpp).
  int back_segment() const { return back_segment_; }
  double phase_m(double t_s) const { return PhaseAt(period_, t_s); }
  double ForceNow(double t_s, const double* y) const;  // MeshForce in the current mode

  // State events since the last Reset: times and new states.
  struct Event {
    double t_s = 0;
    ContactState from = ContactState::kDriveFlank, to = ContactState::kDriveFlank;
  };
  const std::vector<Event>& events() const { return events_; }
  void ClearEvents() { events_.clear(); }

  // HybridOdeSystem.
  int Dimension() const override { return 2; }
  void Derivative(double t, const double* y, double* dydt) const override;
  int GuardCount() const override;
  double Guard(int i, double t, const double* y) const override;
  double NextScheduledTime(double t) const override;
  void Switch(int guard, double t, double* y) override;

 private:
  // x'' at the mesh force f; on the back flanks with their own mesh, in its segment
  // back_segment at its phase back_phase_m (for their friction).
  double AccelerationWith(ContactState s,
                          int segment,
                          double phase_m,
                          double x_m,
                          double f,
                          int back_segment = -1,
                          double back_phase_m = 0) const;
  // Adds the friction torques T_f1, T_f2 [N m] of the pairs of mesh m in its segment at its
  // phase, carrying `force` [N] > 0 shared at the approach [m].
  void FrictionTorques(const TorsionalMesh& m,
                       int segment,
                       double phase_m,
                       double approach_m,
                       double force_n,
                       double* tf1,
                       double* tf2) const;
  // -F_c of the back flanks on mesh m (the back flanks' mesh, or the drive flanks' one
  // without it) in its segment at its phase.
  double BackFlankForce(
      const TorsionalMesh& m, int segment, double phase_m, double x_m, double v_m_s) const;
  // The back flanks' mode: their phase at t [m], the tracking from t on, and when their
  // segment ends [s].
  double BackPhaseAt(double t_s) const;
  void EnterBackFlanks(double t_s);
  double BackSegmentEndTime() const;
  double DriveSegmentEndTime() const;
  bool TracksBackFlanks() const;

  const TorsionalMesh& mesh_;
  TorsionalParameters p_;
  double m_e_ = 0, c_ = 0, c_back_ = 0, f_static_ = 0, torque_load_nm_ = 0;
  ContactState state_ = ContactState::kDriveFlank;
  int segment_ = 0;
  long period_ = 0;
  int back_segment_ = 0;  // segment of the back flanks' mesh (on the back flanks)
  long back_period_ = 0;  // its period count
  std::vector<Event> events_;
};

}  // namespace tehl
