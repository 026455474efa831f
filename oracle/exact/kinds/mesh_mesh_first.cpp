// mesh_mesh_first in exact arithmetic: every pair of triangles near contact, exactly
// (exact_meshes.h); the library's one pair is judged against them.
#include "oracle/exact/exact_meshes.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/judges.h"

namespace cc::exact {

template <>
ExactVerdict judge(const harness::MeshMeshFirstInput& in) {
  return judge_meshes(in.meshes);
}

template <>
harness::Explanation explain(const harness::MeshMeshFirstInput& in) {
  return explain_meshes(in.meshes);
}

}  // namespace cc::exact
