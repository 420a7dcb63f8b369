// Surface shapes (roughness, waviness, measured profiles) that move with their surface.
//
// SIGN CONVENTION used everywhere in tehl's ehl layer:
//   h(x, t) = h0 + x^2/(2R) + v(x) - height1(x, t) - height2(x, t)
// where height_i is the height of surface i above its smooth form, measured along that
// surface's own normal INTO the film. A positive height (a bump, an asperity pointing into the
// film) of EITHER surface REDUCES the film.
// Mapping onto DESIGN.md section 4, h = h0 + x^2/(2R) + delta2 - delta1 + v, whose deltas are
// displacements along one common axis pointing from surface 1 to surface 2:
//   delta1 = +height1,   delta2 = -height2.
// Seed 004's waviness delta_i = A sin(2 pi (x - x_i0 - int u_i dt)/Lambda) is, for surface 1,
// SinusoidalWaviness{A, Lambda, -2 pi x_10 / Lambda}; for surface 2 use amplitude -A (or add
// pi to the phase) to keep DESIGN.md's sign.
//
// Motion: the contact frame follows the contact point; surface i travels through it at speed
// u_i. `travel_m` = integral of u_i dt since t = 0 [m]. The feature at contact-frame position x
// and travel d is the material point x - d of the surface: Height(x + d, d) = Height(x, 0).
//
// All shapes are immutable after construction; Height() is pure and thread-safe.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tehl {

class SurfaceShape {
 public:
  virtual ~SurfaceShape() = default;
  // Height of the surface above its smooth form at contact-frame position x_m after the surface
  // has travelled travel_m = int u_i dt [m] (see the sign convention above) [m].
  virtual double Height(double x_m, double travel_m) const = 0;
  virtual std::string Describe() const = 0;  // one line, for logs and result files
};

// out[i] = shape.Height(x_m[i], travel_m), i = 0..n-1 [m].
void SampleHeights(
    const SurfaceShape& shape, const double* x_m, int n, double travel_m, double* out_m);

// A smooth surface: height 0 everywhere.
class SmoothSurface final : public SurfaceShape {
 public:
  double Height(double, double) const override { return 0.0; }
  std::string Describe() const override;
};

// Sinusoidal waviness (DESIGN.md section 4, seed 004):
//   height(x, d) = A sin(2 pi (x - d) / Lambda + phase).
class SinusoidalWaviness final : public SurfaceShape {
 public:
  // amplitude_m: A, finite, any sign (a negative A flips the wave) [m];
  // wavelength_m: Lambda > 0 [m]; phase_rad: finite [rad]. Throws InputError otherwise.
  SinusoidalWaviness(double amplitude_m, double wavelength_m, double phase_rad = 0.0);
  double Height(double x_m, double travel_m) const override;
  std::string Describe() const override;

  double amplitude_m() const { return amplitude_m_; }
  double wavelength_m() const { return wavelength_m_; }
  double phase_rad() const { return phase_rad_; }

 private:
  double amplitude_m_;
  double wavelength_m_;
  double phase_rad_;
};

// The longest profile file read (a measured trace of a few million points) [bytes].
inline constexpr std::uintmax_t kMaxProfileFileBytes = 256u << 20;

// A measured profile: points (x_k, z_k), k = 0..m-1, x strictly increasing.
//  - Linear interpolation between points.
//  - Periodic continuation: the profile is taken as ONE PERIOD of the surface. The period is
//    L = (x_{m-1} - x_0) + (x_{m-1} - x_0)/(m - 1), i.e. the sampled length plus one mean
//    spacing; over that last spacing the height goes linearly from z_{m-1} back to z_0, so the
//    continued surface has no step where the copies join.
//  - Mean removed: the mean of that periodic piecewise-linear surface over one period (its
//    exact integral / L) is subtracted from every z_k, so the profile describes roughness
//    about the smooth form.
// The profile's x is a material coordinate: at travel d, contact-frame x sees profile x - d.
class MeasuredProfile final : public SurfaceShape {
 public:
  // Reads a text file of two columns per line, x [m] and height [m], separated by spaces,
  // tabs or a comma; '#' starts a comment; blank lines are ignored. Rules: at least 2 points,
  // x strictly increasing, every value a finite number, exactly two columns. Every violation
  // is reported in one InputError with the file and line.
  static MeasuredProfile ReadFile(const std::string& path);

  // From arrays (same rules; problems are reported against `source`, line 0).
  MeasuredProfile(std::vector<double> x_m,
                  std::vector<double> height_m,
                  std::string source = "<array>");

  double Height(double x_m, double travel_m) const override;
  std::string Describe() const override;

  int points() const { return static_cast<int>(x_m_.size()); }
  double period_m() const { return period_m_; }
  double removed_mean_m() const { return removed_mean_m_; }  // mean subtracted [m]
  double rms_m() const;  // root mean square of the periodic profile (after mean removal) [m]

 private:
  std::vector<double> x_m_;  // as given [m]
  std::vector<double> z_m_;  // heights with the mean removed [m]
  std::string source_;
  double period_m_ = 0;
  double removed_mean_m_ = 0;
};

}  // namespace tehl
