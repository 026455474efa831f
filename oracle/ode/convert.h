// Conversions from the library's types to ODE's, and ODE's geoms held by RAII (internal to
// oracle/ode).
#pragma once

#include <ode/ode.h>

#include <cmath>
#include <memory>

#include "collide/obb.h"
#include "collide/proper_frame.h"

namespace cc::ode_oracle {

/// A geom destroyed with its holder.
struct GeomDeleter {
  void operator()(dGeomID g) const { dGeomDestroy(g); }
};
using Geom = std::unique_ptr<dxGeom, GeomDeleter>;

/// A space destroyed with its holder (its geoms are destroyed with it unless cleanup is off).
struct SpaceDeleter {
  void operator()(dSpaceID s) const { dSpaceDestroy(s); }
};
using Space = std::unique_ptr<dxSpace, SpaceDeleter>;

/// Euclidean length.
inline double length_of(const Vec3& v) { return std::hypot(v.x, v.y, v.z); }

/// ODE's rotation (rows of 4, the last unused) of the basis whose columns are m's.
inline void to_ode(const Mat3& m, dMatrix3 r) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) r[4 * i + j] = m(i, j);
    r[4 * i + 3] = 0;
  }
}

/// A dBox of the OBB: its sides 2 half (exact), placed at its centre with its frame made proper
/// (a box is symmetric, so negating an axis of a mirror-image frame leaves it unchanged).
inline Geom box_geom(const Obb& box) {
  Geom g(dCreateBox(nullptr, 2 * box.half.x, 2 * box.half.y, 2 * box.half.z));
  dMatrix3 r;
  to_ode(proper_frame(box.axes), r);
  dGeomSetRotation(g.get(), r);
  dGeomSetPosition(g.get(), box.center.x, box.center.y, box.center.z);
  return g;
}

/// Whether dCollide reports at least one contact for the two geoms.
inline bool any_contact(dGeomID a, dGeomID b) {
  dContactGeom contact[4];
  return dCollide(a, b, 4, contact, sizeof(dContactGeom)) > 0;
}

}  // namespace cc::ode_oracle
