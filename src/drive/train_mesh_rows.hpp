// The kinematic relation of one mesh of a gear train (include/tehl/drive/gear_train.hpp):
// Willis' z_b (w_b - w_c) = s z_a (w_a - w_c) per mesh on carrier c (seed 001 eq. 2.7), or a
// rack's v = w r, with the rules a mesh must keep (member kinds, one module, worm hands, one
// mesh per pair). Private to src/drive.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "tehl/drive/gear_train.hpp"
#include "tehl/error.hpp"

namespace tehl::internal {

// One row of the train's linear system A w = b.
struct TrainRow {
  std::vector<std::pair<int, double>> coeffs;  // (member, coefficient)
  double rhs = 0.0;
  bool input = false;
  int member = -1;    // input rows: the member
  std::string label;  // for messages
  std::string where;  // kinematic rows: the mesh or member section that gave the row
};

// "%.6g", for messages.
std::string TrainNumber(double x);

// Collects the rows of the meshes of `spec`, one call per mesh; problems (keys
// "<where>.<field>") go to `problems`.
class MeshRows {
 public:
  MeshRows(const GearTrainSpec& spec, std::vector<TrainRow>* rows, ProblemList* problems)
      : spec_(spec), rows_(*rows), problems_(*problems) {}
  void Add(const TrainMesh& mesh);

 private:
  void Problem(const std::string& where,
               const std::string& field,
               std::string rule,
               std::string allowed);
  int MeshFrame(const TrainMesh& mesh, const TrainMember& a, const TrainMember& b);
  bool FirstMeshOfPair(const TrainMesh& mesh, int ia, int ib);

  const GearTrainSpec& spec_;
  std::vector<TrainRow>& rows_;
  ProblemList& problems_;
  std::map<std::pair<int, int>, std::string> pair_mesh_;  // meshed pair -> its mesh
};

}  // namespace tehl::internal
