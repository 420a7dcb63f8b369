#include "tehl/gear/undercut.hpp"

#include <algorithm>
#include <cmath>

#include "tehl/gear/involute.hpp"

namespace tehl {
namespace {

struct Vec {
  double u, y;
};
Vec Rotate(Vec p, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {c * p.u - s * p.y, s * p.u + c * p.y};
}

// The gear's frame at rotation 0: centre at the origin, pitch point P0 = (0, r) on the rolling
// line y = r. The rack flank that generates this involute passes through P0 at alpha from the
// normal, the rack tooth lying at u < (y - r) tan(alpha); its tip line is h_fP m_n below the
// reference line y = r + x m_n, and the corner between tip and flank is a circle of radius
// rho about C. As the gear turns by phi the rack moves by r phi (rolling), and C traces the
// trochoid G(phi) = Rot(-phi) (C - (r phi, 0)) in the gear's frame; the corner circle sweeps
// the envelope G +- rho n (n the trochoid's unit normal), which cuts the involute of an
// undercut gear where it crosses it.
class CornerPath {
 public:
  explicit CornerPath(const RackCut& c)
      : r_(c.pitch_radius_m),
        rb_(c.pitch_radius_m * std::cos(c.pressure_angle_rad)),
        inv_alpha_(Involute(c.pressure_angle_rad)),
        rho_(c.root_fillet_coefficient * c.module_m) {
    const double alpha = c.pressure_angle_rad;
    const double y_tip = r_ + (c.profile_shift - c.dedendum_coefficient) * c.module_m;
    corner_ = {(y_tip + rho_ - r_) * std::tan(alpha) - rho_ / std::cos(alpha), y_tip + rho_};
  }

  // A point of the envelope at phi, on side +1 or -1 of the trochoid.
  Vec Envelope(double phi, int side) const {
    const Vec g = Trochoid(phi);
    const double h = 1e-6;
    const Vec a = Trochoid(phi - h), b = Trochoid(phi + h);
    const double tu = b.u - a.u, ty = b.y - a.y, len = std::hypot(tu, ty);
    return {g.u - side * rho_ * ty / len, g.y + side * rho_ * tu / len};
  }

  // Polar angle of p (from the +y axis toward +x) less the involute's at |p|: the involute
  // through P0 has theta(R) = inv(acos(r_b / R)) - inv(alpha). NaN below the base circle.
  double AngleToInvolute(Vec p) const {
    const double radius = std::hypot(p.u, p.y);
    if (!(radius > rb_)) return std::nan("");
    return std::atan2(p.u, p.y) - (Involute(std::acos(rb_ / radius)) - inv_alpha_);
  }

  double r() const { return r_; }
  double rb() const { return rb_; }

 private:
  Vec Trochoid(double phi) const { return Rotate({corner_.u - r_ * phi, corner_.y}, -phi); }

  double r_, rb_, inv_alpha_, rho_;
  Vec corner_;
};

}  // namespace

double UndercutRollLength(const RackCut& c) {
  const double sin_t = std::sin(c.pressure_angle_rad);
  const double alpha_n =
      c.normal_pressure_angle_rad > 0 ? c.normal_pressure_angle_rad : c.pressure_angle_rad;
  const double h0 = c.dedendum_coefficient - c.root_fillet_coefficient * (1.0 - std::sin(alpha_n));
  // Not undercut: the straight flank ends at or before T (ISO 21771 form circle q >= 0); the
  // corner's envelope then meets the involute tangentially at the form circle.
  if (c.pitch_radius_m * sin_t - (h0 - c.profile_shift) * c.module_m / sin_t >= 0) return 0.0;
  const CornerPath path(c);
  // The outermost crossing of the envelope with the involute between r_b and r: scan the
  // gear's turn while the corner is within some tip heights of the pitch point (+-0.6 rad, or
  // six modules of rack travel on small gears), then bisect each sign change.
  const double span = std::max(0.6, 6.0 * c.module_m / c.pitch_radius_m);
  const int n = 20000;
  double outermost = path.rb();
  for (int side : {-1, 1}) {
    const auto f = [&](double phi) { return path.AngleToInvolute(path.Envelope(phi, side)); };
    // A crossing between a and b (f of opposite signs): bisect it, keep its radius.
    const auto crossing = [&](double a, double b, double f_a) {
      for (int it = 0; it < 80; ++it) {
        const double mid = 0.5 * (a + b), f_mid = f(mid);
        if (std::isfinite(f_mid) && (f_mid > 0) == (f_a > 0))
          a = mid, f_a = f_mid;
        else
          b = mid;
      }
      const Vec e = path.Envelope(0.5 * (a + b), side);
      const double radius = std::hypot(e.u, e.y);
      // A sign change far off the involute's angle is the branch cut of atan2, not the flank.
      if (radius < path.r() && std::abs(path.AngleToInvolute(e)) < 1e-6)
        outermost = std::max(outermost, radius);
    };
    // Sign changes of f on [a, b] sampled in `steps`.
    const auto scan = [&](double a, double b, int steps, auto&& self, bool fine) -> void {
      double prev_phi = a, prev = f(a);
      for (int k = 1; k <= steps; ++k) {
        const double phi = a + (b - a) * k / steps, value = f(phi);
        if (std::isfinite(value) && std::isfinite(prev) && (value > 0) != (prev > 0))
          crossing(prev_phi, phi, prev);
        // Where the envelope dips below the base circle f is undefined: a slightly undercut
        // flank's crossing lies within a step of that edge, so look closer there.
        else if (!fine && std::isfinite(value) != std::isfinite(prev))
          self(prev_phi, phi, 2000, self, true);
        prev = value, prev_phi = phi;
      }
    };
    scan(-span, span, n, scan, false);
  }
  return std::sqrt(std::max(0.0, outermost * outermost - path.rb() * path.rb()));
}

}  // namespace tehl
