#include "tehl/ehl/surface_roughness.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "base/number_text.hpp"
#include "tehl/error.hpp"
#include "tehl/units.hpp"

namespace tehl {

namespace {

std::string Num(double v) {
  std::ostringstream s;
  s.precision(12);
  s << v;
  return s.str();
}

// Strict number: the whole token must parse and be finite.
bool ParseFinite(const std::string& token, double* out) { return internal::ParseReal(token, out); }

// The rules of a profile given as arrays (ReadFile checks the same rules line by line).
void CheckPoints(const std::vector<double>& x,
                 const std::vector<double>& z,
                 const std::string& source,
                 ProblemList* problems) {
  if (x.size() != z.size()) {
    problems->Add({source, 0, "height", std::to_string(z.size()) + " values",
                   "must have as many values as x (" + std::to_string(x.size()) + ")",
                   "one height per x"});
    return;
  }
  for (size_t k = 0; k < x.size(); ++k) {
    if (!std::isfinite(x[k])) {
      problems->Add(
          {source, 0, "x", Num(x[k]), "must be a finite number [m]", "a position in metres"});
    }
    if (!std::isfinite(z[k])) {
      problems->Add(
          {source, 0, "height", Num(z[k]), "must be a finite number [m]", "a height in metres"});
    }
    if (k > 0 && !(x[k] > x[k - 1])) {
      problems->Add({source, 0, "x", Num(x[k]),
                     "must be > the previous x = " + Num(x[k - 1]) + " [m]",
                     "strictly increasing positions"});
    }
  }
  if (x.size() < 2) {
    problems->Add({source, 0, "points", std::to_string(x.size()),
                   "a profile needs at least 2 points", "two or more (x, height) rows"});
  }
}

}  // namespace

void SampleHeights(
    const SurfaceShape& shape, const double* x_m, int n, double travel_m, double* out_m) {
  for (int i = 0; i < n; ++i) out_m[i] = shape.Height(x_m[i], travel_m);
}

std::string SmoothSurface::Describe() const { return "smooth surface (height 0)"; }

SinusoidalWaviness::SinusoidalWaviness(double amplitude_m, double wavelength_m, double phase_rad)
    : amplitude_m_(amplitude_m), wavelength_m_(wavelength_m), phase_rad_(phase_rad) {
  ProblemList problems;
  if (!std::isfinite(amplitude_m)) {
    problems.Add({"", 0, "SinusoidalWaviness::amplitude_m", Num(amplitude_m), "must be finite [m]",
                  "an amplitude in metres"});
  }
  if (!(wavelength_m > 0) || !std::isfinite(wavelength_m)) {
    problems.Add({"", 0, "SinusoidalWaviness::wavelength_m", Num(wavelength_m), "must be > 0 [m]",
                  "a positive wavelength in metres"});
  }
  if (!std::isfinite(phase_rad)) {
    problems.Add({"", 0, "SinusoidalWaviness::phase_rad", Num(phase_rad), "must be finite [rad]",
                  "a phase in radians"});
  }
  problems.ThrowIfAny();
}

double SinusoidalWaviness::Height(double x_m, double travel_m) const {
  return amplitude_m_ * std::sin(2.0 * kPi * (x_m - travel_m) / wavelength_m_ + phase_rad_);
}

std::string SinusoidalWaviness::Describe() const {
  return "sinusoidal waviness A = " + Num(amplitude_m_) + " m, wavelength = " + Num(wavelength_m_) +
         " m, phase = " + Num(phase_rad_) + " rad";
}

MeasuredProfile MeasuredProfile::ReadFile(const std::string& path) {
  // Only a regular file of sensible size: a device such as /dev/zero would be read forever.
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  const bool regular = std::filesystem::is_regular_file(status);
  const auto bytes = regular ? std::filesystem::file_size(path, ec) : 0;
  if (regular && !ec && bytes > kMaxProfileFileBytes)
    throw InputError(InputProblem{
        path, 0, "file", path, "is " + std::to_string(bytes) + " bytes long",
        "a profile file of at most " + std::to_string(kMaxProfileFileBytes) + " bytes"});
  std::ifstream in;
  if (regular && !ec) in.open(path);
  if (!in.is_open() || !in) {
    throw InputError(InputProblem{
        path, 0, "file", path,
        std::filesystem::exists(status) && !regular ? "is not a regular file" : "cannot be opened",
        "a readable two-column text file (x [m], height [m])"});
  }
  ProblemList problems;
  std::vector<double> x, z;
  std::string text;
  int line = 0;
  while (std::getline(in, text)) {
    ++line;
    const auto hash = text.find('#');
    if (hash != std::string::npos) text.erase(hash);
    for (char& c : text) {
      if (c == ',' || c == '\t' || c == '\r') c = ' ';
    }
    std::istringstream fields(text);
    std::vector<std::string> tokens;
    for (std::string t; fields >> t;) tokens.push_back(t);
    if (tokens.empty()) continue;
    if (tokens.size() != 2) {
      problems.Add({path, line, "row", text, "has " + std::to_string(tokens.size()) + " columns",
                    "exactly two columns: x [m] and height [m]"});
      continue;
    }
    double xv = 0, zv = 0;
    const bool x_ok = ParseFinite(tokens[0], &xv);
    const bool z_ok = ParseFinite(tokens[1], &zv);
    if (!x_ok) {
      problems.Add({path, line, "x", tokens[0], "is not a finite number [m]",
                    "a position in metres, e.g. 1.5e-4"});
    }
    if (!z_ok) {
      problems.Add({path, line, "height", tokens[1], "is not a finite number [m]",
                    "a height in metres, e.g. -2.0e-7"});
    }
    if (x_ok && z_ok) {
      if (!x.empty() && !(xv > x.back())) {
        problems.Add({path, line, "x", tokens[0],
                      "must be > the previous x = " + Num(x.back()) + " [m]",
                      "strictly increasing positions"});
        continue;
      }
      x.push_back(xv);
      z.push_back(zv);
    }
  }
  if (x.size() < 2) {
    problems.Add({path, line, "points", std::to_string(x.size()),
                  "a profile needs at least 2 valid points", "two or more (x, height) rows"});
  }
  problems.ThrowIfAny();
  return MeasuredProfile(std::move(x), std::move(z), path);
}

MeasuredProfile::MeasuredProfile(std::vector<double> x_m,
                                 std::vector<double> height_m,
                                 std::string source)
    : x_m_(std::move(x_m)), z_m_(std::move(height_m)), source_(std::move(source)) {
  ProblemList problems;
  CheckPoints(x_m_, z_m_, source_, &problems);
  problems.ThrowIfAny();
  const size_t m = x_m_.size();
  const double length = x_m_.back() - x_m_.front();
  const double closing = length / static_cast<double>(m - 1);  // last point -> next period
  period_m_ = length + closing;
  // Exact integral of the periodic piecewise-linear surface over one period (trapezoids,
  // including the closing segment from z_{m-1} to z_0).
  double integral = 0.5 * closing * (z_m_.back() + z_m_.front());
  for (size_t k = 1; k < m; ++k)
    integral += 0.5 * (x_m_[k] - x_m_[k - 1]) * (z_m_[k] + z_m_[k - 1]);
  removed_mean_m_ = integral / period_m_;
  for (double& z : z_m_) z -= removed_mean_m_;
}

double MeasuredProfile::Height(double x_m, double travel_m) const {
  // Material coordinate s in [0, L) from the first point.
  double s = x_m - travel_m - x_m_.front();
  s -= period_m_ * std::floor(s / period_m_);
  const double length = x_m_.back() - x_m_.front();
  if (s >= length) {  // closing segment back to the first point of the next period
    const double t = (s - length) / (period_m_ - length);
    return z_m_.back() + t * (z_m_.front() - z_m_.back());
  }
  const double xs = x_m_.front() + s;
  // Last k with x_k <= xs (binary search; x is strictly increasing).
  size_t lo = 0, hi = x_m_.size() - 1;
  while (hi - lo > 1) {
    const size_t mid = (lo + hi) / 2;
    if (x_m_[mid] <= xs)
      lo = mid;
    else
      hi = mid;
  }
  const double t = (xs - x_m_[lo]) / (x_m_[hi] - x_m_[lo]);
  return z_m_[lo] + t * (z_m_[hi] - z_m_[lo]);
}

double MeasuredProfile::rms_m() const {
  // Exact mean square of a linear segment from a to b: (a^2 + a b + b^2) / 3.
  auto seg = [](double dx, double a, double b) { return dx * (a * a + a * b + b * b) / 3.0; };
  const double length = x_m_.back() - x_m_.front();
  double sum = seg(period_m_ - length, z_m_.back(), z_m_.front());
  for (size_t k = 1; k < x_m_.size(); ++k) sum += seg(x_m_[k] - x_m_[k - 1], z_m_[k - 1], z_m_[k]);
  return std::sqrt(sum / period_m_);
}

std::string MeasuredProfile::Describe() const {
  return "measured profile '" + source_ + "' (" + std::to_string(x_m_.size()) + " points, period " +
         Num(period_m_) + " m, mean removed " + Num(removed_mean_m_) + " m, rms " + Num(rms_m()) +
         " m)";
}

}  // namespace tehl
