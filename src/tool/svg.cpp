// Drawing a case as SVG: its drawing (harness/formats/drawing.h) in three orthographic views
// (x-y, x-z, y-z), and the projections of both shapes onto the deciding axis as two intervals on
// a line.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "harness/formats/drawing.h"
#include "tool/cases.h"

namespace cc::tool {
namespace {

using namespace harness;

const char* const kColour[] = {"#1f6fb4", "#e07b00"};

}  // namespace

std::string svg_of(const Input& input, const Explanation& why) {
  Drawing s = drawing_of(input);
  draw_rays(s);
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  const auto grow = [&](const Vec3& p, double r) {
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(p[k])) continue;
      lo[k] = std::min(lo[k], p[k] - r);
      hi[k] = std::max(hi[k], p[k] + r);
    }
  };
  for (const Drawing::Segment& g : s.segments) grow(g.p, 0), grow(g.q, 0);
  for (const Drawing::Circle& c : s.circles) grow(c.center, std::isfinite(c.radius) ? std::fabs(c.radius) : 0);
  for (const Drawing::Point& p : s.points) grow(p.p, 0);
  for (int k = 0; k < 3; ++k) {
    if (!(lo[k] <= hi[k])) lo[k] = -1, hi[k] = 1;
  }
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-300}) * 1.1;
  const Vec3 mid = 0.5 * (lo + hi);

  constexpr int kPanel = 320, kMargin = 24;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << 3 * kPanel << "\" height=\"" << kPanel + 140
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  const int views[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  const char* const axis_name = "xyz";
  for (int v = 0; v < 3; ++v) {
    const int u = views[v][0], w = views[v][1];
    const double ox = v * kPanel;
    const auto px = [&](const Vec3& p) {
      return ox + kMargin + (p[u] - mid[u] + extent / 2) / extent * (kPanel - 2 * kMargin);
    };
    const auto py = [&](const Vec3& p) {
      return kPanel - kMargin - (p[w] - mid[w] + extent / 2) / extent * (kPanel - 2 * kMargin);
    };
    svg << "<rect x=\"" << ox + 2 << "\" y=\"2\" width=\"" << kPanel - 4 << "\" height=\"" << kPanel - 4
        << "\" fill=\"none\" stroke=\"#ccc\"/>\n";
    svg << "<text x=\"" << ox + 8 << "\" y=\"16\">" << axis_name[u] << " (right), " << axis_name[w]
        << " (up); <tspan fill=\"" << kColour[0] << "\">A</tspan>, <tspan fill=\"" << kColour[1] << "\">B</tspan></text>\n";
    for (const Drawing::Segment& g : s.segments) {
      svg << "<line x1=\"" << px(g.p) << "\" y1=\"" << py(g.p) << "\" x2=\"" << px(g.q) << "\" y2=\"" << py(g.q)
          << "\" stroke=\"" << kColour[g.shape % 2] << "\" stroke-width=\"1.5\"/>\n";
    }
    for (const Drawing::Circle& c : s.circles) {
      svg << "<circle cx=\"" << px(c.center) << "\" cy=\"" << py(c.center) << "\" r=\""
          << std::fabs(c.radius) / extent * (kPanel - 2 * kMargin) << "\" fill=\"none\" stroke=\"" << kColour[c.shape % 2] << "\"/>\n";
    }
    for (const Drawing::Point& p : s.points) {
      svg << "<circle cx=\"" << px(p.p) << "\" cy=\"" << py(p.p) << "\" r=\"3\" fill=\"" << kColour[p.shape % 2] << "\"/>\n";
    }
  }
  // The deciding axis as a number line with both projected intervals.
  const double y0 = kPanel + 40;
  svg << "<text x=\"10\" y=\"" << y0 - 18 << "\">" << (why.deciding.empty() ? std::string("(no deciding axis)") : why.deciding)
      << "</text>\n";
  if (why.axis) {
    const double l = std::min(why.a_lo, why.b_lo), h = std::max(why.a_hi, why.b_hi);
    const double span = std::max(h - l, 1e-300) * 1.2, centre = 0.5 * (l + h);
    const auto x = [&](double t) { return 40 + (t - centre + span / 2) / span * (3 * kPanel - 80); };
    const auto bar = [&](double a, double b, int shape, double y) {
      svg << "<rect x=\"" << x(a) << "\" y=\"" << y << "\" width=\"" << std::max(x(b) - x(a), 1.0)
          << "\" height=\"12\" fill=\"" << kColour[shape] << "\" opacity=\"0.7\"/>\n";
    };
    bar(why.a_lo, why.a_hi, 0, y0);
    bar(why.b_lo, why.b_hi, 1, y0 + 18);
    char label[200];
    std::snprintf(label, sizeof label, "axis (%.6g, %.6g, %.6g): A [%.10g, %.10g] (blue), B [%.10g, %.10g] (orange)",
                  why.axis->x, why.axis->y, why.axis->z, why.a_lo, why.a_hi, why.b_lo, why.b_hi);
    svg << "<text x=\"10\" y=\"" << y0 + 52 << "\">" << label << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace cc::tool
