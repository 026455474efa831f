#include "harness/shrinking/shrink_faces.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>


namespace cc::harness {
namespace {

// The document with each mesh of the pair at `pointer` cut down to the listed faces, written as
// triangles.
Json with_faces(const Json& current, const std::string& pointer, const MeshPair& m,
                const std::vector<std::uint32_t>& faces_a, const std::vector<std::uint32_t>& faces_b) {
  Json doc = current;
  doc[Json::json_pointer(pointer + "/a")] = mesh_to_json(triangles_mesh(submesh(*m.a.mesh, faces_a)));
  doc[Json::json_pointer(pointer + "/b")] = mesh_to_json(triangles_mesh(submesh(*m.b.mesh, faces_b)));
  return doc;
}

std::vector<std::uint32_t> all_faces(const Mesh& mesh) {
  std::vector<std::uint32_t> faces(mesh.size());
  std::iota(faces.begin(), faces.end(), 0u);
  return faces;
}

}  // namespace

std::vector<std::uint32_t> disputed_faces(const Evaluation& e, bool first_hit, bool second) {
  const auto& exact = e.exact.answer.pairs;
  std::set<std::uint32_t> faces;
  const auto side = [&](const FacePair& p) { return second ? p.second : p.first; };
  std::vector<const Answer*> answers{&e.library};
  for (const Opinion& o : e.opinions) {
    if (o.status == Opinion::Status::answered) answers.push_back(&o.answer);
  }
  for (const Answer* a : answers) {
    for (const FacePair& p : a->pairs) {
      if (!std::binary_search(exact.begin(), exact.end(), p)) faces.insert(side(p));
    }
    // A first hit names one pair: the exact pairs are then only disputed when it names none.
    if (first_hit && !a->pairs.empty()) continue;
    for (const FacePair& p : exact) {
      if (std::find(a->pairs.begin(), a->pairs.end(), p) == a->pairs.end()) faces.insert(side(p));
    }
  }
  if (faces.empty() && !e.exact.pair_margins.empty()) {
    const auto nearest = std::min_element(e.exact.pair_margins.begin(), e.exact.pair_margins.end(),
                                          [](const auto& x, const auto& y) { return std::fabs(x.margin) < std::fabs(y.margin); });
    faces.insert(side(nearest->pair));
  }
  return {faces.begin(), faces.end()};
}

bool shrink_faces(const Json& current, const std::string& pointer, const MeshPair& meshes, bool first_hit,
                  const Evaluation& start, const Attempt& attempt) {
  std::vector<std::uint32_t> keep[2] = {all_faces(*meshes.a.mesh), all_faces(*meshes.b.mesh)};
  bool dropped = false;
  // Only the disputed faces, if the case still shows its disagreement with them alone.
  const std::vector<std::uint32_t> disputed[2] = {disputed_faces(start, first_hit, false),
                                                    disputed_faces(start, first_hit, true)};
  if (!disputed[0].empty() && !disputed[1].empty() &&
      (disputed[0].size() < keep[0].size() || disputed[1].size() < keep[1].size()) &&
      attempt(with_faces(current, pointer, meshes, disputed[0], disputed[1]))) {
    keep[0] = disputed[0], keep[1] = disputed[1];
    dropped = true;
  }
  // Delta debugging: drop a chunk of one mesh's faces at a time, chunks halving in size.
  for (int side = 0; side < 2; ++side) {
    for (std::size_t chunk = keep[side].size() / 2; chunk >= 1; chunk /= 2) {
      for (std::size_t at = 0; at < keep[side].size() && keep[side].size() > 1;) {
        std::vector<std::uint32_t> fewer = keep[side];
        fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(at),
                    fewer.begin() + static_cast<std::ptrdiff_t>(std::min(at + chunk, fewer.size())));
        const Json doc = side == 0 ? with_faces(current, pointer, meshes, fewer, keep[1])
                                   : with_faces(current, pointer, meshes, keep[0], fewer);
        if (attempt(doc)) {
          keep[side] = std::move(fewer);
          dropped = true;
        } else {
          at += chunk;
        }
      }
    }
  }
  return dropped;
}

}  // namespace cc::harness
