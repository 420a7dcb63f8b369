// tehl gear CASE [--csv FILE] [--profile FILE] [--points N] [--mu MU]
// The gear pair of a case: geometry, contact ratios, path of contact, kinematics, load,
// Hertz scales and mesh stiffness by each method. Exit 2 (with every problem) for bad
// geometry.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "cli/commands.hpp"
#include "cli/gear_film_estimates.hpp"
#include "cli/number_format.hpp"
#include "io/atomic_file.hpp"
#include "scene/case_reader.hpp"
#include "scene/film_case.hpp"
#include "scene/gear_case.hpp"
#include "tehl/ehl/flash_temperature.hpp"
#include "tehl/error.hpp"
#include "tehl/gear/flank_phase.hpp"
#include "tehl/gear/path_of_contact.hpp"
#include "tehl/gear/tooth_blank.hpp"
#include "tehl/gear/tooth_profile.hpp"
#include "tehl/units.hpp"

namespace tehl::cli {
namespace {

// One line "label  pinion  wheel".
// Why a stiffness method does not apply: every rule it breaks, with the value and the range.
std::string WhyNot(const InputError& e) {
  std::string s;
  for (const InputProblem& p : e.problems())
    s += (s.empty() ? "" : "; ") + p.rule + (p.value.empty() ? "" : " (" + p.value + ")") +
         (p.allowed.empty() ? "" : ", valid for " + p.allowed);
  return s;
}

void Row(std::ostream& o, const std::string& label, const std::string& a, const std::string& b) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "  %-30s %14s %14s\n", label.c_str(), a.c_str(), b.c_str());
  o << buf;
}

void Geometry(std::ostream& o, const internal::GearCase& c) {
  const GearPair& p = *c.pair;
  const GearPairSpec& s = p.spec();
  const bool asym = s.drive_pressure_angle_rad != s.coast_pressure_angle_rad;
  o << "Gear pair: " << (s.internal ? "internal" : "external") << ", "
    << (s.helix_angle_rad > 0 ? "helical (film model: transverse section as spur)" : "spur") << ", "
    << (asym ? "asymmetric teeth" : "symmetric teeth") << "\n";
  o << "  module m_n = " << Fmt("%.4f", s.module_m * 1e3)
    << " mm, face width b = " << Fmt("%.3f", s.face_width_m * 1e3) << " mm, pressure angle "
    << Fmt("%.4f", RadToDeg(s.drive_pressure_angle_rad)) << " deg"
    << (asym ? " (drive) / " + Fmt("%.4f", RadToDeg(s.coast_pressure_angle_rad)) + " deg (coast)"
             : std::string())
    << (s.helix_angle_rad > 0 ? ", helix " + Fmt("%.3f", RadToDeg(s.helix_angle_rad)) + " deg"
                              : std::string())
    << "\n";
  o << "  basic rack: h_aP = " << Fmt("%.3f", s.addendum_coefficient)
    << " m, h_fP = " << Fmt("%.3f", s.dedendum_coefficient)
    << " m, rho_fP = " << Fmt("%.3f", s.root_fillet_coefficient) << " m\n";
  const GearGeometry& g1 = p.pinion();
  const GearGeometry& g2 = p.wheel();
  auto mm = [](double m) { return Fmt("%.4f", m * 1e3); };
  Row(o, "", "pinion", s.internal ? "ring" : "wheel");
  Row(o, "teeth z", std::to_string(g1.teeth), std::to_string(g2.teeth));
  Row(o, "profile shift x", Fmt("%.4f", g1.profile_shift), Fmt("%.4f", g2.profile_shift));
  Row(o, "pitch radius r [mm]", mm(g1.pitch_radius_m), mm(g2.pitch_radius_m));
  Row(o, asym ? "base radius r_b, drive [mm]" : "base radius r_b [mm]", mm(g1.drive.base_radius_m),
      mm(g2.drive.base_radius_m));
  if (asym)
    Row(o, "base radius r_b, coast [mm]", mm(g1.coast.base_radius_m), mm(g2.coast.base_radius_m));
  Row(o, "tip radius r_a [mm]", mm(g1.tip_radius_m), mm(g2.tip_radius_m));
  Row(o, "root radius r_f [mm]", mm(g1.root_radius_m), mm(g2.root_radius_m));
  Row(o, asym ? "form radius r_F, drive [mm]" : "form radius r_F [mm]", mm(g1.drive.form_radius_m),
      mm(g2.drive.form_radius_m));
  if (asym)
    Row(o, "form radius r_F, coast [mm]", mm(g1.coast.form_radius_m), mm(g2.coast.form_radius_m));
  Row(o, "pitch thickness s [mm]", mm(g1.reference_thickness_m), mm(g2.reference_thickness_m));
  Row(o, "top land s_a [mm]", mm(g1.tip_thickness_m), mm(g2.tip_thickness_m));
  Row(o, "pointed-tip radius [mm]", g1.internal ? "-" : mm(g1.pointed_tip_radius_m),
      g2.internal ? "-" : mm(g2.pointed_tip_radius_m));
  // Asymmetric teeth: each flank has its own limit; the flank of the smaller pressure angle
  // (usually the coast flank) undercuts first and governs.
  for (Flank f : {Flank::kDrive, Flank::kCoast}) {
    if (f == Flank::kCoast && !asym) break;
    Row(o, asym ? "x_min without undercut, " + ToString(f) : std::string("x_min without undercut"),
        Fmt("%.4f", g1.flank(f).min_shift_no_undercut),
        g2.internal ? "-" : Fmt("%.4f", g2.flank(f).min_shift_no_undercut));
  }
  if (asym)
    Row(o, "K = r_bc / r_bd", Fmt("%.4f", g1.BaseRadiusRatio()), Fmt("%.4f", g2.BaseRadiusRatio()));
  o << "  centre distance a = " << mm(p.center_distance_m())
    << " mm (a0 = " << mm(p.reference_center_distance_m()) << " mm, y = "
    << Fmt("%.5f", std::abs(p.center_distance_modification()) < 5e-6
                       ? 0.0
                       : p.center_distance_modification())
    << ", zero backlash at " << mm(p.zero_backlash_center_distance_m()) << " mm), backlash "
    << Fmt("%.2f", std::abs(p.backlash_m()) < 5e-9 ? 0.0 : p.backlash_m() * 1e6) << " um\n";
  o << "  radial clearances: pinion tip " << mm(p.pinion_tip_clearance_m()) << " mm, wheel tip "
    << mm(p.wheel_tip_clearance_m()) << " mm\n";
  for (Flank f : {Flank::kDrive, Flank::kCoast}) {
    if (f == Flank::kCoast && !asym) break;
    const LineOfAction& l = p.line(f);
    o << "  " << (asym ? ToString(f) + " flank: " : std::string()) << "working pressure angle "
      << Fmt("%.4f", RadToDeg(l.working_pressure_angle_rad))
      << " deg, base pitch p_b = " << mm(l.base_pitch_m)
      << " mm, eps_alpha = " << Fmt("%.4f", l.contact_ratio) << "\n";
  }
  if (s.helix_angle_rad > 0)
    o << "  eps_beta = " << Fmt("%.4f", p.face_contact_ratio())
      << ", eps_gamma = " << Fmt("%.4f", p.total_contact_ratio()) << "\n";
}

void Path(std::ostream& o, const internal::GearCase& c) {
  const GearPair& p = *c.pair;
  const PathOfContact path(p, c.operating.pinion_speed_rad_s);
  const LineOfAction& l = path.line();
  auto mm = [](double m) { return Fmt("%.3f", m * 1e3); };
  o << "\nPath of contact (drive flanks), along the line of action, T1T2 = "
    << mm(l.tangent_length_m) << " mm:\n";
  o << "  from T1 [mm]:  A " << mm(l.a_m) << "  B " << mm(l.b_m) << "  C " << mm(l.c_m) << "  D "
    << mm(l.d_m) << "  E " << mm(l.e_m) << "\n";
  o << "  from A  [mm]:  AB " << mm(path.s_b_m()) << "  AC " << mm(path.s_c_m()) << "  AD "
    << mm(path.s_d_m()) << "  AE " << mm(path.length_m()) << " (g_alpha)\n";
  // B = E - p_b and D = A + p_b; with eps_alpha >= 2 there is no single contact: B lies after
  // D, and two or three pairs share the load everywhere.
  const double eps = path.contact_ratio();
  if (eps < 2.0)
    o << "  single contact B-D " << mm(std::max(0.0, path.s_d_m() - path.s_b_m())) << " mm";
  else
    o << "  no single contact (eps_alpha = " << Fmt("%.4f", eps)
      << " >= 2: " << (eps < 3.0 ? "two or three" : "three or more")
      << " pairs in contact at every instant; "
      << "B = E - p_b and D = A + p_b mark where a third pair enters and leaves)";
  o << "; mesh period " << Fmt("%.4f", path.mesh_period_s() * 1e3) << " ms, A to E "
    << Fmt("%.4f", path.duration_s() * 1e3) << " ms\n";

  const ToothLoad load = NominalToothLoad(p, c.operating);
  o << "\nOperating point: pinion " << Fmt("%.2f", RadPerSToRpm(path.pinion_speed_rad_s()))
    << " rpm (" << Fmt("%.3f", path.pinion_speed_rad_s()) << " rad/s), wheel "
    << Fmt("%.2f", RadPerSToRpm(path.wheel_speed_rad_s()))
    << " rpm, T1 = " << Fmt("%.3f", c.operating.pinion_torque_nm)
    << " N m, P = " << Fmt("%.3f", c.power_w * 1e-3) << " kW\n";
  if (c.speed_from_motor)
    o << "  the pinion speed is the [motor]'s operating point under T1 (docs/trains.md)\n";
  o << "  normal load F_bt = T1 / r_b1 = " << Fmt("%.2f", load.normal_force_n)
    << " N, w = F_bt / b = " << Fmt("%.3f", load.load_per_width_n_per_m * 1e-3) << " kN/m\n";

  const double e_prime = c.ReducedModulusPa();
  const ContactPoint pc = path.At(path.s_c_m());
  const HertzScales h = LineContactHertz(load.load_per_width_n_per_m, pc.reduced_radius_m, e_prime);
  o << "  pitch point C (full load w): R = " << mm(pc.reduced_radius_m)
    << " mm, um = " << Fmt("%.4f", pc.um_m_s) << " m/s, E' = " << Fmt("%.2f", e_prime * 1e-9)
    << " GPa, p_H = " << Fmt("%.1f", h.max_pressure_pa * 1e-6)
    << " MPa, b = " << Fmt("%.1f", h.half_width_m * 1e6) << " um\n";
  for (const auto& [name, s] : {std::pair<const char*, double>{"A", 0.0}, {"E", path.length_m()}}) {
    const ContactPoint q = path.At(s);
    o << "  at " << name << ": R = " << mm(q.reduced_radius_m)
      << " mm, u1 = " << Fmt("%.4f", q.u1_m_s) << ", u2 = " << Fmt("%.4f", q.u2_m_s)
      << " m/s, SRR = " << Fmt("%.4f", q.srr) << "\n";
  }
}

void Stiffness(std::ostream& o, const internal::GearCase& c) {
  const GearPair& p = *c.pair;
  const PathOfContact path(p, c.operating.pinion_speed_rad_s);
  const double b_mm = p.spec().face_width_m * 1e3;
  auto per_width = [&](double k) { return Fmt("%.3f", k * 1e-6 / b_mm); };  // N/(mm um)
  o << "\nMesh stiffness per unit face width [N/(mm um)]:\n";
  char head[160];
  std::snprintf(head, sizeof head, "  %-18s %12s %12s %12s %12s\n", "method", "mean mesh",
                "min mesh", "max mesh", "pair max");
  o << head;
  for (const char* method : {"potential_energy", "kuang_yang"}) {
    std::shared_ptr<const PairStiffnessModel> owner;
    if (p.spec().helix_angle_rad > 0) {  // as the case reader refuses them (gear_case.cpp)
      o << "  " << method << ": not applicable: a spur-tooth model (helix_angle_deg = "
        << Fmt("%.4g", RadToDeg(p.spec().helix_angle_rad)) << "; iso below is for helical pairs)\n";
      continue;
    }
    try {
      const PairStiffnessFn k = internal::MakePairStiffness(p, method, &owner);
      const MeshStiffnessSummary m = SummarizeMeshStiffness(path, k);
      char buf[160];
      std::snprintf(buf, sizeof buf, "  %-18s %12s %12s %12s %12s\n", method,
                    per_width(m.mean_n_per_m).c_str(), per_width(m.min_n_per_m).c_str(),
                    per_width(m.max_n_per_m).c_str(), per_width(m.single_pair_max_n_per_m).c_str());
      o << buf;
    } catch (const InputError& e) {
      o << "  " << method << ": not applicable: " << WhyNot(e) << "\n";
    }
  }
  // Asymmetric teeth: the coast flanks' mesh (the pair seen from its coast side,
  // flank_phase.hpp), which carries the load when the wheel drives back (docs/dynamics.md,
  // "Back flanks").
  if (p.spec().coast_pressure_angle_rad != p.spec().drive_pressure_angle_rad &&
      p.spec().helix_angle_rad == 0 && c.mesh_stiffness != "iso") {
    try {
      const GearPair coast(CoastSideSpec(p.spec()));
      std::shared_ptr<const PairStiffnessModel> owner;
      const PairStiffnessFn k = internal::MakePairStiffness(coast, c.mesh_stiffness, &owner);
      const MeshStiffnessSummary m =
          SummarizeMeshStiffness(PathOfContact(coast, c.operating.pinion_speed_rad_s), k);
      char buf[200];
      std::snprintf(buf, sizeof buf,
                    "  %-18s %12s %12s %12s %12s  (%s, when the wheel drives back)\n",
                    "coast flanks", per_width(m.mean_n_per_m).c_str(),
                    per_width(m.min_n_per_m).c_str(), per_width(m.max_n_per_m).c_str(),
                    per_width(m.single_pair_max_n_per_m).c_str(), c.mesh_stiffness.c_str());
      o << buf;
    } catch (const InputError& e) {
      o << "  coast flanks: not applicable: " << WhyNot(e) << "\n";
    }
  }
  try {
    const IsoStiffness iso =
        IsoMethodB(PinionBlank(p), WheelBlank(p), p.line(Flank::kDrive).contact_ratio,
                   p.spec().helix_angle_rad);
    o << "  iso (6336-1 B)     c' = " << Fmt("%.3f", iso.c_prime_n_per_mm_um)
      << ", c_gamma_alpha = " << Fmt("%.3f", iso.c_gamma_alpha_n_per_mm_um) << "\n";
  } catch (const InputError& e) {
    o << "  iso: not applicable: " << WhyNot(e) << "\n";
  }
  o << "  load sharing: " << ToString(c.load_sharing)
    << (c.load_sharing != LoadSharing::kLinear ? " (" + c.mesh_stiffness + ")" : std::string())
    << "\n";
  if (c.load_sharing != LoadSharing::kLinear && c.pair_stiffness) {
    double lo = 1e300, hi = 0;
    for (const MeshCycleRow& row : internal::GearCaseCycle(c, 401)) {
      lo = std::min(lo, row.transmission_error_m);
      hi = std::max(hi, row.transmission_error_m);
    }
    o << "  static transmission error under F_bt: " << Fmt("%.3f", lo * 1e6) << " .. "
      << Fmt("%.3f", hi * 1e6) << " um (peak to peak " << Fmt("%.3f", (hi - lo) * 1e6) << " um)\n";
  }
  const TipRelief& r = c.tip_relief;
  if (r.Active()) {
    o << "  tip relief: pinion C_a = " << Fmt("%.2f", r.pinion_amount_m * 1e6) << " um over "
      << Fmt("%.3f", r.pinion_length_m * 1e3) << " mm before E (" << ToString(r.pinion_shape)
      << "), wheel C_a = " << Fmt("%.2f", r.wheel_amount_m * 1e6) << " um over "
      << Fmt("%.3f", r.wheel_length_m * 1e3) << " mm after A (" << ToString(r.wheel_shape) << ")\n";
    o << "  loaded part of the path (share >= 1 %): " << Fmt("%.3f", c.loaded_path.begin_m * 1e3)
      << " .. " << Fmt("%.3f", c.loaded_path.end_m * 1e3) << " mm; the pair stays loaded to A"
      << " below a wheel relief of " << Fmt("%.2f", c.relief_limit_a_m * 1e6)
      << " um, to E below a pinion relief of " << Fmt("%.2f", c.relief_limit_e_m * 1e6) << " um\n";
  }
}

// The solids of the flash temperature and the case's surface model.
struct FlashModel {
  ContactSolids solids;
  bool finite_peclet = false;  // effects.finite_peclet: Jaeger's kernel (docs/thermal.md)
};

// Blok's flash temperature rise of each row with friction coefficient mu (docs/thermal.md
// "Flash temperature"): the row's pair load w, its speeds and the Hertz half-width at w [K].
std::vector<double> FlashRises(const internal::GearCase& c,
                               const std::vector<MeshCycleRow>& rows,
                               const FlashModel& m,
                               double mu) {
  std::vector<double> out;
  const double e_prime = c.ReducedModulusPa();
  for (const MeshCycleRow& r : rows) {
    const ContactPoint& q = r.contact;
    out.push_back(
        r.load_n_per_m > 0
            ? FlashTemperature(
                  {mu, r.load_n_per_m, q.u1_m_s, q.u2_m_s,
                   LineContactHertz(r.load_n_per_m, q.reduced_radius_m, e_prime).half_width_m},
                  m.solids.body1, m.solids.body2, m.finite_peclet)
            : 0.0);
  }
  return out;
}

void Flash(std::ostream& o, const internal::GearCase& c, const FlashModel& m, double mu) {
  const std::vector<MeshCycleRow> rows = internal::GearCaseCycle(c, 401);
  const std::vector<double> rise = FlashRises(c, rows, m, mu);
  const size_t at = static_cast<size_t>(std::max_element(rise.begin(), rise.end()) - rise.begin());
  o << "\nFlash temperature (Blok" << (m.finite_peclet ? ", finite Peclet" : "")
    << ", mu = " << Fmt("%.4g", mu)
    << ", the load sharing's pair load, Hertz half-width at it):\n  largest rise "
    << Fmt("%.2f", rise[at]) << " K at s = " << Fmt("%.3f", rows[at].contact.s_m * 1e3)
    << " mm (SRR " << Fmt("%+.3f", rows[at].contact.srr) << "); at A " << Fmt("%.2f", rise.front())
    << " K, at E " << Fmt("%.2f", rise.back())
    << " K\n  a film's own surfaces can run up to twice as hot with the same mu (docs/thermal.md\n"
       "  \"Flash temperature\"); `tehl run` with thermal = true solves them\n";
}

void WriteCsv(const std::string& file,
              const internal::GearCase& c,
              int points,
              const FlashModel& m,
              std::optional<double> mu) {
  std::ostringstream out;  // written atomically once complete
  out << "s_m,t_s,rho1_m,rho2_m,R_m,u1_m_s,u2_m_s,um_m_s,SRR,v_slide_m_s,k_pair_n_per_m,"
         "k_mesh_n_per_m,share,w_n_per_m,r1_m,r2_m,pairs_in_contact,ste_m"
      << (mu ? ",dT_flash_blok_k" : "") << "\n";
  out.precision(10);
  const std::vector<MeshCycleRow> rows = internal::GearCaseCycle(c, points);
  const std::vector<double> rise = mu ? FlashRises(c, rows, m, *mu) : std::vector<double>();
  for (size_t i = 0; i < rows.size(); ++i) {
    const MeshCycleRow& r = rows[i];
    const ContactPoint& q = r.contact;
    out << q.s_m << ',' << q.time_s << ',' << q.rho1_m << ',' << q.rho2_m << ','
        << q.reduced_radius_m << ',' << q.u1_m_s << ',' << q.u2_m_s << ',' << q.um_m_s << ','
        << q.srr << ',' << q.sliding_m_s << ',' << r.pair_stiffness_n_per_m << ','
        << r.mesh_stiffness_n_per_m << ',' << r.share << ',' << r.load_n_per_m << ',' << q.r1_m
        << ',' << q.r2_m << ',' << q.pairs_in_contact << ',' << r.transmission_error_m;
    if (mu) out << ',' << rise[i];
    out << '\n';
  }
  internal::WriteTextAtomically(file, out.str());
}

void WriteProfile(const std::string& file, const GearPair& pair) {
  std::ostringstream out;  // written atomically once complete
  out << "gear,flank,x_m,y_m\n";
  out.precision(12);
  for (const ProfileCurve& curve : ToothProfile(pair))
    for (const ProfilePoint& p : curve.points)
      out << curve.gear << ',' << curve.flank << ',' << p.x_m << ',' << p.y_m << '\n';
  internal::WriteTextAtomically(file, out.str());
}

}  // namespace

Command AddGearCommand(CLI::App& app) {
  struct Args {
    std::string case_file, csv, profile;
    int points = 201;
    std::optional<double> mu;
  };
  auto args = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand(
      "gear",
      "Report the gear pair of a case: geometry, contact ratios, path of contact, "
      "load, Hertz scales, mesh stiffness");
  sub->add_option("CASE", args->case_file, "Case file with [gear] and [operating]")->required();
  sub->add_option("--csv", args->csv,
                  "Write the along-path table (s, t, rho1, rho2, R, u1, u2, um, SRR, sliding, "
                  "k_pair, k_mesh, share, w, r1, r2, pairs in contact; SI units in the header)");
  sub->add_option("--profile", args->profile, "Write tooth profile points (gear, flank, x_m, y_m)");
  sub->add_option("--points", args->points, "Samples from A to E in --csv (2 ... 100000)")
      ->check(CLI::Range(2, 100000));
  sub->add_option("--mu", args->mu,
                  "Friction coefficient for Blok's flash temperature along the path (printed; "
                  "with --csv also the column dT_flash_blok_k)")
      ->check(CLI::Range(0.0, 1.0));
  return {sub, [args]() {
            internal::Document doc = internal::ReadCaseDocument(args->case_file);
            std::optional<internal::GearCase> c = internal::ReadGearCase(doc);
            doc.ThrowIfProblems();
            std::ostringstream o;
            o << "tehl gear: " << args->case_file << "\n";
            Geometry(o, *c);
            Path(o, *c);
            Stiffness(o, *c);
            const FlashModel flash{internal::ReadContactSolids(doc),
                                   doc.Bool("effects", "finite_peclet")};
            if (args->mu) Flash(o, *c, flash, *args->mu);
            {
              // The lubricant's problems belong to `tehl run`; the report goes without them.
              internal::Document film_doc = internal::ReadCaseDocument(args->case_file);
              const internal::FilmCase film = internal::ReadFilmCase(film_doc);
              FilmEstimates(o, *c, film, CompositeWavinessRq(film_doc));
            }
            for (const auto& w : c->warnings) o << "warning: " << w.ToString() << "\n";
            std::cout << o.str();
            if (!args->csv.empty()) WriteCsv(args->csv, *c, args->points, flash, args->mu);
            if (!args->profile.empty()) WriteProfile(args->profile, *c->pair);
            return kExitOk;
          }};
}

}  // namespace tehl::cli
