#include "harness/shrinking/shrink.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <vector>

#include "harness/formats/input_json.h"
#include "harness/formats/number_text.h"
#include "harness/shrinking/shrink_faces.h"
#include "harness/shrinking/shrink_lists.h"
#include "harness/shrinking/signature.h"
#include "harness/model/kind_pieces.h"

namespace cc::harness {
namespace {

// A shrunk mesh case is written with its triangles only if it has at most this many.
constexpr std::size_t kMaxWrittenFaces = 64;

// The same double, bit for bit (NaN equal to NaN, -0 not equal to 0).
bool same_value(double a, double b) { return format_double(a) == format_double(b); }

// Mantissa bits a finite nonzero double needs (1 for powers of two, up to 53).
int mantissa_bits(double x) {
  int e = 0;
  double m = std::fabs(std::frexp(x, &e));  // in [0.5, 1)
  int bits = 0;
  while (m != 0 && bits < 60) {
    m = m * 2 - std::floor(m * 2);
    ++bits;
  }
  return std::max(bits, 1);
}

// What the shrinker can simplify besides single values, found by a walk over the input's fields:
// frames (a box's axes, any orthonormal frame; a pose's rotation, a proper one), point sets to
// thin out, and, before the values, meshes, boxes over frames and lists of parts (walls) to cut
// down.
struct Targets {
  struct Frame {
    std::string pointer;
    bool proper;
  };
  std::vector<Frame> frames;
  std::vector<std::string> point_sets;
  std::vector<std::pair<std::string, const MeshPair*>> mesh_pairs;
  std::vector<std::pair<std::string, const MeshRef*>> meshes;
  std::vector<std::pair<std::string, const BoxFrames*>> box_frames;
  std::vector<std::pair<std::string, std::size_t>> lists;  // lists of parts (walls), with their sizes
  bool first_hit = false;  // a query for the first colliding pair
};

template <class T, class As>
void collect(const T& value, const std::string& pointer, Targets& out) {
  if constexpr (std::is_same_v<T, Mat3>) {
    out.frames.push_back({pointer, std::is_same_v<As, AsRotation>});
  } else if constexpr (std::is_same_v<T, std::vector<Vec3>>) {
    out.point_sets.push_back(pointer);
  } else if constexpr (std::is_same_v<T, MeshRef>) {
    out.meshes.emplace_back(pointer, &value);
  } else if constexpr (std::is_same_v<T, BoxFrames>) {
    out.box_frames.emplace_back(pointer, &value);
  } else if constexpr (PartList<T>) {
    out.lists.emplace_back(pointer, value.size());
  } else if constexpr (HasFields<T>) {
    if constexpr (std::is_same_v<T, MeshPair>) out.mesh_pairs.emplace_back(pointer, &value);
    for_each_field<T>([&](const auto& f) {
      using F = std::decay_t<decltype(f)>;
      if constexpr (std::is_same_v<T, MeshPair> && std::is_same_v<typename F::Type, MeshRef>) return;  // cut as a pair
      collect<typename F::Type, typename F::As>(F::of(value), f.inline_part() ? pointer : pointer + "/" + std::string(f.name), out);
    });
  }
}

Targets targets_of(const Input& input) {
  Targets t;
  std::visit([&t]<class In>(const In& in) { collect<In, Plain>(in, "", t); }, input);
  t.first_hit = pieces_of(kind_of(input)).judged == Judged::first_pair;
  return t;
}

// The identity first, then the other 47 signed permutation matrices: the simplest frames, exactly
// orthonormal; only the 24 proper rotations among them if asked. (As columns or rows alike: the
// set is closed under transposition.)
std::vector<Json> simple_frames(bool proper_only) {
  std::vector<Json> out;
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  const bool odd[6] = {false, true, true, false, false, true};
  for (int k = 0; k < 6; ++k) {
    const auto& p = perms[k];
    for (int signs = 0; signs < 8; ++signs) {
      if (proper_only && odd[k] != (std::popcount(static_cast<unsigned>(signs)) % 2 == 1)) continue;
      Json m = Json::array();
      for (int j = 0; j < 3; ++j) {
        Vec3 column;
        column[p[j]] = (signs >> j) & 1 ? -1.0 : 1.0;
        m.push_back(Json::array({number_to_json(column.x), number_to_json(column.y), number_to_json(column.z)}));
      }
      out.push_back(m);
    }
  }
  return out;
}

// The leaves of a JSON document that hold numbers, as JSON pointers.
void number_leaves(const Json& j, const std::string& pointer, std::vector<std::string>& out) {
  if (j.is_string()) {
    if (parse_double(j.get<std::string>())) out.push_back(pointer);
    return;
  }
  if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) number_leaves(j[i], pointer + "/" + std::to_string(i), out);
  } else if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) number_leaves(it.value(), pointer + "/" + it.key(), out);
  }
}

// Simpler values to try in place of x, simplest first: 0, small integers toward x, halves,
// values of the case that are simpler, and x with fewer mantissa bits.
std::vector<double> candidates(double x, const std::vector<double>& in_case) {
  std::vector<double> c;
  const auto add = [&](double y) {
    if (complexity(y) < complexity(x)) c.push_back(y);
  };
  add(0.0);
  if (!std::isfinite(x)) return c;
  const double t = std::trunc(x);
  for (double m = 1; m < std::fabs(t) && m <= 0x1p20; m *= 2) add(std::copysign(m, x));
  add(t);
  add(std::round(x));
  add(std::floor(x * 2) / 2);
  add(std::ceil(x * 2) / 2);
  add(std::round(x * 2) / 2);
  for (double y : in_case) add(y);
  int e = 0;
  const double m = std::frexp(x, &e);
  for (int k = 1; k < 53; ++k) add(std::ldexp(std::round(std::ldexp(m, k)), e - k));
  std::stable_sort(c.begin(), c.end(), [](double a, double b) { return complexity(a) < complexity(b); });
  c.erase(std::unique(c.begin(), c.end()), c.end());
  return c;
}

}  // namespace

double complexity(double x) {
  if (x == 0) return std::signbit(x) ? 0.5 : 0;  // -0 is a little less simple than 0
  if (!std::isfinite(x)) return 1e9;
  const double a = std::fabs(x);
  const double sign = x < 0 ? 0.25 : 0;
  if (a <= 0x1p20 && a == std::trunc(a)) return 1 + a / 0x1p20 + sign;             // small integers
  if (a <= 0x1p20 && a * 2 == std::trunc(a * 2)) return 3 + a / 0x1p20 + sign;     // small halves
  int e = 0;
  std::frexp(a, &e);
  return 10 + mantissa_bits(a) + std::abs(e) + sign;  // then by mantissa bits and size
}

int complex_values(const Input& input) {
  const Json j = input_to_json(input);
  std::vector<std::string> leaves;
  number_leaves(j, "", leaves);
  int n = 0;
  for (const std::string& p : leaves) {
    const double x = *parse_double(j.at(Json::json_pointer(p)).get<std::string>());
    const bool simple = std::isfinite(x) && std::fabs(x) <= 1024 && x * 2 == std::trunc(x * 2);
    n += !simple;
  }
  return n;
}

ShrinkResult shrink(const Input& input, const Evaluation& start, const Evaluator& evaluate, int max_attempts,
                    double max_seconds, const std::filesystem::path& case_dir) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(max_seconds);
  const QueryKind kind = kind_of(input);
  const std::string target = signature_of(kind, start);
  ShrinkResult r{input, start, 0, 0, false};
  Json current = input_to_json(input);

  // Accepts a candidate document if it still shows the same disagreement.
  const auto attempt = [&](const Json& doc) {
    if (r.attempts >= max_attempts) return false;
    if (std::chrono::steady_clock::now() > deadline) {
      r.out_of_time = true;
      return false;
    }
    ++r.attempts;
    Input candidate;
    try {
      candidate = input_from_json(kind, doc, "", case_dir);
    } catch (const FormatError&) {
      return false;
    }
    Evaluation e = evaluate(candidate);
    if (signature_of(kind, e) != target) return false;
    r.input = candidate;
    r.evaluation = std::move(e);
    current = doc;
    ++r.accepted;
    return true;
  };

  // Structure before values: meshes lose faces, boxes over frames boxes and frames, lists their
  // parts (a wall touched may be renamed: the signature does not name walls). A mesh written
  // out as triangles is kept only if it is small enough to read.
  const Targets targets = targets_of(input);
  const auto written_faces = [](const Input& in) {
    std::size_t n = 0;
    const Targets t = targets_of(in);
    for (const auto& [pointer, pair] : t.mesh_pairs) n += pair->a.mesh->size() + pair->b.mesh->size();
    for (const auto& [pointer, mesh] : t.meshes) n += mesh->mesh->size();
    return n;
  };
  const ShrinkResult before = r;
  const Json before_doc = current;
  bool dropped = false;
  for (const auto& [pointer, pair] : targets.mesh_pairs) dropped |= shrink_faces(current, pointer, *pair, targets.first_hit, start, attempt);
  for (const auto& [pointer, frames] : targets.box_frames) dropped |= shrink_box_frames(current, pointer, *frames, attempt);
  for (const auto& [pointer, mesh] : targets.meshes) dropped |= shrink_mesh_faces(current, pointer, *mesh, attempt);
  for (const auto& [pointer, size] : targets.lists) shrink_list(current, pointer, size, attempt);
  if (dropped && written_faces(r.input) > kMaxWrittenFaces) {
    const int attempts = r.attempts;
    const bool out_of_time = r.out_of_time;
    r = before;
    r.attempts = attempts;
    r.out_of_time = out_of_time;
    current = before_doc;
  }

  for (bool progress = true; progress && r.attempts < max_attempts;) {
    if (std::chrono::steady_clock::now() >= deadline) {
      r.out_of_time = true;
      break;
    }
    progress = false;
    // Frames toward the identity and the signed permutations, as a whole.
    for (const Targets::Frame& frame : targets.frames) {
      const Json::json_pointer ptr(frame.pointer);
      for (const Json& m : simple_frames(frame.proper)) {
        if (current.at(ptr) == m) break;  // already the simplest one that works
        Json doc = current;
        doc[ptr] = m;
        if (attempt(doc)) {
          progress = true;
          break;
        }
      }
    }
    // Fewer points (point sets): drop one at a time, keeping at least one per set.
    for (const std::string& pointer : targets.point_sets) {
      const Json::json_pointer set(pointer);
      for (std::size_t i = 0; i < current[set].size() && current[set].size() > 1;) {
        Json doc = current;
        doc[set].erase(i);
        if (attempt(doc)) {
          progress = true;
        } else {
          ++i;
        }
      }
    }
    std::vector<std::string> leaves;
    number_leaves(current, "", leaves);
    // Every occurrence of a value at once (coordinates shared by construction move together).
    std::vector<double> distinct;
    for (const std::string& p : leaves) {
      const double x = *parse_double(current.at(Json::json_pointer(p)).get<std::string>());
      if (std::find_if(distinct.begin(), distinct.end(), [&](double d) { return same_value(d, x); }) == distinct.end()) {
        distinct.push_back(x);
      }
    }
    for (double x : distinct) {
      for (double y : candidates(x, {})) {
        Json doc = current;
        for (const std::string& p : leaves) {
          const Json::json_pointer ptr(p);
          if (same_value(*parse_double(doc.at(ptr).get<std::string>()), x)) doc[ptr] = number_to_json(y);
        }
        if (attempt(doc)) {
          progress = true;
          break;
        }
      }
    }
    // Then each value on its own (the values in the case are read again after each change).
    const auto values_in_case = [&] {
      std::vector<double> values;
      for (const std::string& q : leaves) values.push_back(*parse_double(current.at(Json::json_pointer(q)).get<std::string>()));
      return values;
    };
    std::vector<double> in_case = values_in_case();
    for (const std::string& p : leaves) {
      const Json::json_pointer ptr(p);
      const double x = *parse_double(current.at(ptr).get<std::string>());
      for (double y : candidates(x, in_case)) {
        Json doc = current;
        doc[ptr] = number_to_json(y);
        if (attempt(doc)) {
          progress = true;
          in_case = values_in_case();
          break;
        }
      }
    }
  }
  return r;
}

}  // namespace cc::harness
