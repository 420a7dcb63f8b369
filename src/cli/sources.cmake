# The `tehl` program: main.cpp and one file per subcommand (linked into the executable only).
list(APPEND TEHL_CLI_SOURCES
  src/cli/main.cpp
  src/cli/command_errors.cpp
  src/cli/case_command.cpp
  src/cli/run_command.cpp
  src/cli/run_notes.cpp
  src/cli/lubricant_command.cpp
  src/cli/gear_command.cpp
  src/cli/gear_film_estimates.cpp
  src/cli/plot_command.cpp
  src/cli/python_script.cpp
  src/cli/sweep_command.cpp
  src/cli/sweep_mpi.cpp
  src/cli/train_command.cpp
  src/cli/train_report.cpp
  src/cli/dynamics_command.cpp
)
