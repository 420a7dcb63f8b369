// Members and meshes of a GearTrainSpec for the train tests: a gear (optionally on a shaft
// and a carrier), a carrier and a mesh, named as a train file would name their sections.
#pragma once

#include <string>
#include <utility>

#include "tehl/drive/gear_train.hpp"
#include "tehl/error.hpp"

namespace tehl::testing {

inline TrainMember Gear(const std::string& name,
                        int z,
                        std::string shaft = "",
                        std::string carrier = "") {
  TrainMember m;
  m.name = name;
  m.teeth = z;
  m.shaft = std::move(shaft);
  m.carrier = std::move(carrier);
  m.where = "gear." + name;
  return m;
}

inline TrainMember Arm(const std::string& name, std::string shaft = "") {
  TrainMember m;
  m.name = name;
  m.kind = MemberKind::kCarrier;
  m.shaft = std::move(shaft);
  m.where = "carrier." + name;
  return m;
}

inline TrainMesh Mesh(const std::string& a,
                      const std::string& b,
                      MeshKind k = MeshKind::kExternal) {
  return {a, b, k, false, "mesh." + a + b};
}

// The message of the input error SolveGearTrain throws for s; "" when it solves.
inline std::string Message(const GearTrainSpec& s) {
  try {
    SolveGearTrain(s);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace tehl::testing
