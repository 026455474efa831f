// crosscheck bvh-report: FCL's env.obj against rob.obj over random and near-contact poses, for
// every volume type, build strategy and update. Per hierarchy: build time, pairs, the counters
// n_v, n_p, n_u per query, query time, how much larger the approximate update's volumes are
// than the exact update's, and how its pair sets stand against the exact reference. FCL's
// BVHModel parties answer the same poses; then collision determination, the library's corners
// of each colliding pair against FCL's contacts.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>

#include "harness/judging/classify.h"
#include "harness/formats/input_json.h"
#include "harness/judging/hull_distance.h"
#include "harness/judging/median.h"
#include "harness/model/input.h"
#include "harness/model/mesh_collide.h"
#include "harness/formats/mesh_files.h"
#include "harness/generation/mesh_poses.h"
#include "harness/generation/choices.h"
#include "collide/mesh_contacts.h"
#include "oracle/exact/exact_meshes.h"
#include "oracle/fcl/parties.h"
#include "tool/output_file.h"
#include "tool/commands.h"
#include "tool/flag_checks.h"

namespace cc::tool {
namespace {

using harness::median;

using harness::Json;
using harness::MeshPair;
using Clock = std::chrono::steady_clock;

// The kind whose answers the report judges: every colliding pair of triangles.
const harness::QueryKind kAllPairsKind = harness::mesh_kind(CollisionMode::all_pairs);

struct ReportArgs {
  int random = 100, near = 100;
  int leaf_size = 1;
  std::uint64_t seed = 1;
  std::string corpora = "corpora";
  std::string json;
};

double ms_since(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

// One pose and what the exact reference says of it.
struct Pose {
  MeshPair m;
  bool near = false;
  harness::ExactVerdict exact;
};

// Totals over the poses for one party (a library hierarchy or an FCL model).
struct Tally {
  std::string name;
  bool counted = true;  // the library's hierarchies count; FCL's models do not
  double build_ms = 0;
  std::uint64_t pairs = 0, n_v = 0, n_p = 0, n_u = 0, update_points = 0;
  int right = 0, within_band = 0, wrong = 0, failed = 0;
  std::vector<double> query_us, tightness;
  void stand(harness::Standing s) {
    right += s == harness::Standing::right;
    within_band += s == harness::Standing::within_band;
    wrong += s == harness::Standing::wrong;
    failed += s == harness::Standing::failed;
  }
};

// How much larger b's moved volumes are with the approximate update than with the exact one:
// the median ratio of their volumes over up to 64 of b's nodes.
template <class BV>
double approximate_over_exact(const Bvh<BV>& b, const RigidTransform& t) {
  std::vector<double> ratios;
  const std::size_t step = std::max<std::size_t>(1, b.nodes.size() / 64);
  for (std::size_t n = 0; n < b.nodes.size(); n += step) {
    const double approx = BoundingVolume<BV>::size(moved_volume(b, n, t, BvUpdate::approximate)).volume;
    const double exact = BoundingVolume<BV>::size(moved_volume(b, n, t, BvUpdate::exact)).volume;
    if (exact > 0) ratios.push_back(approx / exact);
  }
  return median(ratios);
}

Tally run_library(const harness::LibraryBvh& library, const std::vector<Pose>& poses) {
  Tally t;
  t.name = std::string(to_string(library.bv)) + " " + std::string(to_string(library.build.strategy)) + " " +
           std::string(to_string(library.update));
  harness::with_bv_type(library.bv, [&]<class BV>() {
    const auto start = Clock::now();
    const Bvh<BV> a = build_bvh<BV>(*poses[0].m.a.mesh, harness::build_options(library));
    const Bvh<BV> b = build_bvh<BV>(*poses[0].m.b.mesh, harness::build_options(library));
    t.build_ms = ms_since(start);
    for (const Pose& p : poses) {
      const auto q = Clock::now();
      const CollideOptions options{CollisionMode::all_pairs, library.update, library.descent};
      const CollisionResult r = collide(a, p.m.pose_a, b, p.m.pose_b, options);
      t.query_us.push_back(1e3 * ms_since(q));
      t.pairs += r.pairs.size();
      t.n_v += r.counters.bv_tests, t.n_p += r.counters.primitive_tests, t.n_u += r.counters.bv_updates;
      t.update_points += r.counters.update_points;
      harness::Answer answer;
      answer.hit = !r.pairs.empty();
      for (const auto& [fa, fb] : r.pairs) answer.pairs.emplace_back(fa, fb);
      t.stand(harness::classify(kAllPairsKind, answer, p.exact, {}).parties[0].standing);
      if (library.update == BvUpdate::approximate && !harness::moved_whole(library.bv)) {
        t.tightness.push_back(approximate_over_exact(b, relative(p.m.pose_a, p.m.pose_b)));
      }
    }
  });
  return t;
}

Tally run_fcl(const std::string& party, const std::vector<Pose>& poses) {
  Tally t;
  t.name = party;
  t.counted = false;
  for (const Pose& p : poses) {
    const auto q = Clock::now();
    const harness::Opinion o = fcl_oracle::fcl_collide_meshes(party, p.m);
    t.query_us.push_back(1e3 * ms_since(q));
    t.pairs += o.answer.pairs.size();
    const harness::Verdict v = harness::classify(kAllPairsKind, o.answer, p.exact, {o});
    if (v.parties.size() > 1) t.stand(v.parties[1].standing);  // none when the verdict judges no party
  }
  return t;
}

// Collision determination on the poses with a pair: the library's corners of each colliding pair
// (mesh_contacts on the OBB tree's pairs) against FCL's contacts (OBBRSS models, enable_contact):
// the pairs each gives, how many points, the time, and how far FCL's contact points lie from the
// library's corners of the same pair (the hull of a n b, in the world), over the meshes' scale.
struct ContactRow {
  std::size_t poses = 0, library_pairs = 0, pairs_with_corners = 0, corners = 0, fcl_pairs = 0, fcl_contacts = 0;
  std::size_t common_pairs = 0, on_the_intersection = 0, measured = 0;
  std::vector<double> library_us, fcl_us, distance;  // distance: FCL contact to the library's hull, over the scale
};

ContactRow run_contacts(const std::vector<Pose>& poses) {
  ContactRow row;
  const Mesh& ma = *poses[0].m.a.mesh;
  const Mesh& mb = *poses[0].m.b.mesh;
  const Bvh<Obb> a = build_bvh<Obb>(ma, {}), b = build_bvh<Obb>(mb, {});
  double scale = 0;
  for (const Mesh* m : {&ma, &mb}) {
    for (const Vec3& v : m->vertices) scale = std::max(scale, max_abs(v));
  }
  for (const Pose& p : poses) {
    if (!p.exact.answer.hit) continue;
    ++row.poses;
    auto q = Clock::now();
    const CollisionResult r = collide(a, p.m.pose_a, b, p.m.pose_b, {});
    const std::vector<PairContact> mine = mesh_contacts(ma, p.m.pose_a, mb, p.m.pose_b, r.pairs);
    row.library_us.push_back(1e3 * ms_since(q));
    q = Clock::now();
    const std::vector<fcl_oracle::FclContact> theirs = fcl_oracle::fcl_mesh_contacts(p.m);
    row.fcl_us.push_back(1e3 * ms_since(q));
    row.library_pairs += mine.size();
    std::vector<std::pair<std::uint32_t, std::uint32_t>> fcl_pairs;
    for (const auto& c : theirs) fcl_pairs.emplace_back(c.face_a, c.face_b);
    std::sort(fcl_pairs.begin(), fcl_pairs.end());
    fcl_pairs.erase(std::unique(fcl_pairs.begin(), fcl_pairs.end()), fcl_pairs.end());
    row.fcl_pairs += fcl_pairs.size();
    row.fcl_contacts += theirs.size();
    for (const PairContact& c : mine) {
      row.pairs_with_corners += !c.corners.empty();
      row.corners += static_cast<std::size_t>(c.corners.count);
      if (std::binary_search(fcl_pairs.begin(), fcl_pairs.end(), std::pair{c.face_a, c.face_b})) ++row.common_pairs;
      if (c.corners.empty()) continue;
      std::vector<Vec3> world;
      for (int k = 0; k < c.corners.count; ++k) world.push_back(apply(p.m.pose_a, c.corners.points[static_cast<std::size_t>(k)]));
      for (const auto& f : theirs) {
        if (f.face_a != c.face_a || f.face_b != c.face_b) continue;
        const double d = harness::distance_to_hull(f.position, world) / scale;
        row.distance.push_back(d);
        ++row.measured;
        row.on_the_intersection += d <= 0x1p-30;
      }
    }
  }
  return row;
}

// Lazy top-down trees of one volume type, both made anew for each pose of one kind (near
// contact or not): the nodes made per query against the whole trees', and the query's time,
// the making of its nodes included.
struct LazyRow {
  std::string name;
  double nodes_made = 0, nodes_total = 0, median_us = 0;
  std::size_t poses = 0;
};

LazyRow run_lazy(harness::BvType bv, const std::vector<Pose>& poses, bool near, int leaf_size) {
  LazyRow row;
  row.name = std::string(to_string(bv)) + (near ? " near" : " random");
  harness::with_bv_type(bv, [&]<class BV>() {
    BuildOptions build;
    build.leaf_size = leaf_size;
    const Mesh &a = *poses[0].m.a.mesh, &b = *poses[0].m.b.mesh;
    row.nodes_total = static_cast<double>(build_bvh<BV>(a, build).nodes.size() + build_bvh<BV>(b, build).nodes.size());
    std::vector<double> us;
    std::size_t made = 0;
    for (const Pose& p : poses) {
      if (p.near != near) continue;
      const auto start = Clock::now();
      LazyBvh<BV> la(a, build), lb(b, build);
      collide(la, p.m.pose_a, lb, p.m.pose_b, CollideOptions{});
      us.push_back(1e3 * ms_since(start));
      made += la.nodes_made() + lb.nodes_made();
    }
    row.poses = us.size();
    row.nodes_made = us.empty() ? 0 : static_cast<double>(made) / static_cast<double>(us.size());
    row.median_us = median(us);
  });
  return row;
}

std::vector<harness::LibraryBvh> every_hierarchy(int leaf_size) {
  std::vector<harness::LibraryBvh> out;
  for (harness::BvType bv : harness::kAllBvTypes) {
    for (BuildStrategy s : {BuildStrategy::top_down, BuildStrategy::bottom_up, BuildStrategy::incremental}) {
      for (BvUpdate u : {BvUpdate::approximate, BvUpdate::exact, BvUpdate::hill_climbing}) {
        if (harness::moved_whole(bv) && u != BvUpdate::approximate) continue;  // an OBB or a ball moves as it is
        harness::LibraryBvh l;
        l.bv = bv;
        l.build.strategy = s;
        l.build.leaf_size = leaf_size;  // top-down only: the other builds put one triangle in a leaf
        l.update = u;
        out.push_back(l);
      }
    }
  }
  return out;
}

void print_row(const Tally& t, std::size_t queries) {
  const double q = static_cast<double>(queries);
  const auto cell = [&](double x, const char* format) {
    char text[32] = "-";
    if (t.counted) std::snprintf(text, sizeof text, format, x);
    return std::string(text);
  };
  char tight[32] = "-", points[32] = "-";
  if (!t.tightness.empty()) std::snprintf(tight, sizeof tight, "%.2f", median(t.tightness));
  if (t.update_points > 0) {
    std::snprintf(points, sizeof points, "%.1f", static_cast<double>(t.update_points) / static_cast<double>(t.n_u));
  }
  std::printf("%-38s %9s %7llu %10s %10s %10s %9s %12.1f %9s %6d %6d %6d %6d\n", t.name.c_str(),
              cell(t.build_ms, "%.1f").c_str(), static_cast<unsigned long long>(t.pairs),
              cell(static_cast<double>(t.n_v) / q, "%.0f").c_str(), cell(static_cast<double>(t.n_p) / q, "%.0f").c_str(),
              cell(static_cast<double>(t.n_u) / q, "%.0f").c_str(), points, median(t.query_us), tight, t.right,
              t.within_band, t.wrong, t.failed);
}

Json row_json(const Tally& t) {
  return {{"name", t.name},       {"build_ms", t.build_ms},       {"pairs", t.pairs},
          {"n_v", t.n_v},         {"n_p", t.n_p},                 {"n_u", t.n_u},
          {"update_points", t.update_points},
          {"median_query_us", median(t.query_us)},
          {"approximate_over_exact_volume", t.tightness.empty() ? Json() : Json(median(t.tightness))},
          {"right", t.right},     {"within_band", t.within_band}, {"wrong", t.wrong},
          {"failed", t.failed}};
}

// The poses: --random ones drawn as FCL's test draws them, then --near ones bisected to contact,
// each with the exact reference's answer.
std::vector<Pose> draw_poses(const ReportArgs& args, const MeshPair& base) {
  harness::RandomChoices c(args.seed);
  std::vector<Pose> poses;
  for (int i = 0; i < args.random + args.near; ++i) {
    Pose p{base, i >= args.random, {}};
    if (p.near) {
      p.m.pose_b.rotation = harness::fcl_style_rotation(c);
      harness::bisect_to_contact(p.m, c);  // with the default hierarchy: OBB, top-down
    } else {
      p.m.pose_b = harness::fcl_style_pose(c);
    }
    p.exact = exact::judge_meshes(p.m);
    poses.push_back(std::move(p));
  }
  return poses;
}

// The lazy top-down trees' table (printed), one row per volume type and kind of pose.
Json print_lazy_rows(const std::vector<Pose>& poses, int leaf_size) {
  std::printf("\n%-38s %6s %16s %16s %9s %12s\n", "lazy top-down (volume poses)", "poses", "nodes made/query",
              "of whole trees", "made %", "median us");
  Json lazy_rows = Json::array();
  for (harness::BvType bv : harness::kAllBvTypes) {
    for (bool near : {false, true}) {
      const LazyRow r = run_lazy(bv, poses, near, leaf_size);
      if (r.poses == 0) continue;
      std::printf("%-38s %6zu %16.1f %16.0f %8.1f%% %12.1f\n", r.name.c_str(), r.poses, r.nodes_made, r.nodes_total,
                  100 * r.nodes_made / r.nodes_total, r.median_us);
      lazy_rows.push_back({{"name", r.name},
                           {"poses", r.poses},
                           {"nodes_made_per_query", r.nodes_made},
                           {"nodes_total", r.nodes_total},
                           {"median_query_us", r.median_us}});
    }
  }
  return lazy_rows;
}

// Collision determination (printed): the library's pairs and corners against FCL's contacts;
// null when no pose has a colliding pair.
Json print_contacts(const std::vector<Pose>& poses) {
  const ContactRow contacts = run_contacts(poses);
  Json contact_json;
  if (contacts.poses > 0) {
    std::vector<double> sorted = contacts.distance;
    std::sort(sorted.begin(), sorted.end());
    const auto at = [&sorted](double f) { return sorted.empty() ? 0.0 : sorted[static_cast<std::size_t>(f * static_cast<double>(sorted.size() - 1))]; };
    std::printf("\ncollision determination over %zu poses with a pair:\n", contacts.poses);
    std::printf("  library (obb top-down, mesh_contacts): %zu pairs, %zu with corners, %.2f corners per pair, median %.1f us "
                "(pairs and corners)\n",
                contacts.library_pairs, contacts.pairs_with_corners, contacts.pairs_with_corners ? double(contacts.corners) / double(contacts.pairs_with_corners) : 0.0,
                median(contacts.library_us));
    std::printf("  FCL (OBBRSS, enable_contact): %zu pairs, %zu of them the library's, %.2f contacts per pair, median %.1f us\n",
                contacts.fcl_pairs, contacts.common_pairs, contacts.fcl_pairs ? double(contacts.fcl_contacts) / double(contacts.fcl_pairs) : 0.0, median(contacts.fcl_us));
    std::printf("  FCL's contact points from the library's corners of the same pair (hull of a n b), over the scale: "
                "median %.3g, 90%% %.3g, max %.3g; on it (within 2^-30): %zu of %zu\n",
                at(0.5), at(0.9), at(1.0), contacts.on_the_intersection, contacts.measured);
    contact_json = {{"poses", contacts.poses},
                    {"library_pairs", contacts.library_pairs},
                    {"pairs_with_corners", contacts.pairs_with_corners},
                    {"corners", contacts.corners},
                    {"library_median_us", median(contacts.library_us)},
                    {"fcl_pairs", contacts.fcl_pairs},
                    {"common_pairs", contacts.common_pairs},
                    {"fcl_contacts", contacts.fcl_contacts},
                    {"fcl_median_us", median(contacts.fcl_us)},
                    {"fcl_contact_distance_median", at(0.5)},
                    {"fcl_contact_distance_max", at(1.0)},
                    {"fcl_contacts_on_the_intersection", contacts.on_the_intersection}};
  }
  return contact_json;
}

int run(const ReportArgs& args) {
  if (args.random + args.near == 0) {
    std::fprintf(stderr, "crosscheck bvh-report: --random and --near are both 0: no pose to report on (give one at least 1)\n");
    return kExitBadInput;
  }
  const auto folder = harness::mesh_folder(args.corpora);
  const auto env = harness::find_mesh_file("env.obj", folder), rob = harness::find_mesh_file("rob.obj", folder);
  if (!env || !rob) {
    std::fprintf(stderr, "crosscheck bvh-report: env.obj and rob.obj not found in %s\n", folder.string().c_str());
    return kExitBadInput;
  }
  MeshPair base;
  base.a.source = base.b.source = harness::MeshRef::Source::file;
  base.a.file = "meshes/env.obj", base.b.file = "meshes/rob.obj";
  base.a.mesh = harness::load_mesh_file(*env), base.b.mesh = harness::load_mesh_file(*rob);

  const std::vector<Pose> poses = draw_poses(args, base);
  std::size_t exact_pairs = 0, colliding = 0;
  for (const Pose& p : poses) exact_pairs += p.exact.answer.pairs.size(), colliding += p.exact.answer.hit;
  std::printf("env.obj (%zu triangles) against rob.obj (%zu triangles): %d random poses (as FCL's test draws them), "
              "%d near contact; seed %llu\n",
              base.a.mesh->size(), base.b.mesh->size(), args.random, args.near, static_cast<unsigned long long>(args.seed));
  std::printf("exact reference: %zu colliding pairs over %zu poses with a pair; top-down builds: longest side, midpoint, "
              "%d triangle(s) per leaf\n\n",
              exact_pairs, colliding, args.leaf_size);
  std::printf("%-38s %9s %7s %10s %10s %10s %9s %12s %9s %6s %6s %6s %6s\n", "hierarchy (volume build update)",
              "build ms", "pairs", "n_v/query", "n_p/query", "n_u/query", "pts/upd", "median us", "apx/exact", "right",
              "band", "wrong", "failed");
  Json rows = Json::array();
  for (const harness::LibraryBvh& l : every_hierarchy(args.leaf_size)) {
    const Tally t = run_library(l, poses);
    print_row(t, poses.size());
    rows.push_back(row_json(t));
  }
  std::printf("\n");
  for (const std::string& party : fcl_oracle::fcl_mesh_parties()) {
    const Tally t = run_fcl(party, poses);
    print_row(t, poses.size());
    rows.push_back(row_json(t));
  }
  const Json lazy_rows = print_lazy_rows(poses, args.leaf_size);
  const Json contact_json = print_contacts(poses);
  std::printf("\nn_v, n_p, n_u: volume tests, triangle tests and volume updates per query (all pairs, descent into a's\n"
              "hierarchy). pts/upd: hull points per update that the exact update moves, or that hill climbing\n"
              "evaluates on its walks (plus the exact update's when a walk is not certified). apx/exact: median ratio of the approximate update's moved volume to the exact update's.\n"
              "right/band/wrong: poses whose pair set equals the exact one / differs only within the band / beyond it.\n"
              "lazy top-down: both trees made anew per query (top-down, longest side, midpoint), all pairs; the time\n"
              "includes making the nodes the query needs.\n"
              "collision determination: FCL's contacts are the deepest vertices of one triangle below the other's\n"
              "plane, not points where the triangles meet; the distance says how far from a n b they lie.\n");
  if (!args.json.empty()) {
    const std::string why = write_output_file(
        args.json, Json{{"seed", args.seed}, {"random", args.random}, {"near", args.near}, {"exact_pairs", exact_pairs},
                        {"rows", rows}, {"lazy", lazy_rows}, {"contacts", contact_json}}.dump(2) + "\n");
    if (!why.empty()) {
      std::fprintf(stderr, "crosscheck bvh-report: %s\n", why.c_str());
      return kExitIncomplete;
    }
  }
  return 0;
}

}  // namespace

void add_bvh_report_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ReportArgs>();
  auto* cmd = app.add_subcommand("bvh-report", "env.obj against rob.obj for every hierarchy: counters, times, FCL, exact");
  cmd->add_option("--random", args->random, "Poses drawn as FCL's test draws them")
      ->capture_default_str()
      ->check(whole_in(0, 1000000));
  cmd->add_option("--near", args->near, "Poses brought to near contact")->capture_default_str()->check(whole_in(0, 1000000));
  cmd->add_option("--leaf-size", args->leaf_size, "Triangles per leaf of a top-down build")
      ->capture_default_str()
      ->check(whole_in(1, 1024));
  cmd->add_option("--seed", args->seed, "Seed of the poses")->capture_default_str()->check(seed_value());
  cmd->add_option("--corpora", args->corpora, "The corpus root (its meshes/ folder has the meshes)")
      ->capture_default_str()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--json", args->json, "Also write the table as JSON")->check(writable_file());
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace cc::tool
