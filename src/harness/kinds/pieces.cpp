// The table of each kind's pieces (model/kind_pieces.h), filled from every kind's unit: the one
// file below the tools that includes every kind. A unit that lacks a piece does not compile here.
#include "harness/model/kind_pieces.h"

#include <array>

#include "harness/kinds/aabb_aabb.h"
#include "harness/kinds/broadphase.h"
#include "harness/kinds/disc_walls.h"
#include "harness/kinds/kdop_kdop.h"
#include "harness/kinds/mesh_mesh.h"
#include "harness/kinds/mesh_mesh_distance.h"
#include "harness/kinds/mesh_mesh_first.h"
#include "harness/kinds/moving_obb.h"
#include "harness/kinds/obb_obb.h"
#include "harness/kinds/obb_obb_distance.h"
#include "harness/kinds/ray_aabb.h"
#include "harness/kinds/ray_mesh.h"
#include "harness/kinds/sphere_obb_distance.h"
#include "harness/kinds/sphere_sphere.h"
#include "harness/kinds/sphere_sphere_distance.h"
#include "harness/kinds/tri_aabb.h"
#include "harness/kinds/tri_obb.h"
#include "harness/kinds/tri_obb_distance.h"
#include "harness/kinds/tri_tri.h"
#include "harness/kinds/tri_tri_distance.h"
#include "harness/kinds/tri_tri_intersection.h"

namespace cc::harness {
namespace {

#define CC_QUERY_KIND_UNIT(name, Name) static_assert(QueryUnit<Name##Input>, "the unit of " #name " lacks a piece");
CC_FOR_EACH_QUERY_KIND(CC_QUERY_KIND_UNIT)
#undef CC_QUERY_KIND_UNIT

template <class In>
KindPieces pieces_of_unit() {
  using Q = Query<In>;
  KindPieces p;
  p.band = Q::band;
  p.relations = Q::relations;
  p.judged = Q::judged;
  p.builds_hierarchies = Q::builds_hierarchies;
  p.parallel_applies = Q::parallel_applies;
  p.ask = [](const Input& in) { return Q::ask(std::get<In>(in)); };
  p.library_alternatives = [](const Input& in) -> std::vector<Opinion> {
    if constexpr (requires { Q::library_parties(); }) {
      return ask_parties(Q::library_parties(), std::get<In>(in));
    } else {
      return {};
    }
  };
  p.generate = [](ValueSource& values, const GenerateOptions& options) -> Input { return Q::generate(values, options); };
  p.touch = [](Input& in, ValueSource& values) { Q::touch(std::get<In>(in), values); };
  p.features = [](const Input& in) { return Q::features(std::get<In>(in)); };
  p.configurations = [] { return Q::configurations(); };
  p.recognise = [](const Input& in, Configurations& found) { Q::recognise(std::get<In>(in), found); };
  p.bound_terms = [] { return Q::bound_terms(); };
  p.probe = [](const Input& in, std::vector<bounds::Records>& records) { Q::probe(std::get<In>(in), records); };
  p.admits = [](const Input& in, Relation relation) {
    if constexpr (requires { Q::admits(std::get<In>(in), relation); }) {
      return Q::admits(std::get<In>(in), relation);
    } else {
      return true;
    }
  };
  return p;
}

}  // namespace

const KindPieces& pieces_of(QueryKind kind) {
  static const auto table = [] {
    std::array<KindPieces, kAllQueryKinds.size()> t;
    for (QueryKind k : kAllQueryKinds) {
      t[static_cast<std::size_t>(k)] = with_kind(k, []<class In>() { return pieces_of_unit<In>(); });
    }
    return t;
  }();
  return table[static_cast<std::size_t>(kind)];
}

}  // namespace cc::harness
