#include "scene/case_plan.hpp"

#include <optional>

#include "scene/contact_case.hpp"
#include "scene/film_case.hpp"
#include "scene/gear_case.hpp"
#include "scene/mesh_cycle_plan.hpp"

namespace tehl::internal {

std::string CheckCasePlan(Document& doc) {
  if (!doc.problems().empty()) return "";
  std::optional<GearCase> gear;
  if (doc.HasSection("gear")) gear = ReadGearCase(doc);
  const FilmCase film = ReadFilmCase(doc);
  std::string text;
  if (doc.problems().empty() && gear && gear->pair) {
    const CyclePath cycle(*gear);
    const MeshCyclePlan plan = PlanMeshCycle(doc, cycle, gear->ReducedModulusPa(), film);
    text = "mesh cycle of " + std::to_string(plan.s_steps.size() - 1) + " steps (" +
           plan.step_rule + ") on " + std::to_string(plan.grid.size()) + " nodes (" +
           plan.grid_rule + ")";
    if (!plan.inlet_note.empty()) text += "\n  note: " + plan.inlet_note;
    for (const std::string& n : plan.input_notes) text += "\n  note: " + n;
  } else if (doc.problems().empty() && doc.HasSection("contact")) {
    const ContactInputs in = ReadContact(doc);
    if (doc.problems().empty()) CheckFilmScale(doc, in, film);
    if (doc.problems().empty()) {
      const ContactGridPlan plan = PlanContactGrid(doc, in, film);
      text = "line contact on " + std::to_string(plan.grid.size()) + " nodes (" + plan.rule + ")";
      if (!plan.inlet_note.empty()) text += "\n  note: " + plan.inlet_note;
      for (const std::string& n : plan.input_notes) text += "\n  note: " + n;
    }
  }
  return text;
}

}  // namespace tehl::internal
