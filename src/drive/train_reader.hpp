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

namespace tehl::internal {

// A simple planetary set found on a carrier: sun (external mesh with the planet), planet
// riding on the carrier, ring (internal mesh with the planet); sun and ring on fixed axes.
struct PlanetarySetOnCarrier {
  std::string carrier, sun, planet, ring;
  PlanetarySet set;
  PlanetRules rules;
  std::optional<int> planets;  // the count declared in [carrier.NAME] planets
};

struct TrainFile {
  std::string path;
  std::string name;               // [train] name
  GearTrainSpec spec;             // speeds in rad/s (racks m/s)
  std::vector<PlanetarySetOnCarrier> planetary;
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
};

// Solves the file's train (and motor). Problems of the solve are reported at the file's
// lines (InputError).
TrainResult SolveTrainFile(const TrainFile& file);

}  // namespace tehl::internal
