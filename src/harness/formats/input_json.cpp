#include "harness/formats/input_json.h"

#include <cmath>
#include <limits>

#include "collide/kdop.h"
#include "harness/formats/mesh_files.h"
#include "harness/formats/number_text.h"
#include "harness/formats/obj_file.h"
#include "harness/model/parts.h"

namespace cc::harness {

Json number_to_json(double x) { return format_double(x); }

double number_from_json(const Json& json, const std::string& pointer) {
  if (json.is_number()) return json.get<double>();
  if (!json.is_string()) throw FormatError(pointer, "expected a number (as a string such as \"0.1\" or \"-inf\")");
  const auto text = json.get<std::string>();
  if (auto x = parse_double(text)) return *x;
  throw FormatError(pointer, "\"" + text + "\" is not a number");
}

namespace {

// Writing: a leaf by its type (and layout), a part made of fields as an object of them.

Json to_json(double x, Plain) { return number_to_json(x); }
Json to_json(const Vec3& v, Plain) {
  return Json::array({number_to_json(v.x), number_to_json(v.y), number_to_json(v.z)});
}
Json to_json(const Mat3& m, AsFrame) {
  return Json::array({to_json(m.col[0], Plain{}), to_json(m.col[1], Plain{}), to_json(m.col[2], Plain{})});
}
Json to_json(const Mat3& m, AsRotation) {
  return Json::array({to_json(m.row(0), Plain{}), to_json(m.row(1), Plain{}), to_json(m.row(2), Plain{})});
}
Json to_json(const Vec2& v, Plain) { return Json::array({number_to_json(v.x), number_to_json(v.y)}); }
Json to_json(int k, AsKdopK) { return k; }
Json to_json(const Triangle& t, Plain) {
  return Json::array({to_json(t.v[0], Plain{}), to_json(t.v[1], Plain{}), to_json(t.v[2], Plain{})});
}
Json to_json(const std::vector<Vec3>& points, Plain) {
  Json a = Json::array();
  for (const Vec3& p : points) a.push_back(to_json(p, Plain{}));
  return a;
}
Json to_json(const MeshRef& m, Plain) {
  switch (m.source) {
    case MeshRef::Source::file: return {{"file", m.file}};
    case MeshRef::Source::procedural:
      return {{"procedural", to_string(m.recipe.shape)},
              {"seed", m.recipe.seed},
              {"resolution", m.recipe.resolution},
              {"size", number_to_json(m.recipe.size)},
              {"thickness", number_to_json(m.recipe.thickness)},
              {"degenerate_percent", m.recipe.degenerate_percent}};
    case MeshRef::Source::triangles: break;
  }
  Json list = Json::array();
  for (std::size_t f = 0; f < m.mesh->size(); ++f) list.push_back(to_json(m.mesh->triangle(f), Plain{}));
  return {{"triangles", list}};
}
Json to_json(const LibraryBvh& l, Plain) {
  return {{"bv", to_string(l.bv)},
          {"build", to_string(l.build.strategy)},
          {"split_axis", to_string(l.build.axis)},
          {"split_point", to_string(l.build.point)},
          {"leaf_size", l.build.leaf_size},
          {"update", to_string(l.update)},
          {"descent", to_string(l.descent)}};
}
Json to_json(const BoxFrames& frames, Plain) {
  Json list = Json::array();
  for (const auto& frame : frames) {
    Json boxes = Json::array();
    for (const auto& box : frame) {
      boxes.push_back(box ? Json{{"lo", to_json(box->lo, Plain{})}, {"hi", to_json(box->hi, Plain{})}} : Json(nullptr));
    }
    list.push_back(boxes);
  }
  return list;
}

template <HasFields T>
Json to_json(const T& value, Plain);

// A list of parts: an array of their objects.
template <PartList L>
Json to_json(const L& parts, Plain) {
  Json a = Json::array();
  for (const auto& part : parts) a.push_back(to_json(part, Plain{}));
  return a;
}

template <HasFields T>
Json to_json(const T& value, Plain) {
  Json j = Json::object();
  for_each_field<T>([&](const auto& f) {
    using F = std::decay_t<decltype(f)>;
    Json member = to_json(F::of(value), typename F::As{});
    if (!f.inline_part()) {
      j[std::string(f.name)] = std::move(member);
      return;
    }
    for (auto& [key, part] : member.items()) j[key] = std::move(part);
  });
  return j;
}

// Reading: each leaf from its JSON at `pointer` (for error messages); a part made of fields from
// an object, each member where its name says (an inline part from the same object).

struct Context {
  std::filesystem::path case_dir;  // where mesh files are looked for
};

void read(const Json& j, const std::string& p, double& x, Plain, const Context&) { x = number_from_json(j, p); }
void read(const Json& j, const std::string& p, Vec3& v, Plain, const Context&) {
  if (!j.is_array() || j.size() != 3) throw FormatError(p, "expected an array of 3 numbers");
  v = {number_from_json(j[0], p + "/0"), number_from_json(j[1], p + "/1"), number_from_json(j[2], p + "/2")};
}
void read(const Json& j, const std::string& p, Vec2& v, Plain, const Context&) {
  if (!j.is_array() || j.size() != 2) throw FormatError(p, "expected an array of 2 numbers");
  v = {number_from_json(j[0], p + "/0"), number_from_json(j[1], p + "/1")};
}
void read(const Json& j, const std::string& p, std::vector<Vec3>& points, Plain, const Context& c) {
  if (!j.is_array()) throw FormatError(p, "expected an array of points");
  points.clear();
  for (std::size_t i = 0; i < j.size(); ++i) read(j[i], p + "/" + std::to_string(i), points.emplace_back(), Plain{}, c);
}
// Exactly three points (a triangle's vertices, a matrix's columns or rows).
std::vector<Vec3> three_points(const Json& j, const std::string& p, const char* what, const Context& c) {
  std::vector<Vec3> points;
  read(j, p, points, Plain{}, c);
  if (points.size() != 3) throw FormatError(p, std::string("expected 3 ") + what);
  return points;
}
void read(const Json& j, const std::string& p, Mat3& m, AsFrame, const Context& c) {
  const std::vector<Vec3> axes = three_points(j, p, "columns", c);
  m = Mat3::from_columns(axes[0], axes[1], axes[2]);
}
void read(const Json& j, const std::string& p, Mat3& m, AsRotation, const Context& c) {
  const std::vector<Vec3> rows = three_points(j, p, "rows", c);
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) m(i, k) = rows[static_cast<std::size_t>(i)][k];
  }
}
void read(const Json& j, const std::string& p, int& k, AsKdopK, const Context&) {
  if (!j.is_number_integer() || !is_supported_kdop(j.get<int>())) throw FormatError(p, "k must be one of 6, 14, 16, 18, 24, 26");
  k = j.get<int>();
}
void read(const Json& j, const std::string& p, Triangle& t, Plain, const Context& c) {
  const std::vector<Vec3> v = three_points(j, p, "vertices", c);
  t = {{v[0], v[1], v[2]}};
}

// An object's members, each named.
class Members {
 public:
  Members(const Json& json, std::string pointer) : json_(json), pointer_(std::move(pointer)) {
    if (!json_.is_object()) throw FormatError(pointer_, "expected an object");
  }
  bool has(const std::string& name) const { return json_.contains(name); }
  const Json& member(const std::string& name) const {
    const auto it = json_.find(name);
    if (it == json_.end()) throw FormatError(pointer_, "missing field \"" + name + "\"");
    return *it;
  }
  std::string path(const std::string& name) const { return pointer_ + "/" + name; }
  double number(const std::string& name) const { return number_from_json(member(name), path(name)); }
  std::string text(const std::string& name) const {
    const Json& j = member(name);
    if (!j.is_string()) throw FormatError(path(name), "expected a string");
    return j.get<std::string>();
  }
  std::int64_t integer(const std::string& name) const {
    const Json& j = member(name);
    if (!j.is_number_integer()) throw FormatError(path(name), "expected an integer");
    return j.get<std::int64_t>();
  }
  // A whole number in [lo, hi]: a value out of range is refused, never clamped.
  int integer_in(const std::string& name, int lo, int hi) const {
    const Json& j = member(name);
    const bool whole = j.is_number_integer() && !(j.is_number_unsigned() && j.get<std::uint64_t>() > std::uint64_t{1} << 62);
    const std::int64_t value = whole ? j.get<std::int64_t>() : 0;
    if (!whole || value < lo || value > hi) {
      throw FormatError(path(name), "must be a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                                        "]; got " + j.dump());
    }
    return static_cast<int>(value);
  }
  // A finite number of at least `lo` (a NaN or an infinity refused).
  double finite_at_least(const std::string& name, double lo) const {
    const double x = number(name);
    if (!(std::isfinite(x) && x >= lo)) {
      throw FormatError(path(name), "must be a finite number of at least " + format_double(lo) + "; got " + format_double(x));
    }
    return x;
  }
  // A name from a fixed set (an enum's to_string).
  template <class E, std::size_t N>
  E choice(const std::string& name, const E (&options)[N]) const {
    const std::string t = text(name);
    std::string known;
    for (E e : options) {
      if (to_string(e) == t) return e;
      known += (known.empty() ? "" : ", ") + std::string(to_string(e));
    }
    throw FormatError(path(name), "\"" + t + "\" is not one of " + known);
  }

 private:
  const Json& json_;
  std::string pointer_;
};

void read(const Json& j, const std::string& p, MeshRef& out, Plain, const Context& c) {
  const Members r(j, p);
  if (r.has("file")) {
    MeshRef m;
    m.source = MeshRef::Source::file;
    m.file = r.text("file");
    const auto found = find_mesh_file(m.file, c.case_dir);
    if (!found) throw FormatError(r.path("file"), "mesh file \"" + m.file + "\" not found next to the case or in a folder above it");
    try {
      m.mesh = load_mesh_file(*found);
    } catch (const MeshFileError& e) {
      throw FormatError(r.path("file"), e.what());
    }
    out = std::move(m);
    return;
  }
  if (r.has("procedural")) {
    static constexpr ProceduralMesh::Shape kShapes[] = {ProceduralMesh::Shape::sphere, ProceduralMesh::Shape::torus,
                                                        ProceduralMesh::Shape::terrain, ProceduralMesh::Shape::plate,
                                                        ProceduralMesh::Shape::soup};
    ProceduralMesh recipe;
    recipe.shape = r.choice("procedural", kShapes);
    recipe.seed = static_cast<std::uint64_t>(r.integer("seed"));
    // The generator's own ranges (collide/procedural_mesh.h), refused rather than clamped.
    recipe.resolution = r.integer_in("resolution", 1, 200);
    recipe.size = r.finite_at_least("size", 0);
    recipe.thickness = r.has("thickness") ? r.finite_at_least("thickness", 0) : 0.0;
    recipe.degenerate_percent = r.has("degenerate_percent") ? r.integer_in("degenerate_percent", 0, 100) : 0;
    out = procedural_mesh(recipe);
    return;
  }
  if (r.has("triangles")) {
    const Json& list = r.member("triangles");
    if (!list.is_array()) throw FormatError(r.path("triangles"), "expected an array of triangles");
    if (list.empty()) throw FormatError(r.path("triangles"), "a mesh needs at least one triangle");
    Mesh mesh;
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string at = r.path("triangles") + "/" + std::to_string(i);
      if (!list[i].is_array() || list[i].size() != 3) throw FormatError(at, "expected 3 vertices");
      const auto n = static_cast<std::uint32_t>(mesh.vertices.size());
      for (std::size_t k = 0; k < 3; ++k) read(list[i][k], at + "/" + std::to_string(k), mesh.vertices.emplace_back(), Plain{}, c);
      mesh.faces.push_back({n, n + 1, n + 2});
    }
    out = triangles_mesh(std::move(mesh));
    return;
  }
  throw FormatError(p, "expected \"file\", \"procedural\" or \"triangles\"");
}

// Every member optional: the default hierarchy where one is missing.
void read(const Json& j, const std::string& p, LibraryBvh& l, Plain, const Context&) {
  const Members r(j, p);
  static constexpr BuildStrategy kStrategies[] = {BuildStrategy::top_down, BuildStrategy::bottom_up,
                                                  BuildStrategy::incremental, BuildStrategy::lazy_top_down};
  static constexpr SplitAxis kAxes[] = {SplitAxis::longest_side, SplitAxis::splatter, SplitAxis::min_sum,
                                        SplitAxis::min_max};
  static constexpr SplitPoint kPoints[] = {SplitPoint::midpoint, SplitPoint::mean, SplitPoint::median};
  static constexpr BvUpdate kUpdates[] = {BvUpdate::approximate, BvUpdate::exact, BvUpdate::hill_climbing};
  static constexpr Descent kDescents[] = {Descent::first_model, Descent::larger};
  l = {};
  if (r.has("bv")) l.bv = r.choice("bv", kAllBvTypes);
  if (r.has("build")) l.build.strategy = r.choice("build", kStrategies);
  if (r.has("split_axis")) l.build.axis = r.choice("split_axis", kAxes);
  if (r.has("split_point")) l.build.point = r.choice("split_point", kPoints);
  if (r.has("leaf_size")) l.build.leaf_size = r.integer_in("leaf_size", 1, std::numeric_limits<int>::max());
  if (r.has("update")) l.update = r.choice("update", kUpdates);
  if (r.has("descent")) l.descent = r.choice("descent", kDescents);
}

void read(const Json& list, const std::string& p, BoxFrames& out, Plain, const Context& c) {
  if (!list.is_array()) throw FormatError(p, "expected an array of frames");
  out.clear();
  for (std::size_t f = 0; f < list.size(); ++f) {
    const std::string at = p + "/" + std::to_string(f);
    if (!list[f].is_array()) throw FormatError(at, "expected an array of boxes (or null)");
    if (!out.empty() && list[f].size() != out.front().size()) {
      throw FormatError(at, "expected " + std::to_string(out.front().size()) + " boxes, as in frame 0");
    }
    auto& frame = out.emplace_back();
    for (std::size_t i = 0; i < list[f].size(); ++i) {
      if (list[f][i].is_null()) {
        frame.emplace_back();
        continue;
      }
      const std::string box_at = at + "/" + std::to_string(i);
      const Members box(list[f][i], box_at);
      Aabb b;
      read(box.member("lo"), box.path("lo"), b.lo, Plain{}, c);
      read(box.member("hi"), box.path("hi"), b.hi, Plain{}, c);
      frame.emplace_back(b);
    }
  }
}

template <HasFields T>
void read(const Json& j, const std::string& p, T& value, Plain, const Context& c);

// A list of parts: each from its object in the array.
template <PartList L>
void read(const Json& j, const std::string& p, L& parts, Plain, const Context& c) {
  if (!j.is_array()) throw FormatError(p, "expected an array of objects");
  parts.clear();
  for (std::size_t i = 0; i < j.size(); ++i) read(j[i], p + "/" + std::to_string(i), parts.emplace_back(), Plain{}, c);
}

// A part whose fields are members of the object `j` at `p` (an inline part's, of its owner's).
template <HasFields T>
void read(const Json& j, const std::string& p, T& value, Plain, const Context& c) {
  const Members r(j, p);
  for_each_field<T>([&](const auto& f) {
    using F = std::decay_t<decltype(f)>;
    if (f.inline_part()) {
      read(j, p, F::of(value), typename F::As{}, c);
      return;
    }
    const std::string name(f.name);
    if constexpr (std::is_same_v<typename F::Type, LibraryBvh>) {
      if (!r.has(name)) {  // the default hierarchy
        F::of(value) = {};
        return;
      }
    }
    read(r.member(name), r.path(name), F::of(value), typename F::As{}, c);
  });
}

}  // namespace

Json mesh_to_json(const MeshRef& mesh) { return to_json(mesh, Plain{}); }

Json input_to_json(const Input& input) {
  return std::visit([](const auto& in) { return to_json(in, Plain{}); }, input);
}

Input input_from_json(QueryKind kind, const Json& json, const std::string& pointer,
                      const std::filesystem::path& case_dir) {
  const Context context{case_dir};
  return with_kind(kind, [&]<class In>() -> Input {
    In in{};
    read(json, pointer, in, Plain{}, context);
    return in;
  });
}

}  // namespace cc::harness
