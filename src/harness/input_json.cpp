#include "harness/input_json.h"

#include "collide/kdop.h"
#include "harness/number_text.h"

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
  Obb obb(const std::string& name) const {
    const Reader r = object(name);
    const std::vector<Vec3> axes = r.points("axes");
    if (axes.size() != 3) throw FormatError(r.path("axes"), "expected 3 columns");
    return {r.vec3("center"), r.vec3("half"), Mat3::from_columns(axes[0], axes[1], axes[2])};
  }
  Sphere sphere(const std::string& name) const {
    const Reader r = object(name);
    return {r.vec3("center"), r.number("radius")};
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

struct ToJson {
  Json operator()(const RayAabbInput& in) const {
    return {{"origin", vec3(in.ray.origin)}, {"dir", vec3(in.ray.dir)},        {"tmin", number_to_json(in.ray.tmin)},
            {"tmax", number_to_json(in.ray.tmax)}, {"box", aabb(in.box)}};
  }
  Json operator()(const SphereSphereInput& in) const { return {{"a", sphere(in.a)}, {"b", sphere(in.b)}}; }
  Json operator()(const AabbAabbInput& in) const { return {{"a", aabb(in.a)}, {"b", aabb(in.b)}}; }
  Json operator()(const KdopKdopInput& in) const { return {{"k", in.k}, {"a", points(in.a)}, {"b", points(in.b)}}; }
  Json operator()(const ObbObbInput& in) const { return {{"a", obb(in.a)}, {"b", obb(in.b)}}; }
  Json operator()(const TriAabbInput& in) const { return {{"triangle", triangle(in.tri)}, {"box", aabb(in.box)}}; }
  Json operator()(const TriObbInput& in) const { return {{"triangle", triangle(in.tri)}, {"box", obb(in.box)}}; }
  Json operator()(const TriTriInput& in) const { return {{"a", triangle(in.a)}, {"b", triangle(in.b)}}; }
};

}  // namespace

Json input_to_json(const Input& input) { return std::visit(ToJson{}, input); }

Input input_from_json(QueryKind kind, const Json& json, const std::string& pointer) {
  const Reader r(json, pointer);
  switch (kind) {
    case QueryKind::ray_aabb: {
      RayAabbInput in;
      in.ray = {r.vec3("origin"), r.vec3("dir"), r.number("tmin"), r.number("tmax")};
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
  }
  throw FormatError(pointer, "unknown query kind");
}

}  // namespace cc::harness
