// mesh_mesh_distance in exact arithmetic: both meshes placed exactly by their poses, the least
// squared distance over their pairs of triangles (exact_meshes.h, exact_mesh_distance), against
// which an answer's distance and points are checked, each point against its mesh's surface.
#include <cstdio>
#include <string>

#include "oracle/exact/distance_check.h"
#include "oracle/exact/exact_meshes.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/judges.h"

namespace cc::exact {

template <>
ExactVerdict judge(const harness::MeshMeshDistanceInput& in) {
  return judge_mesh_distance(in.meshes);
}

template <>
harness::Explanation explain(const harness::MeshMeshDistanceInput& in) {
  harness::Explanation e = explain_meshes(in.meshes);
  if (meshes_outside_domain(in.meshes)) return e;
  const ExactMeshDistance d = exact_mesh_distance(in.meshes, kMaxDistancePairs);
  if (!d.complete) {
    e.facts.emplace_back("exact distance", "undecided: more than " + std::to_string(kMaxDistancePairs) + " pairs to compare");
    return e;
  }
  if (!d.faces) return e;
  char text[96];
  std::snprintf(text, sizeof text, "%.17g, between face %u of a and face %u of b", root_of(d.squared), d.faces->first,
                d.faces->second);
  e.facts.emplace_back("exact distance", text);
  return e;
}

}  // namespace cc::exact
