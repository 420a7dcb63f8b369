// The steady film at one point of a gear pair's path of contact, as a [contact] case: two
// discs with the flanks' radii of curvature, surface speeds, materials and tooth load at that
// point, and the gear case's lubricant, surfaces, effects and numerics (`tehl run --at`). The
// classic one-point check of a gear film (the pitch point C, the slow-rolling, sliding
// engagement A, the ends B and D of single contact) on a grid of its own, written as a case
// file the user can read, change and run again.
#pragma once

#include <string>

namespace tehl {

struct PathPointCase {
  std::string label;              // the point as printed: "C", "s = 2.5 mm"
  std::string tag;                // its part of the file names: "C", "s2.5mm"
  double s_m = 0;                 // distance from A along the line of action [m]
  double path_length_m = 0;       // g_alpha, A to E [m]
  double reduced_radius_m = 0;    // R of the two flanks there [m]
  double u1_m_s = 0, u2_m_s = 0;  // pinion and wheel surface speeds [m/s]
  double srr = 0;                 // slide-to-roll ratio (u1 - u2) / um [-]
  double load_n_per_m = 0;        // the tracked pair's load there (the dynamic one with the
                                  //   effect dynamic_load) [N/m]
  double load_share = 0;          // its static load over F_bt / b [-]
  int pairs_in_contact = 0;       // tooth pairs in contact there [-]
  bool internal = false;          // internal pair: body 2 of the case is a plane, R carries
                                  //   the concave ring's curvature
  std::string case_path;          // where the [contact] case goes: DIR/NAME_at_TAG.toml
  std::string case_text;          // the [contact] case
};

// Reads the gear case and builds the [contact] case of the point `at` (below), without
// writing it.
PathPointCase ContactCaseAtPoint(const std::string& gear_case_path,
                                 const std::string& at,
                                 const std::string& output_dir);

// Reads the gear case, builds the [contact] case of the point `at` and writes it (creating
// the folder). `at`: "A" … "E" (B and D on their single-contact side, where the pair carries
// the whole load), or a distance from A with its unit, "2.5mm" or "0.0025m". `output_dir`:
// the folder of the case and of its results; "" = the gear case's [output] directory. Bad
// input throws InputError: the gear case's problems at their file:line, a bad point as key
// "--at" with what is allowed.
PathPointCase WriteContactCaseAtPoint(const std::string& gear_case_path,
                                      const std::string& at,
                                      const std::string& output_dir);

}  // namespace tehl
