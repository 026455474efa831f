// crosscheck scene: rocks tumbling down a slope through the two-level pipeline (sweep-and-prune,
// then BVH-vs-BVH), each frame timed per level and checked against brute force (every pair of
// fitted boxes, then collide) and against FCL's pipeline with each broad-phase manager; object
// pairs on which FCL differs are judged by the exact reference and classified (as answers of the
// query for every colliding pair of triangles of two meshes).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

#include "collide/box_pairs.h"
#include "collide/collision_world.h"
#include "harness/judging/classify.h"
#include "harness/formats/input_json.h"
#include "harness/judging/median.h"
#include "harness/model/input.h"
#include "harness/model/mesh_collide.h"
#include "tool/output_file.h"
#include "tool/scenes/rock_slide.h"
#include "oracle/exact/exact_meshes.h"
#include "oracle/fcl/fcl_oracle.h"
#include "oracle/fcl/fcl_scene.h"
#include "tool/commands.h"
#include "tool/flag_checks.h"

namespace cc::tool {
namespace {

// The kind whose answers the scene judges: every colliding pair of triangles of two meshes.
const harness::QueryKind kAllPairsKind = harness::mesh_kind(CollisionMode::all_pairs);

// The party the scene's FCL pipeline stands for, and its band as oracle/fcl declares it.
const std::string kFclParty = "fcl.BVHModel<OBBRSSd>";
harness::Band fcl_party_band() {
  for (const harness::PartyBand& p : fcl_oracle::FclSecondOpinion().parties(kAllPairsKind)) {
    if (p.party == kFclParty) return p.band;
  }
  throw std::logic_error("oracle/fcl declares no party " + kFclParty);
}

using harness::median;

using Clock = std::chrono::steady_clock;

struct SceneArgs {
  int objects = 300, frames = 500;
  std::uint64_t seed = 1;
  std::string bv = "obb";
  std::string bounds = "refit";
  std::vector<std::string> managers;
  bool quiet = false;
  std::string json;
  std::string boxes_case;
};

double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

std::size_t triangle_pairs(const std::vector<ObjectContact>& contacts) {
  std::size_t n = 0;
  for (const ObjectContact& c : contacts) n += c.triangles.size();
  return n;
}

// Per FCL manager: its times, and the object pairs on which it differs, by class.
struct ManagerTally {
  std::vector<double> ms;
  std::size_t candidates = 0, differing = 0;
  std::map<harness::CaseClass, int> classes;
};

// The object pairs (with their triangle pairs) where two pipelines differ.
std::vector<ObjectPair> differing(const std::vector<ObjectContact>& x, const std::vector<ObjectContact>& y) {
  std::map<ObjectPair, const ObjectContact*> in_y;
  for (const ObjectContact& c : y) in_y[c.objects] = &c;
  std::vector<ObjectPair> out;
  for (const ObjectContact& c : x) {
    auto it = in_y.find(c.objects);
    if (it == in_y.end() || it->second->triangles != c.triangles) out.push_back(c.objects);
    if (it != in_y.end()) in_y.erase(it);
  }
  for (const auto& [pair, c] : in_y) out.push_back(pair);
  std::sort(out.begin(), out.end());
  return out;
}

const std::vector<std::pair<std::uint32_t, std::uint32_t>>* triangles_of(const std::vector<ObjectContact>& contacts,
                                                                         const ObjectPair& p) {
  for (const ObjectContact& c : contacts) {
    if (c.objects == p) return &c.triangles;
  }
  return nullptr;
}

harness::Answer answer_of(const std::vector<std::pair<std::uint32_t, std::uint32_t>>* triangles) {
  harness::Answer a;
  if (triangles != nullptr) {
    for (const auto& [x, y] : *triangles) a.pairs.emplace_back(x, y);
  }
  a.hit = !a.pairs.empty();
  return a;
}

template <class BV>
using Hierarchies = std::map<const Mesh*, std::shared_ptr<const Bvh<BV>>>;

// Brute force for a frame: every pair of fitted boxes, then collide (the same leaf computations
// as the pipeline's, so the contacts are equal).
template <class BV>
std::vector<ObjectContact> brute_force_contacts(const harness::RockSlide& slide, const Hierarchies<BV>& hierarchies) {
  std::vector<Aabb> boxes;
  for (std::size_t i = 0; i < slide.size(); ++i) boxes.push_back(fitted_box(*slide.mesh_of(i), slide.pose_of(i)));
  std::vector<ObjectContact> brute;
  for (const auto& [a, b] : box_pairs_brute_force(boxes)) {
    CollisionResult r = collide(*hierarchies.at(slide.mesh_of(a).get()), slide.pose_of(a),
                                *hierarchies.at(slide.mesh_of(b).get()), slide.pose_of(b), CollideOptions{});
    if (!r.pairs.empty()) brute.push_back({{a, b}, std::move(r.pairs)});
  }
  return brute;
}

// The object pairs on which an FCL manager's contacts (`theirs`) differ from the library's
// (`ours`), each judged by the exact reference and classified into `tally`; impl_bug and
// oracle_defect pairs are printed unless --quiet. Returns how many differ.
std::size_t judge_differences(const SceneArgs& args, int frame, const std::string& manager, harness::BvType bv_type,
                              const harness::RockSlide& slide, const std::vector<ObjectContact>& ours,
                              const std::vector<ObjectContact>& theirs, ManagerTally& tally) {
  static const harness::Band fcl_band = fcl_party_band();
  const std::vector<ObjectPair> diff = differing(ours, theirs);
  tally.differing += diff.size();
  for (const ObjectPair& p : diff) {
    harness::MeshPair mp;
    mp.a = harness::triangles_mesh(*slide.mesh_of(p.first));
    mp.b = harness::triangles_mesh(*slide.mesh_of(p.second));
    mp.pose_a = slide.pose_of(p.first), mp.pose_b = slide.pose_of(p.second);
    mp.library.bv = bv_type;
    const harness::Opinion said{kFclParty, harness::Opinion::Status::answered, answer_of(triangles_of(theirs, p)), "",
                                fcl_band};
    const harness::Verdict v =
        harness::classify(kAllPairsKind, answer_of(triangles_of(ours, p)), exact::judge_meshes(mp), {said});
    ++tally.classes[v.cls];
    if ((v.cls == harness::CaseClass::impl_bug || v.cls == harness::CaseClass::oracle_defect) && !args.quiet) {
      std::string why;
      for (const harness::PartyStanding& s : v.parties) why += s.why.empty() ? "" : " " + s.party + ": " + s.why;
      std::printf("frame %d, %s: rocks %u and %u: %s;%s\n", frame, manager.c_str(), p.first, p.second,
                  std::string(to_string(v.cls)).c_str(), why.c_str());
    }
  }
  return diff.size();
}

// The library's side of the run, over all frames.
struct LibraryTally {
  std::vector<double> broad_ms, narrow_ms;
  std::size_t candidates = 0, colliding = 0, tri_pairs = 0, brute_mismatches = 0;
  std::uint64_t swaps = 0;
};

// The summary on standard output, and the --json file.
void report_scene(const SceneArgs& args, const std::vector<std::string>& managers, const LibraryTally& library,
                  const std::vector<ManagerTally>& tallies) {
  const double frames = args.frames;
  const auto per_frame = [frames](std::size_t total) { return static_cast<double>(total) / frames; };
  std::printf("\n%d rocks (%s trees, %s bounds), %d frames, seed %llu\n", args.objects, args.bv.c_str(), args.bounds.c_str(),
              args.frames, static_cast<unsigned long long>(args.seed));
  std::printf("library: broad phase %.3f ms, narrow phase %.3f ms per frame (medians); per frame %.1f candidates, "
              "%.1f colliding object pairs, %.1f triangle pairs; %llu swaps in all\n",
              median(library.broad_ms), median(library.narrow_ms), per_frame(library.candidates),
              per_frame(library.colliding), per_frame(library.tri_pairs), static_cast<unsigned long long>(library.swaps));
  std::printf("brute force (every pair of fitted boxes, then collide): %zu object pairs differ over all frames\n",
              library.brute_mismatches);
  std::printf("\n%-22s %10s %12s %10s  %s\n", "FCL manager", "ms/frame", "candidates", "differ", "classes of the differing pairs");
  harness::Json managers_json = harness::Json::object();
  for (std::size_t m = 0; m < managers.size(); ++m) {
    std::string classes;
    harness::Json classes_json = harness::Json::object();
    for (const auto& [cls, n] : tallies[m].classes) {
      classes += std::string(to_string(cls)) + " " + std::to_string(n) + "  ";
      classes_json[std::string(to_string(cls))] = n;
    }
    std::printf("%-22s %10.3f %12.1f %10zu  %s\n", managers[m].c_str(), median(tallies[m].ms), per_frame(tallies[m].candidates),
                tallies[m].differing, classes.empty() ? "-" : classes.c_str());
    managers_json[managers[m]] = {{"median_ms", median(tallies[m].ms)}, {"candidates_per_frame", per_frame(tallies[m].candidates)},
                                  {"differing_pairs", tallies[m].differing}, {"classes", classes_json}};
  }
  std::printf("(FCL: the manager's update and collide, with BVHModel<OBBRSSd> collide on each candidate, all contacts)\n");
  if (!args.json.empty()) {
    const std::string why = write_output_file(
        args.json,
        harness::Json{{"objects", args.objects}, {"frames", args.frames}, {"seed", args.seed}, {"bv", args.bv},
                      {"bounds", args.bounds}, {"median_broad_ms", median(library.broad_ms)},
                      {"median_narrow_ms", median(library.narrow_ms)}, {"candidates_per_frame", per_frame(library.candidates)},
                      {"colliding_per_frame", per_frame(library.colliding)},
                      {"triangle_pairs_per_frame", per_frame(library.tri_pairs)},
                      {"brute_force_mismatches", library.brute_mismatches}, {"managers", managers_json}}
                .dump(2) +
            "\n");
    if (!why.empty()) throw std::runtime_error(why);
  }
}

// FCL's world box (for spatial hashing): the objects' boxes and some room around them.
template <class BV>
Aabb fcl_world_box(const CollisionWorld<BV>& world, std::size_t objects) {
  Aabb box{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
  for (std::size_t i = 0; i < objects; ++i) {
    const Aabb b = world.box_of(static_cast<ObjectId>(i));
    for (int k = 0; k < 3; ++k) box.lo[k] = std::min(box.lo[k], b.lo[k] - 50), box.hi[k] = std::max(box.hi[k], b.hi[k] + 50);
  }
  return box;
}

template <class BV>
int run_scene(const SceneArgs& args, harness::BvType bv_type) {
  harness::RockSlide slide({args.objects, args.seed, 20});
  const RotationBounds bounds = args.bounds == "cube"     ? RotationBounds::bounding_cube
                                : args.bounds == "sphere" ? RotationBounds::bounding_sphere
                                                          : RotationBounds::refit;
  CollisionWorld<BV> world(bounds);
  Hierarchies<BV> hierarchies;
  for (const auto& mesh : slide.shapes()) hierarchies[mesh.get()] = std::make_shared<const Bvh<BV>>(build_bvh<BV>(*mesh, {}));
  for (std::size_t i = 0; i < slide.size(); ++i) world.add(slide.mesh_of(i), hierarchies.at(slide.mesh_of(i).get()), slide.pose_of(i));
  const Aabb world_box = fcl_world_box(world, slide.size());
  const std::vector<std::string> managers = args.managers.empty() ? fcl_oracle::FclScene::managers() : args.managers;
  std::vector<std::unique_ptr<fcl_oracle::FclScene>> fcl;
  for (const std::string& m : managers) {
    fcl.push_back(std::make_unique<fcl_oracle::FclScene>(m, world_box));
    for (std::size_t i = 0; i < slide.size(); ++i) fcl.back()->add(slide.mesh_of(i), slide.pose_of(i));
  }
  std::vector<ManagerTally> tallies(managers.size());
  LibraryTally library;
  harness::BoxFrames fcl_boxes;  // the boxes FCL's first manager saw, per frame, for --boxes-case
  if (!args.quiet) {
    std::printf("%6s %9s %10s %10s %10s %10s %8s %9s %9s\n", "frame", "broad ms", "narrow ms", "candidates", "colliding",
                "tri pairs", "swaps", "FCL ms", "FCL diff");
  }
  for (int frame = 0; frame < args.frames; ++frame) {
    for (std::size_t i = 0; i < slide.size(); ++i) world.move(static_cast<ObjectId>(i), slide.pose_of(i));
    auto t = Clock::now();
    const std::vector<ObjectPair> pairs = world.broad_phase();
    library.broad_ms.push_back(ms_since(t));
    t = Clock::now();
    const std::vector<ObjectContact> contacts = world.narrow_phase();
    library.narrow_ms.push_back(ms_since(t));
    library.candidates += pairs.size(), library.colliding += contacts.size(), library.tri_pairs += triangle_pairs(contacts);
    const std::uint64_t swaps = world.sweep().swaps() - library.swaps;
    library.swaps = world.sweep().swaps();
    const std::size_t mismatched = differing(contacts, brute_force_contacts(slide, hierarchies)).size();
    library.brute_mismatches += mismatched;

    double fcl_ms_first = 0;
    std::size_t fcl_diff_first = 0;
    for (std::size_t m = 0; m < managers.size(); ++m) {
      for (std::size_t i = 0; i < slide.size(); ++i) fcl[m]->move(i, slide.pose_of(i));
      std::size_t fcl_candidates = 0;
      t = Clock::now();
      const std::vector<ObjectContact> theirs = fcl[m]->collide(fcl_candidates);
      tallies[m].ms.push_back(ms_since(t));
      tallies[m].candidates += fcl_candidates;
      const std::size_t diff = judge_differences(args, frame, managers[m], bv_type, slide, contacts, theirs, tallies[m]);
      if (m == 0) fcl_ms_first = tallies[m].ms.back(), fcl_diff_first = diff;
    }
    if (!args.boxes_case.empty() && !fcl.empty()) {
      auto& frame_boxes = fcl_boxes.emplace_back();
      for (const Aabb& b : fcl.front()->boxes()) frame_boxes.emplace_back(b);
    }
    if (!args.quiet) {
      std::printf("%6d %9.3f %10.3f %10zu %10zu %10zu %8llu %9.3f %9zu%s\n", frame, library.broad_ms.back(),
                  library.narrow_ms.back(), pairs.size(), contacts.size(), triangle_pairs(contacts),
                  static_cast<unsigned long long>(swaps), fcl_ms_first, fcl_diff_first,
                  mismatched ? "  BRUTE FORCE DIFFERS" : "");
    }
    slide.step();
  }
  report_scene(args, managers, library, tallies);
  if (!args.boxes_case.empty()) {
    const std::string why =
        write_output_file(args.boxes_case, harness::input_to_json(harness::box_frames_input(std::move(fcl_boxes))).dump() + "\n");
    if (!why.empty()) throw std::runtime_error(why);
  }
  bool wrong = library.brute_mismatches > 0;
  for (const ManagerTally& t : tallies) wrong = wrong || t.classes.count(harness::CaseClass::impl_bug) > 0;
  return wrong ? kExitFound : 0;
}

int run(const SceneArgs& args) {
  const auto bv = harness::bv_type_named(args.bv);
  if (!bv) {
    std::fprintf(stderr, "crosscheck scene: unknown volume type \"%s\"\n", args.bv.c_str());
    return kExitBadInput;
  }
  if (args.bounds != "refit" && args.bounds != "cube" && args.bounds != "sphere") {
    std::fprintf(stderr, "crosscheck scene: --bounds is refit, cube or sphere, not \"%s\"\n", args.bounds.c_str());
    return kExitBadInput;
  }
  for (const std::string& m : args.managers) {
    const auto all = fcl_oracle::FclScene::managers();
    if (std::find(all.begin(), all.end(), m) == all.end()) {
      std::fprintf(stderr, "crosscheck scene: unknown FCL manager \"%s\"\n", m.c_str());
      return kExitBadInput;
    }
  }
  return harness::with_bv_type(*bv, [&]<class BV>() { return run_scene<BV>(args, *bv); });
}

}  // namespace

void add_scene_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<SceneArgs>();
  auto* cmd = app.add_subcommand("scene", "Rocks down a slope through sweep-and-prune and BVH-vs-BVH, checked against brute force and FCL");
  cmd->add_option("--objects", args->objects, "Rocks")->capture_default_str()->check(whole_in(1, 100000));
  cmd->add_option("--frames", args->frames, "Frames")->capture_default_str()->check(whole_in(1, 1000000));
  cmd->add_option("--seed", args->seed, "Seed of the scene")->capture_default_str()->check(seed_value());
  cmd->add_option("--bv", args->bv, "Volume type of the library's trees (aabb, obb, kdop6 ... kdop26, sphere)")->capture_default_str();
  cmd->add_option("--bounds", args->bounds, "Bounds of rotating rocks: refit (a box per frame), cube (any rotation) or sphere (a ball, moved)")->capture_default_str();
  cmd->add_option("--manager", args->managers, "FCL broad-phase managers to check against (repeat; default: all seven)");
  cmd->add_flag("--quiet", args->quiet, "Only the summary, not a line per frame");
  cmd->add_option("--json", args->json, "Also write the summary as JSON")->check(writable_file());
  cmd->add_option("--boxes-case", args->boxes_case,
                  "Write the boxes FCL's managers saw, every frame, as the inputs of a case of the query on boxes over "
                  "frames (for `crosscheck add`)")
      ->check(writable_file());
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace cc::tool
