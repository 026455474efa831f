// The exact reference's verdict for each kind of query (one file per kind).
#pragma once

#include "harness/model/input.h"
#include "harness/model/oracle.h"

namespace cc::exact {

using harness::ExactVerdict;

ExactVerdict judge(const harness::RayAabbInput& in);
ExactVerdict judge(const harness::SphereSphereInput& in);
ExactVerdict judge(const harness::AabbAabbInput& in);
ExactVerdict judge(const harness::KdopKdopInput& in);
ExactVerdict judge(const harness::ObbObbInput& in);
ExactVerdict judge(const harness::TriAabbInput& in);
ExactVerdict judge(const harness::TriObbInput& in);
ExactVerdict judge(const harness::TriTriInput& in);
ExactVerdict judge(const harness::MeshMeshInput& in);
ExactVerdict judge(const harness::MeshMeshFirstInput& in);
ExactVerdict judge(const harness::BroadphaseInput& in);
ExactVerdict judge(const harness::RayMeshInput& in);
ExactVerdict judge(const harness::MovingObbInput& in);

}  // namespace cc::exact
