// Planet rules of a train file (train_checks.hpp): the simple set of planet_design.hpp, then
// the centre distance and tip clearance of every other gear on the carrier.
#include "drive/train_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "tehl/drive/planet_design.hpp"
#include "tehl/error.hpp"
#include "tehl/units.hpp"

namespace tehl::internal {
namespace {

std::string Mm(double x_m) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g mm", x_m * 1e3);
  return buf;
}

// A simple planetary set on `carrier`: sun (external mesh with the planet), planet, ring
// (internal mesh, b of the mesh, more teeth than the planet), sun and ring on fixed axes.
// Without one, `why` says what stands in the way when it is a ring that cannot hold its
// planet.
std::optional<PlanetarySetOnCarrier> FindSet(const GearTrainSpec& s,
                                             const std::string& carrier,
                                             std::string* why) {
  for (const TrainMember& p : s.members) {
    if (p.kind != MemberKind::kGear || p.carrier != carrier) continue;
    std::string sun, ring;
    for (const TrainMesh& m : s.meshes) {
      if (m.a != p.name && m.b != p.name) continue;
      const std::string other = m.a == p.name ? m.b : m.a;
      const int o = s.Index(other);
      if (o < 0 || s.members[o].kind != MemberKind::kGear || !s.members[o].carrier.empty())
        continue;
      if (m.kind == MeshKind::kExternal && sun.empty()) sun = other;
      if (m.kind != MeshKind::kInternal || m.a != p.name || !ring.empty()) continue;
      if (s.members[o].teeth > p.teeth) {
        ring = other;
      } else if (why->empty()) {
        *why = "ring " + other + " (z = " + std::to_string(s.members[o].teeth) +
               ") cannot hold planet " + p.name + " (z = " + std::to_string(p.teeth) +
               ") inside it, [" + m.where + "]: a ring needs more teeth than its planet";
      }
    }
    if (sun.empty() || ring.empty()) continue;
    PlanetarySetOnCarrier f;
    f.carrier = carrier;
    f.sun = sun;
    f.planet = p.name;
    f.ring = ring;
    f.set.sun_teeth = s.members[s.Index(sun)].teeth;
    f.set.ring_teeth = s.members[s.Index(ring)].teeth;
    f.set.planet_teeth = p.teeth;
    return f;
  }
  return std::nullopt;
}

// A mesh of a planet gear with a gear on the central axis (the carrier's axis).
struct CentralMesh {
  const TrainMesh* mesh = nullptr;
  std::string central;
  double a_modules = 0;  // standard centre distance / module: external (z1 + z2)/2,
                         // internal (z_ring - z_planet)/2 [-]
  double module_m = 0;   // the pair's module; 0 = not given [m]
};

std::vector<CentralMesh> CentralMeshes(const GearTrainSpec& s, const TrainMember& g) {
  std::vector<CentralMesh> out;
  for (const TrainMesh& m : s.meshes) {
    if (m.a != g.name && m.b != g.name) continue;
    if (m.kind != MeshKind::kExternal && m.kind != MeshKind::kInternal) continue;
    const int o = s.Index(m.a == g.name ? m.b : m.a);
    if (o < 0) continue;
    const TrainMember& c = s.members[o];
    if (c.kind != MemberKind::kGear || !c.carrier.empty()) continue;
    CentralMesh cm;
    cm.mesh = &m;
    cm.central = c.name;
    cm.a_modules = m.kind == MeshKind::kExternal ? 0.5 * (g.teeth + c.teeth)
                                                 : 0.5 * std::abs(c.teeth - g.teeth);
    cm.module_m = g.module_m > 0 ? g.module_m : c.module_m;
    out.push_back(cm);
  }
  return out;
}

// Largest integer strictly below `limit`, an integer limit up to round-off counting as
// touching tips.
int StrictlyBelow(double limit) {
  const double r = std::round(limit);
  const double snapped = std::abs(limit - r) < 1e-9 * std::max(1.0, limit) ? r : limit;
  return std::max(1, static_cast<int>(std::ceil(snapped)) - 1);
}

// Every planet gear of carrier `c` but the simple set's planet: centre distances of each
// planet shaft agree, then the tip clearance of each gear.
void CheckSteps(Document& doc,
                const GearTrainSpec& s,
                const std::string& c,
                const std::string& set_planet,
                double h_a,
                std::optional<int> declared,
                PlanetarySetOnCarrier* report) {
  // Planet shafts: gears on one shaft, or a gear alone.
  std::map<std::string, std::vector<const TrainMember*>> units;
  for (const TrainMember& g : s.members)
    if (g.kind == MemberKind::kGear && g.carrier == c)
      units[g.shaft.empty() ? "gear " + g.name : "shaft " + g.shaft].push_back(&g);
  for (auto& [unit, gears] : units) {
    // The simple set's planet first: its meshes give the reference distance.
    std::stable_partition(gears.begin(), gears.end(),
                          [&](const TrainMember* g) { return g->name == set_planet; });
    bool unknown_module = false;
    for (const TrainMember* g : gears)
      for (const CentralMesh& cm : CentralMeshes(s, *g)) unknown_module |= cm.module_m <= 0;
    if (gears.size() > 1 && unknown_module)
      report->notes.push_back("the centre distances of the steps of planet " + unit +
                              " are not compared (no module_m on every step)");
    // The shaft's distance from the central axis, from every mesh that gives it in metres.
    std::optional<double> a_min, a_first;
    std::optional<CentralMesh> first;
    for (const TrainMember* g : gears)
      for (const CentralMesh& cm : CentralMeshes(s, *g)) {
        if (cm.module_m <= 0) continue;
        const double a = cm.module_m * cm.a_modules;
        if (!first) {
          first = cm;
          a_first = a;
        } else if (std::abs(a - *a_first) >
                   kMaxPlanetShiftModules * std::max(cm.module_m, first->module_m) * (1 + 1e-9)) {
          doc.Problem(cm.mesh->where, "b",
                      "planet " + unit + " would sit " + Mm(a) +
                          " from the central axis "
                          "by this mesh (" +
                          g->name + "-" + cm.central + ") and " + Mm(*a_first) + " by [" +
                          first->mesh->where +
                          "]: one planet axis "
                          "has one centre distance (external m (z1 + z2)/2, internal "
                          "m (z_ring - z_planet)/2; seed 001 eq. 2.14)",
                      "teeth and modules giving the same centre distance, within the " +
                          FormatShort(kMaxPlanetShiftModules) + " modules profile shifts bridge");
        }
        a_min = a_min ? std::min(*a_min, a) : a;
      }
    for (const TrainMember* g : gears) {
      if (g->name == set_planet) continue;
      PlanetStep step;
      step.gear = g->name;
      step.teeth = g->teeth;
      double x = 0;  // d_a / (2 a)
      const std::vector<CentralMesh> own = CentralMeshes(s, *g);
      double m = g->module_m;
      for (const CentralMesh& cm : own)
        if (m <= 0) m = cm.module_m;
      if (m > 0 && a_min) {
        x = m * (g->teeth + 2 * h_a) / (2 * *a_min);
        step.basis = "a = " + Mm(*a_min) + ", d_a = " + Mm(m * (g->teeth + 2 * h_a));
      } else if (!own.empty()) {
        // Standard gears: a / m from its own mesh, the module cancels (eq. 2.13).
        x = (g->teeth + 2 * h_a) / (2 * own.front().a_modules);
        step.basis =
            "from its mesh with " + own.front().central + ", standard gears (the module cancels)";
      } else {
        step.basis =
            "not checked: no module_m gives the distance of its axis from the central axis";
        report->steps.push_back(step);
        continue;
      }
      step.clearance_limit = x >= 1 ? 2.0 : kPi / std::asin(x);
      step.max_by_clearance = StrictlyBelow(*step.clearance_limit);
      if (declared && *declared > step.max_by_clearance)
        doc.Problem("carrier." + c, "planets",
                    "adjacent tips of planet gear " + g->name + " would touch: N < " +
                        PlanetLimitText(*step.clearance_limit) + " (" + step.basis +
                        "; seed 001 eq. 2.13, N < 180 deg / asin(d_a / 2a))",
                    "at most " + std::to_string(step.max_by_clearance) + " planets");
      report->steps.push_back(step);
    }
  }
}

}  // namespace

void NoteCloseInternalPairs(const GearTrainSpec& spec, std::vector<std::string>* notes) {
  for (const TrainMesh& m : spec.meshes) {
    if (m.kind != MeshKind::kInternal) continue;
    const int a = spec.Index(m.a), b = spec.Index(m.b);
    if (a < 0 || b < 0) continue;
    const int difference = spec.members[b].teeth - spec.members[a].teeth;
    if (difference <= 0 || difference >= kMinInternalToothDifference) continue;
    notes->push_back(
        "[" + m.where + "]: ring " + m.b + " has only " + std::to_string(difference) +
        " teeth more than " + m.a +
        " inside it; standard 20 deg full-depth teeth need a "
        "difference of at least " +
        std::to_string(kMinInternalToothDifference) +
        " to clear the tips (trochoid interference; SDP/SI, Elements of Metric Gear "
        "Technology, section 5.2): such a pair needs profile-shifted teeth (and is assembled "
        "axially); the speeds hold either way");
  }
}

std::string PlanetLimitText(double limit) {
  const double r = std::round(limit);
  char buf[32];
  if (std::abs(limit - r) < 1e-9 * std::max(1.0, limit))
    std::snprintf(buf, sizeof buf, "%.0f", r);
  else
    std::snprintf(buf, sizeof buf, "%.4g", limit);
  return buf;
}

void CheckPlanets(Document& doc, TrainFile* file) {
  const GearTrainSpec& spec = file->spec;
  for (const TrainMember& c : spec.members) {
    if (c.kind != MemberKind::kCarrier) continue;
    const std::string sec = "carrier." + c.name;
    std::string why;
    std::optional<PlanetarySetOnCarrier> found = FindSet(spec, c.name, &why);
    const bool declared = doc.Given(sec, "planets");
    if (!found) {
      if (declared)
        doc.Problem(sec, "planets",
                    "no simple planetary set (sun, planet, ring) on this carrier to check" +
                        (why.empty() ? std::string() : ": " + why),
                    "planets only for a carrier with a sun-planet external mesh and a "
                    "planet-ring internal mesh (a = the planet, b = a ring with more teeth)");
      continue;
    }
    found->set.addendum_coefficient = doc.Real(sec, "addendum_coefficient");
    try {
      found->rules = CheckPlanetRules(found->set);
    } catch (const InputError& e) {
      for (const auto& p : e.problems())
        doc.Problem("gear." + (p.key == "sun_teeth"      ? found->sun
                               : p.key == "planet_teeth" ? found->planet
                                                         : found->ring),
                    "teeth", p.rule, p.allowed);
      continue;
    }
    if (declared) {
      const int n = static_cast<int>(doc.Int(sec, "planets"));
      found->planets = n;
      const PlanetRules& r = found->rules;
      if (!r.Assembles(n))
        doc.Problem(
            sec, "planets",
            "cannot be equally spaced: (z_sun + z_ring)/N = " + std::to_string(r.total_teeth) +
                "/" + std::to_string(n) + " is not an integer (seed 001 eq. 2.12)",
            "a divisor of " + std::to_string(r.total_teeth));
      if (!r.Clears(n))
        doc.Problem(sec, "planets",
                    "adjacent planet tips would touch: N < " + PlanetLimitText(r.clearance_limit) +
                        " (seed 001 eq. 2.13)",
                    "at most " + std::to_string(r.max_by_clearance) + " planets");
    }
    CheckSteps(doc, spec, c.name, found->planet, found->set.addendum_coefficient, found->planets,
               &*found);
    file->planetary.push_back(*found);
  }
}

}  // namespace tehl::internal
