// Subcommands of the `tehl` program. Each Add*Command adds its CLI11 subcommand to the app
// and returns how to run it once parsed. A runner returns the exit code: 0 success, 1 a
// solver that did not converge, 2 bad input (runners throw InputError for that; main()
// prints it and returns 2).
#pragma once

#include <CLI/CLI.hpp>
#include <exception>
#include <functional>
#include <string>

namespace tehl::cli {

struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

Command AddCaseCommand(CLI::App& app);       // tehl case --print-default | --check FILE
Command AddLubricantCommand(CLI::App& app);  // tehl lubricant NAME --p ... --T ...
Command AddGearCommand(CLI::App& app);       // tehl gear CASE [--csv F] [--profile F]
Command AddRunCommand(CLI::App& app);        // tehl run CASE
Command AddPlotCommand(CLI::App& app);       // tehl plot RESULT.h5 [-o DIR]
Command AddTrainCommand(CLI::App& app);      // tehl train FILE [--csv F]
Command AddDynamicsCommand(CLI::App& app);   // tehl dynamics CASE [--speeds A:B:H] [-o DIR]
Command AddSweepCommand(CLI::App& app);      // tehl sweep STUDY [-j N] [--resume] [--dry-run]

// Exit codes.
inline constexpr int kExitOk = 0;
inline constexpr int kExitNotConverged = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitInternal = 3;

// What main() prints on stderr for an error a runner threw, and the exit code: an InputError
// (its problems) or a std::filesystem::filesystem_error (a folder or file that cannot be
// written) 2, anything else 3 (an internal error).
struct CommandError {
  int exit_code = kExitInternal;
  std::string message;  // without the final newline
};
CommandError DescribeCommandError(const std::exception_ptr& error);

}  // namespace tehl::cli
