// tehl: thermo-elastohydrodynamic lubrication of spur gears. One program, subcommands.
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "cli/commands.hpp"

int main(int argc, char** argv) {
  using namespace tehl::cli;
  CLI::App app{
      "tehl: thermo-elastohydrodynamic lubrication of spur gears along the mesh cycle.\n"
      "Exit codes: 0 success, 1 a solver did not converge, 2 bad input (including an output\n"
      "folder that cannot be written), 3 internal error (a defect of tehl: please report it)."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "tehl 0.1.0");
  // One line per subcommand; each lives in its own file.
  const std::vector<Command> commands = {
      AddCaseCommand(app),
      AddLubricantCommand(app),
      AddGearCommand(app),
      AddRunCommand(app),
      AddPlotCommand(app),
      AddSweepCommand(app),
      AddTrainCommand(app),
      AddDynamicsCommand(app),
  };
  // A first word that is neither an option nor a command is a mistyped command: name it.
  if (argc > 1 && argv[1][0] != '-') {
    bool known = false;
    std::string names;
    for (const auto& c : commands) {
      known = known || c.app->get_name() == argv[1];
      names += (names.empty() ? "" : ", ") + c.app->get_name();
    }
    if (!known) {
      std::cerr << "tehl: unknown command '" << argv[1] << "' (allowed: " << names
                << "; tehl --help lists them)\n";
      return kExitBadInput;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitBadInput;
  }
  try {
    for (const auto& c : commands)
      if (c.app->parsed()) return c.run();
  } catch (...) {
    const CommandError e = DescribeCommandError(std::current_exception());
    std::cerr << e.message << "\n";
    return e.exit_code;
  }
  return kExitOk;
}
