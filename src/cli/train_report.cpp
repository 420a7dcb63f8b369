// The torques and the DC motor of a `tehl train` report (train_report.hpp).
#include "cli/train_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "cli/commands.hpp"
#include "tehl/units.hpp"

namespace tehl::cli {
namespace {

std::string Fmt(const char* format, double x) { return TrainFmt(format, x); }

// What the motor's input power includes: the armature's E I_a always, the shunt field's
// E I_f from the same supply; a separately excited field has a supply of its own.
std::string InputPowerParts(const DcMotor& motor, const MotorOperatingPoint& p) {
  const DcMotorSpec& s = motor.spec();
  const double e = s.supply_voltage_v, ia = p.armature_current_a, i_f = motor.FieldCurrent();
  switch (s.type) {
    case DcMotorType::kShunt:
      return "armature E I_a = " + Fmt("%.6g", e * ia) +
             " W + shunt field E I_f = " + Fmt("%.6g", e * i_f) + " W, I_f = " + Fmt("%.6g", i_f) +
             " A";
    case DcMotorType::kSeparatelyExcited:
      return "armature E I_a = " + Fmt("%.6g", e) + " V x " + Fmt("%.6g", ia) +
             " A; the separately excited field, I_f = " + Fmt("%.6g", i_f) +
             " A, has its own supply, not included";
    case DcMotorType::kSeries:
      return "E I_a = " + Fmt("%.6g", e) + " V x " + Fmt("%.6g", ia) +
             " A; the series field is in the armature circuit";
    case DcMotorType::kPermanentMagnet:
      break;
  }
  return "E I_a = " + Fmt("%.6g", e) + " V x " + Fmt("%.6g", ia) +
         " A; a permanent magnet, no field";
}

}  // namespace

// With a [motor]: the load's torque on the loaded member, T_L against the lossless output
// torque's sense (the output torque opposes the motion), and the train's losses, the rest.
std::optional<double> TrainLoadTorque(const internal::TrainFile& f,
                                      const internal::TrainResult& r) {
  if (!f.motor || !r.torques.solved) return std::nullopt;
  double t_l = f.load.torque_nm;
  if (r.motor) {
    if (!r.motor->usable()) return std::nullopt;
    t_l = r.motor->load_torque_nm;
  } else if (r.controlled) {
    if (!r.controlled->feasible) return std::nullopt;
    t_l += f.load.viscous_nm_s * std::abs(r.load_train_value * *f.speed_command_rad_s);
  }
  return std::copysign(t_l, *r.torques.torque[r.torques.output]);
}

void PrintTrainTorques(std::ostream& o,
                       const internal::TrainFile& f,
                       const internal::TrainResult& r) {
  const TrainTorques& t = r.torques;
  const bool motor = f.motor.has_value();
  if (!t.solved) {
    o << "\nTorques: not given (" << t.message << ")\n";
    return;
  }
  const TrainMember& in = f.spec.members[t.input];
  const std::string per = in.kind == MemberKind::kRack ? "per 1 N on " : "per 1 N m on ";
  o << "\nTorques (frictionless, by virtual work; applied to each member from outside, "
       "positive counter-clockwise; "
    << (motor ? "at the motor's torque " + Fmt("%.6g", *t.torque[t.input]) + " N m on " + in.name
              : per + in.name)
    << "; racks: force [N]):\n";
  double sum = 0;
  bool parallel = true;  // every torque on a gear or carrier about a fixed axis
  for (size_t j = 0; j < f.spec.members.size(); ++j) {
    if (!t.torque[j]) continue;
    const TrainMember& m = f.spec.members[j];
    const bool rack = m.kind == MemberKind::kRack;
    parallel = parallel && !rack && m.carrier.empty();
    sum += *t.torque[j];
    const int k = static_cast<int>(j);
    const std::string role = k == t.input    ? (motor ? "input (the motor)" : "input")
                             : k == t.output ? (motor ? "output at the motor's torque, lossless"
                                                      : "output (the load's torque, lossless)")
                                             : "held (the frame's reaction)";
    char buf[160];
    std::snprintf(buf, sizeof buf, "  %-12s %14s %-4s %s\n", m.name.c_str(),
                  Fmt("%+.6g", *t.torque[j]).c_str(), rack ? "N" : "N m", role.c_str());
    o << buf;
  }
  o << "  power balance sum T w = " << Fmt("%.2e", t.power_residual) << " of the input power\n";
  // Parallel axes: what the listed torques leave over, the frame takes through the bearings
  // of the fixed axes (moment balance of the gears about the axis direction).
  if (parallel && !std::any_of(f.spec.meshes.begin(), f.spec.meshes.end(), [](const auto& m) {
        return m.kind == MeshKind::kBevel || m.kind == MeshKind::kWorm;
      }))
    o << "  housing (frame) reaction through the bearings: "
      << (std::abs(sum) < 1e-12 * std::abs(*t.torque[t.input]) ? "0" : Fmt("%+.6g", -sum))
      << " N m (applied to the gears by the frame, positive counter-clockwise: minus the sum of "
         "the torques above; the gears push the frame with the opposite)\n";
  const std::string& loaded = f.spec.members[t.output].name;
  if (const std::optional<double> load = TrainLoadTorque(f, r)) {
    const double out = *t.torque[t.output], loss = out - *load;
    o << "  load on " << loaded << ": " << Fmt("%+.6g", *load)
      << " N m (the load's torque T_L = " << Fmt("%.6g", std::abs(*load))
      << " N m, against the motion); the train's losses: "
      << (std::abs(loss) <= 1e-12 * std::abs(out) ? "0" : Fmt("%+.6g", loss)) << " N m (efficiency "
      << Fmt("%.4g", f.load.efficiency) << ")\n";
  } else if (motor) {
    o << "  load on " << loaded << ": no share of the load and losses, the motor does not run\n";
  }
}

int PrintTrainMotor(std::ostream& o, const internal::TrainFile& f, const internal::TrainResult& r) {
  const DcMotor motor(*f.motor);
  const DcMotorSpec& s = motor.spec();
  o << "\nDC motor (" << ToString(s.type) << "): E = " << Fmt("%.6g", s.supply_voltage_v)
    << " V, R_a = " << Fmt("%.6g", s.armature_resistance_ohm)
    << " Ohm, K_a = " << Fmt("%.6g", motor.TorqueConstant());
  if (s.type != DcMotorType::kPermanentMagnet && s.type != DcMotorType::kSeries)
    o << ", I_f = " << Fmt("%.6g", motor.FieldCurrent()) << " A";
  o << "\n  no-load speed "
    << (std::isfinite(motor.NoLoadSpeed()) ? Fmt("%.6g", RadPerSToRpm(motor.NoLoadSpeed())) + " rpm"
                                           : std::string("unbounded (series)"))
    << ", stall torque " << Fmt("%.6g", motor.StallTorque()) << " N m\n";
  if (s.rated_current_a > 0 && s.type == DcMotorType::kPermanentMagnet)
    o << "  base speed " << Fmt("%.6g", RadPerSToRpm(motor.BaseSpeed())) << " rpm: constant torque "
      << Fmt("%.6g", motor.RatedTorque())
      << " N m below it; nothing above it (a permanent magnet has no field to weaken)\n";
  else if (s.rated_current_a > 0)
    o << "  base speed " << Fmt("%.6g", RadPerSToRpm(motor.BaseSpeed())) << " rpm: constant torque "
      << Fmt("%.6g", motor.RatedTorque()) << " N m below it, constant power "
      << Fmt("%.6g", motor.RatedTorque() * motor.BaseSpeed()) << " W above it\n";
  o << "  load on " << (f.load_member.empty() ? "the motor shaft" : f.load_member) << ": "
    << Fmt("%.6g", f.load.torque_nm) << " N m + " << Fmt("%.6g", f.load.viscous_nm_s)
    << " N m s/rad |w|, w_load / w_motor = " << Fmt("%.8g", r.load_train_value) << ", efficiency "
    << Fmt("%.4g", f.load.efficiency) << "\n";
  if (r.controlled) {
    const ControlledPoint& c = *r.controlled;
    o << "  speed command " << Fmt("%.6g", RadPerSToRpm(*f.speed_command_rad_s))
      << " rpm: " << ToString(c.region) << "\n  armature voltage "
      << Fmt("%.6g", c.armature_voltage_v) << " V, "
      << (s.type == DcMotorType::kSeparatelyExcited || s.type == DcMotorType::kShunt
              ? "field current " + Fmt("%.6g", c.field_current_a) + " A, "
              : std::string())
      << "armature current " << Fmt("%.6g", c.armature_current_a) << " A, motor torque "
      << Fmt("%.6g", c.motor_torque_nm) << " N m: " << c.message << "\n";
    return c.feasible ? kExitOk : kExitNotConverged;
  }
  const MotorOperatingPoint& p = *r.motor;
  o << "  operating point: " << p.message << "\n";
  o << "    motor  " << Fmt("%.6g", RadPerSToRpm(p.motor_speed_rad_s)) << " rpm ("
    << Fmt("%.6g", p.motor_speed_rad_s) << " rad/s), torque " << Fmt("%.6g", p.motor_torque_nm)
    << " N m, armature current " << Fmt("%.6g", p.armature_current_a) << " A\n";
  // A power that is the rounding residue of a balance at no load prints as 0.
  const auto watts = [&](double w) {
    return Fmt("%.6g", std::abs(w) < 1e-9 * std::max(1.0, std::abs(p.input_power_w)) ? 0.0 : w);
  };
  o << "    power  input " << watts(p.input_power_w) << " W (" << InputPowerParts(motor, p)
    << "), shaft " << watts(p.shaft_power_w) << " W, load " << watts(p.load_power_w) << " W\n";
  o << "    load   " << Fmt("%.6g", RadPerSToRpm(p.load_speed_rad_s)) << " rpm ("
    << Fmt("%.6g", p.load_speed_rad_s) << " rad/s), torque " << Fmt("%.6g", p.load_torque_nm)
    << " N m\n";
  return p.usable() ? kExitOk : kExitNotConverged;
}

}  // namespace tehl::cli
