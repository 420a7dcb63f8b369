#!/usr/bin/env python3
"""Derives malformed case files from the shipped cases: tests/malformed/case/mutated_*.toml.

Each mutation takes one shipped case (cases/*.toml, comments and blank lines dropped so the
files stay short), breaks it in one way and writes it with the header line the corpus runner
(tests/unit/cli/malformed_input_test.cpp) checks:

    # ERROR <key> at line <n|->: <what is wrong>

`tehl case --check FILE` must exit with code 2 and print "FILE:<n>: <key>". The line numbers
count the header line. The kinds of mutation:

  missing_*     a required key or section deleted (reported at its section's line, or "-")
  type_*        wrong types: a string for a number, an array for a scalar, a float for an
                integer, a number for a string, a string for a boolean
  range_*       out-of-range values: negative radius, teeth or module, zero speed or load
  unit_*        unit slips: degrees Celsius for kelvin, millimetres for metres, radians for
                degrees, rpm in the rad/s key
  truncated_*   the file cut in the middle of a line (the line is the TOML parser's)
  binary_*      a few random bytes (fixed seed) written into a line
  duplicate_*   a key or a section written twice (the parser reports the second one)
  gear_*        impossible gear pairs: undercut pinion, centre distance too small, pointed
                teeth, tip inside the base circle, contact ratio below 1

Deterministic: the same shipped cases give the same files byte for byte (random bytes come
from random.Random with a fixed seed). Run from anywhere:

    python3 scripts/make_malformed.py           # (re)writes tests/malformed/case/mutated_*
    python3 scripts/make_malformed.py --check   # exit 1 if the committed files are stale

Old mutated_* files that the generator no longer makes are deleted.
"""
import argparse
import pathlib
import random
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
OUT = ROOT / "tests" / "malformed" / "case"


class Case:
    """A shipped case as a list of lines, without comments and blank lines."""

    def __init__(self, name):
        self.name = name
        self.lines = []
        for raw in (ROOT / "cases" / name).read_text().splitlines():
            line = raw.strip()
            if not line or line.startswith("#"):
                continue
            # Inline comments: the shipped cases have no '#' inside strings.
            line = re.sub(r"\s+#.*$", "", line)
            self.lines.append(line)

    def copy(self):
        c = Case.__new__(Case)
        c.name, c.lines = self.name, list(self.lines)
        return c

    def section(self, name):
        """Index of the line "[name]"."""
        return self.lines.index("[" + name + "]")

    def key(self, section, key):
        """Index of "key = ..." inside [section]."""
        i = self.section(section) + 1
        while i < len(self.lines) and not self.lines[i].startswith("["):
            if re.match(re.escape(key) + r"\s*=", self.lines[i]):
                return i
            i += 1
        raise KeyError(f"{self.name}: no {key} in [{section}]")

    def set(self, section, key, value):
        i = self.key(section, key)
        self.lines[i] = f"{key} = {value}"
        return i

    def add(self, section, key, value):
        """Appends key = value at the end of [section] (which must exist)."""
        i = self.section(section) + 1
        while i < len(self.lines) and not self.lines[i].startswith("["):
            i += 1
        self.lines.insert(i, f"{key} = {value}")
        return i

    def delete(self, section, key):
        del self.lines[self.key(section, key)]

    def delete_section(self, name):
        i = self.section(name)
        j = i + 1
        while j < len(self.lines) and not self.lines[j].startswith("["):
            j += 1
        del self.lines[i:j]


def line_of(index):
    """1-based line in the written file (the header is line 1)."""
    return index + 2


MUTATIONS = []


def mutation(name):
    def register(f):
        MUTATIONS.append((name, f))
        return f
    return register


G = "seed004_sae40.toml"   # gear case (35/105, m = 2 mm)
F = "fzg_c.toml"           # gear case with shifts, tip radii and centre distance
D = "disc_steady.toml"     # [contact] case
A = "asymmetric_35_20.toml"  # asymmetric teeth
R = "seed004_sae40_tip_relief.toml"  # tip relief on both gears


# --- Deleted keys and sections ------------------------------------------------------------
def missing(base, section, key):
    def f():
        c = Case(base)
        c.delete(section, key)
        return c, f"{section}.{key}", line_of(c.section(section)), \
            f"required key {key} deleted from [{section}] (reported at the section line)"
    return f


mutation("missing_module")(missing(G, "gear", "module_m"))
mutation("missing_face_width")(missing(F, "gear", "face_width_m"))
mutation("missing_pinion_teeth")(missing(G, "gear.pinion", "teeth"))
mutation("missing_wheel_teeth")(missing(F, "gear.wheel", "teeth"))
mutation("missing_lubricant_name")(missing(G, "lubricant", "name"))
mutation("missing_contact_radius")(missing(D, "contact", "radius_1_m"))
mutation("missing_contact_load")(missing(D, "contact", "load_n_per_m"))


@mutation("missing_speed")
def _():
    c = Case(G)
    c.delete("operating", "pinion_speed_rpm")
    return c, "operating.pinion_speed_rpm", line_of(c.section("operating")), \
        "no pinion speed in [operating] (reported at the section line)"


@mutation("missing_torque")
def _():
    c = Case(F)
    c.delete("operating", "pinion_torque_nm")
    return c, "operating.power_w", line_of(c.section("operating")), \
        "no load in [operating]: neither power_w nor pinion_torque_nm"


@mutation("missing_lubricant_section")
def _():
    c = Case(D)
    c.delete_section("lubricant")
    return c, "[lubricant]", None, "the required [lubricant] section deleted (no line)"


@mutation("missing_wheel_section")
def _():
    c = Case(G)
    c.delete_section("gear.wheel")
    return c, "[gear.wheel]", None, "a gear case without [gear.wheel] (no line)"


# --- Wrong types --------------------------------------------------------------------------
def wrong(base, section, key, value, what):
    def f():
        c = Case(base)
        return c, f"{section}.{key}", line_of(c.set(section, key, value)), what
    return f


mutation("type_string_module")(wrong(G, "gear", "module_m", '"0.002"', "module as a string"))
mutation("type_string_teeth")(wrong(F, "gear.pinion", "teeth", '"16"', "teeth as a string"))
mutation("type_array_power")(wrong(G, "operating", "power_w", "[10000.0]",
                                   "an array where one number is expected"))
mutation("type_array_teeth")(wrong(A, "gear.wheel", "teeth", "[105, 106]",
                                   "an array of teeth where one integer is expected"))
mutation("type_float_grid")(wrong(D, "numerics", "grid_points", "513.0",
                                  "grid_points written as a float"))
mutation("type_number_lubricant")(wrong(G, "lubricant", "name", "40",
                                        "a number where the lubricant name is expected"))
mutation("type_string_bool")(wrong(G, "effects", "thermal", '"false"',
                                   "a string where a boolean is expected"))
mutation("type_table_speed")(wrong(D, "contact", "speed_1_m_s", "{ value = 1.0 }",
                                   "an inline table where a number is expected"))
mutation("type_bool_pressure_angle")(wrong(F, "gear", "pressure_angle_deg", "true",
                                           "a boolean where an angle is expected"))
mutation("type_date_speed")(wrong(F, "operating", "pinion_speed_rpm", "2024-01-01",
                                  "a date where a speed is expected"))

# --- Out of range -------------------------------------------------------------------------
mutation("range_negative_radius")(wrong(D, "contact", "radius_2_m", "-0.02",
                                        "negative radius of body 2"))
mutation("range_negative_teeth")(wrong(G, "gear.pinion", "teeth", "-35", "negative teeth"))
mutation("range_zero_teeth")(wrong(F, "gear.wheel", "teeth", "0", "zero teeth"))
mutation("range_negative_module")(wrong(F, "gear", "module_m", "-0.0045", "negative module"))
mutation("range_zero_speed")(wrong(G, "operating", "pinion_speed_rpm", "0.0",
                                   "zero pinion speed"))
mutation("range_zero_load")(wrong(D, "contact", "load_n_per_m", "0.0", "zero load"))
mutation("range_zero_face_width")(wrong(A, "gear", "face_width_m", "0.0", "zero face width"))
mutation("range_negative_power")(wrong(G, "operating", "power_w", "-10000.0",
                                       "negative power"))
mutation("range_poisson")(wrong(G, "gear.wheel", "poisson_ratio", "0.5",
                                "Poisson's ratio 0.5 (incompressible: E' undefined)"))
mutation("range_speed_of_light")(wrong(D, "contact", "speed_1_m_s", "3e8",
                                       "a surface speed of 3e8 m/s"))
mutation("range_inf_module")(wrong(G, "gear", "module_m", "inf", "an infinite module"))
mutation("range_huge_grid")(wrong(D, "numerics", "grid_points", "2147483649",
                                  "more grid points than an int holds"))
mutation("range_even_grid")(wrong(G, "numerics", "grid_points", "512",
                                  "an even number of grid points (no node at x = 0)"))
mutation("range_power_beyond_hertz")(wrong(G, "operating", "power_w", "1.0e12",
                                           "a power 1e8 times the case's: Hertz b beyond 0.2 R"))

# --- Unit slips ---------------------------------------------------------------------------
mutation("unit_celsius_inlet")(wrong(G, "lubricant", "inlet_temperature_k", "40.0",
                                     "inlet temperature in degrees Celsius (40) for 313.15 K"))
mutation("unit_module_mm")(wrong(G, "gear", "module_m", "2.0",
                                 "module in millimetres (2) for metres (0.002)"))
mutation("unit_face_width_mm")(wrong(F, "gear", "face_width_m", "14.0",
                                     "face width in millimetres (14) for metres (0.014)"))
mutation("unit_pressure_angle_rad")(wrong(F, "gear", "pressure_angle_deg", "0.349",
                                          "pressure angle in radians for degrees"))
mutation("unit_modulus_gpa")(wrong(G, "gear.pinion", "youngs_modulus_pa", "117.0",
                                   "Young's modulus in GPa (117) for Pa (117e9)"))
mutation("unit_density_g_cm3")(wrong(G, "gear.pinion", "density_kg_m3", "7.85",
                                     "solid density in g/cm^3 (7.85) for kg/m^3 (7850)"))
mutation("unit_conductivity_w_mmk")(wrong(G, "gear.pinion", "conductivity_w_mk", "0.046",
                                          "conductivity in W/(mm K) (0.046) for W/(m K) (46)"))
mutation("unit_heat_capacity_kj")(wrong(G, "gear.wheel", "heat_capacity_j_kgk", "0.47",
                                        "heat capacity in kJ/(kg K) (0.47) for J/(kg K) (470)"))
mutation("unit_center_distance_mm")(wrong(F, "gear", "center_distance_m", "91.5",
                                          "centre distance in millimetres (91.5) for metres"))
# Not in the corpus, because no rule rejects it: [contact] radius_1_m = 20.0 (mm for m) is a
# valid 20 m disc: large bearing races are metres in radius, so no upper bound separates a
# slip from a real contact.


# --- Truncated files ----------------------------------------------------------------------
def truncated(base, section, key, keep, what):
    """Cuts the file after the first `keep` characters of a line (no newline at the end)."""
    def f():
        c = Case(base)
        i = c.key(section, key) if key else c.section(section)
        c.lines = c.lines[:i + 1]
        c.lines[i] = c.lines[i][:keep]
        c.no_final_newline = True
        return c, "(syntax)", line_of(i), what
    return f


mutation("truncated_in_string")(truncated(G, "lubricant", "name", len('name = "sa'),
                                          "cut inside the lubricant name string"))
mutation("truncated_after_equals")(truncated(F, "gear", "module_m", len("module_m ="),
                                             "cut right after the = of module_m"))
mutation("truncated_in_header")(truncated(G, "gear.wheel", None, len("[gear.wh"),
                                          "cut inside the [gear.wheel] header"))
mutation("truncated_in_key")(truncated(D, "contact", "load_n_per_m", len("load_n_p"),
                                       "cut inside the key load_n_per_m"))


# --- Binary garbage -----------------------------------------------------------------------
def garbage(base, section, key, seed, nul, what):
    """Replaces the value of a line with random bytes (fixed seed); with or without NUL."""
    def f():
        c = Case(base)
        i = c.key(section, key)
        rng = random.Random(seed)
        data = bytes(rng.randrange(1, 256) for _ in range(12))
        if nul:
            data = data[:5] + b"\x00" + data[6:]
        else:
            # Bytes that cannot start a TOML value (no quote, digit, sign, bracket, letter).
            data = bytes(b if b >= 0x80 else 0x80 | b for b in data)
        c.raw = {i: key.encode() + b" = " + data}
        return c, "(file)" if nul else "(syntax)", line_of(i), what
    return f


mutation("binary_nul_in_value")(garbage(G, "gear", "face_width_m", 4004, True,
                                        "random bytes with a NUL written as a value"))
mutation("binary_high_bytes")(garbage(D, "contact", "speed_2_m_s", 2024, False,
                                      "random non-ASCII bytes written as a value"))


# --- Duplicates ---------------------------------------------------------------------------
@mutation("duplicate_teeth")
def _():
    c = Case(G)
    i = c.add("gear.pinion", "teeth", "36")
    return c, "(syntax)", line_of(i), "teeth given twice in [gear.pinion]"


@mutation("duplicate_lubricant_name")
def _():
    c = Case(D)
    i = c.add("lubricant", "name", '"sae90"')
    return c, "(syntax)", line_of(i), "the lubricant name given twice"


@mutation("duplicate_operating_section")
def _():
    c = Case(F)
    c.lines += ["[operating]", "pinion_speed_rpm = 1000.0"]
    return c, "(syntax)", line_of(len(c.lines) - 2), "the table [operating] defined twice"


@mutation("duplicate_gear_section")
def _():
    c = Case(A)
    c.lines += ["[gear]", "module_m = 0.003"]
    return c, "(syntax)", line_of(len(c.lines) - 2), "the table [gear] defined twice"


# --- Impossible gear pairs ----------------------------------------------------------------
@mutation("gear_undercut_pinion")
def _():
    c = Case(G)
    c.set("gear.pinion", "teeth", "10")
    return c, "gear.pinion.profile_shift", line_of(c.section("gear.pinion")), \
        "10 teeth without profile shift: undercut (reported at [gear.pinion])"


@mutation("gear_center_distance_too_small")
def _():
    c = Case(F)
    return c, "gear.center_distance_m", line_of(c.set("gear", "center_distance_m", "0.08")), \
        "centre distance 80 mm below the sum of the base radii (~84.6 mm)"


@mutation("gear_teeth_overlap")
def _():
    c = Case(F)
    return c, "gear.center_distance_m", line_of(c.set("gear", "center_distance_m", "0.0905")), \
        "centre distance 90.5 mm, below the zero-backlash distance of the shifts: teeth overlap"


@mutation("gear_pointed_tip")
def _():
    c = Case(F)
    return c, "gear.pinion.tip_radius_m", line_of(c.set("gear.pinion", "tip_radius_m", "0.047")), \
        "pinion tip radius 47 mm, beyond where its flanks meet: pointed tooth"


@mutation("gear_tip_inside_base")
def _():
    c = Case(F)
    return c, "gear.wheel.tip_radius_m", line_of(c.set("gear.wheel", "tip_radius_m", "0.05")), \
        "wheel tip radius 50 mm inside its base circle (50.7 mm)"


@mutation("gear_contact_ratio_below_one")
def _():
    c = Case(G)
    c.add("gear", "addendum_coefficient", "0.5")
    return c, "gear.addendum_coefficient", line_of(c.key("gear", "addendum_coefficient")), \
        "half-height teeth (addendum 0.5 m): the contact ratio drops below 1 (reported at " \
        "the short addendum)"


@mutation("gear_tip_relief_without_length")
def _():
    c = Case(G)
    c.add("gear.pinion", "tip_relief_m", "10e-6")
    return c, "gear.pinion.tip_relief_length_m", line_of(c.section("gear.pinion")), \
        "a tip relief amount without its length along the line of action (reported at " \
        "[gear.pinion])"


@mutation("gear_tip_relief_longer_than_path")
def _():
    c = Case(G)
    c.add("gear.wheel", "tip_relief_m", "10e-6")
    return c, "gear.wheel.tip_relief_length_m", \
        line_of(c.add("gear.wheel", "tip_relief_length_m", "0.02")), \
        "a 20 mm tip relief on a 10.46 mm path of contact"


mutation("unit_tip_relief_um")(wrong(R, "gear.pinion", "tip_relief_m", "13.0",
                                     "tip relief in micrometres (13) for metres (13e-6)"))


# --- Writing ------------------------------------------------------------------------------
def render(name, f):
    c, key, line, what = f()
    header = f"# ERROR {key} at line {'-' if line is None else line}: {what} " \
             f"(mutation of cases/{c.name})"
    raw = getattr(c, "raw", {})
    body = [raw.get(i, l.encode()) for i, l in enumerate(c.lines)]
    data = b"\n".join([header.encode()] + body)
    if not getattr(c, "no_final_newline", False):
        data += b"\n"
    return OUT / f"mutated_{name}.toml", data


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--check", action="store_true",
                    help="exit 1 if a committed file differs from what would be written")
    args = ap.parse_args()
    names = [n for n, _ in MUTATIONS]
    assert len(names) == len(set(names)), "duplicate mutation name"
    files = dict(render(n, f) for n, f in MUTATIONS)
    stale = [p for p in OUT.glob("mutated_*.toml") if p not in files]
    if args.check:
        bad = [p for p, d in files.items() if not p.exists() or p.read_bytes() != d] + stale
        for p in bad:
            print(f"stale: {p.relative_to(ROOT)}", file=sys.stderr)
        return 1 if bad else 0
    for p in stale:
        p.unlink()
    for p, d in files.items():
        p.write_bytes(d)
    print(f"make_malformed: {len(files)} files in {OUT.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
