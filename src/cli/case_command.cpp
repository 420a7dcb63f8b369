// tehl case --print-default | --check FILE...
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "cli/commands.hpp"
#include "scene/case_plan.hpp"
#include "scene/case_reader.hpp"
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
              // What a run would do (steps and grid), checked as the run checks it.
              const std::string plan_text = internal::CheckCasePlan(doc);
              if (doc.problems().empty())
                std::cout << path << ": ok" << (plan_text.empty() ? "" : ": " + plan_text) << "\n";
              all.Append(doc.problems());
            }
            all.ThrowIfAny();
            return kExitOk;
          }};
}

}  // namespace tehl::cli
