// The maze scene: a grid maze carved from a seed (a depth-first walk that knocks down walls),
// its walls as unit segments (ends shared where walls meet), and the positions of a disc that
// walks from the entrance cell to the exit cell, together with probes placed on the boundary:
// touching each wall of the cells it passes at the middle of the side, one ulp closer and one
// ulp farther, and at distance exactly r from each corner of those cells (where wall ends
// meet) along a 3-4-5 direction.
#pragma once

#include <cstdint>
#include <vector>

#include "collide/disc_walls.h"

namespace cc::harness {

struct MazeOptions {
  int width = 12, height = 12;   // cells
  std::uint64_t seed = 1;
  Vec2 origin{0x1p20, -0x1p20};  // the lower-left corner: far from 0, so rounding is relative to it
  double radius = 0.3125;        // of the disc, in cells (5/16: the 3-4-5 probes are exact)
  int substeps = 8;              // positions between two cells' centres
};

struct MazeStep {
  Disc disc;
  enum class Kind { walk, side_touch, side_closer, side_farther, corner } kind = Kind::walk;
  int cell = 0;  // index of the cell on the path the step belongs to
};

struct Maze {
  MazeOptions options;
  std::vector<Wall> walls;
  std::vector<int> path;  // cells (y * width + x) from the entrance to the exit
  std::vector<MazeStep> steps;
};

/// The maze of the options; throws std::invalid_argument for sizes outside [1, 200], a radius
/// outside [0, 0.5) (the disc must fit a corridor) or substeps outside [1, 64].
Maze make_maze(const MazeOptions& options);

const char* to_string(MazeStep::Kind kind);

}  // namespace cc::harness
