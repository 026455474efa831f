// crosscheck car: rays as probes. A car drives over a terrain; each step prints the signed
// distance of its four wheels to the road (0 on it, > 0 above, < 0 into it) and the height the
// simple response gives the car. Every probe is checked against brute force over all triangles.
#include <cmath>
#include <cstdio>

#include "collide/ray_mesh.h"
#include "tool/scenes/car_on_road.h"
#include "tool/commands.h"
#include "tool/flag_checks.h"

namespace cc::tool {
namespace {

struct CarArgs {
  int steps = 100;
  std::uint64_t seed = 1;
};

int run(const CarArgs& args) {
  harness::CarOnRoad car(args.seed);
  std::printf("%5s %10s %10s %10s %10s %10s %12s\n", "step", "front L", "front R", "rear L", "rear R", "car z", "brute force");
  int mismatches = 0;
  for (int step = 0; step < args.steps; ++step) {
    const auto wheels = car.step();
    bool same = true;
    for (const harness::WheelProbe& w : wheels) {
      const RayMeshHit brute = ray_mesh_brute_force(car.road(), w.ray);
      same = same && brute.hit == w.hit.hit && (!brute.hit || (brute.t == w.hit.t && brute.face == w.hit.face));
    }
    mismatches += !same;
    std::printf("%5d %10.5f %10.5f %10.5f %10.5f %10.5f %12s\n", step, wheels[2].distance, wheels[3].distance,
                wheels[0].distance, wheels[1].distance, car.height(), same ? "same" : "DIFFERS");
  }
  std::printf("\n%d of %d steps differ from brute force (closest hit t and face of every wheel's ray)\n", mismatches,
              args.steps);
  return mismatches ? kExitFound : 0;
}

}  // namespace

void add_car_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CarArgs>();
  auto* cmd = app.add_subcommand("car", "A car on a road probed by four wheel rays: signed distances and the response per step");
  cmd->add_option("--steps", args->steps, "Steps to drive")->capture_default_str()->check(whole_in(1, 1000000));
  cmd->add_option("--seed", args->seed, "Seed of the terrain")->capture_default_str()->check(seed_value());
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace cc::tool
