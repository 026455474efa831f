#include "harness/formats/input_json.h"

#include "collide/kdop.h"
#include "harness/formats/mesh_files.h"
#include "harness/formats/number_text.h"
#include "harness/formats/obj_file.h"

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

// Reading: each helper takes the parent object and the member's name, so errors name the place.
class Reader {
 public:
  Reader(const Json& json, std::string pointer) : json_(json), pointer_(std::move(pointer)) {
    if (!json_.is_object()) throw FormatError(pointer_, "expected an object");
  }
  const Json& member(const std::string& name) const {
    const auto it = json_.find(name);
    if (it == json_.end()) throw FormatError(pointer_, "missing field \"" + name + "\"");
    return *it;
  }
  std::string path(const std::string& name) const { return pointer_ + "/" + name; }
  double number(const std::string& name) const { return number_from_json(member(name), path(name)); }
  Vec3 vec3(const std::string& name) const { return vec3_at(member(name), path(name)); }
  static Vec3 vec3_at(const Json& j, const std::string& p) {
    if (!j.is_array() || j.size() != 3) throw FormatError(p, "expected an array of 3 numbers");
    return {number_from_json(j[0], p + "/0"), number_from_json(j[1], p + "/1"), number_from_json(j[2], p + "/2")};
  }
  std::vector<Vec3> points(const std::string& name) const {
    const Json& j = member(name);
    if (!j.is_array()) throw FormatError(path(name), "expected an array of points");
    std::vector<Vec3> out;
    for (std::size_t i = 0; i < j.size(); ++i) out.push_back(vec3_at(j[i], path(name) + "/" + std::to_string(i)));
    return out;
  }
  Triangle triangle(const std::string& name) const {
    const std::vector<Vec3> p = points(name);
    if (p.size() != 3) throw FormatError(path(name), "expected 3 vertices");
    return {{p[0], p[1], p[2]}};
  }
  Reader object(const std::string& name) const { return Reader(member(name), path(name)); }
  Aabb aabb(const std::string& name) const {
    const Reader r = object(name);
    return {r.vec3("lo"), r.vec3("hi")};
  }
  Obb obb(const std::string& name) const { return obb_fields(object(name)); }
  Sphere sphere(const std::string& name) const {
    const Reader r = object(name);
    return {r.vec3("center"), r.number("radius")};
  }
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
  bool has(const std::string& name) const { return json_.contains(name); }
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
  RigidTransform pose(const std::string& name) const {
    const Reader r = object(name);
    const std::vector<Vec3> rows = r.points("rotation");
    if (rows.size() != 3) throw FormatError(r.path("rotation"), "expected 3 rows");
    RigidTransform t;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) t.rotation(i, j) = rows[i][j];
    }
    t.translation = r.vec3("translation");
    return t;
  }
  MeshRef mesh(const std::string& name, const std::filesystem::path& case_dir) const {
    const Reader r = object(name);
    if (r.has("file")) {
      MeshRef m;
      m.source = MeshRef::Source::file;
      m.file = r.text("file");
      const auto found = find_mesh_file(m.file, case_dir);
      if (!found) throw FormatError(r.path("file"), "mesh file \"" + m.file + "\" not found next to the case or in a folder above it");
      try {
        m.mesh = load_mesh_file(*found);
      } catch (const MeshFileError& e) {
        throw FormatError(r.path("file"), e.what());
      }
      return m;
    }
    if (r.has("procedural")) {
      static constexpr ProceduralMesh::Shape kShapes[] = {ProceduralMesh::Shape::sphere, ProceduralMesh::Shape::torus,
                                                          ProceduralMesh::Shape::terrain, ProceduralMesh::Shape::plate,
                                                          ProceduralMesh::Shape::soup};
      ProceduralMesh recipe;
      recipe.shape = r.choice("procedural", kShapes);
      recipe.seed = static_cast<std::uint64_t>(r.integer("seed"));
      recipe.resolution = static_cast<int>(r.integer("resolution"));
      recipe.size = r.number("size");
      recipe.thickness = r.has("thickness") ? r.number("thickness") : 0.0;
      recipe.degenerate_percent = r.has("degenerate_percent") ? static_cast<int>(r.integer("degenerate_percent")) : 0;
      return procedural_mesh(recipe);
    }
    if (r.has("triangles")) {
      const Json& list = r.member("triangles");
      if (!list.is_array()) throw FormatError(r.path("triangles"), "expected an array of triangles");
      Mesh mesh;
      for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string p = r.path("triangles") + "/" + std::to_string(i);
        if (!list[i].is_array() || list[i].size() != 3) throw FormatError(p, "expected 3 vertices");
        const auto n = static_cast<std::uint32_t>(mesh.vertices.size());
        for (int k = 0; k < 3; ++k) mesh.vertices.push_back(vec3_at(list[i][k], p + "/" + std::to_string(k)));
        mesh.faces.push_back({n, n + 1, n + 2});
      }
      return triangles_mesh(std::move(mesh));
    }
    throw FormatError(pointer_ + "/" + name, "expected \"file\", \"procedural\" or \"triangles\"");
  }
  LibraryBvh library(const std::string& name) const {
    LibraryBvh l;
    if (!has(name)) return l;
    const Reader r = object(name);
    static constexpr BuildStrategy kStrategies[] = {BuildStrategy::top_down, BuildStrategy::bottom_up,
                                                    BuildStrategy::incremental};
    static constexpr SplitAxis kAxes[] = {SplitAxis::longest_side, SplitAxis::splatter, SplitAxis::min_sum,
                                          SplitAxis::min_max};
    static constexpr SplitPoint kPoints[] = {SplitPoint::midpoint, SplitPoint::mean, SplitPoint::median};
    static constexpr BvUpdate kUpdates[] = {BvUpdate::approximate, BvUpdate::exact};
    static constexpr Descent kDescents[] = {Descent::first_model, Descent::larger};
    if (r.has("bv")) l.bv = r.choice("bv", kAllBvTypes);
    if (r.has("build")) l.build.strategy = r.choice("build", kStrategies);
    if (r.has("split_axis")) l.build.axis = r.choice("split_axis", kAxes);
    if (r.has("split_point")) l.build.point = r.choice("split_point", kPoints);
    if (r.has("leaf_size")) l.build.leaf_size = static_cast<int>(r.integer("leaf_size"));
    if (r.has("update")) l.update = r.choice("update", kUpdates);
    if (r.has("descent")) l.descent = r.choice("descent", kDescents);
    return l;
  }
  MovingObb moving(const std::string& name) const {
    const Reader r = object(name);
    return {obb_fields(r), r.vec3("velocity")};
  }
  static Obb obb_fields(const Reader& r) {
    const std::vector<Vec3> axes = r.points("axes");
    if (axes.size() != 3) throw FormatError(r.path("axes"), "expected 3 columns");
    return {r.vec3("center"), r.vec3("half"), Mat3::from_columns(axes[0], axes[1], axes[2])};
  }
  Ray ray() const { return {vec3("origin"), vec3("dir"), number("tmin"), number("tmax")}; }
  std::vector<std::vector<std::optional<Aabb>>> frames(const std::string& name) const {
    const Json& list = member(name);
    if (!list.is_array()) throw FormatError(path(name), "expected an array of frames");
    std::vector<std::vector<std::optional<Aabb>>> out;
    for (std::size_t f = 0; f < list.size(); ++f) {
      const std::string p = path(name) + "/" + std::to_string(f);
      if (!list[f].is_array()) throw FormatError(p, "expected an array of boxes (or null)");
      if (!out.empty() && list[f].size() != out.front().size()) {
        throw FormatError(p, "expected " + std::to_string(out.front().size()) + " boxes, as in frame 0");
      }
      auto& frame = out.emplace_back();
      for (std::size_t i = 0; i < list[f].size(); ++i) {
        if (list[f][i].is_null()) {
          frame.emplace_back();
          continue;
        }
        const Reader box(list[f][i], p + "/" + std::to_string(i));
        frame.emplace_back(Aabb{box.vec3("lo"), box.vec3("hi")});
      }
    }
    return out;
  }
  MeshPair meshes(const std::filesystem::path& case_dir) const {
    return {mesh("a", case_dir), mesh("b", case_dir), pose("pose_a"), pose("pose_b"), library("library")};
  }

 private:
  const Json& json_;
  std::string pointer_;
};

Json vec3(const Vec3& v) { return Json::array({number_to_json(v.x), number_to_json(v.y), number_to_json(v.z)}); }
Json points(const std::vector<Vec3>& ps) {
  Json a = Json::array();
  for (const Vec3& p : ps) a.push_back(vec3(p));
  return a;
}
Json triangle(const Triangle& t) { return Json::array({vec3(t.v[0]), vec3(t.v[1]), vec3(t.v[2])}); }
Json aabb(const Aabb& b) { return {{"lo", vec3(b.lo)}, {"hi", vec3(b.hi)}}; }
Json obb(const Obb& b) {
  return {{"center", vec3(b.center)},
          {"half", vec3(b.half)},
          {"axes", Json::array({vec3(b.axes.col[0]), vec3(b.axes.col[1]), vec3(b.axes.col[2])})}};
}
Json sphere(const Sphere& s) { return {{"center", vec3(s.center)}, {"radius", number_to_json(s.radius)}}; }
Json pose(const RigidTransform& t) {
  Json rows = Json::array();
  for (int i = 0; i < 3; ++i) rows.push_back(vec3(t.rotation.row(i)));
  return {{"rotation", rows}, {"translation", vec3(t.translation)}};
}
Json mesh(const MeshRef& m) {
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
  for (std::size_t f = 0; f < m.mesh->size(); ++f) list.push_back(triangle(m.mesh->triangle(f)));
  return {{"triangles", list}};
}
Json library(const LibraryBvh& l) {
  return {{"bv", to_string(l.bv)},
          {"build", to_string(l.build.strategy)},
          {"split_axis", to_string(l.build.axis)},
          {"split_point", to_string(l.build.point)},
          {"leaf_size", l.build.leaf_size},
          {"update", to_string(l.update)},
          {"descent", to_string(l.descent)}};
}
Json meshes(const MeshPair& m) {
  return {{"a", mesh(m.a)}, {"pose_a", pose(m.pose_a)}, {"b", mesh(m.b)}, {"pose_b", pose(m.pose_b)}, {"library", library(m.library)}};
}

Json ray_fields(const Ray& r) {
  return {{"origin", vec3(r.origin)}, {"dir", vec3(r.dir)}, {"tmin", number_to_json(r.tmin)}, {"tmax", number_to_json(r.tmax)}};
}

struct ToJson {
  Json operator()(const RayAabbInput& in) const {
    Json j = ray_fields(in.ray);
    j["box"] = aabb(in.box);
    return j;
  }
  Json operator()(const SphereSphereInput& in) const { return {{"a", sphere(in.a)}, {"b", sphere(in.b)}}; }
  Json operator()(const AabbAabbInput& in) const { return {{"a", aabb(in.a)}, {"b", aabb(in.b)}}; }
  Json operator()(const KdopKdopInput& in) const { return {{"k", in.k}, {"a", points(in.a)}, {"b", points(in.b)}}; }
  Json operator()(const ObbObbInput& in) const { return {{"a", obb(in.a)}, {"b", obb(in.b)}}; }
  Json operator()(const TriAabbInput& in) const { return {{"triangle", triangle(in.tri)}, {"box", aabb(in.box)}}; }
  Json operator()(const TriObbInput& in) const { return {{"triangle", triangle(in.tri)}, {"box", obb(in.box)}}; }
  Json operator()(const TriTriInput& in) const { return {{"a", triangle(in.a)}, {"b", triangle(in.b)}}; }
  Json operator()(const MeshMeshInput& in) const { return meshes(in.meshes); }
  Json operator()(const MeshMeshFirstInput& in) const { return meshes(in.meshes); }
  Json operator()(const BroadphaseInput& in) const {
    Json frames = Json::array();
    for (const auto& frame : in.frames) {
      Json boxes = Json::array();
      for (const auto& box : frame) boxes.push_back(box ? aabb(*box) : Json(nullptr));
      frames.push_back(boxes);
    }
    return {{"frames", frames}};
  }
  Json operator()(const RayMeshInput& in) const {
    Json j = ray_fields(in.ray);
    j["mesh"] = mesh(in.mesh);
    j["library"] = library(in.library);
    return j;
  }
  Json operator()(const MovingObbInput& in) const {
    const auto moving = [](const MovingObb& m) {
      Json j = obb(m.box);
      j["velocity"] = vec3(m.velocity);
      return j;
    };
    return {{"a", moving(in.a)}, {"b", moving(in.b)}};
  }
};

}  // namespace

Json input_to_json(const Input& input) { return std::visit(ToJson{}, input); }

Input input_from_json(QueryKind kind, const Json& json, const std::string& pointer,
                      const std::filesystem::path& case_dir) {
  const Reader r(json, pointer);
  switch (kind) {
    case QueryKind::ray_aabb: {
      RayAabbInput in;
      in.ray = r.ray();
      in.box = r.aabb("box");
      return in;
    }
    case QueryKind::sphere_sphere: return SphereSphereInput{r.sphere("a"), r.sphere("b")};
    case QueryKind::aabb_aabb: return AabbAabbInput{r.aabb("a"), r.aabb("b")};
    case QueryKind::kdop_kdop: {
      const Json& k = r.member("k");
      if (!k.is_number_integer() || !is_supported_kdop(k.get<int>())) {
        throw FormatError(r.path("k"), "k must be one of 6, 14, 16, 18, 24, 26");
      }
      return KdopKdopInput{k.get<int>(), r.points("a"), r.points("b")};
    }
    case QueryKind::obb_obb: return ObbObbInput{r.obb("a"), r.obb("b")};
    case QueryKind::tri_aabb: return TriAabbInput{r.triangle("triangle"), r.aabb("box")};
    case QueryKind::tri_obb: return TriObbInput{r.triangle("triangle"), r.obb("box")};
    case QueryKind::tri_tri: return TriTriInput{r.triangle("a"), r.triangle("b")};
    case QueryKind::mesh_mesh: return MeshMeshInput{r.meshes(case_dir)};
    case QueryKind::mesh_mesh_first: return MeshMeshFirstInput{r.meshes(case_dir)};
    case QueryKind::broadphase: return BroadphaseInput{r.frames("frames")};
    case QueryKind::ray_mesh: return RayMeshInput{r.mesh("mesh", case_dir), r.ray(), r.library("library")};
    case QueryKind::moving_obb: return MovingObbInput{r.moving("a"), r.moving("b")};
  }
  throw FormatError(pointer, "unknown query kind");
}

}  // namespace cc::harness
