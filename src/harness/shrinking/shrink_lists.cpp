#include "harness/shrinking/shrink_lists.h"

#include <algorithm>
#include <numeric>

namespace cc::harness {
namespace {

// Delta debugging over the indices in `keep` (at least one stays): `doc_of` writes the document
// that keeps only the given indices.
bool drop_elements(std::vector<std::size_t>& keep, const std::function<Json(const std::vector<std::size_t>&)>& doc_of,
                   const Attempt& attempt) {
  bool dropped = false;
  for (std::size_t chunk = keep.size() / 2; chunk >= 1; chunk /= 2) {
    for (std::size_t at = 0; at < keep.size() && keep.size() > 1;) {
      std::vector<std::size_t> fewer = keep;
      fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(at),
                  fewer.begin() + static_cast<std::ptrdiff_t>(std::min(at + chunk, fewer.size())));
      if (!fewer.empty() && attempt(doc_of(fewer))) {
        keep = std::move(fewer);
        dropped = true;
      } else {
        at += chunk;
      }
    }
  }
  return dropped;
}

std::vector<std::size_t> indices(std::size_t n) {
  std::vector<std::size_t> all(n);
  std::iota(all.begin(), all.end(), std::size_t{0});
  return all;
}

}  // namespace

bool shrink_box_frames(const Json& current, const std::string& pointer, const BoxFrames& frames, const Attempt& attempt) {
  if (frames.empty()) return false;
  const Json::json_pointer at(pointer);
  Json base = current;
  std::vector<std::size_t> boxes = indices(frames.front().size());
  const bool fewer_boxes = drop_elements(boxes, [&](const std::vector<std::size_t>& kept) {
    Json doc = base;
    for (Json& frame : doc[at]) {
      Json slots = Json::array();
      for (std::size_t i : kept) slots.push_back(frame[i]);
      frame = slots;
    }
    return doc;
  }, attempt);
  if (fewer_boxes) {  // the frames of the document as it now is
    for (Json& frame : base[at]) {
      Json slots = Json::array();
      for (std::size_t i : boxes) slots.push_back(frame[i]);
      frame = slots;
    }
  }
  std::vector<std::size_t> kept_frames = indices(frames.size());
  const bool fewer_frames = drop_elements(kept_frames, [&](const std::vector<std::size_t>& kept) {
    Json doc = base;
    doc[at] = Json::array();
    for (std::size_t f : kept) doc[at].push_back(base[at][f]);
    return doc;
  }, attempt);
  return fewer_boxes || fewer_frames;
}

bool shrink_list(const Json& current, const std::string& pointer, std::size_t size, const Attempt& attempt) {
  const Json::json_pointer at(pointer);
  const Json original = current.at(at);  // the indices kept are the original list's
  std::vector<std::size_t> parts = indices(size);
  return drop_elements(parts, [&](const std::vector<std::size_t>& kept) {
    Json doc = current;
    Json list = Json::array();
    for (std::size_t i : kept) list.push_back(original[i]);
    doc[at] = list;
    return doc;
  }, attempt);
}

bool shrink_mesh_faces(const Json& current, const std::string& pointer, const MeshRef& mesh, const Attempt& attempt) {
  std::vector<std::size_t> faces = indices(mesh.mesh->size());
  return drop_elements(faces, [&](const std::vector<std::size_t>& kept) {
    const std::vector<std::uint32_t> list(kept.begin(), kept.end());
    Json doc = current;
    doc[Json::json_pointer(pointer)] = mesh_to_json(triangles_mesh(submesh(*mesh.mesh, list)));
    return doc;
  }, attempt);
}

}  // namespace cc::harness
