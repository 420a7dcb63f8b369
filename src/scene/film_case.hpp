// The film side of a case: lubricant, effects, numerics and surfaces read from a case
// Document into the ehl solver's inputs. Shared by the [contact] scene and, later, the
// mesh cycle. Private to src/.
#pragma once

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "base/schema.hpp"
#include "tehl/ehl/film_effects.hpp"
#include "tehl/ehl/grid.hpp"
#include "tehl/ehl/line_contact_solver.hpp"
#include "tehl/ehl/surface_roughness.hpp"
#include "tehl/lubricant/lubricant.hpp"

namespace tehl::internal {

struct FilmCase {
  std::shared_ptr<const Lubricant> lubricant;     // empty if it could not be read
  double inlet_temperature_k = 0;                 // T0 of the run [K]
  FilmEffects effects;
  LineContactSolver::Options options;
  int grid_points = 0;                            // [-] 0 = automatic (automatic_grid.hpp)
  double x_start_b = -4.5, x_end_b = 1.5;         // grid ends in GridUnits lengths [-]
  std::shared_ptr<const SurfaceShape> surface1, surface2;  // null = smooth
  ContactSolids solids;                           // thermal properties of the two bodies
  // [numerics] failed_step = "steady_restart": a failed time step is replaced by the steady
  // film at its time (step_restart.hpp); false: the run stops at it.
  bool steady_restart = true;
  // failed_step = "steady_restart_or_skip": a step whose steady film fails too is left failed
  // and the run goes on from the last converged film (step_restart.hpp).
  bool skip_failed = false;
};

// The lubricant at the inlet state (p = 0, T0); deta_dp = 0 when the film is not
// piezoviscous (effects.piezoviscous = false), as the solver then takes eta(0, T).
ViscosityValue InletViscosity(const FilmCase& film);

// The lengths [numerics] x_start_b (inlet) and x_end_b (outlet) are measured in, for a contact
// of reduced radius R, entrainment speed um and load w whose Hertz half-width is b [m].
// Elastic solids: b for both. Rigid solids (effects.elastic = false) form no Hertz zone; their
// film builds up over the Martin length l = sqrt(2 R h0), h0 = 4.896 eta0 um R / w
// (VALIDATION.md section 2): the default inlet (-4.5) then lies 40 l upstream, where Martin's
// load integral is within 0.1 % of its limit, and the default outlet (1.5) 2 l downstream,
// beyond the film rupture at 0.475 l.
struct GridUnits {
  double inlet_m = 0, outlet_m = 0;
  GridUnits Max(const GridUnits& o) const {
    return {std::max(inlet_m, o.inlet_m), std::max(outlet_m, o.outlet_m)};
  }
};
inline constexpr double kRigidInletUnit = 40.0 / 4.5;   // inlet unit / l [-]
inline constexpr double kRigidOutletUnit = 2.0 / 1.5;   // outlet unit / l [-]
// Elastic films whose Martin film is not small against b^2/R (light loads, Moes' M ~ 1 or
// below) are nearly rigid: with `isoviscous_inlet` their inlet unit grows to the rigid one
// weighted by that ratio (IsoviscousInletLength, include/tehl/ehl/inlet_truncation.hpp), so
// that the default inlet reaches where such a film builds its pressure.
GridUnits GridUnitsFor(const FilmCase& film,
                       double b_m,
                       double r_m,
                       double um_m_s,
                       double w_n_per_m,
                       bool isoviscous_inlet = true);

// Martin's rigid isoviscous film h = 4.896 eta0 um R / w (VALIDATION.md section 2) bounds
// the film from below (elasticity and piezoviscosity only thicken it); Reynolds' equation is
// a thin-film theory (h / l =
// sqrt(h / 2R) << 1 over the film's length l = sqrt(2 R h)), so a load whose Martin film
// exceeds kMaxFilmToRadius R is reported at its key (a load of 1e-100 N/m otherwise gives an
// infinite film) [-].
inline constexpr double kMartinFilm = 4.896;
inline constexpr double kMaxFilmToRadius = 1e-2;

// The smallest [numerics] time_tolerance other than 0 [-].
inline constexpr double kMinTimeTolerance = 1e-7;

// The inlet viscosities a case accepts (those of the lubricant files: Roelands' eta_inf
// 6.31e-5 Pa s, and 1e4 Pa s) [Pa s].
inline constexpr double kMinInletViscosityPaS = 6.31e-5;
inline constexpr double kMaxInletViscosityPaS = 1e4;

// Sinusoidal waviness shorter than two cells of the film grid (dx [m]) is not represented on
// it at all (Nyquist): reported at the surface's wavelength_m.
void CheckRoughnessResolution(Document& doc, const FilmCase& film, double dx_m);

// Cells per wavelength from which the thinnest film of sinusoidal waviness is within about
// 1.5 % of the grid-converged one (docs/studies.md, "Roughness grid": min h_min moves by 15 %
// on doubling from 3.7 cells, 3.9-4.6 % from 7.4, 1.2-1.6 % from 15); the note allows 14.9
// (a 25 um wave on 513 nodes of the seed 004 grid) and asks for 15.
inline constexpr double kWaveCellsResolved = 15.0;
inline constexpr double kWaveCellsNote = 14.0;

// "" when every sinusoidal waviness spans at least kWaveCellsNote cells of the grid
// (nodes, spacing dx [m]); else a note naming the shortest wave, its cells and the
// grid_points (2^k + 1, the same x range) that give it kWaveCellsResolved.
std::string RoughnessResolutionNote(const FilmCase& film, double dx_m, int nodes);

// A sinusoidal waviness longer than this many times the film grid's span is, across the
// contact, an offset and a tilt of at most 2 pi A / kLongWaveSpans over the grid, which the film
// takes up by its approach: no roughness. Such a wavelength is most often micrometres written
// in metres (wavelength_m = 50.0 for 50 um) [-].
inline constexpr double kLongWaveSpans = 10.0;

// One note per sinusoidal waviness longer than kLongWaveSpans grid spans (the grid of `nodes`
// nodes at spacing dx [m]).
std::vector<std::string> LongWavinessNotes(const FilmCase& film, double dx_m, int nodes);

// An inlet temperature more than this from the lubricant file's reference temperature takes
// the exponential (roelands_gamma, barus) temperature laws beyond where their one gamma
// describes a real oil (lubricants/sae40.toml: 7.2 instead of 12.5-16.3 mPa s at 100 C) [K].
inline constexpr double kGammaLawNoteK = 30.0;

// The notes on the inputs a run prints before its results (and `case --check` with its
// plan): RoughnessResolutionNote, LongWavinessNotes, and an inlet far from an exponential
// law's T0.
std::vector<std::string> InputNotes(const FilmCase& film, double dx_m, int nodes);

// Reads [lubricant], [effects], [numerics] and [surfaces]; problems go into `doc`.
// Effects this version cannot simulate yet are problems at their key, never ignored.
FilmCase ReadFilmCase(Document& doc);

// Thermal properties of the two bodies: [gear.pinion] / [gear.wheel] or [contact] (keys with
// _1 / _2); the defaults of the schema where not given.
ContactSolids ReadContactSolids(const Document& doc);

}  // namespace tehl::internal
