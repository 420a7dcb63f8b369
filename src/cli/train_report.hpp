// The torques and the DC motor of a `tehl train` report (docs/trains.md, "Torques" and
// "[motor]"): what each printed torque is (frictionless, at the input's torque), the load's
// share and the train's losses, and what the motor's input power includes. Private to the
// command line.
#pragma once

#include <cmath>
#include <cstdio>
#include <optional>
#include <ostream>
#include <string>

#include "drive/train_reader.hpp"

namespace tehl::cli {

// One number of a train report; round-off below 5e-13 prints as 0.
inline std::string TrainFmt(const char* format, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, std::abs(x) < 5e-13 ? 0.0 : x);
  return buf;
}

// With a [motor] that runs: the load's torque on the loaded member, T_L against the lossless
// output torque's sense (which opposes the motion) [N m]; otherwise none.
std::optional<double> TrainLoadTorque(const internal::TrainFile& f, const internal::TrainResult& r);

// The frictionless torques (per 1 N m on the input, or at the motor's torque), the housing
// reaction of a train on parallel axes, and with a [motor] the load's share and the losses.
void PrintTrainTorques(std::ostream& o,
                       const internal::TrainFile& f,
                       const internal::TrainResult& r);

// The DC motor block; returns the exit code (kExitNotConverged without a running point).
int PrintTrainMotor(std::ostream& o, const internal::TrainFile& f, const internal::TrainResult& r);

}  // namespace tehl::cli
