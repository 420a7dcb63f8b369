// Train files (docs/trains.md): [train], [gear.NAME], [carrier.NAME], [rack.NAME],
// [mesh.NAME], and optionally [motor] and [load]. The member names are the user's: the
// schema is built per file from the names found in it, so every key is still declared,
// typed and range-checked with file:line (base/schema.hpp). Private to src/.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "tehl/drive/dc_motor.hpp"
#include "tehl/drive/gear_train.hpp"
#include "tehl/drive/gear_train_tabulation.hpp"
#include "tehl/drive/planet_design.hpp"
#include "tehl/drive/train_torques.hpp"

namespace tehl::internal {

// A simple planetary set found on a carrier: sun (external mesh with the planet), planet
// riding on the carrier, ring (internal mesh with the planet); sun and ring on fixed axes.
// Every other gear of the carrier (the other step of a compound planet, say) is a PlanetStep
// with its own tip clearance: N < 180 deg / asin(d_a / (2 a)), d_a = m (z + 2 h_a*), a the
// distance of its axis from the central axis (seed 001 eq. 2.13 before the module cancels).
struct PlanetStep {
  std::string gear;
  int teeth = 0;                          // [-]
  std::optional<double> clearance_limit;  // N < this; absent = not checked [-]
  int max_by_clearance = 0;               // largest N strictly below the limit [-]
  std::string basis;                      // how a was found, or why the step is not checked
};

struct PlanetarySetOnCarrier {
  std::string carrier, sun, planet, ring;
  PlanetarySet set;
  PlanetRules rules;
  std::optional<int> planets;      // the count declared in [carrier.NAME] planets
  std::vector<PlanetStep> steps;   // the carrier's other gears
  std::vector<std::string> notes;  // rules that could not be checked, for the report
};

struct TrainFile {
  std::string path;
  std::string name;               // [train] name
  GearTrainSpec spec;             // speeds in rad/s (racks m/s)
  std::vector<PlanetarySetOnCarrier> planetary;
  std::vector<std::string> notes;  // design notes for the report (close internal pairs)
  std::optional<DcMotorSpec> motor;
  std::optional<double> speed_command_rad_s;  // [motor] speed_command_rpm
  std::string load_member;        // [load] member (default: the train's output)
  MotorLoad load;                 // torque, viscous, efficiency (train_value filled on solve)
};

// Reads, validates and solves nothing yet; throws InputError with every problem.
TrainFile ReadTrainFile(const std::string& path);

// What `tehl train` reports.
struct TrainResult {
  TrainSolution solution;                 // speeds [rad/s] (racks [m/s])
  std::vector<TabulationTable> tables;
  std::optional<MotorOperatingPoint> motor;   // fixed supply
  std::optional<ControlledPoint> controlled;  // speed command
  double load_train_value = 0;            // w_load / w_input, with a motor [-]
  // Frictionless external torques (train_torques.hpp): per 1 N m on the driven member, or,
  // with a motor, at the motor's torque with the loaded member as output.
  TrainTorques torques;
};

// Solves the file's train (and motor). Problems of the solve are reported at the file's
// lines (InputError).
TrainResult SolveTrainFile(const TrainFile& file);

}  // namespace tehl::internal
