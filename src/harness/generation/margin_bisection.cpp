#include "harness/generation/margin_bisection.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace cc::harness {
namespace {

// Doubles in order as integers: -0 and 0 next to each other, negative below.
std::int64_t ordered(double x) {
  const auto bits = std::bit_cast<std::int64_t>(x);
  return bits >= 0 ? bits : std::numeric_limits<std::int64_t>::min() - bits;
}
double from_ordered(std::int64_t i) {
  return std::bit_cast<double>(i >= 0 ? i : std::numeric_limits<std::int64_t>::min() - i);
}

// A double strictly between a and b, or a when they are adjacent: halfway in value while they
// are far apart, halfway in the order of doubles when they are close.
double between(double a, double b) {
  const double mid = 0.5 * a + 0.5 * b;
  const std::int64_t ia = ordered(a), ib = ordered(b);
  if (std::fabs(b - a) > 0x1p-20 * std::max(std::fabs(a), std::fabs(b)) && mid != a && mid != b) return mid;
  const std::int64_t im = ia / 2 + ib / 2 + ((ia % 2) + (ib % 2)) / 2;
  return im == ia || im == ib ? a : from_ordered(im);
}

class Search {
 public:
  Search(const Family& family, double target, const ExactReference& exact, int budget)
      : family_(family), target_(target), exact_(exact), budget_(budget) {}

  // margin(s) - target, or nothing (out of the domain, undecided, out of budget).
  std::optional<double> value(double s) { return value(family_(s)); }
  std::optional<double> value(const Input& input) {
    if (budget_-- <= 0) return std::nullopt;
    const ExactVerdict v = exact_.judge(input);
    if (v.contract != Contract::in || !v.decided || std::isnan(v.margin)) return std::nullopt;
    return v.margin - target_;
  }
  Input at(double s) const { return family_(s); }
  bool exhausted() const { return budget_ <= 0; }

 private:
  const Family& family_;
  double target_;
  const ExactReference& exact_;
  int budget_;
};

bool inside(double f) { return f >= 0; }

}  // namespace

std::optional<double> bisect_to_margin(const Family& family, double s0, double s1, double target, Side side,
                                       const ExactReference& exact, int max_judgements) {
  Search search(family, target, exact, max_judgements);
  auto f0 = search.value(s0), f1 = search.value(s1);
  if (!f0 || !f1 || s0 == s1) return std::nullopt;
  // Until the crossing is bracketed: secant steps, kept between a sixteenth and 16 times the last.
  while (inside(*f0) == inside(*f1)) {
    const double step = s1 - s0;
    double next = s1 + 2 * step;
    if (*f1 != *f0 && std::isfinite(*f1) && std::isfinite(*f0)) {
      const double secant = -*f1 * step / (*f1 - *f0);
      if (std::isfinite(secant)) next = s1 + std::copysign(std::clamp(std::fabs(secant), std::fabs(step) / 16, 16 * std::fabs(step)), secant);
    }
    const auto f2 = search.value(next);
    if (!f2) return std::nullopt;
    s0 = s1, f0 = f1, s1 = next, f1 = f2;
  }
  // [a, b] brackets the crossing (a inside, b outside). The margin is a gap outside and a depth
  // inside, each linear in s while one axis decides, so a secant through the last two points on
  // one side lands within a few ULPs of the crossing (the outside preferred: a flat shape's depth
  // is 0); from there steps of 4^k ULPs away from it find the other side, and bisection (in value
  // while far apart, in the order of doubles when near) closes in.
  struct Point {
    double s, f;
    Input input;
  };
  Point a{s0, *f0, search.at(s0)}, b{s1, *f1, search.at(s1)};
  if (!inside(a.f)) std::swap(a, b);
  std::optional<Point> before_a, before_b;  // the previous point on each side
  double landing = 0;                       // a secant's landing, galloped away from while galloping
  bool galloping = false, landing_inside = false;
  int gallop = 0;
  for (int step = 0;; ++step) {
    double m = between(a.s, b.s);
    if (m == a.s) break;  // adjacent
    const double lo = std::min(a.s, b.s), hi = std::max(a.s, b.s);
    const auto within = [lo, hi](double x) { return x > lo && x < hi; };
    // The secant through an end and the previous point on its side, when it lands inside.
    const auto secant_from = [&](const Point& p, const std::optional<Point>& q) -> std::optional<double> {
      if (!q || !std::isfinite(p.f) || !std::isfinite(q->f) || p.f == q->f) return std::nullopt;
      const double x = p.s - p.f * (p.s - q->s) / (p.f - q->f);
      return within(x) ? std::optional(x) : std::nullopt;
    };
    bool secant_step = false;
    if (galloping) {
      const double other = landing_inside ? b.s : a.s;
      const double ulp = std::fabs(std::nextafter(landing, other) - landing);
      const double next = landing + std::copysign(std::ldexp(ulp, 2 * ++gallop), other - landing);
      // Past four steps, or outside the bracket, the landing was far off: back to secants. (Each
      // step is judged or moves an end inward, so galloping ends.)
      if (within(next) && gallop <= 4) {
        m = next;
      } else {
        galloping = false;
      }
    }
    if (!galloping && step % 4 != 3) {
      std::optional<double> x = secant_from(b, before_b);
      if (!x) x = secant_from(a, before_a);
      if (x) m = *x, secant_step = true;
    }
    if (search.exhausted()) break;  // the ends are on their sides, only not adjacent
    // The family rounds: a parameter may give an end's very case, which needs no judgement.
    Input input = search.at(m);
    if (input == a.input || input == b.input) {
      (input == a.input ? a : b).s = m;
      if (galloping) --gallop;
      continue;
    }
    const auto fm = search.value(input);
    if (!fm) return std::nullopt;
    const bool crossed = galloping && inside(*fm) != landing_inside;
    if (inside(*fm)) {
      before_a = a, a = {m, *fm, std::move(input)};
    } else {
      before_b = b, b = {m, *fm, std::move(input)};
    }
    if (secant_step) landing = m, landing_inside = inside(*fm), gallop = 0, galloping = true;
    if (crossed) galloping = false;
  }
  return side == Side::inside ? a.s : b.s;
}

}  // namespace cc::harness
