// Train files: a schema per file (train_schema.cpp: the user's member names become sections),
// the cross-key rules, then a trial solve whose problems are reported at the lines of the keys
// concerned.
#include "drive/train_reader.hpp"

#include <map>

#include "base/schema.hpp"
#include "drive/motor_schema.hpp"
#include "drive/train_checks.hpp"
#include "drive/train_schema.hpp"
#include "tehl/units.hpp"

namespace tehl::internal {
namespace {

class TrainReader {
 public:
  TrainReader(Document* doc, TrainFile* out) : doc_(*doc), out_(*out) {}

  void Read(const TrainMemberNames& names) {
    out_.name = doc_.String("train", "name");
    std::map<std::string, std::string> seen;  // name -> section
    for (const char* g : {"gear", "carrier", "rack"}) {
      for (const auto& n : names.count(g) ? names.at(g) : std::vector<std::string>{}) {
        const std::string sec = std::string(g) + "." + n;
        if (const auto it = seen.find(n); it != seen.end()) {
          doc_.Problem(sec, "", "the name '" + n + "' is also [" + it->second + "]",
                       "one name per gear, carrier and rack");
          continue;
        }
        seen[n] = sec;
        out_.spec.members.push_back(Member(g, n, sec));
      }
    }
    for (const auto& n : names.count("mesh") ? names.at("mesh") : std::vector<std::string>{})
      Mesh("mesh." + n);
    out_.spec.input = doc_.String("train", "input");
    out_.spec.output = doc_.String("train", "output");
    for (const char* k : {"input", "output"})
      if (doc_.Given("train", k) && out_.spec.Index(doc_.String("train", k)) < 0)
        doc_.Problem("train", k, "no member of this name", "the name of a gear, carrier or rack");
    Motor();
  }

  // Problems of SolveGearTrain ("<section>.<field>") at the lines of the file.
  void Report(const InputError& e) {
    for (const InputProblem& p : e.problems()) {
      const auto dot = p.key.rfind('.');
      std::string sec = dot == std::string::npos ? "" : p.key.substr(0, dot);
      std::string key = dot == std::string::npos ? p.key : p.key.substr(dot + 1);
      if (key == "speed") {
        key = "";
        for (const char* k : {"speed_rpm", "speed_rad_s", "speed_m_s", "held"})
          if (doc_.Given(sec, k)) key = k;
      } else if (key == "name") {
        key = "";
      } else if (!doc_.Given(sec, key)) {
        key = "";
      }
      doc_.Problem(sec, key, p.rule, p.allowed);
    }
  }

 private:
  std::optional<double> Speed(const std::string& sec, bool rack) {
    const std::vector<const char*> keys =
        rack ? std::vector<const char*>{"speed_m_s"}
             : std::vector<const char*>{"speed_rpm", "speed_rad_s"};
    int given = doc_.Bool(sec, "held") ? 1 : 0;
    for (const char* k : keys) given += doc_.Given(sec, k);
    if (given > 1) {
      doc_.Problem(
          sec, doc_.Bool(sec, "held") ? "held" : keys.back(),
          "a member is driven at one speed or held, not both",
          rack ? "one of speed_m_s, held = true" : "one of speed_rpm, speed_rad_s, held = true");
      return std::nullopt;
    }
    if (doc_.Bool(sec, "held")) return 0.0;
    if (rack) {
      if (doc_.Given(sec, "speed_m_s")) return doc_.Real(sec, "speed_m_s");
    } else {
      if (doc_.Given(sec, "speed_rpm")) return RpmToRadPerS(doc_.Real(sec, "speed_rpm"));
      if (doc_.Given(sec, "speed_rad_s")) return doc_.Real(sec, "speed_rad_s");
    }
    return std::nullopt;
  }

  TrainMember Member(const std::string& group, const std::string& name, const std::string& sec) {
    TrainMember m;
    m.name = name;
    m.where = sec;
    m.kind = group == "gear"      ? MemberKind::kGear
             : group == "carrier" ? MemberKind::kCarrier
                                  : MemberKind::kRack;
    m.speed = Speed(sec, m.kind == MemberKind::kRack);
    if (m.kind == MemberKind::kGear) {
      m.teeth = static_cast<int>(doc_.Int(sec, "teeth"));
      if (!doc_.Has(sec, "teeth")) m.teeth = 1;  // reported by the schema; keep solving quiet
      const std::string hand = doc_.String(sec, "worm_hand");
      m.worm_hand = hand == "right"  ? WormHand::kRight
                    : hand == "left" ? WormHand::kLeft
                                     : WormHand::kNone;
      m.carrier = doc_.String(sec, "carrier");
    }
    if (m.kind != MemberKind::kCarrier) m.module_m = doc_.Real(sec, "module_m");
    if (m.kind != MemberKind::kRack) m.shaft = doc_.String(sec, "shaft");
    return m;
  }

  void Mesh(const std::string& sec) {
    TrainMesh m;
    m.where = sec;
    m.a = doc_.String(sec, "a");
    m.b = doc_.String(sec, "b");
    m.kind = MeshKindFromString(doc_.String(sec, "kind")).value_or(MeshKind::kExternal);
    m.bevel_same_sense = doc_.String(sec, "bevel_sense") == "same";
    if (doc_.Given(sec, "bevel_sense") && m.kind != MeshKind::kBevel)
      doc_.Problem(sec, "bevel_sense", "only a bevel mesh has a sense to choose",
                   "kind = \"bevel\", or remove bevel_sense");
    if (doc_.Has(sec, "a") && doc_.Has(sec, "b")) out_.spec.meshes.push_back(m);
  }

  void Motor() {
    const bool motor = doc_.HasSection("motor");
    if (doc_.HasSection("load") && !motor)
      doc_.Problem("load", "", "a load needs a [motor] to drive it", "a [motor] section");
    if (!motor) return;
    out_.motor = ReadMotorSection(doc_, "motor");
    out_.speed_command_rad_s = MotorSpeedCommand(doc_, "motor");
    out_.load.torque_nm = doc_.Real("load", "torque_nm");
    out_.load.viscous_nm_s = doc_.Real("load", "viscous_nm_s");
    out_.load.efficiency = doc_.Real("load", "efficiency");
    if (!doc_.Has("load", "efficiency")) out_.load.efficiency = 1.0;
    out_.load_member = doc_.String("load", "member");
    if (out_.load_member.empty()) out_.load_member = doc_.String("train", "output");
    const std::string input = doc_.String("train", "input");
    if (out_.spec.members.empty()) {
      // A motor on its own: the load sits on the motor shaft.
      if (!out_.load_member.empty())
        doc_.Problem("load", "member", "a file without gears has no members",
                     "member = \"\" (the load is on the motor shaft)");
      return;
    }
    if (input.empty() || out_.spec.Index(input) < 0) {
      doc_.Problem("train", "input",
                   "the motor drives the train's input member, which is "
                   "missing or unknown",
                   "input = the name of the member the motor drives");
      return;
    }
    // A defaulted member is [train] output's value: the problem is that key's.
    const bool defaulted = !doc_.Given("load", "member") && doc_.Given("train", "output");
    const std::string sec = defaulted ? "train" : "load";
    const std::string key = defaulted ? "output" : "member";
    const std::string named =
        defaulted ? "the loaded member (by default [train] output, " + out_.load_member + ")"
                  : "the loaded member";
    const int loaded = out_.spec.Index(out_.load_member);
    if (loaded < 0)
      doc_.Problem("load", "member", "the loaded member is missing or unknown",
                   "member = a gear or carrier of the train (or [train] output)");
    else if (out_.spec.members[loaded].kind == MemberKind::kRack)
      doc_.Problem(sec, key, named + " is a rack: a load torque needs a rotating member",
                   "the rack's pinion, with the rack force times its pitch radius as torque" +
                       std::string(defaulted ? ", in [load] member" : ""));
    else if (out_.spec.members[loaded].speed && *out_.spec.members[loaded].speed == 0.0)
      doc_.Problem(sec, key,
                   named +
                       " is held: a held member does no work, and the motor would run "
                       "at no load",
                   "a member that turns (the train's output)");
    for (const TrainMember& m : out_.spec.members) {
      if (m.name == input && m.speed && *m.speed == 0.0)
        doc_.Problem(m.where, "held", "the motor drives " + input + ", which is held",
                     "held = false on the member the motor drives");
      else if (m.name == input && m.speed)
        doc_.Problem(m.where, doc_.Given(m.where, "speed_rad_s") ? "speed_rad_s" : "speed_rpm",
                     "the motor gives the speed of " + input + " (speed given twice)",
                     "no speed on the member the motor drives");
      else if (m.speed && *m.speed != 0.0)
        doc_.Problem(m.where, doc_.Given(m.where, "speed_rad_s") ? "speed_rad_s" : "speed_rpm",
                     "with a motor the only other inputs are held members",
                     "held = true, or no speed");
    }
  }

  Document& doc_;
  TrainFile& out_;
};

}  // namespace

TrainFile ReadTrainFile(const std::string& path) {
  const auto names = ScanTrainMemberNames(path);
  const Schema schema = BuildTrainSchema(names);
  Document doc = Document::ReadFile(schema, path);
  for (const auto& p : doc.problems())
    if (p.key == "(syntax)" || p.key == "(file)") doc.ThrowIfProblems();
  TrainFile file;
  file.path = path;
  TrainReader reader(&doc, &file);
  reader.Read(names);
  // The planet rules are checked after a failed trial solve too: they say why a carrier's
  // set is no planetary set (a ring smaller than its planet, say).
  const bool read = doc.problems().empty();
  if (!file.spec.members.empty() && !file.motor && !doc.HasSection("motor") &&
      doc.problems().empty()) {
    try {
      SolveGearTrain(file.spec);
    } catch (const InputError& e) {
      reader.Report(e);
    }
  } else if (file.motor && doc.problems().empty() && !file.spec.members.empty()) {
    try {
      SolveUnitInput(file.spec);
    } catch (const InputError& e) {
      reader.Report(e);
    }
  }
  if (file.spec.members.empty() && !doc.HasSection("motor"))
    doc.Problem("gear", "", "a train file needs gears (or a [motor] on its own)",
                "[gear.NAME] sections with [mesh.NAME] sections between them");
  if (read) CheckPlanets(doc, &file);
  NoteCloseInternalPairs(file.spec, &file.notes);
  doc.ThrowIfProblems();
  return file;
}

TrainResult SolveTrainFile(const TrainFile& file) {
  TrainResult r;
  if (!file.motor) {
    r.solution = SolveGearTrain(file.spec);
    r.tables = TabulateEpicyclic(file.spec, r.solution);
    r.torques = SolveTrainTorques(file.spec, r.solution);
    return r;
  }
  const DcMotor motor(*file.motor);
  MotorLoad load = file.load;
  TrainSolution unit;
  if (!file.spec.members.empty()) {
    unit = SolveUnitInput(file.spec);
    r.load_train_value = unit.speed[file.spec.Index(file.load_member)];
  } else {
    r.load_train_value = 1.0;
  }
  load.train_value = r.load_train_value;
  double w = 0;
  if (file.speed_command_rad_s) {
    w = *file.speed_command_rad_s;
    r.controlled = SolveControlledPoint(motor, load, w);
  } else {
    r.motor = SolveOperatingPoint(motor, load);
    w = r.motor->motor_speed_rad_s;
  }
  if (!file.spec.members.empty()) {
    GearTrainSpec scaled = file.spec;
    for (TrainMember& m : scaled.members)
      if (m.name == file.spec.input) m.speed = w;
    if (w != 0) {
      r.solution = SolveGearTrain(scaled);
      r.tables = TabulateEpicyclic(scaled, r.solution);
    } else {
      r.solution = unit;
      for (double& x : r.solution.speed) x = 0.0;
    }
    // The torques at the motor's torque, the loaded member as output: the train at unit input
    // speed has the same free motions and the same torques.
    GearTrainSpec unit_spec = file.spec;
    for (TrainMember& m : unit_spec.members)
      if (m.name == file.spec.input)
        m.speed = 1.0;
      else if (m.speed)
        m.speed = 0.0;
    unit_spec.output = file.load_member;
    const double t_motor = r.controlled ? r.controlled->motor_torque_nm : r.motor->motor_torque_nm;
    r.torques = SolveTrainTorques(unit_spec, unit, t_motor);
  }
  return r;
}

}  // namespace tehl::internal
