// crosscheck maze: a disc walks through a generated maze; at every position (the walk, and
// probes touching the walls of the cells it passes) each wall is tested by both of the library's
// methods (the disc against the wall; the centre against the wall grown by the radius) and
// judged as the query kind of a disc against walls judges it (found in the registry): by its
// exact reference, each wall on its own margin, against the kind's band. A miss of a wall the
// disc touches, or a hit of one apart by more than the band (the library's 2^-44 of the scale),
// is wrong: exit 1.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "collide/disc_walls.h"
#include "harness/judging/bands.h"
#include "oracle/exact/exact_reference.h"
#include "tool/commands.h"
#include "tool/flag_checks.h"
#include "tool/scenes/maze.h"

namespace cc::tool {
namespace {

constexpr std::array kMethods{DiscWallsMethod::disc_against_walls, DiscWallsMethod::point_against_grown_walls};
constexpr const char* kMethodNames[] = {"disc against walls", "point against grown walls"};

struct MazeArgs {
  int size = 12;
  std::uint64_t seed = 1;
  double radius = 0.3125;
  int substeps = 8;
};

struct Tally {
  long checks = 0, contacts = 0, touching = 0, right = 0, within_band = 0, wrong = 0;
};

// True when the disc is certainly farther than one cell from the wall: its centre lies outside
// the wall's bounding box grown by r + 1 (a margin no rounding of these comparisons comes near).
bool certainly_apart(const Disc& disc, const Wall& wall) {
  const double reach = disc.radius + 1;
  return disc.center.x < std::min(wall.a.x, wall.b.x) - reach || disc.center.x > std::max(wall.a.x, wall.b.x) + reach ||
         disc.center.y < std::min(wall.a.y, wall.b.y) - reach || disc.center.y > std::max(wall.a.y, wall.b.y) + reach;
}

int run(const MazeArgs& args) {
  if (!(args.radius >= 0 && args.radius < 0.5)) {
    std::fprintf(stderr, "crosscheck maze: --radius must lie in [0, 0.5) cells (the disc must fit a corridor), got %g\n",
                 args.radius);
    return kExitBadInput;
  }
  harness::MazeOptions options;
  options.width = options.height = args.size;
  options.seed = args.seed;
  options.radius = args.radius;
  options.substeps = args.substeps;
  harness::Maze maze;
  try {
    maze = harness::make_maze(options);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "crosscheck maze: %s\n", e.what());
    return kExitBadInput;
  }
  std::printf("crosscheck maze: %d x %d cells, seed %llu, disc radius %g, origin (%g, %g); %zu walls, a path of %zu cells\n",
              args.size, args.size, static_cast<unsigned long long>(args.seed), args.radius, options.origin.x,
              options.origin.y, maze.walls.size(), maze.path.size());

  // The kind asked of a disc against walls: its exact reference and its band.
  const exact::ExactRationalReference reference;
  const harness::Band band = harness::library_band(harness::kind_of(harness::disc_and_walls_input({}, {})));
  Tally tally[2];
  std::map<std::string, long> kinds;
  long differing = 0, wrong_steps = 0;
  for (const harness::MazeStep& step : maze.steps) {
    ++kinds[harness::to_string(step.kind)];
    // The walls near the disc, judged as one case of the kind; the others are certainly apart.
    std::vector<Wall> near;
    std::vector<std::uint32_t> place(maze.walls.size());  // a near wall's index in the case
    for (std::size_t w = 0; w < maze.walls.size(); ++w) {
      if (certainly_apart(step.disc, maze.walls[w])) continue;
      place[w] = static_cast<std::uint32_t>(near.size());
      near.push_back(maze.walls[w]);
    }
    const harness::ExactVerdict verdict = reference.judge(harness::disc_and_walls_input(step.disc, near));
    bool step_wrong = false;
    for (std::size_t w = 0; w < maze.walls.size(); ++w) {
      const Wall& wall = maze.walls[w];
      const bool apart = certainly_apart(step.disc, wall);
      const harness::FacePair pair{place[w], 0};
      const bool touches =
          !apart && std::binary_search(verdict.answer.pairs.begin(), verdict.answer.pairs.end(), pair);
      const double margin = apart ? -INFINITY : verdict.margin_of(pair);
      bool says[2];
      for (int m = 0; m < 2; ++m) {
        says[m] = kMethods[m] == DiscWallsMethod::disc_against_walls
                      ? test_disc_wall(step.disc, wall)
                      : test_point_grown_wall(step.disc.center, step.disc.radius, wall);
        Tally& t = tally[m];
        ++t.checks;
        t.contacts += touches;
        t.touching += touches && margin == 0;
        const bool right = says[m] == touches || harness::within_band(band, says[m], margin);
        if (!right) {
          ++t.wrong;
          step_wrong = true;
          std::printf("WRONG (%s): %s step of cell %d, disc (%.17g, %.17g) r %.17g, wall (%.17g, %.17g)-(%.17g, %.17g): says %s, exact margin %.3g\n",
                      kMethodNames[m], harness::to_string(step.kind), maze.path[static_cast<std::size_t>(step.cell)],
                      step.disc.center.x, step.disc.center.y, step.disc.radius, wall.a.x, wall.a.y, wall.b.x, wall.b.y,
                      says[m] ? "touch" : "miss", margin);
        } else if (says[m] != touches) {
          ++t.within_band;
        } else {
          ++t.right;
        }
      }
      differing += says[0] != says[1];
    }
    wrong_steps += step_wrong;
  }

  std::printf("\npositions: %zu (", maze.steps.size());
  const char* separator = "";
  for (const auto& [kind, count] : kinds) std::printf("%s%s %ld", separator, kind.c_str(), count), separator = ", ";
  std::printf(")\n\n%-34s %14s %14s\n", "per wall test", kMethodNames[0], kMethodNames[1]);
  const auto row = [&](const char* name, long Tally::*field) {
    std::printf("%-34s %14ld %14ld\n", name, tally[0].*field, tally[1].*field);
  };
  row("wall tests", &Tally::checks);
  row("contacts in exact arithmetic", &Tally::contacts);
  row("  of which exactly touching", &Tally::touching);
  row("right", &Tally::right);
  row("touch reported, apart within band", &Tally::within_band);
  row("wrong", &Tally::wrong);
  std::printf("\nthe two methods answer differently on %ld wall tests (each within the band: %s)\n", differing,
              tally[0].wrong + tally[1].wrong == 0 ? "yes" : "no");
  std::printf("every step checked: %zu positions, %ld with a wrong answer (band 2^%d of the scale, %s)\n",
              maze.steps.size(), wrong_steps, std::ilogb(band.width), std::string(harness::to_string(band.sides)).c_str());
  return wrong_steps ? kExitFound : 0;
}

}  // namespace

void add_maze_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<MazeArgs>();
  auto* cmd = app.add_subcommand("maze", "A disc walks through a generated maze: every wall at every step tested both ways and judged exactly");
  cmd->add_option("--size", args->size, "Cells per side")->capture_default_str()->check(whole_in(1, 200));
  cmd->add_option("--seed", args->seed, "Seed of the maze")->capture_default_str()->check(seed_value());
  cmd->add_option("--radius", args->radius, "The disc's radius in cells, in [0, 0.5)")
      ->capture_default_str()
      ->check(finite_in(0, 0.5));
  cmd->add_option("--substeps", args->substeps, "Positions between two cells' centres")->capture_default_str()->check(whole_in(1, 64));
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace cc::tool
