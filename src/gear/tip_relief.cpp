#include "tehl/gear/tip_relief.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace tehl {
namespace {

double Shape(ReliefShape shape, double x) {
  x = std::clamp(x, 0.0, 1.0);
  return shape == ReliefShape::kParabolic ? x * x : x;
}

struct Pair {
  double s, k, gap;
};

double Approach(const std::vector<Pair>& pairs, double force) {
  std::vector<double> k, gap;
  for (const Pair& p : pairs) {
    k.push_back(p.k);
    gap.push_back(p.gap);
  }
  return CommonApproach(k, gap, force);
}

// The pairs in contact when the tracked pair is at s, s itself among them; with `corner`
// also the pairs beyond A and E within its extension (their stiffness that of the pair at the
// nearer end, their separation the corner's plus the relief at that tip).
std::vector<Pair> PairsAt(const PathOfContact& path,
                          double s,
                          const PairStiffnessFn& k,
                          const TipRelief& relief,
                          const CornerContact* corner) {
  std::vector<Pair> pairs;
  bool found = false;
  const double g = path.length_m();
  for (double q : path.SimultaneousContacts(s)) {
    const ContactPoint c = path.At(q);
    pairs.push_back({q, k(c.r1_m, c.r2_m), relief.GapAt(q, g)});
    if (q == s) found = true;
  }
  if (!found) {  // s off the path (beyond the round-off guard of A and E)
    const ContactPoint c = path.At(s);
    pairs.push_back({s, k(c.r1_m, c.r2_m), relief.GapAt(s, g)});
  }
  if (corner) {
    const double pb = path.base_pitch_m();
    const double lo = -corner->before_m(), hi = g + corner->after_m();
    for (int j = static_cast<int>(std::ceil((lo - s) / pb)); s + j * pb <= hi; ++j) {
      const double q = s + j * pb;
      if (j == 0 || (q >= 0 && q <= g)) continue;  // the tracked pair and those on the path
      const double end = std::clamp(q, 0.0, g);
      const ContactPoint c = path.At(end);
      pairs.push_back({q, k(c.r1_m, c.r2_m), corner->GapAt(q) + relief.GapAt(end, g)});
    }
  }
  return pairs;
}

}  // namespace

double CommonApproach(const std::vector<double>& k, const std::vector<double>& gap, double force) {
  // Start from every pair loaded and drop the pairs whose gap the approach does not close;
  // each drop lowers delta, so a dropped pair never comes back and the loop ends after at
  // most one pass per pair.
  std::vector<bool> active(k.size(), true);
  double delta = std::numeric_limits<double>::infinity();
  for (size_t pass = 0; pass <= k.size(); ++pass) {
    double ksum = 0, kgap = 0;
    for (size_t j = 0; j < k.size(); ++j)
      if (active[j]) {
        ksum += k[j];
        kgap += k[j] * gap[j];
      }
    if (!(ksum > 0)) return std::numeric_limits<double>::infinity();
    delta = (force + kgap) / ksum;
    bool dropped = false;
    for (size_t j = 0; j < k.size(); ++j)
      if (active[j] && gap[j] >= delta) {
        active[j] = false;
        dropped = true;
      }
    if (!dropped) break;
  }
  return delta;
}

std::string ToString(ReliefShape shape) {
  return shape == ReliefShape::kParabolic ? "parabolic" : "linear";
}

std::optional<ReliefShape> ReliefShapeFromString(const std::string& name) {
  if (name == "linear") return ReliefShape::kLinear;
  if (name == "parabolic") return ReliefShape::kParabolic;
  return std::nullopt;
}

double TipRelief::GapAt(double s, double g) const {
  double e = 0;
  if (wheel_amount_m > 0 && wheel_length_m > 0 && s < wheel_length_m)
    e += wheel_amount_m * Shape(wheel_shape, (wheel_length_m - s) / wheel_length_m);
  if (pinion_amount_m > 0 && pinion_length_m > 0 && s > g - pinion_length_m)
    e += pinion_amount_m * Shape(pinion_shape, (s - (g - pinion_length_m)) / pinion_length_m);
  return e;
}

RelievedShare RelievedLoadShare(const PathOfContact& path,
                                double s,
                                const PairStiffnessFn& k,
                                const TipRelief& relief,
                                double force,
                                const CornerContact* corner) {
  const std::vector<Pair> pairs = PairsAt(path, s, k, relief, corner);
  RelievedShare out;
  out.approach_m = Approach(pairs, force);
  for (const Pair& p : pairs)
    if (p.s == s) {
      out.share = std::max(0.0, p.k * (out.approach_m - p.gap)) / force;
      break;
    }
  return out;
}

double ApproachWithoutPair(const PathOfContact& path,
                           double s,
                           const PairStiffnessFn& k,
                           const TipRelief& relief,
                           double force,
                           const CornerContact* corner) {
  std::vector<Pair> pairs = PairsAt(path, s, k, relief, corner);
  pairs.erase(std::remove_if(pairs.begin(), pairs.end(), [s](const Pair& p) { return p.s == s; }),
              pairs.end());
  return pairs.empty() ? std::numeric_limits<double>::infinity() : Approach(pairs, force);
}

LoadedPath LoadedPathOf(const PathOfContact& path,
                        const PairStiffnessFn& k,
                        const TipRelief& relief,
                        double force,
                        double min_share,
                        const CornerContact* corner) {
  const double g = path.length_m();
  if (!relief.Active()) return {0.0, g};
  auto loaded = [&](double s) {
    return RelievedLoadShare(path, s, k, relief, force, corner).share >= min_share;
  };
  const int n = 400;
  std::vector<bool> on(n + 1);
  for (int i = 0; i <= n; ++i) on[i] = loaded(g * i / n);
  int first = 0, last = n;
  while (first <= n && !on[first]) ++first;
  while (last >= 0 && !on[last]) --last;
  if (first > last) return {g, 0.0};
  for (int i = first; i <= last; ++i)
    if (!on[i]) return {g, 0.0};  // lifted off between the ends
  // The share rises through min_share between samples first - 1 and first (and falls between
  // last and last + 1); bisect on the one-sided loaded test.
  auto bisect = [&](double off, double on_s) {
    for (int it = 0; it < 60 && std::abs(on_s - off) > 1e-9 * g; ++it) {
      const double mid = 0.5 * (off + on_s);
      (loaded(mid) ? on_s : off) = mid;
    }
    return on_s;
  };
  LoadedPath out;
  out.begin_m = first == 0 ? 0.0 : bisect(g * (first - 1) / n, g * first / n);
  out.end_m = last == n ? g : bisect(g * (last + 1) / n, g * last / n);
  return out;
}

}  // namespace tehl
