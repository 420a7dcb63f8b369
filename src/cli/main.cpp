// tehl: thermo-elastohydrodynamic lubrication of spur gears. One program, subcommands.
#include <cstdio>
#include <exception>
#include <iostream>
#include <vector>

#include "cli/commands.hpp"
#include "tehl/error.hpp"

int main(int argc, char** argv) {
  using namespace tehl::cli;
  CLI::App app{
      "tehl: thermo-elastohydrodynamic lubrication of spur gears along the mesh cycle.\n"
      "Exit codes: 0 success, 1 a solver did not converge, 2 bad input."};
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
  } catch (const tehl::InputError& e) {
    std::cerr << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "tehl: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  return kExitOk;
}
