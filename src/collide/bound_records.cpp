#include "collide/bound_records.h"

namespace cc::bounds {

Records& next_call(std::vector<Records>& calls) { return calls.emplace_back(); }

template <class Record>
void record(Records& records, const Record& r) {
  records.add(r);
}

template void record(Records&, const Quotient&);
template void record(Records&, const SphereSquares&);
template void record(Records&, const KdopProjection&);
template void record(Records&, const ObbTest&);
template void record(Records&, const ObbAxis&);
template void record(Records&, const SatAxis&);
template void record(Records&, const FrameChange&);
template void record(Records&, const Independence&);
template void record(Records&, const RayTriangleSlab&);
template void record(Records&, const RayMeshFaceHit&);
template void record(Records&, const Placement&);
template void record(Records&, const RadiusRoot&);
template void record(Records&, const Cube&);
template void record(Records&, const SphereSeparation&);
template void record(Records&, const SphereObbSeparation&);
template void record(Records&, const TriangleSeparation&);
template void record(Records&, const ObbSeparation&);
template void record(Records&, const TriangleBoxSeparation&);

}  // namespace cc::bounds
