// The schema of a train file (train_schema.hpp): the keys of a gear, a carrier, a rack and a
// mesh, a section for each member name found in the file, [train], [motor] and [load].
#include "drive/train_schema.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <toml.hpp>

#include "base/gear_module.hpp"
#include "base/toml_guard.hpp"
#include "drive/motor_schema.hpp"

namespace tehl::internal {
namespace {

const char* const kGroups[] = {"gear", "carrier", "rack", "mesh"};

std::vector<KeySpec> SpeedKeys(bool rack) {
  if (rack)
    return {Real("speed_m_s", "m/s", "", "driven speed of the rack (input)"),
            Flag("held", "false", "the rack is held (speed 0)")};
  return {Real("speed_rpm", "rpm", "", "driven speed (input), + counter-clockwise"),
          Real("speed_rad_s", "rad/s", "", "driven speed (alternative to speed_rpm)"),
          Flag("held", "false", "the member is held (speed 0)")};
}

SectionSpec GearSection(const std::string& name) {
  SectionSpec s{
      "gear." + name,
      "a gear (spur, helical, bevel, ring, worm wheel or worm)",
      false,
      {Required(Integer("teeth", "-", "", "number of teeth; a worm: thread starts", 1.0, 100000.0),
                "30"),
       GearModule("module_m", "", "module (needed by a rack's pinion)"),
       Text("worm_hand", "", "makes the gear a worm of this hand", {"right", "left"}),
       Text("shaft", "\"\"", "shaft name: members on one shaft turn together"),
       Text("carrier", "\"\"", "carrier (arm) its axis rides on; \"\" = the frame")}};
  for (auto& k : SpeedKeys(false)) s.keys.push_back(k);
  return s;
}

SectionSpec CarrierSection(const std::string& name) {
  SectionSpec s{
      "carrier." + name,
      "a carrier (arm) of an epicyclic train",
      false,
      {Text("shaft", "\"\"", "shaft name: members on one shaft turn together"),
       Integer("planets", "-", "", "equally spaced planets (design rules checked)", 1.0, 1000.0),
       Real("addendum_coefficient", "-", "1.0",
            "planet addendum / module, for the tip clearance rule", 0.0, 2.0, false, false)}};
  for (auto& k : SpeedKeys(false)) s.keys.push_back(k);
  return s;
}

SectionSpec RackSection(const std::string& name) {
  SectionSpec s{"rack." + name,
                "a rack meshing with a pinion",
                false,
                {GearModule("module_m", "", "module of the rack (= its pinion's)")}};
  for (auto& k : SpeedKeys(true)) s.keys.push_back(k);
  return s;
}

SectionSpec MeshSection(const std::string& name) {
  return {"mesh." + name,
          "a mesh between two members",
          false,
          {Required(Text("a", "", "first gear (a worm; a rack's pinion)"), "\"A\""),
           Required(Text("b", "", "second gear (a worm wheel; a rack)"), "\"B\""),
           Text("kind", "\"external\"", "kind of mesh",
                {"external", "internal", "bevel", "worm", "rack"}),
           Text("bevel_sense", "\"opposite\"",
                "bevel: \"opposite\" with both gears seen from their backs, \"same\" when one "
                "is seen from its front",
                {"opposite", "same"})}};
}

}  // namespace

Schema BuildTrainSchema(const TrainMemberNames& names) {
  Schema s;
  s.kind = "train";
  s.sections.push_back(
      {"train",
       "the train and which members the train value relates",
       false,
       {Text("name", "\"\"", "title shown in the report"),
        Text("input", "\"\"", "input member of the train value w_output / w_input"),
        Text("output", "\"\"", "output member of the train value")}});
  for (const char* g : kGroups) {
    s.sections.push_back({g, std::string("the ") + g + "s, one [" + g + ".NAME] each", false, {}});
    for (const auto& n : names.count(g) ? names.at(g) : std::vector<std::string>{}) {
      const std::string group = g;
      s.sections.push_back(group == "gear"      ? GearSection(n)
                           : group == "carrier" ? CarrierSection(n)
                           : group == "rack"    ? RackSection(n)
                                                : MeshSection(n));
    }
  }
  SectionSpec motor{"motor", "a DC motor driving the train's input member", false, MotorKeys()};
  s.sections.push_back(motor);
  s.sections.push_back(
      {"load",
       "the load on a member driven by the motor: T = torque_nm + viscous_nm_s |w|",
       false,
       {Text("member", "\"\"", "loaded member; \"\" = the train's output"),
        Real("torque_nm", "N m", "0.0", "constant load torque", 0.0),
        Real("viscous_nm_s", "N m s/rad", "0.0", "viscous load coefficient", 0.0),
        Real("efficiency", "-", "1.0", "efficiency of the train from motor to load", 0.0, 1.0,
             false, true)}});
  return s;
}

TrainMemberNames ScanTrainMemberNames(const std::string& path) {
  TrainMemberNames names;
  try {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    // Text the parser does not survive is left to the Document, which reports it.
    if (!in || FindUnsafeTomlText(text.str()).line > 0) return names;
    std::istringstream parse_in(text.str());
    const toml::value root = toml::parse(parse_in, path);
    if (!root.is_table()) return names;
    for (const char* g : kGroups) {
      if (!root.contains(g) || !root.at(g).is_table()) continue;
      std::vector<std::pair<int, std::string>> found;  // in file order
      for (const auto& [k, v] : root.at(g).as_table())
        if (v.is_table()) found.emplace_back(static_cast<int>(v.location().line()), k);
      std::sort(found.begin(), found.end());
      for (const auto& f : found) names[g].push_back(f.second);
    }
  } catch (const std::exception&) {
    // Unreadable: the Document reports why.
  }
  return names;
}

}  // namespace tehl::internal
