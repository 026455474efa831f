#include "harness/model/subject.h"

#include <dlfcn.h>

#include <crosscheck/subject.h>

#include <stdexcept>
#include <tuple>
#include <type_traits>

#include "harness/formats/fields.h"

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

std::shared_ptr<const Subject>& under_test() {
  static std::shared_ptr<const Subject> subject;
  return subject;
}

}  // namespace

std::shared_ptr<const Subject> Subject::load(const std::string& path) {
  const std::string where = path.find('/') == std::string::npos ? "./" + path : path;
  void* handle = dlopen(where.c_str(), RTLD_NOW | RTLD_LOCAL);  // kept open for the process's life
  if (handle == nullptr) throw std::runtime_error(path + ": cannot be loaded: " + dlerror());
  const auto version = reinterpret_cast<int (*)()>(dlsym(handle, "crosscheck_subject_version"));
  if (version == nullptr) throw std::runtime_error(path + ": exports no crosscheck_subject_version(): not a crosscheck subject");
  if (const int v = version(); v != CROSSCHECK_SUBJECT_VERSION) {
    throw std::runtime_error(path + ": interface version " + std::to_string(v) + ", this crosscheck takes version " +
                             std::to_string(CROSSCHECK_SUBJECT_VERSION) + " (include/crosscheck/subject.h)");
  }
  auto subject = std::make_shared<Subject>();
  subject->path_ = path;
  bool any = false;
  for (QueryKind kind : kAllQueryKinds) {
    with_kind(kind, [&]<class In>() {
      if constexpr (expressible<In>()) {
        void* f = dlsym(handle, ("crosscheck_" + std::string(name(kind))).c_str());
        subject->functions_[static_cast<std::size_t>(kind)] = f;
        any |= f != nullptr;
      }
    });
  }
  if (!any) throw std::runtime_error(path + ": exports no crosscheck_<kind> function of include/crosscheck/subject.h");
  return subject;
}

Answer Subject::ask(const Input& input) const {
  void* function = functions_[static_cast<std::size_t>(kind_of(input))];
  if (function == nullptr) {
    throw std::runtime_error("the subject " + path_ + " does not answer " + std::string(name(kind_of(input))));
  }
  const int said = std::visit(
      [function]<class In>(const In& in) {
        if constexpr (expressible<In>()) {
          return call(function, in);
        } else {
          return -1;  // never: only expressible kinds have a function
        }
      },
      input);
  if (said != 0 && said != 1) {
    throw std::runtime_error("the subject's crosscheck_" + std::string(name(kind_of(input))) + " returned " +
                             std::to_string(said) + ", neither 0 (miss) nor 1 (hit)");
  }
  return Answer::of(said == 1);
}

void put_under_test(std::shared_ptr<const Subject> subject) { under_test() = std::move(subject); }
const Subject* subject_under_test() { return under_test().get(); }

bool library_answers(QueryKind kind) {
  const Subject* subject = subject_under_test();
  return subject == nullptr || subject->answers(kind);
}

}  // namespace cc::harness
