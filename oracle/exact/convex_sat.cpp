#include "oracle/exact/convex_sat.h"

#include <cmath>
#include <limits>

namespace cc::exact {

ExactShape::Interval ExactShape::project(const QVec3& axis) const {
  if (!vertices.empty()) {
    Interval r{dot(axis, vertices[0]), dot(axis, vertices[0])};
    for (std::size_t i = 1; i < vertices.size(); ++i) {
      const Rational p = dot(axis, vertices[i]);
      if (p < r.lo) r.lo = p;
      if (p > r.hi) r.hi = p;
    }
    return r;
  }
  const Rational mid = dot(axis, center);
  Rational radius = 0;
  for (const QVec3& h : half_edges) radius += abs(dot(axis, h));
  return {mid - radius, mid + radius};
}

ExactShape triangle_shape(const Vec3& p0, const Vec3& p1, const Vec3& p2, const std::string& name) {
  return rational_triangle_shape(rational(p0), rational(p1), rational(p2), name);
}

ExactShape rational_triangle_shape(const QVec3& p0, const QVec3& p1, const QVec3& p2, const std::string& name) {
  ExactShape s;
  s.vertices = {p0, p1, p2};
  s.center = Rational(1, 3) * (s.vertices[0] + s.vertices[1] + s.vertices[2]);
  for (int i = 0; i < 3; ++i) {
    const QVec3 e = s.vertices[(i + 1) % 3] - s.vertices[i];
    if (is_zero(e)) continue;
    s.directions.push_back(e);
    s.names.push_back(name + ".e" + std::to_string(i));
  }
  return s;
}

ExactShape parallelepiped_shape(const Vec3& center, const Vec3& half, const Mat3& columns, const std::string& name) {
  static const char* kAxisNames[] = {"x", "y", "z"};
  ExactShape s;
  s.center = rational(center);
  for (int i = 0; i < 3; ++i) {
    const QVec3 c = rational(columns.col[i]);
    const Rational h = rational(half[i]);
    if (sgn(h) == 0 || is_zero(c)) continue;
    s.half_edges.push_back(h * c);
    s.directions.push_back(c);
    s.names.push_back(name + "." + kAxisNames[i]);
  }
  return s;
}

ExactShape box_shape(const Vec3& lo, const Vec3& hi, const std::string& name) {
  ExactShape s = parallelepiped_shape({}, {}, Mat3::identity(), name);
  const QVec3 l = rational(lo), h = rational(hi);
  s.center = Rational(1, 2) * (l + h);
  static const char* kAxisNames[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    if (l[i] == h[i]) continue;
    QVec3 axis{0, 0, 0};
    axis[i] = 1;
    QVec3 half{0, 0, 0};
    half[i] = (h[i] - l[i]) / 2;
    s.half_edges.push_back(half);
    s.directions.push_back(axis);
    s.names.push_back(name + "." + kAxisNames[i]);
  }
  return s;
}

namespace {

using Candidate = CandidateAxis;

int rank_of(const std::vector<QVec3>& d) {
  if (d.empty()) return 0;
  int rank = 1;
  for (std::size_t i = 0; i < d.size(); ++i) {
    for (std::size_t j = i + 1; j < d.size(); ++j) {
      const QVec3 c = cross(d[i], d[j]);
      if (is_zero(c)) continue;
      rank = 2;
      for (std::size_t k = 0; k < d.size(); ++k) {
        if (sgn(dot(c, d[k])) != 0) return 3;
      }
    }
  }
  return rank;
}

}  // namespace

namespace {

struct Directions {
  std::vector<QVec3> dirs;
  std::vector<std::string> names;
  std::vector<Magnitude> lengths;
  int rank = 0;
};

Directions directions_of(const ExactShape& a, const ExactShape& b) {
  Directions d{a.directions, a.names, {}, 0};
  d.dirs.insert(d.dirs.end(), b.directions.begin(), b.directions.end());
  d.names.insert(d.names.end(), b.names.begin(), b.names.end());
  for (const QVec3& v : d.dirs) d.lengths.push_back(length(v));
  d.rank = rank_of(d.dirs);
  return d;
}

// The axes of the full-dimensional and the flat cases, which do not depend on the offset.
std::vector<Candidate> spanning_axes(const Directions& d) {
  const auto& dirs = d.dirs;
  const auto& names = d.names;
  const auto& lengths = d.lengths;
  std::vector<Candidate> candidates;
  if (d.rank == 3) {
    for (std::size_t i = 0; i < dirs.size(); ++i) {
      for (std::size_t j = i + 1; j < dirs.size(); ++j) {
        const QVec3 c = cross(dirs[i], dirs[j]);
        if (!is_zero(c)) candidates.push_back({names[i] + " x " + names[j], c, lengths[i] * lengths[j]});
      }
    }
  } else if (d.rank == 2) {
    // The plane normal from the best-conditioned pair: largest |di x dj|^2 / (|di|^2 |dj|^2).
    std::size_t bi = 0, bj = 0;
    Rational best = -1;
    for (std::size_t i = 0; i < dirs.size(); ++i) {
      for (std::size_t j = i + 1; j < dirs.size(); ++j) {
        const QVec3 c = cross(dirs[i], dirs[j]);
        const Rational quality = dot(c, c) / (dot(dirs[i], dirs[i]) * dot(dirs[j], dirs[j]));
        if (quality > best) best = quality, bi = i, bj = j;
      }
    }
    const QVec3 n = cross(dirs[bi], dirs[bj]);
    const std::string n_name = "(" + names[bi] + " x " + names[bj] + ")";
    const Magnitude n_conditioning = lengths[bi] * lengths[bj];
    candidates.push_back({n_name, n, n_conditioning});
    for (std::size_t k = 0; k < dirs.size(); ++k) {
      candidates.push_back({n_name + " x " + names[k], cross(n, dirs[k]), n_conditioning * lengths[k]});
    }
  }
  return candidates;
}

}  // namespace

std::vector<CandidateAxis> candidate_axes_for_any_offset(const ExactShape& a, const ExactShape& b) {
  const Directions d = directions_of(a, b);
  if (d.rank >= 2) return spanning_axes(d);
  std::vector<Candidate> candidates;
  static const char* kAxisNames[] = {"x", "y", "z"};
  if (d.rank == 1) {
    const QVec3& g = d.dirs[0];
    candidates.push_back({d.names[0], g, d.lengths[0]});
    for (int k = 0; k < 3; ++k) {  // the coordinate axis least parallel to g
      QVec3 e{0, 0, 0};
      e[k] = 1;
      const QVec3 u = cross(g, e);
      if (is_zero(u) || abs(g[k]) > abs(g[(k + 1) % 3]) || abs(g[k]) > abs(g[(k + 2) % 3])) continue;
      candidates.push_back({d.names[0] + " x " + kAxisNames[k], u, length(u)});
      const QVec3 v = cross(g, u);
      candidates.push_back({d.names[0] + " x (" + d.names[0] + " x " + kAxisNames[k] + ")", v, length(v)});
      break;
    }
    return candidates;
  }
  for (int k = 0; k < 3; ++k) {
    QVec3 e{0, 0, 0};
    e[k] = 1;
    candidates.push_back({kAxisNames[k], e, Magnitude::of(1)});
  }
  return candidates;
}

double separation_along(Magnitude gap, Magnitude conditioning) { return (gap / conditioning).to_double(); }

double overlap_along(Magnitude gap, Magnitude length) { return gap.m == 0 ? 0.0 : -(gap / length).to_double(); }

SatResult exact_sat(const ExactShape& a, const ExactShape& b) {
  const Directions d = directions_of(a, b);
  SatResult result;
  result.rank = d.rank;
  std::vector<Candidate> candidates = spanning_axes(d);
  const QVec3 o = b.center - a.center;
  if (result.rank == 1) {  // the line and the direction across it towards o
    const QVec3& g = d.dirs[0];
    candidates.push_back({d.names[0], g, d.lengths[0]});
    const QVec3 across = cross(g, cross(g, o));
    if (!is_zero(across)) candidates.push_back({d.names[0] + " x (" + d.names[0] + " x o)", across, length(across)});
  } else if (result.rank == 0 && !is_zero(o)) {
    candidates.push_back({"o", o, length(o)});
  }

  double worst_overlap = std::numeric_limits<double>::infinity();
  double best_separation = -std::numeric_limits<double>::infinity();
  int overlap_axis = -1, separation_axis = -1;
  for (const Candidate& c : candidates) {
    AxisReport r{c.name, c.axis, a.project(c.axis), b.project(c.axis), 0, c.conditioning, length(c.axis)};
    const Rational g1 = r.b.lo - r.a.hi, g2 = r.a.lo - r.b.hi;
    r.gap = g1 > g2 ? g1 : g2;
    const int index = static_cast<int>(result.axes.size());
    if (sgn(r.gap) > 0) {
      result.hit = false;
      const double separation = separation_along(Magnitude::of(r.gap), r.conditioning);
      if (separation > best_separation) best_separation = separation, separation_axis = index;
    } else {
      const double overlap = overlap_along(Magnitude::of(r.gap), r.length);
      if (overlap < worst_overlap) worst_overlap = overlap, overlap_axis = index;
    }
    result.axes.push_back(std::move(r));
  }
  result.hit = separation_axis < 0;
  if (result.hit) {
    result.margin = (result.rank == 3 && overlap_axis >= 0) ? worst_overlap : 0;
    result.deciding_axis = overlap_axis;
  } else {
    result.margin = -best_separation;
    result.deciding_axis = separation_axis;
  }
  return result;
}

}  // namespace cc::exact
