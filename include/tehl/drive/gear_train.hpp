// Gear trains: simple, compound (idlers, reverted), worm, bevel, rack-and-pinion and
// epicyclic trains with any member driven or held and several sub-trains on one arm, solved
// as ONE linear system of their kinematic relations (seed 001 section 2, seed 002):
//   mesh of gears a and b whose axes ride on carrier c (c = frame when both axes are fixed):
//       (w_b - w_c) = s z_a / z_b (w_a - w_c)       Willis, seed 001 eq. (2.7)
//     with s = -1 external, +1 internal, -1 bevel (each bevel gear's positive sense seen
//     from its back, looking towards the cone apex; +1 when one of the two is seen from its
//     front, `bevel_same_sense`), and for a worm a (z_a = thread starts) driving wheel b:
//     s = +1 right hand, -1 left hand (the wheel's positive sense is, by definition, the one
//     a right-hand worm turning positively drives it in);
//   rack b on pinion a:       v_b = w_a r_a,  r_a = m z_a / 2      (Example 2.3)
//   shaft coupling:           w_i = w_j for members on one shaft (compound gears, arms)
//   input / held member:      w_i = given / 0
// Sign convention: angular speeds are positive counter-clockwise looking along the common
// axis of the train from its chosen viewing side (the same side for every parallel axis).
// A rack's speed is positive in the direction the pitch point of its pinion moves when the
// pinion turns positively.
//
// The rank of the system is checked: a train whose speeds are not all fixed, a locked train
// (a member the meshes and shafts alone hold at rest), a speed given for a member the other
// relations already fix, a second mesh between the same two members, an input member at
// rest (w_output / w_input undefined) and an output that is the input member are input
// errors naming the members and relations concerned.
// Precision: members tied by meshes on fixed axes, shafts and racks turn in proportions that
// are products of tooth ratios along those relations; only the meshes on carriers (Willis)
// and the inputs are solved as a linear system, in one speed per such group, scaled to
// unit size. So every speed is exact to round-off (about 1e-15 relative for 20 stages)
// whatever the ratio. A group whose scaled speed is below 1e-12 times the largest of the
// groups carrier meshes tie it to is round-off of rest and returned as exactly 0, with all
// its members.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tehl {

enum class MeshKind { kExternal, kInternal, kBevel, kWorm, kRack };
std::string ToString(MeshKind k);  // "external", "internal", "bevel", "worm", "rack"
std::optional<MeshKind> MeshKindFromString(std::string_view s);

enum class WormHand { kNone, kRight, kLeft };
std::string ToString(WormHand h);  // "", "right", "left"

enum class MemberKind { kGear, kCarrier, kRack };
std::string ToString(MemberKind k);  // "gear", "carrier", "rack"

// One moving member of the train: a gear (spur, helical, bevel, ring, worm or worm wheel),
// a carrier (arm) or a rack.
struct TrainMember {
  std::string name;  // unique over all members
  MemberKind kind = MemberKind::kGear;
  int teeth = 0;                         // gear teeth, or thread starts of a worm [-]
  double module_m = 0.0;                 // module; 0 = not given (needed for racks, planets) [m]
  WormHand worm_hand = WormHand::kNone;  // kNone: not a worm
  std::string shaft;                     // members with the same non-empty shaft turn together
  std::string carrier;                   // gears only: carrier their axis rides on; "" = frame
  std::optional<double> speed;           // driven speed [rad/s] (rack: [m/s]); 0 = held
  std::string where;                     // section for messages, e.g. "gear.A"; may be ""
};

struct TrainMesh {
  std::string a, b;  // member names; a worm or a rack's pinion is a
  MeshKind kind = MeshKind::kExternal;
  bool bevel_same_sense = false;  // bevel only: s = +1 instead of -1
  std::string where;              // section for messages, e.g. "mesh.AB"
};

struct GearTrainSpec {
  std::vector<TrainMember> members;
  std::vector<TrainMesh> meshes;
  std::string input;   // member whose speed divides in the train value; "" = none
  std::string output;  // member whose speed is divided; "" = none
  int Index(std::string_view name) const;  // -1 if absent
};

struct TrainSolution {
  std::vector<double> speed;          // per member, order of spec.members [rad/s] (rack [m/s])
  std::optional<double> train_value;  // w_output / w_input, seed 001 eq. (2.2) [-]
  int equations = 0;                  // rows of the linear system
  int unknowns = 0;                   // one speed per member
  int rank = 0;                       // rank of the system (== unknowns when solved)
  double residual = 0.0;              // max |A w - b| over the rows, relative [-]
  // A basis of the motions the meshes and shafts alone allow (the null space of their rows,
  // before inputs and held members): free_motions[k][member], each motion scaled to a
  // largest entry of 1, rack entries in m/s. Used for the torques by virtual work
  // (train_torques.hpp).
  std::vector<std::vector<double>> free_motions;
};

// Solves the train. Throws InputError for a spec that breaks a rule (unknown member in a
// mesh, a mesh between two carriers' planets, a rack mesh without module, ...) or whose
// system is under- or over-determined; each problem's key is "<where>.<field>" with field
// one of teeth, module_m, worm_hand, shaft, carrier, speed, a, b, kind, input, output.
TrainSolution SolveGearTrain(const GearTrainSpec& spec);

// The same train with every given speed replaced: `input` at 1 rad/s, every other driven
// member held. Used to scale a train that a motor drives; throws like SolveGearTrain.
TrainSolution SolveUnitInput(const GearTrainSpec& spec);

}  // namespace tehl
