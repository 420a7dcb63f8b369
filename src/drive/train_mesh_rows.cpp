#include "drive/train_mesh_rows.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

namespace tehl::internal {

std::string TrainNumber(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

void MeshRows::Problem(const std::string& where,
                       const std::string& field,
                       std::string rule,
                       std::string allowed) {
  problems_.Add({"", 0, where.empty() ? field : where + "." + field, "", std::move(rule),
                 std::move(allowed)});
}

// The carrier index a mesh turns with (-1: the frame), or -2 after a problem.
int MeshRows::MeshFrame(const TrainMesh& mesh, const TrainMember& a, const TrainMember& b) {
  if (!a.carrier.empty() && !b.carrier.empty() && a.carrier != b.carrier) {
    Problem(mesh.where, "b",
            a.name + " rides on " + a.carrier + " and " + b.name + " on " + b.carrier,
            "a mesh between gears of one carrier, or between a carrier's gear and a gear "
            "on a fixed axis");
    return -2;
  }
  const std::string& c = a.carrier.empty() ? b.carrier : a.carrier;
  return c.empty() ? -1 : spec_.Index(c);
}

void MeshRows::Add(const TrainMesh& mesh) {
  const int ia = spec_.Index(mesh.a), ib = spec_.Index(mesh.b);
  bool ok = true;
  for (auto [i, field, name] : {std::tuple{ia, "a", mesh.a}, std::tuple{ib, "b", mesh.b}}) {
    if (i < 0) {
      Problem(mesh.where, field, "no member named '" + name + "'",
              "the name of a [gear.NAME] (or, for b of a rack mesh, [rack.NAME]) section");
      ok = false;
    }
  }
  if (!ok) return;
  if (ia == ib)
    return Problem(mesh.where, "b", "a gear cannot mesh with itself", "two different gears");
  const TrainMember& a = spec_.members[ia];
  const TrainMember& b = spec_.members[ib];
  const std::string what = mesh.a + "-" + mesh.b;
  if (a.kind != MemberKind::kGear)
    return Problem(mesh.where, "a", mesh.a + " is a " + ToString(a.kind) + ", not a gear",
                   "a gear (for a rack mesh: the pinion)");
  if (mesh.kind == MeshKind::kRack) {
    if (b.kind != MemberKind::kRack)
      return Problem(mesh.where, "b", mesh.b + " is not a rack", "a [rack.NAME] section");
    if (!a.carrier.empty())
      return Problem(mesh.where, "a", "a rack's pinion on a carrier is not supported",
                     "a pinion on a fixed axis");
    double m = a.module_m;
    if (b.module_m > 0 && m > 0 && std::abs(b.module_m - m) > 1e-9 * m)
      return Problem(mesh.where, "b",
                     "rack module " + TrainNumber(b.module_m) + " m differs from the pinion's " +
                         TrainNumber(m) + " m",
                     "equal modules (a rack meshes only with its own module)");
    if (m <= 0) m = b.module_m;
    if (m <= 0)
      return Problem(a.where, "module_m", "the pinion of rack " + b.name + " needs a module",
                     "module_m of the pinion or of the rack [m]");
    if (!FirstMeshOfPair(mesh, ia, ib)) return;
    const double r = 0.5 * m * a.teeth;  // pitch radius, Example 2.3: D = m N
    rows_.push_back({{{ib, 1.0}, {ia, -r}}, 0.0, false, -1, "rack mesh " + what, mesh.where});
    return;
  }
  if (b.kind != MemberKind::kGear)
    return Problem(mesh.where, "b", mesh.b + " is a " + ToString(b.kind) + ", not a gear",
                   "a gear; a rack only in a mesh of kind \"rack\"");
  if (a.teeth < 1 || b.teeth < 1) return;  // reported with the member
  // Two gears mesh only with one module (worm: axial module = the wheel's transverse one;
  // bevel: the module at the large end).
  if (a.module_m > 0 && b.module_m > 0 &&
      std::abs(a.module_m - b.module_m) > 1e-9 * std::max(a.module_m, b.module_m))
    return Problem(mesh.where, "b",
                   mesh.b + " has module " + TrainNumber(b.module_m) + " m and " + mesh.a + " " +
                       TrainNumber(a.module_m) + " m: gears of different modules do not mesh",
                   "equal module_m on both gears of a mesh");
  double s = -1.0;
  switch (mesh.kind) {
    case MeshKind::kExternal:
    case MeshKind::kBevel:
      s = (mesh.kind == MeshKind::kBevel && mesh.bevel_same_sense) ? 1.0 : -1.0;
      break;
    case MeshKind::kInternal: {
      // b is the ring, a the gear inside it; their centre distance m (z_b - z_a)/2 must be
      // positive.
      s = 1.0;
      // (A second mesh of the pair is reported as such below.)
      if (b.teeth <= a.teeth && !pair_mesh_.count(std::minmax(ia, ib)))
        return Problem(mesh.where, "b",
                       "the ring " + b.name + " (b, internal teeth) has " +
                           std::to_string(b.teeth) + " teeth, " +
                           (b.teeth == a.teeth ? "as many as" : "fewer than") + " " + a.name +
                           " (a, " + std::to_string(a.teeth) +
                           ") inside it: the centre distance m (z_ring - z_pinion)/2 = m (" +
                           std::to_string(b.teeth) + " - " + std::to_string(a.teeth) + ")/2 is " +
                           (b.teeth == a.teeth ? "zero" : "negative"),
                       "z_ring > z_pinion, with b = the ring and a = the pinion or planet inside "
                       "it (swap a and b if " +
                           a.name + " is the ring)");
      break;
    }
    case MeshKind::kWorm:
      if (a.worm_hand == WormHand::kNone)
        return Problem(mesh.where, "a", mesh.a + " is not a worm",
                       "a gear with worm_hand = \"right\" or \"left\" (teeth = starts)");
      s = a.worm_hand == WormHand::kRight ? 1.0 : -1.0;
      break;
    case MeshKind::kRack:
      break;
  }
  if (mesh.kind != MeshKind::kWorm) {
    for (const TrainMember* g : {&a, &b})
      if (g->worm_hand != WormHand::kNone)
        return Problem(mesh.where, "kind", g->name + " is a worm", "kind = \"worm\"");
  } else if (b.worm_hand != WormHand::kNone) {
    return Problem(mesh.where, "b", "a worm drives a worm wheel, not another worm",
                   "a gear without worm_hand");
  }
  const int c = MeshFrame(mesh, a, b);
  if (c == -2) return;
  if (c >= 0 && mesh.kind == MeshKind::kWorm)
    return Problem(mesh.where, "kind", "a worm pair on a carrier is not supported",
                   "worms on fixed axes");
  if (!FirstMeshOfPair(mesh, ia, ib)) return;
  // z_b (w_b - w_c) - s z_a (w_a - w_c) = 0, Willis (2.7) per mesh.
  const double za = a.teeth, zb = b.teeth;
  TrainRow row{
      {{ib, zb}, {ia, -s * za}}, 0.0, false, -1, ToString(mesh.kind) + " mesh " + what, mesh.where};
  if (c >= 0) {
    row.coeffs.push_back({c, s * za - zb});
    row.label += " (on carrier " + spec_.members[c].name + ")";
  }
  rows_.push_back(std::move(row));
}

// Two gears touch at one pitch point: a second mesh of the same pair (say once external,
// once internal) is a slip of the file, reported at the second mesh.
bool MeshRows::FirstMeshOfPair(const TrainMesh& mesh, int ia, int ib) {
  const auto [it, fresh] = pair_mesh_.emplace(
      std::minmax(ia, ib), mesh.where.empty() ? mesh.a + "-" + mesh.b : "[" + mesh.where + "]");
  if (!fresh)
    Problem(mesh.where, "b",
            mesh.a + " and " + mesh.b + " already mesh in " + it->second +
                ": one pair of gears has one mesh",
            "one [mesh.NAME] per pair of members (remove this one)");
  return fresh;
}

}  // namespace tehl::internal
