// tehl train FILE [--csv FILE]
// A gear train file (docs/trains.md): every member's speed and direction, the train value,
// rack speeds, the tabulation table of each carrier, the planet design rules, and the DC
// motor's operating point when the file has a [motor]. Exit 2 for bad input, 1 when the
// motor has no running operating point.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include "cli/commands.hpp"
#include "cli/train_report.hpp"
#include "drive/train_checks.hpp"
#include "drive/train_reader.hpp"
#include "io/atomic_file.hpp"
#include "tehl/error.hpp"
#include "tehl/units.hpp"

namespace tehl::cli {
namespace {

std::string Fmt(const char* format, double x) { return TrainFmt(format, x); }

// A solved speed (or the train value) as it is: the solver returns rest as exactly 0, and a
// slow output of a train of many stages (1e-12 of its input and less) is no round-off.
std::string Exact(const char* format, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, x == 0.0 ? 0.0 : x);
  return buf;
}

std::string Speed(double w) { return Exact("%.6g", w); }

std::string Direction(const TrainMember& m, double w) {
  if (w == 0.0) return "at rest";
  if (m.kind == MemberKind::kRack) return w > 0 ? "+ (with the pinion's pitch point)" : "-";
  return w > 0 ? "counter-clockwise (+)" : "clockwise (-)";
}

// A gear riding on a carrier that meshes through a bevel pair: its axis is not the train's,
// so w_carrier + spin is no speed of anything; only its spin relative to the carrier is.
bool BevelPlanet(const GearTrainSpec& spec, const TrainMember& m) {
  if (m.kind != MemberKind::kGear || m.carrier.empty()) return false;
  for (const TrainMesh& mesh : spec.meshes)
    if (mesh.kind == MeshKind::kBevel && (mesh.a == m.name || mesh.b == m.name)) return true;
  return false;
}

// The units of the train value w_output / w_input and of the speed ratio, its inverse: a
// rack's speed is in m/s, so a rack output gives m/rad (speed ratio rad/m), a rack input the
// other way round.
std::pair<std::string, std::string> TrainValueUnits(const GearTrainSpec& spec) {
  const int in = spec.Index(spec.input), out = spec.Index(spec.output);
  const bool rack_in = spec.members[in].kind == MemberKind::kRack;
  const bool rack_out = spec.members[out].kind == MemberKind::kRack;
  if (rack_in == rack_out) return {"", ""};
  return rack_in ? std::pair{" rad/m", " m/rad"} : std::pair{" m/rad", " rad/m"};
}

// "[input]" on a driven member (the motor's included), "[held]" on a held one.
std::string Mark(const internal::TrainFile& f, const TrainMember& m) {
  if (f.motor && m.name == f.spec.input) return "  [input, motor]";
  if (!m.speed) return "";
  return *m.speed == 0 ? "  [held]" : "  [input]";
}

void Speeds(std::ostream& o, const internal::TrainFile& f, const TrainSolution& s) {
  char buf[200];
  const bool crossed = std::any_of(f.spec.meshes.begin(), f.spec.meshes.end(), [](const auto& m) {
    return m.kind == MeshKind::kBevel || m.kind == MeshKind::kWorm;
  });
  o << (crossed ? "Speeds (positive = counter-clockwise about each member's own axis, parallel "
                  "axes seen from one side; bevel gears seen from their backs; worm wheels: "
                  "positive as a right-hand worm drives them):\n"
                : "Speeds (positive = counter-clockwise looking along the common axis):\n");
  std::snprintf(buf, sizeof buf, "  %-12s %-8s %6s %14s %14s  %s\n", "member", "kind", "z",
                "speed [rad/s]", "speed [rpm]", "direction");
  o << buf;
  for (size_t i = 0; i < f.spec.members.size(); ++i) {
    const TrainMember& m = f.spec.members[i];
    const double w = s.speed[i];
    std::string z = m.kind == MemberKind::kGear ? std::to_string(m.teeth) : "-";
    if (m.worm_hand != WormHand::kNone) z += m.worm_hand == WormHand::kRight ? "R" : "L";
    if (m.kind == MemberKind::kRack) {
      std::snprintf(buf, sizeof buf, "  %-12s %-8s %6s %14s %14s  %s, %s m/s = %s m/min%s\n",
                    m.name.c_str(), "rack", "-", "-", "-", Direction(m, w).c_str(),
                    Speed(w).c_str(), Speed(w * 60).c_str(), Mark(f, m).c_str());
    } else if (BevelPlanet(f.spec, m)) {
      const double spin = w - s.speed[f.spec.Index(m.carrier)];
      std::snprintf(buf, sizeof buf,
                    "  %-12s %-8s %6s %14s %14s  spins %s rad/s (%s rpm) about "
                    "its own axis, relative to carrier %s\n",
                    m.name.c_str(), "gear", z.c_str(), "-", "-", Fmt("%.6g", spin).c_str(),
                    Fmt("%.6g", RadPerSToRpm(spin)).c_str(), m.carrier.c_str());
    } else {
      std::snprintf(buf, sizeof buf, "  %-12s %-8s %6s %14s %14s  %s%s\n", m.name.c_str(),
                    ToString(m.kind).c_str(), z.c_str(), Speed(w).c_str(),
                    Speed(RadPerSToRpm(w)).c_str(), Direction(m, w).c_str(), Mark(f, m).c_str());
    }
    o << buf;
  }
  if (s.train_value) {
    const auto [unit, inverse] = TrainValueUnits(f.spec);
    o << "Train value w_" << f.spec.output << " / w_" << f.spec.input << " = "
      << Exact("%.8g", *s.train_value) << unit << " (speed ratio "
      << Exact("%.8g", 1.0 / *s.train_value) << inverse << " : 1)\n";
  }
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
      << "\n  tip clearance: N < " << internal::PlanetLimitText(r.clearance_limit) << ", at most "
      << r.max_by_clearance << " planets\n  equally spaced ((z_sun + z_ring)/N "
      << "integer, " << r.total_teeth << "/N): N in {";
    for (size_t i = 0; i < r.equally_spaced.size(); ++i)
      o << (i ? ", " : "") << r.equally_spaced[i];
    o << "}; maximum " << r.max_planets << " planets\n";
    std::vector<std::string> unchecked;
    for (const internal::PlanetStep& st : p.steps) {
      o << "  planet gear " << st.gear << " (z = " << st.teeth << "): ";
      if (st.clearance_limit)
        o << "tip clearance N < " << internal::PlanetLimitText(*st.clearance_limit) << ", at most "
          << st.max_by_clearance << " planets (" << st.basis << ")\n";
      else {
        o << st.basis << "\n";
        unchecked.push_back(st.gear);
      }
    }
    for (const std::string& n : p.notes) o << "  " << n << "\n";
    if (p.planets) {
      o << "  declared " << *p.planets << ": fits";
      if (!p.notes.empty() && unchecked.empty()) o << " the rules checked";
      if (!unchecked.empty()) {
        o << " the rules checked; the tip clearance of planet gear";
        for (size_t i = 0; i < unchecked.size(); ++i) o << (i ? ", " : " ") << unchecked[i];
        o << " is not checked (give module_m)";
      }
      o << "\n";
    }
  }
}

void Notes(std::ostream& o, const internal::TrainFile& f) {
  if (f.notes.empty()) return;
  o << "\nNotes:\n";
  for (const std::string& n : f.notes) o << "  " << n << "\n";
}

// The member table as CSV: teeth empty for carriers and racks; a bevel planet's speed
// columns empty (its spin relative to the carrier in its own column); torque_nm (racks:
// force_n) the frictionless torque (per 1 N m on the input, or at the motor's torque),
// empty where no external torque acts; load_torque_nm, with a [motor], the load's torque
// on the loaded member.
std::string SpeedsCsv(const internal::TrainFile& f, const internal::TrainResult& r) {
  const TrainSolution& s = r.solution;
  const TrainTorques& t = r.torques;
  const std::optional<double> load = TrainLoadTorque(f, r);
  std::ostringstream out;
  out << "member,kind,teeth,worm_hand,speed_rad_s,speed_rpm,speed_m_s,"
         "spin_relative_to_carrier_rad_s,torque_nm,force_n,load_torque_nm\n";
  for (size_t i = 0; i < f.spec.members.size(); ++i) {
    const TrainMember& m = f.spec.members[i];
    const bool rack = m.kind == MemberKind::kRack;
    const bool bevel_planet = BevelPlanet(f.spec, m);
    const bool absolute = !rack && !bevel_planet;
    const std::string torque = t.solved && t.torque[i] ? Fmt("%.10g", *t.torque[i]) : "";
    out << m.name << "," << ToString(m.kind) << ","
        << (m.kind == MemberKind::kGear ? std::to_string(m.teeth) : "") << ","
        << ToString(m.worm_hand) << "," << (absolute ? Exact("%.10g", s.speed[i]) : "") << ","
        << (absolute ? Exact("%.10g", RadPerSToRpm(s.speed[i])) : "") << ","
        << (rack ? Exact("%.10g", s.speed[i]) : "") << ","
        << (bevel_planet ? Fmt("%.10g", s.speed[i] - s.speed[f.spec.Index(m.carrier)]) : "") << ","
        << (rack ? "" : torque) << "," << (rack ? torque : "") << ","
        << (load && static_cast<int>(i) == t.output ? Fmt("%.10g", *load) : "") << "\n";
  }
  return out.str();
}

void WriteCsv(const std::string& path, const std::string& text) {
  try {
    internal::WriteTextAtomically(path, text);
  } catch (const std::filesystem::filesystem_error& e) {
    throw InputError(InputProblem{path, 0, "--csv", path,
                                  std::string("cannot be written: ") + e.code().message(),
                                  "a writable file path"});
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
            // The CSV first: a path that cannot be written fails before any report.
            if (!csv->empty() && !f.spec.members.empty()) WriteCsv(*csv, SpeedsCsv(f, r));
            std::ostream& o = std::cout;
            o << "Train file " << f.path << (f.name.empty() ? "" : ": " + f.name) << "\n";
            int code = kExitOk;
            if (!f.spec.members.empty()) {
              Speeds(o, f, r.solution);
              Tables(o, r.tables);
              Planets(o, f);
              Notes(o, f);
            }
            if (f.motor) code = PrintTrainMotor(o, f, r);
            if (!f.spec.members.empty()) PrintTrainTorques(o, f, r);
            return code;
          }};
}

}  // namespace tehl::cli
