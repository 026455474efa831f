// disc_walls: the maze's 2-D test, a disc against wall segments (collide/disc_walls.h): the walls
// the disc touches, by the disc against each wall; also by its centre against the walls grown by
// the radius.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/disc_walls.h"

namespace cc::harness {

template <>
struct Query<DiscWallsInput> : QueryDefaults {
  static constexpr Band band = {0x1p-44, BandSides::conservative, 0,
                                "both methods are certified against their rounding bounds (collide/disc_walls.h): a wall the "
                                "disc touches is always reported, one apart by more than 2^-44 of the scale (the largest "
                                "|coordinate| of the centre and that wall, or the radius) never is"};
  /// In the plane: x and y swapped (a permutation of the axes that reverses them; z is none of the
  /// plane's) and negated; walls reordered (permute_objects) and their ends swapped
  /// (permute_vertices).
  static constexpr Relations relations = {Relation::permute_axes, Relation::flip_axis, Relation::scale,
                                          Relation::permute_vertices, Relation::permute_objects};
  /// Each wall on its own margin.
  static constexpr Judged judged = Judged::all_pairs;

  /// The walls touched by test_disc_wall: the pairs (wall, 0), ascending; a hit when there is one.
  static Answer ask(const DiscWallsInput& in);
  /// "library.disc_walls(point_against_grown_walls)": the same from test_point_grown_wall.
  static const std::vector<Party<DiscWallsInput>>& library_parties();
  static DiscWallsInput generate(ValueSource& values, const GenerateOptions& options);
  /// The disc moved against a wall: its centre at the radius from an end along an axis, away
  /// from the other end (exactly touching when the sum is exact).
  static void touch(DiscWallsInput& in, ValueSource& values);
  /// Parallel: a wall along an axis, or two parallel walls. Degenerate: radius 0 (a point), a
  /// pillar (a wall whose ends are equal).
  static Features features(const DiscWallsInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const DiscWallsInput& in, Configurations& found);
  /// None: the disc tests record no certified quantities (collide/bound_records.h).
  static std::span<const BoundTerm> bound_terms();
  static void probe(const DiscWallsInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
