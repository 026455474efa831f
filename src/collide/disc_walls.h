// The maze, the notes' 2-D simplification: a disc (a person seen from above) against wall
// segments, decided in the two ways the notes give:
//  - the disc against each wall: the distance from the centre to the segment, at most the radius;
//  - the centre point against the walls moved outward by the radius: each wall grown into a
//    capsule (the band of half width r around its line between its ends, and a disc of radius r
//    at each end), and the point tested against the capsule with unit normals and lengths.
// Both decide the same set (closed: touching counts) with different arithmetic, each checked
// against its own rounding bound, so both are conservative: a disc that touches or crosses a
// wall in exact arithmetic is always reported touching it, and one apart from it by more than
// 2^-44 of the scale (the largest |coordinate| of the centre and the wall, or the radius) never
// is. Inputs are scaled by powers of two first, so no product underflows or overflows within
// the domain.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace cc {

struct Vec2 {
  double x = 0, y = 0;
  friend constexpr bool operator==(const Vec2&, const Vec2&) = default;
};

/// The closed disc of the given radius around the centre. Radius 0 is a point.
struct Disc {
  Vec2 center;
  double radius = 0;
  friend constexpr bool operator==(const Disc&, const Disc&) = default;
};

/// A wall: the closed segment from a to b (a == b: a pillar, a point).
struct Wall {
  Vec2 a, b;
  friend constexpr bool operator==(const Wall&, const Wall&) = default;
};

/// True when the disc and the wall share a point, by the disc's distance to the segment
/// (the nearest end, compared as squares, or the line, |cross(b - a, c - a)| against r |b - a|,
/// when the centre projects between the ends). Conservative as above; symmetric in the wall's ends bit for bit.
///  - Domain: finite inputs of magnitude at most 2^500, radius >= 0.
///  - NaN or infinite input, or a negative radius: false.
bool test_disc_wall(const Disc& disc, const Wall& wall);

/// The same set, by the disc's centre c against the wall grown by the radius: inside the band
/// |n . (c - a)| <= r between the ends (t . (c - a) >= 0 >= t . (c - b), n and t the wall's
/// unit normal and direction as computed), or within r of an end (lengths by square roots).
/// Conservative as above, with the same domain and out-of-contract answers; symmetric in the
/// ends bit for bit.
bool test_point_grown_wall(const Vec2& center, double radius, const Wall& wall);

/// The two methods, for disc_walls().
enum class DiscWallsMethod { disc_against_walls, point_against_grown_walls };

/// The indices of the walls the disc touches (ascending), by one method.
std::vector<std::uint32_t> disc_walls(const Disc& disc, std::span<const Wall> walls, DiscWallsMethod method);

}  // namespace cc
