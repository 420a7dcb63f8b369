// tehl train FILE [--csv FILE]
// A gear train file (docs/trains.md): every member's speed and direction, the train value,
// rack speeds, the tabulation table of each carrier, the planet design rules, and the DC
// motor's operating point when the file has a [motor]. Exit 2 for bad input, 1 when the
// motor has no running operating point.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "drive/train_reader.hpp"
#include "tehl/error.hpp"
#include "tehl/units.hpp"

namespace tehl::cli {
namespace {

std::string Fmt(const char* format, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, std::abs(x) < 5e-13 ? 0.0 : x);
  return buf;
}

std::string Direction(const TrainMember& m, double w) {
  if (std::abs(w) < 1e-12) return "at rest";
  if (m.kind == MemberKind::kRack) return w > 0 ? "+ (with the pinion's pitch point)" : "-";
  return w > 0 ? "counter-clockwise (+)" : "clockwise (-)";
}

void Speeds(std::ostream& o, const internal::TrainFile& f, const TrainSolution& s) {
  char buf[200];
  o << "Speeds (positive = counter-clockwise looking along the common axis; bevel gears seen "
       "from their backs; worm wheels: positive as a right-hand worm drives them):\n";
  std::snprintf(buf, sizeof buf, "  %-12s %-8s %6s %14s %14s  %s\n", "member", "kind", "z",
                "speed [rad/s]", "speed [rpm]", "direction");
  o << buf;
  for (size_t i = 0; i < f.spec.members.size(); ++i) {
    const TrainMember& m = f.spec.members[i];
    const double w = s.speed[i];
    std::string z = m.kind == MemberKind::kGear ? std::to_string(m.teeth) : "-";
    if (m.worm_hand != WormHand::kNone) z += m.worm_hand == WormHand::kRight ? "R" : "L";
    if (m.kind == MemberKind::kRack) {
      std::snprintf(buf, sizeof buf, "  %-12s %-8s %6s %14s %14s  %s, %s m/s = %s m/min\n",
                    m.name.c_str(), "rack", "-", "-", "-", Direction(m, w).c_str(),
                    Fmt("%.6g", w).c_str(), Fmt("%.6g", w * 60).c_str());
    } else {
      std::snprintf(buf, sizeof buf, "  %-12s %-8s %6s %14s %14s  %s%s\n", m.name.c_str(),
                    ToString(m.kind).c_str(), z.c_str(), Fmt("%.6g", w).c_str(),
                    Fmt("%.6g", RadPerSToRpm(w)).c_str(), Direction(m, w).c_str(),
                    m.speed ? (*m.speed == 0 ? "  [held]" : "  [input]") : "");
    }
    o << buf;
  }
  if (s.train_value)
    o << "Train value w_" << f.spec.output << " / w_" << f.spec.input << " = "
      << Fmt("%.8g", *s.train_value) << " (speed ratio " << Fmt("%.8g", 1.0 / *s.train_value)
      << " : 1)\n";
  o << "Linear system: " << s.equations << " equations, " << s.unknowns << " unknowns, rank "
    << s.rank << ", residual " << Fmt("%.2e", s.residual) << "\n";
}

void Tables(std::ostream& o, const std::vector<TabulationTable>& tables) {
  for (const TabulationTable& t : tables) {
    o << "\nTabulation, carrier " << t.carrier << " (reference gear " << t.reference
      << "; row 1 in turns, rows 2-4 in rad/s):\n";
    char buf[64];
    std::snprintf(buf, sizeof buf, "  %-44s", "");
    o << buf;
    for (const auto& c : t.columns) {
      std::snprintf(buf, sizeof buf, " %12s", c.c_str());
      o << buf;
    }
    o << "\n";
    for (const TabulationRow& r : t.rows) {
      std::snprintf(buf, sizeof buf, "  %-44s", r.label.c_str());
      o << buf;
      for (const auto& v : r.values) {
        std::snprintf(buf, sizeof buf, " %12s", v ? Fmt("%+.5g", *v).c_str() : "-");
        o << buf;
      }
      o << "\n";
    }
  }
}

void Planets(std::ostream& o, const internal::TrainFile& f) {
  for (const auto& p : f.planetary) {
    const PlanetRules& r = p.rules;
    o << "\nPlanet rules, carrier " << p.carrier << ": sun " << p.sun << " (z = " << p.set.sun_teeth
      << "), planet " << p.planet << " (z = " << *p.set.planet_teeth << "), ring " << p.ring
      << " (z = " << p.set.ring_teeth << ")\n";
    o << "  coaxial (z_ring = z_sun + 2 z_planet): "
      << (r.coaxial ? "yes"
                    : "no - non-standard planet; the rules use the equivalent z_p = " +
                          Fmt("%.1f", r.coaxial_planet_teeth))
      << "\n  tip clearance: N < " << Fmt("%.4f", r.clearance_limit) << ", at most "
      << r.max_by_clearance << " planets\n  equally spaced ((z_sun + z_ring)/N integer, "
      << r.total_teeth << "/N): N in {";
    for (size_t i = 0; i < r.equally_spaced.size(); ++i)
      o << (i ? ", " : "") << r.equally_spaced[i];
    o << "}; maximum " << r.max_planets << " planets";
    if (p.planets) o << "; declared " << *p.planets << ": fits";
    o << "\n";
  }
}

int Motor(std::ostream& o, const internal::TrainFile& f, const internal::TrainResult& r) {
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
  if (s.rated_current_a > 0)
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
      << Fmt("%.6g", c.armature_voltage_v) << " V, field current " << Fmt("%.6g", c.field_current_a)
      << " A, armature current " << Fmt("%.6g", c.armature_current_a) << " A, motor torque "
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
  o << "    power  input " << watts(p.input_power_w) << " W, shaft " << watts(p.shaft_power_w)
    << " W, load " << watts(p.load_power_w) << " W\n";
  o << "    load   " << Fmt("%.6g", RadPerSToRpm(p.load_speed_rad_s)) << " rpm ("
    << Fmt("%.6g", p.load_speed_rad_s) << " rad/s), torque " << Fmt("%.6g", p.load_torque_nm)
    << " N m\n";
  return p.usable() ? kExitOk : kExitNotConverged;
}

void WriteCsv(const std::string& path, const internal::TrainFile& f, const TrainSolution& s) {
  std::ofstream out(path);
  if (!out)
    throw InputError(
        InputProblem{path, 0, "--csv", path, "cannot be written", "a writable file path"});
  out << "member,kind,teeth,speed_rad_s,speed_rpm,speed_m_s\n";
  for (size_t i = 0; i < f.spec.members.size(); ++i) {
    const TrainMember& m = f.spec.members[i];
    const bool rack = m.kind == MemberKind::kRack;
    out << m.name << "," << ToString(m.kind) << "," << m.teeth << ","
        << (rack ? "" : Fmt("%.10g", s.speed[i])) << ","
        << (rack ? "" : Fmt("%.10g", RadPerSToRpm(s.speed[i]))) << ","
        << (rack ? Fmt("%.10g", s.speed[i]) : "") << "\n";
  }
}

}  // namespace

Command AddTrainCommand(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "train", "Gear train: speeds, train value, tabulation, planet rules, DC motor");
  auto file = std::make_shared<std::string>();
  auto csv = std::make_shared<std::string>();
  sub->add_option("file", *file, "train file (docs/trains.md)")->required();
  sub->add_option("--csv", *csv, "write the member speeds to this CSV file");
  return {sub, [file, csv]() {
            const internal::TrainFile f = internal::ReadTrainFile(*file);
            const internal::TrainResult r = internal::SolveTrainFile(f);
            std::ostream& o = std::cout;
            o << "Train file " << f.path << (f.name.empty() ? "" : ": " + f.name) << "\n";
            int code = kExitOk;
            if (!f.spec.members.empty()) {
              Speeds(o, f, r.solution);
              Tables(o, r.tables);
              Planets(o, f);
              if (!csv->empty()) WriteCsv(*csv, f, r.solution);
            }
            if (f.motor) code = Motor(o, f, r);
            return code;
          }};
}

}  // namespace tehl::cli
