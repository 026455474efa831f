// The cost of a mesh query as the cost function T = n_v c_v + n_p c_p + n_u c_u models it:
// the counters of the query and unit costs measured on this machine with the case's own
// volumes and triangles, next to the measured time of the query itself.
#pragma once

#include "collide/bvh_collide.h"
#include "harness/model/mesh_query.h"

namespace cc::harness {

/// Nanoseconds per operation, each the median over `repeats` timed batches.
struct UnitCosts {
  double bv_test = 0;         // c_v: one overlap test of a's volume and b's moved volume
  double primitive_test = 0;  // c_p: one triangle-triangle test
  double bv_update = 0;       // c_u: one of b's volumes brought into a's frame (moved_volume)
};

struct QueryCost {
  CollisionCounters counters;
  UnitCosts unit;
  double predicted_ns = 0;  // T
  double measured_ns = 0;   // the query (hierarchies already built), median over repeats
};

/// The unit costs for the case's volume type and update, measured on up to 256 of each mesh's
/// nodes and triangles (b's moved by the case's relative transform). Empty meshes cost 0.
UnitCosts measure_unit_costs(const MeshPair& m, int repeats = 5);

/// The counters, the unit costs, T and the measured time of one query.
QueryCost measure_query_cost(const MeshPair& m, CollisionMode mode, int repeats = 5);

}  // namespace cc::harness
