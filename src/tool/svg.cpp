// Drawing a case as SVG: a title, its drawing (harness/formats/drawing.h) in three orthographic
// views (x-y, x-z, y-z), shapes of no size as markers, and the projections of both shapes onto
// the deciding axis as two intervals on a line. Text is escaped: the file is valid XML.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string_view>
#include <vector>

#include "harness/formats/drawing.h"
#include "tool/cases.h"

namespace cc::tool {
namespace {

using namespace harness;

const char* const kColour[] = {"#1f6fb4", "#e07b00"};

// Text as XML character data: &, < and > (and quotes, for attributes) as entities.
std::string escaped(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// A shape of no size in a view (a point, a sphere of radius zero, a segment seen end-on): a
// cross 8 pixels wide with a ring, so that it cannot vanish.
void marker(std::ostringstream& svg, double x, double y, const char* colour) {
  svg << "<path d=\"M" << x - 4 << ' ' << y << "h8M" << x << ' ' << y - 4 << "v8\" stroke=\"" << colour
      << "\" stroke-width=\"1.5\"/><circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"5\" fill=\"none\" stroke=\"" << colour
      << "\"/>\n";
}

}  // namespace

std::string svg_of(const Input& input, const Explanation& why, std::string_view title) {
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
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << 3 * kPanel << "\" height=\"" << kPanel + 160
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n<title>" << escaped(title)
      << "</title>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
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
    // A segment seen end-on is marked unless a segment seen at length ends there (a box's edge
    // along the line of sight lies under the corner of its outline).
    const auto end_on = [&](const Drawing::Segment& g) {
      return std::fabs(px(g.p) - px(g.q)) < 0.5 && std::fabs(py(g.p) - py(g.q)) < 0.5;
    };
    const auto ends_a_segment = [&](double x, double y) {
      return std::any_of(s.segments.begin(), s.segments.end(), [&](const Drawing::Segment& h) {
        if (end_on(h)) return false;
        return (std::fabs(px(h.p) - x) < 0.5 && std::fabs(py(h.p) - y) < 0.5) ||
               (std::fabs(px(h.q) - x) < 0.5 && std::fabs(py(h.q) - y) < 0.5);
      });
    };
    for (const Drawing::Segment& g : s.segments) {
      if (end_on(g)) {
        if (!ends_a_segment(px(g.p), py(g.p))) marker(svg, px(g.p), py(g.p), kColour[g.shape % 2]);
        continue;
      }
      svg << "<line x1=\"" << px(g.p) << "\" y1=\"" << py(g.p) << "\" x2=\"" << px(g.q) << "\" y2=\"" << py(g.q)
          << "\" stroke=\"" << kColour[g.shape % 2] << "\" stroke-width=\"1.5\"/>\n";
    }
    for (const Drawing::Circle& c : s.circles) {
      const double r = std::fabs(c.radius) / extent * (kPanel - 2 * kMargin);
      if (!(r >= 1)) {  // under a pixel, zero or NaN
        marker(svg, px(c.center), py(c.center), kColour[c.shape % 2]);
        continue;
      }
      svg << "<circle cx=\"" << px(c.center) << "\" cy=\"" << py(c.center) << "\" r=\"" << r << "\" fill=\"none\" stroke=\""
          << kColour[c.shape % 2] << "\"/>\n";
    }
    for (const Drawing::Point& p : s.points) {
      svg << "<circle cx=\"" << px(p.p) << "\" cy=\"" << py(p.p) << "\" r=\"3\" fill=\"" << kColour[p.shape % 2] << "\"/>\n";
    }
  }
  // The title, then the deciding axis as a number line with both projected intervals.
  const double y0 = kPanel + 60;
  svg << "<text x=\"10\" y=\"" << kPanel + 16 << "\" font-weight=\"bold\">" << escaped(title) << "</text>\n";
  svg << "<text x=\"10\" y=\"" << y0 - 18 << "\">" << escaped(why.deciding.empty() ? "(no deciding axis)" : why.deciding)
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
    svg << "<text x=\"10\" y=\"" << y0 + 52 << "\">" << escaped(label) << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace cc::tool
