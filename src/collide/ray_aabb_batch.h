// One ray against many axis-aligned boxes: the boxes stored by coordinate (structure of arrays)
// and tested several at a time with SIMD instructions where the processor has them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "collide/ray_aabb.h"
#include "collide/simd.h"

namespace cc {

/// Boxes stored as six arrays of coordinates: box i is [lo_x[i], hi_x[i]] x [lo_y[i], hi_y[i]]
/// x [lo_z[i], hi_z[i]]. The six arrays always have the same length.
struct AabbSoa {
  std::vector<double> lo_x, lo_y, lo_z, hi_x, hi_y, hi_z;

  /// Appends a box (any values, NaN included: the tests below decide what they mean).
  void push_back(const Aabb& box);
  /// The number of boxes.
  std::size_t size() const { return lo_x.size(); }
  /// Box i as an Aabb.
  Aabb operator[](std::size_t i) const { return {{lo_x[i], lo_y[i], lo_z[i]}, {hi_x[i], hi_y[i], hi_z[i]}}; }
};

/// The number of 64-bit words that hold one bit per box.
constexpr std::size_t hit_words(std::size_t boxes) { return (boxes + 63) / 64; }

/// Bit i of a set of hit bits (box i's answer).
inline bool hit_bit(std::span<const std::uint64_t> hits, std::size_t i) { return (hits[i / 64] >> (i % 64)) & 1; }

/// Sets bit i % 64 of hits[i / 64] to intersect_ray_aabb(ray, boxes[i]).hit for every box (the
/// bits past the last box are cleared), and returns how many hit. The answers are those of the
/// scalar test bit for bit, in and out of its contract:
///  - touching (grazing a face, an edge or a corner) is a hit, conservatively as there;
///  - a direction component with |d| <= 2^-1024 (0 and -0 included) makes the ray parallel to
///    that slab: a hit needs the origin in the closed slab (an exact comparison);
///  - NaN or an infinite coordinate in the ray, tmin = +inf, tmax = -inf, tmin > tmax, and a box
///    with a NaN or infinite bound or lo > hi on an axis: no hit.
/// hits must hold at least hit_words(boxes.size()) words (std::invalid_argument otherwise). The
/// boxes are read by the kernel simd::selected() names (the best this processor runs unless one
/// is forced): in blocks of 8 (AVX-512) or 4 (AVX2), the boxes left over one at a time,
/// or all one at a time (scalar); one kernel source, the same IEEE double arithmetic in each.
std::size_t test_ray_aabbs(const Ray& ray, const AabbSoa& boxes, std::span<std::uint64_t> hits);

/// The same with the given kernel, whatever simd::selected() says; std::invalid_argument if
/// this processor cannot run it (simd::unsupported_reason).
std::size_t test_ray_aabbs(const Ray& ray, const AabbSoa& boxes, std::span<std::uint64_t> hits, simd::Kernel kernel);

}  // namespace cc
