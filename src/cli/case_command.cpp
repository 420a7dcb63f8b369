// tehl case --print-default | --check FILE...
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "cli/commands.hpp"
#include "scene/case_reader.hpp"
#include "scene/contact_case.hpp"
#include "scene/film_case.hpp"
#include "scene/gear_case.hpp"
#include "scene/mesh_cycle_plan.hpp"
#include "tehl/scene/case_schema.hpp"

namespace tehl::cli {

Command AddCaseCommand(CLI::App& app) {
  struct Args {
    bool print_default = false;
    std::vector<std::string> check;
  };
  auto args = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand("case", "Print the case-file schema or check case files");
  sub->add_flag("--print-default", args->print_default,
                "Print every key with its default, unit and meaning (a template: keep [gear] with "
                "[operating] or [contact], drop [motor] unless the motor drives the pinion, and "
                "give the required keys)");
  sub->add_option("--check", args->check, "Check case files; exit 2 with every problem found")
      ->expected(1, -1);
  sub->require_option(1);
  return {sub, [args]() {
            if (args->print_default) std::cout << CaseDefaultsText();
            ProblemList all;
            for (const auto& path : args->check) {
              // The same readers as a run: schema, cross-key rules, gear geometry, film inputs.
              internal::Document doc = internal::ReadCaseDocument(path);
              std::string plan_text;  // what a run would do: steps and grid
              if (doc.problems().empty()) {
                std::optional<internal::GearCase> gear;
                if (doc.HasSection("gear")) gear = internal::ReadGearCase(doc);
                const internal::FilmCase film = internal::ReadFilmCase(doc);
                if (doc.problems().empty() && gear && gear->pair) {  // the run's plan
                  const internal::CyclePath cycle(*gear);
                  const internal::MeshCyclePlan plan =
                      internal::PlanMeshCycle(doc, cycle, gear->ReducedModulusPa(), film);
                  plan_text = "mesh cycle of " + std::to_string(plan.s_steps.size() - 1) +
                              " steps (" + plan.step_rule + ") on " +
                              std::to_string(plan.grid.size()) + " nodes (" + plan.grid_rule + ")";
                  if (!plan.inlet_note.empty()) plan_text += "\n  note: " + plan.inlet_note;
                  for (const std::string& n : plan.input_notes) plan_text += "\n  note: " + n;
                } else if (doc.problems().empty() && doc.HasSection("contact")) {
                  const internal::ContactInputs in = internal::ReadContact(doc);
                  if (doc.problems().empty()) internal::CheckFilmScale(doc, in, film);
                  if (doc.problems().empty()) {
                    const internal::ContactGridPlan plan = internal::PlanContactGrid(doc, in, film);
                    plan_text = "line contact on " + std::to_string(plan.grid.size()) + " nodes (" +
                                plan.rule + ")";
                    if (!plan.inlet_note.empty()) plan_text += "\n  note: " + plan.inlet_note;
                    for (const std::string& n : plan.input_notes) plan_text += "\n  note: " + n;
                  }
                }
              }
              if (doc.problems().empty())
                std::cout << path << ": ok" << (plan_text.empty() ? "" : ": " + plan_text) << "\n";
              all.Append(doc.problems());
            }
            all.ThrowIfAny();
            return kExitOk;
          }};
}

}  // namespace tehl::cli
