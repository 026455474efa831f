// ray_aabb's second opinions: libccd's GJK and MPR on a segment against a box, through support
// functions. FCL has no rays; libccd answers for segments only (finite tmin and tmax).
#include <ccd/ccd.h>

#include <cmath>

#include "oracle/fcl/parties.h"
#include "oracle/fcl/time_limit.h"

namespace cc::fcl_oracle {
namespace {

struct Segment {
  Vec3 p, q;
};

void set(ccd_vec3_t* out, const Vec3& v) {
  out->v[0] = v.x;
  out->v[1] = v.y;
  out->v[2] = v.z;
}

void segment_support(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const auto* s = static_cast<const Segment*>(obj);
  const Vec3 d{dir->v[0], dir->v[1], dir->v[2]};
  set(out, dot(d, s->p) >= dot(d, s->q) ? s->p : s->q);
}

void segment_center(const void* obj, ccd_vec3_t* out) {
  const auto* s = static_cast<const Segment*>(obj);
  set(out, 0.5 * (s->p + s->q));
}

void box_support(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const auto* b = static_cast<const Aabb*>(obj);
  for (int i = 0; i < 3; ++i) out->v[i] = dir->v[i] >= 0 ? b->hi[i] : b->lo[i];
}

void box_center(const void* obj, ccd_vec3_t* out) {
  const auto* b = static_cast<const Aabb*>(obj);
  set(out, 0.5 * (b->lo + b->hi));
}

template <class Algorithm>
Opinion segment_box(const harness::RayAabbInput& in, Algorithm intersect) {
  const Ray& r = in.ray;
  if (!std::isfinite(r.tmin) || !std::isfinite(r.tmax)) return not_applicable("a ray of infinite length");
  if (!(r.tmin <= r.tmax)) return not_applicable("an empty parameter range (tmin > tmax)");
  // The segment's end points, rounded to nearest: libccd sees this segment, not the exact one.
  const Segment s{r.origin + r.tmin * r.dir, r.origin + r.tmax * r.dir};
  ccd_t ccd;
  CCD_INIT(&ccd);
  ccd.support1 = segment_support;
  ccd.support2 = box_support;
  ccd.center1 = segment_center;
  ccd.center2 = box_center;
  ccd.max_iterations = 500;
  ccd.mpr_tolerance = 1e-6;  // as FCL configures it for collision queries
  int result = 0;
  if (!run_with_time_limit(kLibccdTimeLimit, [&] { result = intersect(&s, &in.box, &ccd); })) {
    return timed_out("did not return within " + std::to_string(kLibccdTimeLimit) + " s (a libccd loop)");
  }
  return answered(result != 0);
}

}  // namespace

template <>
const std::vector<Party<harness::RayAabbInput>>& fcl_parties() {
  static const std::vector<Party<harness::RayAabbInput>> parties = {
      {"libccd.GJK",
       {0x1p-18, BandSides::two_sided, 0,
        "libccd stops on absolute tolerances (around 1e-6): the band they mean at unit scale"},
       [](const harness::RayAabbInput& in) { return segment_box(in, ccdGJKIntersect); }},
      {"libccd.MPR", {0x1p-18, BandSides::two_sided, 0, "mpr_tolerance = 1e-6, absolute: the band it means at unit scale"},
       [](const harness::RayAabbInput& in) { return segment_box(in, ccdMPRIntersect); }}};
  return parties;
}

}  // namespace cc::fcl_oracle
