#include "harness/model/subject_binding.h"

#include <dlfcn.h>

#include <crosscheck/subject.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <vector>

#include "collide/rigid_transform.h"
#include "harness/model/fields.h"
#include "harness/model/kind_pieces.h"

namespace cc::harness {
namespace {

cc_vec3 to_c(const Vec3& v) { return {v.x, v.y, v.z}; }
cc_aabb to_c(const Aabb& b) { return {to_c(b.lo), to_c(b.hi)}; }
cc_sphere to_c(const Sphere& s) { return {to_c(s.center), s.radius}; }
cc_obb to_c(const Obb& b) { return {to_c(b.center), to_c(b.half), {to_c(b.axes.col[0]), to_c(b.axes.col[1]), to_c(b.axes.col[2])}}; }
cc_triangle to_c(const Triangle& t) { return {{to_c(t.v[0]), to_c(t.v[1]), to_c(t.v[2])}}; }
cc_ray to_c(const Ray& r) { return {to_c(r.origin), to_c(r.dir), r.tmin, r.tmax}; }
cc_moving_obb to_c(const MovingObb& m) { return {to_c(m.box), to_c(m.velocity)}; }

// The interface takes a kind whose input is two shapes it has a struct for, in the input's
// order (found by the fields, as the kinds are made).
template <class In>
constexpr bool expressible() {
  if constexpr (!HasFields<In>) {
    return false;
  } else {
    return std::apply([](const auto&... f) { return sizeof...(f) == 2 && (requires { to_c(f.of(In{})); } && ...); },
                      Fields<In>::list);
  }
}

// Its answer, 0 or 1 (anything else throws).
bool hit_of(int said, QueryKind kind) {
  if (said != 0 && said != 1) {
    throw std::runtime_error("the subject's crosscheck_" + std::string(name(kind)) + " returned " + std::to_string(said) +
                             ", neither 0 (miss) nor 1 (hit)");
  }
  return said == 1;
}

template <class In>
int call(void* function, const In& in) {
  return std::apply(
      [&](const auto&... f) {
        using Fn = int (*)(const decltype(to_c(f.of(in)))*...);
        const auto shapes = std::tuple{to_c(f.of(in))...};
        return std::apply([&](const auto&... s) { return reinterpret_cast<Fn>(function)(&s...); }, shapes);
      },
      Fields<In>::list);
}

// The shapes' largest magnitude: coordinates, radii and half extents (not a box's axes); 1 when
// all are 0, as the exact reference's scale.
double magnitude(const cc_vec3& v) { return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}); }
double magnitude(const cc_sphere& s) { return std::max(magnitude(s.center), std::fabs(s.radius)); }
double magnitude(const cc_obb& b) { return std::max(magnitude(b.center), magnitude(b.half)); }
double magnitude(const cc_triangle& t) { return std::max({magnitude(t.v[0]), magnitude(t.v[1]), magnitude(t.v[2])}); }

// Whether the input's shapes all have a magnitude (the shapes of the distance kinds).
template <class In>
constexpr bool has_magnitudes() {
  return std::apply([](const auto&... f) { return (requires { magnitude(to_c(f.of(In{}))); } && ...); }, Fields<In>::list);
}

// A distance kind's answer: the signed distance and both points, each within the subject's
// tolerance of the case's scale (its largest magnitude; 1 when all are 0).
Answer distance_answer(double distance, const cc_vec3& on_a, const cc_vec3& on_b, double tolerance, double scale) {
  const double bound = tolerance * (scale > 0 ? scale : 1);
  Answer answer = Answer::of(distance <= 0);
  answer.params = {distance, on_a.x, on_a.y, on_a.z, on_b.x, on_b.y, on_b.z, bound, bound};
  return answer;
}

// A distance kind: the signed distance and both points, with the subject's tolerance of the scale
// as the bounds of both.
template <class In>
Answer ask_distance(void* function, const In& in, QueryKind kind, double tolerance) {
  double distance = 0;
  cc_vec3 on_a{}, on_b{};
  double scale = 0;
  const int said = std::apply(
      [&](const auto&... f) {
        using Fn = int (*)(const decltype(to_c(f.of(in)))*..., double*, cc_vec3*, cc_vec3*);
        const auto shapes = std::tuple{to_c(f.of(in))...};
        return std::apply(
            [&](const auto&... s) {
              scale = std::max({magnitude(s)...});
              return reinterpret_cast<Fn>(function)(&s..., &distance, &on_a, &on_b);
            },
            shapes);
      },
      Fields<In>::list);
  if (said != 1) {
    throw std::runtime_error("the subject's crosscheck_" + std::string(name(kind)) + " returned " + std::to_string(said) +
                             ", not 1 (a distance and two points)");
  }
  return distance_answer(distance, on_a, on_b, tolerance, scale);
}

// The kinds of a mesh or of many boxes, found by their inputs as the others are: a ray and a
// mesh; two placed meshes, asked for every pair or one (their mode); boxes frame by frame. Each
// has a signature of its own.
static_assert(sizeof(Vec3) == sizeof(cc_vec3) && sizeof(std::array<std::uint32_t, 3>) == 3 * sizeof(unsigned),
              "a mesh's arrays are handed to the subject as they are");

template <class In>
concept RayAndMesh = requires(const In& in) {
  { in.ray } -> std::convertible_to<const Ray&>;
  { in.mesh } -> std::convertible_to<const MeshRef&>;
};

template <class In>
concept TwoPlacedMeshes = requires(const In& in) {
  { in.meshes } -> std::convertible_to<const MeshPair&>;
  { In::mode } -> std::convertible_to<CollisionMode>;
};

template <class In>
concept TwoPlacedMeshesApart = requires(const In& in) {
  { in.meshes } -> std::convertible_to<const MeshPair&>;
} && !TwoPlacedMeshes<In>;

template <class In>
concept BoxFramesOnly = requires(const In& in) {
  { in.frames } -> std::convertible_to<const BoxFrames&>;
};

template <class In>
constexpr bool has_own_signature = RayAndMesh<In> || TwoPlacedMeshes<In> || TwoPlacedMeshesApart<In> || BoxFramesOnly<In>;

cc_mesh to_c(const MeshRef& ref) {
  if (ref.mesh == nullptr) throw std::runtime_error("a case without its mesh");
  const Mesh& m = *ref.mesh;
  return {reinterpret_cast<const cc_vec3*>(m.vertices.data()), static_cast<unsigned>(m.vertices.size()),
          reinterpret_cast<const unsigned(*)[3]>(m.faces.data()), static_cast<unsigned>(m.faces.size())};
}

cc_pose to_c(const RigidTransform& t) {
  cc_pose p{};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) p.rotation[r][c] = t.rotation(r, c);
  }
  p.translation = to_c(t.translation);
  return p;
}

FacePair checked(const cc_face_pair& p, const MeshPair& m) {
  if (p.a >= m.a.mesh->size() || p.b >= m.b.mesh->size()) {
    throw std::runtime_error("the subject named a face pair (" + std::to_string(p.a) + ", " + std::to_string(p.b) +
                             ") beyond the meshes' faces");
  }
  return {p.a, p.b};
}

// Frames of boxes: the pairs of each frame, as slots (i < j), sorted.
Answer ask_box_frames(void* function, const BoxFrames& frames, QueryKind kind) {
  std::size_t slots = 0;
  for (const auto& frame : frames) slots = std::max(slots, frame.size());
  std::vector<cc_aabb> boxes(slots * frames.size());
  std::vector<unsigned char> present(boxes.size(), 0);
  for (std::size_t f = 0; f < frames.size(); ++f) {
    for (std::size_t i = 0; i < frames[f].size(); ++i) {
      if (frames[f][i]) boxes[f * slots + i] = to_c(*frames[f][i]), present[f * slots + i] = 1;
    }
  }
  const cc_box_frames c{boxes.data(), present.data(), static_cast<unsigned>(slots), static_cast<unsigned>(frames.size())};
  const auto capacity = static_cast<unsigned>(std::min<std::uint64_t>(std::uint64_t{slots} * slots * frames.size() / 2 + 1, 1u << 22));
  std::vector<cc_face_pair> pairs(capacity);
  std::vector<unsigned> ends(frames.size(), 0);
  using Fn = int (*)(const cc_box_frames*, cc_face_pair*, unsigned, unsigned*);
  const int count = reinterpret_cast<Fn>(function)(&c, pairs.data(), capacity, ends.data());
  if (count < 0 || static_cast<unsigned>(count) > capacity) {
    throw std::runtime_error("the subject's crosscheck_" + std::string(name(kind)) + " returned " + std::to_string(count) +
                             " pairs, room for " + std::to_string(capacity));
  }
  Answer answer;
  unsigned begin = 0;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    if (ends[f] < begin || ends[f] > static_cast<unsigned>(count)) throw std::runtime_error("the subject's frame ends are not in order");
    std::vector<FacePair> frame;
    for (unsigned p = begin; p < ends[f]; ++p) {
      const auto [i, j] = std::minmax(pairs[p].a, pairs[p].b);
      if (j >= frames[f].size() || i == j || !frames[f][i] || !frames[f][j]) {
        throw std::runtime_error("the subject named slots (" + std::to_string(i) + ", " + std::to_string(j) +
                                 ") without two boxes in frame " + std::to_string(f));
      }
      frame.emplace_back(i, j);
    }
    std::sort(frame.begin(), frame.end());
    frame.erase(std::unique(frame.begin(), frame.end()), frame.end());
    answer.hit |= !frame.empty();
    answer.frames.push_back(std::move(frame));
    begin = ends[f];
  }
  return answer;
}

// Two placed meshes asked for their distance: as a distance kind's answer, with the subject's
// tolerance of the placed vertices' largest coordinate as the bounds.
Answer ask_mesh_distance(void* function, const MeshPair& m, QueryKind kind, double tolerance) {
  const cc_mesh a = to_c(m.a), b = to_c(m.b);
  const cc_pose pose_a = to_c(m.pose_a), pose_b = to_c(m.pose_b);
  double distance = 0;
  cc_vec3 on_a{}, on_b{};
  using Fn = int (*)(const cc_mesh*, const cc_pose*, const cc_mesh*, const cc_pose*, double*, cc_vec3*, cc_vec3*);
  const int said = reinterpret_cast<Fn>(function)(&a, &pose_a, &b, &pose_b, &distance, &on_a, &on_b);
  if (said != 1) {
    throw std::runtime_error("the subject's crosscheck_" + std::string(name(kind)) + " returned " + std::to_string(said) +
                             ", not 1 (a distance and two points)");
  }
  double scale = 0;
  for (const auto& [mesh, pose] : {std::pair{m.a.mesh, m.pose_a}, std::pair{m.b.mesh, m.pose_b}}) {
    for (const Vec3& p : mesh->vertices) scale = std::max(scale, max_abs(cc::apply(pose, p)));
  }
  return distance_answer(distance, on_a, on_b, tolerance, scale);
}

template <class In>
Answer ask_own_signature(void* function, const In& in, QueryKind kind, double distance_tolerance) {
  if constexpr (BoxFramesOnly<In>) {
    return ask_box_frames(function, in.frames, kind);
  } else if constexpr (RayAndMesh<In>) {
    const cc_ray ray = to_c(in.ray);
    const cc_mesh mesh = to_c(in.mesh);
    unsigned face = 0;
    Answer a = Answer::of(
        hit_of(reinterpret_cast<int (*)(const cc_ray*, const cc_mesh*, unsigned*)>(function)(&ray, &mesh, &face), kind));
    if (!a.hit) return a;
    if (face >= mesh.face_count) {
      throw std::runtime_error("the subject named face " + std::to_string(face) + " of a mesh of " +
                               std::to_string(mesh.face_count));
    }
    a.pairs = {{face, 0}};
    return a;
  } else if constexpr (TwoPlacedMeshesApart<In>) {
    return ask_mesh_distance(function, in.meshes, kind, distance_tolerance);
  } else {
    const MeshPair& m = in.meshes;
    const cc_mesh a = to_c(m.a), b = to_c(m.b);
    const cc_pose pose_a = to_c(m.pose_a), pose_b = to_c(m.pose_b);
    if constexpr (In::mode == CollisionMode::first_hit) {
      cc_face_pair pair{};
      using Fn = int (*)(const cc_mesh*, const cc_pose*, const cc_mesh*, const cc_pose*, cc_face_pair*);
      Answer answer = Answer::of(hit_of(reinterpret_cast<Fn>(function)(&a, &pose_a, &b, &pose_b, &pair), kind));
      if (answer.hit) answer.pairs = {checked(pair, m)};
      return answer;
    } else {
      const auto capacity =
          static_cast<unsigned>(std::min<std::uint64_t>(std::uint64_t{a.face_count} * b.face_count, 1u << 22));
      std::vector<cc_face_pair> pairs(capacity);
      using Fn = int (*)(const cc_mesh*, const cc_pose*, const cc_mesh*, const cc_pose*, cc_face_pair*, unsigned);
      const int count = reinterpret_cast<Fn>(function)(&a, &pose_a, &b, &pose_b, pairs.data(), capacity);
      if (count < 0 || static_cast<unsigned>(count) > capacity) {
        throw std::runtime_error("the subject's crosscheck_" + std::string(name(kind)) + " returned " + std::to_string(count) +
                                 " pairs, room for " + std::to_string(capacity));
      }
      Answer answer = Answer::of(count > 0);
      for (int i = 0; i < count; ++i) answer.pairs.push_back(checked(pairs[static_cast<std::size_t>(i)], m));
      std::sort(answer.pairs.begin(), answer.pairs.end());
      answer.pairs.erase(std::unique(answer.pairs.begin(), answer.pairs.end()), answer.pairs.end());
      return answer;
    }
  }
}

}  // namespace

SubjectBinding SubjectBinding::open(const std::string& path) {
  const std::string where = path.find('/') == std::string::npos ? "./" + path : path;
  void* handle = dlopen(where.c_str(), RTLD_NOW | RTLD_LOCAL);  // kept open for the process's life
  if (handle == nullptr) throw std::runtime_error(path + ": cannot be loaded: " + dlerror());
  const auto version = reinterpret_cast<int (*)()>(dlsym(handle, "crosscheck_subject_version"));
  if (version == nullptr) throw std::runtime_error(path + ": exports no crosscheck_subject_version(): not a crosscheck subject");
  SubjectBinding subject;
  subject.path_ = path;
  subject.version_ = version();
  if (subject.version_ != CROSSCHECK_SUBJECT_VERSION) {
    throw std::runtime_error(path + ": interface version " + std::to_string(subject.version_) +
                             ", this crosscheck takes version " + std::to_string(CROSSCHECK_SUBJECT_VERSION) +
                             " (include/crosscheck/subject.h)");
  }
  bool any = false;
  for (QueryKind kind : kAllQueryKinds) {
    with_kind(kind, [&]<class In>() {
      // The interface declares a yes/no function for the kinds of two shapes judged on their
      // hit, a distance function for those judged on a distance, and its own for the kinds of
      // meshes and of many boxes; a function named for another kind (one judged on the corners
      // of an intersection) is not the interface's, and never called.
      if constexpr (has_own_signature<In> || expressible<In>()) {
        const Judged judged = pieces_of(kind).judged;
        if (!has_own_signature<In> && judged != Judged::hit && judged != Judged::distance) return;
        void* f = dlsym(handle, ("crosscheck_" + std::string(name(kind))).c_str());
        subject.functions_[static_cast<std::size_t>(kind)] = f;
        any |= f != nullptr;
      }
    });
  }
  if (!any) throw std::runtime_error(path + ": exports no crosscheck_<kind> function of include/crosscheck/subject.h");
  for (QueryKind kind : kAllQueryKinds) {
    if (!subject.answers(kind) || pieces_of(kind).judged != Judged::distance) continue;
    const auto tolerance = reinterpret_cast<double (*)()>(dlsym(handle, "crosscheck_distance_tolerance"));
    if (tolerance == nullptr) {
      throw std::runtime_error(path + ": exports crosscheck_" + std::string(name(kind)) +
                               " but no crosscheck_distance_tolerance() (include/crosscheck/subject.h)");
    }
    subject.distance_tolerance_ = tolerance();
    if (!(subject.distance_tolerance_ >= 0 && subject.distance_tolerance_ < 1)) {
      throw std::runtime_error(path + ": crosscheck_distance_tolerance() returned " + std::to_string(subject.distance_tolerance_) +
                               ", not a number in [0, 1)");
    }
    break;
  }
  return subject;
}

std::vector<std::string> SubjectBinding::kinds() const {
  std::vector<std::string> out;
  for (QueryKind kind : kAllQueryKinds) {
    if (answers(kind)) out.emplace_back(name(kind));
  }
  return out;
}

Answer SubjectBinding::ask(const Input& input) const {
  const QueryKind kind = kind_of(input);
  void* function = functions_[static_cast<std::size_t>(kind)];
  if (function == nullptr) throw std::runtime_error("the subject " + path_ + " does not answer " + std::string(name(kind)));
  return std::visit(
      [this, function, kind]<class In>(const In& in) -> Answer {
        if constexpr (has_own_signature<In>) {
          return ask_own_signature(function, in, kind, distance_tolerance_);
        } else if constexpr (expressible<In>()) {
          if (pieces_of(kind).judged == Judged::distance) {
            if constexpr (has_magnitudes<In>()) return ask_distance(function, in, kind, distance_tolerance_);
            throw std::logic_error("a distance kind whose shapes have no magnitude here");
          }
          return Answer::of(hit_of(call(function, in), kind));
        } else {
          throw std::logic_error("no function for this kind");  // never: answers() is false for it
        }
      },
      input);
}

}  // namespace cc::harness
