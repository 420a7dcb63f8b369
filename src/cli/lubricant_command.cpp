// tehl lubricant NAME [--p start:stop:count] [--T start:stop:count] [--csv FILE]
// tehl lubricant --print-default
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "base/schema.hpp"
#include "cli/commands.hpp"
#include "cli/number_format.hpp"
#include "io/atomic_file.hpp"
#include "lubricant/lubricant_schema.hpp"
#include "scene/case_reader.hpp"
#include "tehl/error.hpp"
#include "tehl/lubricant/barus_viscosity.hpp"
#include "tehl/lubricant/constant_viscosity.hpp"
#include "tehl/lubricant/lubricant.hpp"
#include "tehl/lubricant/roelands_gamma_viscosity.hpp"
#include "tehl/lubricant/roelands_viscosity.hpp"

namespace tehl::cli {
namespace {

struct Range {
  double start = 0, stop = 0;
  int count = 0;
  std::vector<double> Values() const {
    std::vector<double> v;
    for (int i = 0; i < count; ++i)
      v.push_back(count == 1 ? start : start + (stop - start) * i / (count - 1));
    return v;
  }
};

bool ParseNumber(const std::string& s, double* x) { return internal::ParseReal(s, x); }

// "start:stop:count" or a single value; min/max bound every value (in the option's unit).
Range ParseRange(const std::string& option,
                 const std::string& text,
                 double min,
                 double max,
                 const std::string& allowed,
                 ProblemList* problems) {
  auto bad = [&](const std::string& rule) {
    problems->Add({"", 0, option, "\"" + text + "\"", rule, allowed});
    return Range{};
  };
  std::vector<std::string> parts;
  size_t from = 0;
  for (size_t colon; (colon = text.find(':', from)) != std::string::npos; from = colon + 1)
    parts.push_back(text.substr(from, colon - from));
  parts.push_back(text.substr(from));
  Range r;
  if (parts.size() == 1) {
    if (!ParseNumber(parts[0], &r.start)) return bad("not a number");
    r.stop = r.start;
    r.count = 1;
  } else if (parts.size() == 3) {
    double count = 0;
    if (!ParseNumber(parts[0], &r.start) || !ParseNumber(parts[1], &r.stop))
      return bad("start and stop must be finite numbers");
    if (!ParseNumber(parts[2], &count) || count != std::floor(count) || count < 1 || count > 10000)
      return bad("count must be an integer from 1 to 10000");
    r.count = static_cast<int>(count);
    if (r.count == 1 && r.start != r.stop)
      return bad("a range of one value needs start = stop (or give one number)");
  } else {
    return bad("not a range start:stop:count");
  }
  if (r.start < min || r.stop < min || r.start > max || r.stop > max) {
    std::string rule = "out of range: every value must be in [" + internal::FormatReal(min) + ", " +
                       internal::FormatReal(max) + "]";
    if (option == "--T" && std::min(r.start, r.stop) < min)
      rule += " (did you give degrees Celsius?)";
    return bad(rule);
  }
  return r;
}

// The pressure-viscosity coefficient of the dimensionless groups, named by where it comes
// from (docs/case_format.md, "Lubricant files"): Houpert's alpha at T0 for the Roelands laws,
// the law's own alpha for Barus, none for a constant viscosity.
std::string AlphaLine(const ViscosityModel& law, double t0_k) {
  const double alpha_per_gpa = law.PressureViscosityCoefficient() * 1e9;
  char line[160];
  if (dynamic_cast<const RoelandsViscosity*>(&law) ||
      dynamic_cast<const RoelandsGammaViscosity*>(&law))
    std::snprintf(line, sizeof line,
                  "Houpert pressure-viscosity coefficient alpha = Z (ln eta0 + 9.67) / 1.96e8 Pa "
                  "= %.5g 1/GPa (at T0 = %.2f K)",
                  alpha_per_gpa, t0_k);
  else if (dynamic_cast<const BarusViscosity*>(&law))
    std::snprintf(line, sizeof line, "Barus pressure-viscosity coefficient alpha = %.5g 1/GPa",
                  alpha_per_gpa);
  else if (dynamic_cast<const ConstantViscosity*>(&law))
    std::snprintf(line, sizeof line,
                  "pressure-viscosity coefficient alpha = 0 1/GPa (constant viscosity)");
  else
    std::snprintf(line, sizeof line, "pressure-viscosity coefficient alpha = %.5g 1/GPa",
                  alpha_per_gpa);
  return line;
}

}  // namespace

Command AddLubricantCommand(CLI::App& app) {
  struct Args {
    std::string name, p = "0:1e9:11", T, csv;
    bool print_default = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand(
      "lubricant", "Print a lubricant's laws and a table of its properties over p and T");
  sub->add_option("name", args->name,
                  "Lubricant: sae40, sae90, reference_z068, or a path to a lubricant .toml file");
  sub->add_option("--p", args->p, "Pressures start:stop:count [Pa] (default 0:1e9:11)");
  sub->add_option("--T", args->T,
                  "Temperatures start:stop:count [K] (default T0:T0+80:5, T0 of the lubricant)");
  sub->add_option("--csv", args->csv, "Also write the table as CSV (SI units) to this file");
  sub->add_flag("--print-default", args->print_default,
                "Print every key of a lubricant file with its unit and meaning");
  return {
      sub, [args]() {
        if (args->print_default) {
          std::cout << internal::LubricantSchema().PrintDefaults();
          if (args->name.empty()) return kExitOk;
        }
        if (args->name.empty())
          throw InputError(InputProblem{"", 0, "NAME", "", "no lubricant given",
                                        "sae40, sae90, reference_z068, or a path to a "
                                        "lubricant .toml file; or --print-default"});
        const std::string path = internal::ResolveLubricantPath(args->name, "");
        if (path.empty())
          throw InputError(InputProblem{"", 0, "NAME", "\"" + args->name + "\"",
                                        "no such lubricant file",
                                        internal::LubricantSearchText("")});
        const Lubricant lube = Lubricant::FromFile(path);
        const double t0 = lube.reference_temperature_k();
        ProblemList problems;
        const Range p = ParseRange("--p", args->p, 0.0, 1e10,
                                   "start:stop:count with pressures in [0, 1e10] Pa, "
                                   "e.g. --p 0:1e9:11",
                                   &problems);
        const std::string t_text =
            args->T.empty() ? Fmt("%.10g", t0) + ":" + Fmt("%.10g", t0 + 80) + ":5" : args->T;
        const Range T = ParseRange("--T", t_text, 200.0, 1000.0,
                                   "start:stop:count with absolute temperatures in "
                                   "[200, 1000] K, e.g. --T 313:393:5",
                                   &problems);
        problems.ThrowIfAny();
        // The table, written atomically once complete (a rejected input leaves no file).
        const bool with_csv = !args->csv.empty();
        std::ostringstream csv;
        // A law may leave the range of doubles inside the allowed pressures (Barus' exp(alpha
        // p) above about 700 / alpha): such a table is refused, not printed as inf and NaN.
        for (double t : T.Values())
          for (double pp : p.Values()) {
            const ViscosityValue eta = lube.viscosity().Evaluate(pp, t);
            if (std::isfinite(eta.eta_pa_s) && std::isfinite(eta.deta_dp) && eta.eta_pa_s > 0)
              continue;
            char what[200];
            std::snprintf(what, sizeof what,
                          "the viscosity law gives eta = %g Pa s at p = %g Pa, T = %g K: "
                          "beyond the range of numbers",
                          eta.eta_pa_s, pp, t);
            // At p = 0 it is the temperature that leaves the law's range.
            if (pp == 0.0)
              throw InputError(InputProblem{"", 0, "--T", "\"" + t_text + "\"", what,
                                            "temperatures where the law is finite"});
            throw InputError(InputProblem{"", 0, "--p", "\"" + args->p + "\"", what,
                                          "pressures below that, where the law is finite"});
          }

        std::cout << lube.Describe() << "  file: " << path << "\n\n";
        // nu = eta / rho in mm^2/s (cSt), the unit of oil data sheets.
        std::printf("%10s %9s %14s %13s %13s %12s %16s\n", "p [MPa]", "T [K]", "eta [Pa s]",
                    "nu [mm^2/s]", "rho [kg/m^3]", "k [W/(m K)]", "dln(eta)/dp");
        std::printf("%10s %9s %14s %13s %13s %12s %16s\n", "", "", "", "(cSt)", "", "", "[1/GPa]");
        if (with_csv) csv << "p_pa,T_k,eta_pa_s,rho_kg_m3,k_w_mk,dln_eta_dp_per_pa,nu_m2_s\n";
        for (double t : T.Values()) {
          for (double pp : p.Values()) {
            const ViscosityValue eta = lube.viscosity().Evaluate(pp, t);
            const DensityValue rho = lube.density().Evaluate(pp, t);
            const ConductivityValue k = lube.conductivity().Evaluate(pp);
            const double alpha_loc = eta.deta_dp / eta.eta_pa_s;  // [1/Pa]
            const double nu = eta.eta_pa_s / rho.rho_kg_m3;       // [m^2/s]
            std::printf("%10.2f %9.2f %14.5e %13.5g %13.3f %12.5f %16.4f\n", pp * 1e-6, t,
                        eta.eta_pa_s, nu * 1e6, rho.rho_kg_m3, k.k_w_mk, alpha_loc * 1e9);
            if (with_csv)
              csv << internal::FormatReal(pp) << ',' << internal::FormatReal(t) << ','
                  << internal::FormatReal(eta.eta_pa_s) << ','
                  << internal::FormatReal(rho.rho_kg_m3) << ',' << internal::FormatReal(k.k_w_mk)
                  << ',' << internal::FormatReal(alpha_loc) << ',' << internal::FormatReal(nu)
                  << '\n';
          }
        }
        if (with_csv) internal::WriteTextAtomically(args->csv, csv.str());
        std::printf("\n%s\n", AlphaLine(lube.viscosity(), t0).c_str());
        std::fflush(stdout);
        return kExitOk;
      }};
}

}  // namespace tehl::cli
