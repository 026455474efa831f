#include "tool/scenes/maze.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "collide/seeded_random.h"

namespace cc::harness {
namespace {

// Walls between cells: vertical[x][y] is the wall on the line x (0..width) beside row y;
// horizontal[x][y] the wall on the line y (0..height) below or above column x.
struct Grid {
  int width, height;
  std::vector<char> vertical, horizontal;  // 1: standing
  Grid(int w, int h)
      : width(w), height(h), vertical(static_cast<std::size_t>((w + 1) * h), 1),
        horizontal(static_cast<std::size_t>(w * (h + 1)), 1) {}
  char& v(int x, int y) { return vertical[static_cast<std::size_t>(x * height + y)]; }
  char& h(int x, int y) { return horizontal[static_cast<std::size_t>(y * width + x)]; }
};

constexpr int kDx[4] = {1, -1, 0, 0}, kDy[4] = {0, 0, 1, -1};

// Knocks down the wall between (x, y) and its neighbour in direction k.
void open(Grid& g, int x, int y, int k) {
  if (k == 0) g.v(x + 1, y) = 0;
  if (k == 1) g.v(x, y) = 0;
  if (k == 2) g.h(x, y + 1) = 0;
  if (k == 3) g.h(x, y) = 0;
}

bool is_open(Grid& g, int x, int y, int k) {
  if (k == 0) return !g.v(x + 1, y);
  if (k == 1) return !g.v(x, y);
  if (k == 2) return !g.h(x, y + 1);
  return !g.h(x, y);
}

}  // namespace

const char* to_string(MazeStep::Kind kind) {
  switch (kind) {
    case MazeStep::Kind::walk: return "walk";
    case MazeStep::Kind::side_touch: return "side_touch";
    case MazeStep::Kind::side_closer: return "side_closer";
    case MazeStep::Kind::side_farther: return "side_farther";
    case MazeStep::Kind::corner: return "corner";
  }
  return "?";
}

namespace {

// Carves a w x h grid: a depth-first walk from cell 0 over unvisited neighbours in random
// order; then opens the entrance (left of the first cell) and the exit (right of the last).
Grid carve(int w, int h, std::uint64_t seed) {
  Grid grid(w, h);
  SeededRandom random(seed);
  std::vector<char> seen(static_cast<std::size_t>(w * h), 0);
  std::vector<int> stack{0};
  seen[0] = 1;
  while (!stack.empty()) {
    const int cell = stack.back(), x = cell % w, y = cell / w;
    int options[4], n = 0;
    for (int k = 0; k < 4; ++k) {
      const int nx = x + kDx[k], ny = y + kDy[k];
      if (nx >= 0 && nx < w && ny >= 0 && ny < h && !seen[static_cast<std::size_t>(ny * w + nx)]) options[n++] = k;
    }
    if (n == 0) {
      stack.pop_back();
      continue;
    }
    const int k = options[random.below(static_cast<std::uint64_t>(n))];
    open(grid, x, y, k);
    const int next = (y + kDy[k]) * w + (x + kDx[k]);
    seen[static_cast<std::size_t>(next)] = 1;
    stack.push_back(next);
  }
  grid.v(0, 0) = 0;
  grid.v(w, h - 1) = 0;
  return grid;
}

// The cells from the entrance cell to the exit cell: breadth-first through open sides.
std::vector<int> path_through(Grid& grid) {
  const int w = grid.width, h = grid.height;
  std::vector<int> parent(static_cast<std::size_t>(w * h), -1);
  std::vector<int> queue{0};
  parent[0] = 0;
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const int cell = queue[i], x = cell % w, y = cell / w;
    for (int k = 0; k < 4; ++k) {
      const int nx = x + kDx[k], ny = y + kDy[k];
      if (nx < 0 || nx >= w || ny < 0 || ny >= h || !is_open(grid, x, y, k)) continue;
      const int next = ny * w + nx;
      if (parent[static_cast<std::size_t>(next)] >= 0) continue;
      parent[static_cast<std::size_t>(next)] = cell;
      queue.push_back(next);
    }
  }
  std::vector<int> path;
  for (int cell = w * h - 1;; cell = parent[static_cast<std::size_t>(cell)]) {
    path.push_back(cell);
    if (cell == 0) break;
  }
  std::reverse(path.begin(), path.end());
  return path;
}

// The probes of the path's i-th cell: the walk to the next cell in substeps; each standing side
// touched at its middle, and one ulp either way; each corner touched at distance exactly r from
// inside the cell, along (3, 4) / 5 and (4, 3) / 5. With the default radius (5/16) and a
// power-of-two substep count, every position is exact at the origin's magnitude: a touch is a
// touch in exact arithmetic.
void add_steps_of_cell(Maze& maze, Grid& grid, std::size_t i) {
  const MazeOptions& o = maze.options;
  const int w = grid.width;
  const auto at = [&](double x, double y) { return Vec2{o.origin.x + x, o.origin.y + y}; };
  const double r = o.radius;
  const int cell = maze.path[i], x = cell % w, y = cell / w;
  const Vec2 centre = at(x + 0.5, y + 0.5);
  const int index = static_cast<int>(i);
  if (i + 1 < maze.path.size()) {
    const int next = maze.path[i + 1];
    const double dx = next % w - x, dy = next / w - y;
    for (int s = 0; s < o.substeps; ++s) {
      const double f = static_cast<double>(s) / o.substeps;
      maze.steps.push_back({{{centre.x + f * dx, centre.y + f * dy}, r}, MazeStep::Kind::walk, index});
    }
  } else {
    maze.steps.push_back({{centre, r}, MazeStep::Kind::walk, index});
  }
  const struct {
    bool standing;
    Vec2 touch;
    int axis;     // the coordinate that moves toward the wall
    double sign;  // toward the wall
  } sides[4] = {
      {grid.v(x + 1, y) != 0, at(x + 1 - r, y + 0.5), 0, 1},
      {grid.v(x, y) != 0, at(x + r, y + 0.5), 0, -1},
      {grid.h(x, y + 1) != 0, at(x + 0.5, y + 1 - r), 1, 1},
      {grid.h(x, y) != 0, at(x + 0.5, y + r), 1, -1},
  };
  for (const auto& side : sides) {
    if (!side.standing) continue;
    maze.steps.push_back({{side.touch, r}, MazeStep::Kind::side_touch, index});
    for (const double direction : {side.sign, -side.sign}) {
      Vec2 moved = side.touch;
      double& c = side.axis == 0 ? moved.x : moved.y;
      c = std::nextafter(c, direction * INFINITY);
      maze.steps.push_back({{moved, r}, direction == side.sign ? MazeStep::Kind::side_closer : MazeStep::Kind::side_farther, index});
    }
  }
  for (const int cx : {0, 1}) {
    for (const int cy : {0, 1}) {
      const double sx = cx ? -1 : 1, sy = cy ? -1 : 1;
      for (const auto& [p, q] : {std::pair{3.0, 4.0}, std::pair{4.0, 3.0}}) {
        const Vec2 corner = at(x + cx, y + cy);
        maze.steps.push_back({{{corner.x + sx * (p * r / 5), corner.y + sy * (q * r / 5)}, r}, MazeStep::Kind::corner, index});
      }
    }
  }
}

}  // namespace

Maze make_maze(const MazeOptions& o) {
  if (o.width < 1 || o.width > 200 || o.height < 1 || o.height > 200) throw std::invalid_argument("maze sizes must lie in [1, 200]");
  if (!(o.radius >= 0 && o.radius < 0.5)) throw std::invalid_argument("the disc's radius must lie in [0, 0.5) cells");
  if (o.substeps < 1 || o.substeps > 64) throw std::invalid_argument("substeps must lie in [1, 64]");
  if (!std::isfinite(o.origin.x) || !std::isfinite(o.origin.y)) throw std::invalid_argument("the origin must be finite");
  const int w = o.width, h = o.height;
  Grid grid = carve(w, h, o.seed);
  Maze maze;
  maze.options = o;
  const auto at = [&](double x, double y) { return Vec2{o.origin.x + x, o.origin.y + y}; };
  for (int x = 0; x <= w; ++x) {
    for (int y = 0; y < h; ++y) {
      if (grid.v(x, y)) maze.walls.push_back({at(x, y), at(x, y + 1)});
    }
  }
  for (int y = 0; y <= h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (grid.h(x, y)) maze.walls.push_back({at(x, y), at(x + 1, y)});
    }
  }
  maze.path = path_through(grid);
  for (std::size_t i = 0; i < maze.path.size(); ++i) add_steps_of_cell(maze, grid, i);
  return maze;
}

}  // namespace cc::harness
