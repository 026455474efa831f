// The axes a penetration depth is measured on: candidates for the face normals of the Minkowski
// difference of two convex polytopes, each with how far its computed direction may lie from the
// exact normal it stands for. The depth is the least overlap over the exact normals.
#pragma once

#include <algorithm>
#include <array>
#include <limits>

#include "collide/vec3.h"

namespace cc {

/// A candidate axis: its direction (of any length), the overlap of the shapes' projections
/// measured on it, how far that overlap may lie from the one on the exact normal it stands for
/// (direction_error, a length) and how far its unit direction may (angle_error).
struct DepthAxis {
  Vec3 n;
  double depth = std::numeric_limits<double>::infinity();
  double direction_error = 0;
  double angle_error = 0;
};

/// Up to N axes, the width the faces left out may cost (slivers: faces of the difference too
/// thin to need an axis of their own, each never nearer than a measured neighbour less its
/// width), and the axis of least overlap (-1 before any is measured).
template <int N>
struct DepthAxes {
  DepthAxes() {}  // the axes past `count` are left unset: they are never read
  union {
    std::array<DepthAxis, N> axis;
  };
  int count = 0;
  double sliver = 0;
  int least = -1;

  void add(const Vec3& n, double direction_error, double angle_error) {
    axis[count++] = {n, std::numeric_limits<double>::infinity(), direction_error, angle_error};
  }

  /// Measures overlap(n) on each axis from `first` on, keeping the least.
  template <class Overlap>
  void measure(int first, const Overlap& overlap) {
    for (int k = first; k < count; ++k) {
      DepthAxis& x = axis[k];
      x.depth = overlap(x.n);
      if (least < 0 || x.depth < axis[least].depth) least = k;
    }
  }

  /// The least overlap measured; +infinity before any.
  double least_depth() const { return least >= 0 ? axis[least].depth : std::numeric_limits<double>::infinity(); }

  /// A lower bound on the depth, given that each overlap lies within `evaluation` of the exact
  /// one on its computed direction: each axis measured is at least its overlap less that and
  /// its direction's error deep, each left out at least that less the slivers. The shapes
  /// overlap for certain when it is positive.
  double certain_depth(double evaluation) const {
    double lower = std::numeric_limits<double>::infinity();
    for (int k = 0; k < count; ++k) lower = std::min(lower, axis[k].depth - evaluation - axis[k].direction_error);
    return lower - sliver;
  }
};

}  // namespace cc
