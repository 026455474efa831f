// The answer of a distance kind from the library's Separation: the one layout the judge reads
// (judging: params of size 9).
#pragma once

#include "collide/separation.h"
#include "harness/model/answer.h"

namespace cc::harness {

/// Hit when the distance is at most 0 (touching or overlapping); params: the distance, on_a,
/// on_b, distance_error, point_error. NaN (outside the domain) is a miss.
inline Answer separation_answer(const Separation& s) {
  Answer answer = Answer::of(s.distance <= 0);
  answer.params = {s.distance, s.on_a.x, s.on_a.y, s.on_a.z, s.on_b.x, s.on_b.y, s.on_b.z, s.distance_error, s.point_error};
  return answer;
}

}  // namespace cc::harness
