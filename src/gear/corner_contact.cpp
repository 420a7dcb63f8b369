#include "tehl/gear/corner_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "tehl/error.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {

struct Vec {
  double x = 0, y = 0;
};
Vec Rotate(Vec v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

// Roll length u of the involute of base circle rb through q (centre at the origin, tangent
// point at +y, line of action in +x; the header's formula), and the radius of the point of
// the involute u0 on the same normal.
double RollLength(Vec q, double rb) {
  const double r = std::hypot(q.x, q.y);
  return std::sqrt(std::max(0.0, r * r - rb * rb)) -
         rb * (std::atan2(q.y, q.x) + std::acos(std::min(1.0, rb / r)) - 0.5 * kPi);
}
double FootRadius(Vec q, double rb, double gap) {
  const double r = std::hypot(q.x, q.y);
  const double l = std::sqrt(std::max(0.0, r * r - rb * rb)) - gap;
  return std::hypot(rb, l);
}

}  // namespace

CornerContact::CornerContact(const GearPair& pair, Flank flank, double max_gap_m) {
  if (!(max_gap_m > 0)) throw std::invalid_argument("CornerContact: max_gap_m must be > 0");
  const LineOfAction& l = pair.line(flank);
  rb1_ = l.pinion_base_radius_m;
  rb2_ = l.wheel_base_radius_m;
  tangent_ = l.tangent_length_m;
  rho_a_ = l.a_m;
  length_ = l.length_m;
  internal_ = pair.spec().internal;
  form1_ = pair.pinion().flank(flank).form_radius_m;
  form2_ = internal_ ? 0.0 : pair.wheel().flank(flank).form_radius_m;
  before_m_ = Extent(true, max_gap_m);
  after_m_ = Extent(false, max_gap_m);
}

// Frame: pinion centre O1 at the origin, T1 = (0, r_b1), the line of action y = r_b1 with s
// growing in +x (x = rho_A + s). The pinion turns clockwise; an external wheel (centre
// (T1T2, r_b1 + r_b2)) counter-clockwise, a ring (centre (-T1T2, r_b1 - r_b2)) clockwise.
double CornerContact::GapBeforeA(double s, double* foot) const {
  const Vec o2 = internal_ ? Vec{-tangent_, rb1_ - rb2_} : Vec{tangent_, rb1_ + rb2_};
  const Vec a{rho_a_ - o2.x, rb1_ - o2.y};
  const Vec r = Rotate(a, (internal_ ? -1.0 : 1.0) * s / rb2_);
  const Vec corner{o2.x + r.x, o2.y + r.y};
  const double gap = RollLength(corner, rb1_) - (rho_a_ + s);
  *foot = FootRadius(corner, rb1_, gap);
  return gap;
}

double CornerContact::GapAfterE(double s, double* foot) const {
  const Vec corner = Rotate({rho_a_ + length_, rb1_}, -(s - length_) / rb1_);
  // The wheel's involutes in its own frame: tangent point at +y, roll length growing in +x.
  // External: turned by pi about O2 (its roll length runs from T2 towards T1, in -x); ring:
  // as it is (from T2 behind T1, in +x).
  double x_wheel = 0;
  Vec q;
  if (internal_) {
    q = {corner.x + tangent_, corner.y - (rb1_ - rb2_)};
    x_wheel = -tangent_ + RollLength(q, rb2_);
  } else {
    q = Rotate({corner.x - tangent_, corner.y - (rb1_ + rb2_)}, kPi);
    x_wheel = tangent_ - RollLength(q, rb2_);
  }
  const double gap = (rho_a_ + s) - x_wheel;
  *foot = FootRadius(q, rb2_, gap);
  return gap;
}

double CornerContact::Extent(bool before, double max_gap) const {
  // The separation grows about quadratically away from the end; march out in steps of a
  // thousandth of the path and bisect the first step that leaves the allowed set.
  auto inside = [&](double d) {
    double foot = 0;
    const double gap = before ? GapBeforeA(-d, &foot) : GapAfterE(length_ + d, &foot);
    const double form = before ? form1_ : form2_;
    return std::isfinite(gap) && gap >= 0 && gap <= max_gap && foot >= form;
  };
  const double h = 1e-3 * length_;
  double lo = 0;
  for (int i = 1; i <= 5000 && inside(i * h); ++i) lo = i * h;
  double hi = lo + h;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (inside(mid) ? lo : hi) = mid;
  }
  return lo;
}

double CornerContact::GapAt(double s) const {
  double foot = 0;
  if (s < 0)
    return -s <= before_m_ ? GapBeforeA(s, &foot) : std::numeric_limits<double>::infinity();
  if (s > length_)
    return s - length_ <= after_m_ ? GapAfterE(s, &foot) : std::numeric_limits<double>::infinity();
  return 0.0;
}

}  // namespace tehl
