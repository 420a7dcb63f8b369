#include "tehl/drive/dynamic_response.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "tehl/units.hpp"

namespace tehl {

std::vector<std::string> DynamicResponseOptions::Validate() const {
  std::vector<std::string> bad;
  auto rule = [&](bool ok, const char* field, double value, const char* constraint) {
    if (ok) return;
    std::ostringstream m;
    m << "DynamicResponseOptions::" << field << " = " << value << " violates " << constraint;
    bad.push_back(m.str());
  };
  rule(relative_tolerance > 0 && relative_tolerance <= 1e-3, "relative_tolerance",
       relative_tolerance, "in (0, 1e-3]");
  rule(periodic_tolerance > 0 && periodic_tolerance < 1, "periodic_tolerance", periodic_tolerance,
       "in (0, 1)");
  rule(min_periods >= 2, "min_periods", min_periods, ">= 2");
  rule(max_periods >= min_periods, "max_periods", max_periods, ">= min_periods");
  rule(output_samples >= 8, "output_samples", output_samples, ">= 8");
  rule(peak_samples_per_step >= 1, "peak_samples_per_step", peak_samples_per_step, ">= 1");
  rule(divergence_factor > 1, "divergence_factor", divergence_factor, "> 1");
  const bool finite = std::all_of(initial_state.begin(), initial_state.end(),
                                  [](double v) { return std::isfinite(v); });
  rule(initial_state.empty() || (initial_state.size() == 2 && finite), "initial_state size",
       static_cast<double>(initial_state.size()), "0, or 2 finite values (x [m], x' [m/s])");
  return bad;
}

DynamicSample DynamicResponse::SampleAt(double phase, bool left) const {
  DynamicSample s;
  if (steps.empty() || !model) return s;
  const double pb = model->mesh().base_pitch_m();
  if (left && phase <= 0) phase = pb;  // periodic: the end of the period
  const double t = period_start_s + phase / contact_speed_m_s;
  auto it = std::upper_bound(steps.begin(), steps.end(), t,
                             [](double v, const Step& st) { return v < st.dense.t0_s; });
  size_t i = it == steps.begin() ? 0 : static_cast<size_t>(it - steps.begin()) - 1;
  if (left && i > 0 && t <= steps[i].dense.t0_s) --i;
  if (!left && t >= steps[i].dense.t_end_s && i + 1 < steps.size()) ++i;
  // At a segment end the times of the two sides may differ by rounding: choose by segment.
  const TorsionalMesh& mesh = model->mesh();
  int want = mesh.SegmentAt(std::min(phase, pb * (1 - 1e-15)));
  if (left) {
    for (int k = 0; k < static_cast<int>(mesh.segments().size()); ++k)
      if (phase > mesh.segments()[k].begin_m && phase <= mesh.segments()[k].end_m) want = k;
  }
  if (steps[i].segment != want) {
    if (i > 0 && steps[i - 1].segment == want)
      --i;
    else if (i + 1 < steps.size() && steps[i + 1].segment == want)
      ++i;
  }
  const Step& st = steps[i];
  const double tc = std::clamp(t, st.dense.t0_s, st.dense.t_end_s);
  double y[2];
  st.dense.Evaluate(tc, y);
  const MeshSegment& seg = model->mesh().segments()[st.segment];
  const double ph = std::clamp(phase, seg.begin_m, seg.end_m);
  s.phase_m = phase;
  s.time_s = t - period_start_s;
  s.x_m = y[0];
  s.v_m_s = y[1];
  s.state = st.state;
  s.force_n = model->ContactForce(st.state, st.segment, st.back_segment, ph, y[0], y[1]);
  s.stiffness_n_per_m = model->mesh().MeshStiffness(st.segment, ph);
  return s;
}

double DynamicResponse::ForceAt(double phase, bool left) const {
  return SampleAt(phase, left).force_n;
}

DynamicResponse SolvePeriodicResponse(TorsionalModel& model, const DynamicResponseOptions& o) {
  DynamicResponse r;
  const TorsionalMesh& mesh = model.mesh();
  r.pinion_speed_rad_s = model.parameters().pinion_speed_rad_s;
  r.mesh_frequency_hz = model.mesh_frequency_hz();
  r.natural_frequency_hz = model.natural_frequency_hz();
  r.mesh_period_s = model.mesh_period_s();
  r.static_force_n = model.static_force_n();
  r.contact_speed_m_s = model.contact_speed_m_s();
  r.model = &model;
  std::vector<std::string> bad = o.Validate();
  for (const auto& b : model.parameters().Validate()) bad.push_back(b);
  if (!bad.empty()) {
    r.message = bad.front();
    return r;
  }
  const double pb = mesh.base_pitch_m(), cs = model.contact_speed_m_s();
  const double x_s = r.static_force_n / mesh.mean_stiffness_n_per_m();
  const double wn = 2.0 * kPi * r.natural_frequency_hz;
  IntegratorOptions io;
  io.relative_tolerance = o.relative_tolerance;
  io.absolute_tolerance = {o.relative_tolerance * x_s, o.relative_tolerance * wn * x_s};
  io.max_step_s = 0.25 * r.mesh_period_s;
  DormandPrince54 dp(io);

  std::vector<double> y = {r.static_force_n / mesh.MeshStiffness(0, 0.0), 0.0};
  if (o.initial_state.size() == 2) y = o.initial_state;
  model.Reset(0.0, y[0], y[1]);
  std::vector<DynamicResponse::Step> current;
  const StepObserver observer = [&](const DenseStep& d) {
    current.push_back({d, model.state(), model.segment(),
                       model.state() == ContactState::kBackFlank && model.mesh().back_flanks()
                           ? model.back_segment()
                           : -1});
    return true;
  };
  std::vector<double> size;  // |(x / x_s, x' / (w_n x_s))| at each period's end
  long n = 0;
  for (; n < o.max_periods; ++n) {
    current.clear();
    model.ClearEvents();
    const std::vector<double> y_prev = y;
    const IntegratorSummary s = dp.Integrate(model, n * pb / cs, (n + 1) * pb / cs, &y, observer);
    r.integrator.Add(s);
    r.integrator.termination = s.termination;
    r.integrator.message = s.message;
    r.periods = static_cast<int>(n + 1);
    if (!s.usable()) {
      r.message = "integrator: " + s.message;
      return r;
    }
    r.end_x_m = y[0];
    r.end_v_m_s = y[1];
    size.push_back(std::hypot(y[0] / x_s, y[1] / (wn * x_s)));
    r.periodicity_error =
        std::max(std::abs(y[0] - y_prev[0]) / x_s, std::abs(y[1] - y_prev[1]) / (wn * x_s));
    if (r.periods >= o.min_periods && r.periodicity_error <= o.periodic_tolerance) {
      r.periodic = true;
      break;
    }
    if (std::abs(y[0]) > o.divergence_factor * x_s ||
        std::abs(y[1]) > o.divergence_factor * wn * x_s) {
      r.diverged = true;
      break;
    }
  }
  if (n == o.max_periods) n = o.max_periods - 1;
  // Out of periods and still growing: the largest size of the last quarter of the periods is
  // over twice that of the second quarter, and beyond 10 static deflections (a bounded
  // response that is not periodic, sub-harmonic or chaotic, keeps its size).
  double grew_from = 0, grew_to = 0;
  if (!r.periodic && !r.diverged && size.size() >= 8) {
    const size_t q = size.size() / 4;
    grew_from = *std::max_element(size.begin() + q, size.begin() + 2 * q);
    grew_to = *std::max_element(size.end() - q, size.end());
    r.diverged = grew_to > 2.0 * grew_from && grew_to > 10.0;
  }
  r.message = r.periodic
                  ? "periodic after " + std::to_string(r.periods) + " mesh periods"
                  : "not periodic in one mesh period after " + std::to_string(r.periods) +
                        " periods (relative change " + std::to_string(r.periodicity_error) + ")";
  if (r.diverged) {
    char buf[480];
    if (grew_to > 0)
      std::snprintf(buf, sizeof buf,
                    "the response grows without bound: still growing after %d mesh periods "
                    "(its size rose from %.3g to %.3g static deflections over the last half; "
                    "the mesh's stiffness variation pumps it: parametric instability; corner "
                    "contact or more damping bound it)",
                    r.periods, grew_from, grew_to);
    else
      std::snprintf(buf, sizeof buf,
                    "the response grows without bound: |x| = %.3g and |x'| / w_n = %.3g static "
                    "deflections after %d mesh periods (the mesh's stiffness variation pumps "
                    "it: parametric instability; corner contact or more damping bound it)",
                    std::abs(y[0]) / x_s, std::abs(y[1]) / (wn * x_s), r.periods);
    r.message = buf;
  }
  r.steps = std::move(current);
  r.period_start_s = n * pb / cs;

  // Extremes and time fractions over the periodic period.
  r.peak_force_n = -1e300;
  r.min_force_n = 1e300;
  double separated = 0, back = 0;
  double yv[2];
  for (const auto& st : r.steps) {
    const MeshSegment& seg = mesh.segments()[st.segment];
    const double dt = st.dense.t_end_s - st.dense.t0_s;
    if (st.state == ContactState::kSeparated) separated += dt;
    if (st.state == ContactState::kBackFlank) back += dt;
    for (int k = 0; k <= o.peak_samples_per_step; ++k) {
      const double t = st.dense.t0_s + dt * k / o.peak_samples_per_step;
      st.dense.Evaluate(t, yv);
      const double ph = std::clamp(cs * t - n * pb, seg.begin_m, seg.end_m);
      const double f = model.ContactForce(st.state, st.segment, st.back_segment, ph, yv[0], yv[1]);
      r.peak_force_n = std::max(r.peak_force_n, f);
      r.min_force_n = std::min(r.min_force_n, f);
    }
  }
  r.separated_fraction = separated / r.mesh_period_s;
  r.back_flank_fraction = back / r.mesh_period_s;
  r.dynamic_load_factor = r.peak_force_n / r.static_force_n;
  for (const auto& e : model.events())
    if (e.from == ContactState::kDriveFlank)
      r.contact_loss_times_s.push_back(e.t_s - r.period_start_s);

  for (int k = 0; k < o.output_samples; ++k)
    r.samples.push_back(r.SampleAt(pb * k / o.output_samples, false));
  for (const MeshSegment& seg : mesh.segments()) {
    r.samples.push_back(r.SampleAt(seg.end_m, true));
    if (seg.end_m < pb) r.samples.push_back(r.SampleAt(seg.end_m, false));
  }
  r.samples.push_back(r.SampleAt(pb, true));
  std::stable_sort(
      r.samples.begin(), r.samples.end(),
      [](const DynamicSample& a, const DynamicSample& b) { return a.phase_m < b.phase_m; });
  return r;
}

std::vector<PairLoadPoint> TrackedPairLoad(const DynamicResponse& r, double b, int points) {
  std::vector<PairLoadPoint> out;
  if (!r.model || points < 2) return out;
  const TorsionalMesh& mesh = r.model->mesh();
  const double g = mesh.length_m(), pb = mesh.base_pitch_m();
  std::vector<std::pair<double, bool>> at;  // (s, left)
  for (int i = 0; i < points; ++i) at.push_back({g * i / (points - 1), i > 0});
  for (double sw : {g - pb, pb})  // B and D
    if (sw > 0 && sw < g) {
      at.push_back({sw, true});
      at.push_back({sw, false});
    }
  std::stable_sort(at.begin(), at.end(), [](const auto& a, const auto& c) {
    return a.first < c.first || (a.first == c.first && a.second && !c.second);
  });
  for (const auto& [s, left] : at) {
    PairLoadPoint p;
    p.s_m = s;
    double phase = s - std::floor(s / pb) * pb;
    if (left && phase < 1e-9 * pb && s > 0) phase = pb;
    if (!mesh.gapped()) {
      p.share = mesh.ShareAt(s, left);
      p.static_n_per_m = r.static_force_n * p.share / b;
      p.dynamic_n_per_m = r.ForceAt(phase, left) * p.share / b;
    } else {  // relief or corner contact: the shares follow the approach, static at
              // F_static, dynamic at x(t) (as DynamicLoad::LoadFactorAt)
      p.share = mesh.ShareAt(s, left, mesh.StaticApproachAt(s, left, r.static_force_n));
      const DynamicSample d = r.SampleAt(phase, left);
      p.static_n_per_m = r.static_force_n * p.share / b;
      p.dynamic_n_per_m = d.force_n * mesh.ShareAt(s, left, d.x_m) / b;
    }
    out.push_back(p);
  }
  return out;
}

}  // namespace tehl
