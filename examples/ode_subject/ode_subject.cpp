// A crosscheck subject made of ODE's own collision tests (include/crosscheck/subject.h), through
// ODE's C interface alone: build it as a shared library and run
// `crosscheck campaign --subject PATH/libcrosscheck_ode_subject.so`. Each function hands the
// shapes to ODE as an ODE user would (geoms through dCollide, boxes through a space) and returns
// its answer. It stands alone, as a user's subject does: it shares no code with crosscheck's ODE
// parties (oracle/ode), though it asks some of the same calls. ODE's answers where its meaning
// differs from the interface's (its ray reports a crossing of a surface; its trimesh contacts
// merge nearby points, naming one pair of faces for several) are left as ODE gives them: a
// campaign reports them.
#include <crosscheck/subject.h>
#include <ode/ode.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace {

// ODE initialised once, before the first call.
void init() {
  static const bool done = [] {
    dInitODE2(0);
    return dAllocateODEDataForThread(dAllocateMaskAll) != 0;
  }();
  (void)done;
}

bool touches(dGeomID a, dGeomID b) {
  dContactGeom contact[8];
  return dCollide(a, b, 8, contact, sizeof(dContactGeom)) > 0;
}

// A box geom of an AABB: its centre and sides.
dGeomID aabb_box(const cc_aabb& b) {
  dGeomID g = dCreateBox(nullptr, b.hi.x - b.lo.x, b.hi.y - b.lo.y, b.hi.z - b.lo.z);
  dGeomSetPosition(g, 0.5 * (b.lo.x + b.hi.x), 0.5 * (b.lo.y + b.hi.y), 0.5 * (b.lo.z + b.hi.z));
  return g;
}

// A box geom of an OBB: a mirror-image frame has its third axis negated (the same box).
dGeomID obb_box(const cc_obb& b) {
  dGeomID g = dCreateBox(nullptr, 2 * b.half.x, 2 * b.half.y, 2 * b.half.z);
  const cc_vec3 &x = b.axis[0], &y = b.axis[1];
  cc_vec3 z = b.axis[2];
  const double det = x.x * (y.y * z.z - y.z * z.y) - x.y * (y.x * z.z - y.z * z.x) + x.z * (y.x * z.y - y.y * z.x);
  if (det < 0) z = {-z.x, -z.y, -z.z};
  const dMatrix3 r = {x.x, y.x, z.x, 0, x.y, y.y, z.y, 0, x.z, y.z, z.z, 0};
  dGeomSetRotation(g, r);
  dGeomSetPosition(g, b.center.x, b.center.y, b.center.z);
  return g;
}

// A trimesh of the mesh's faces in order, placed by a pose; its data freed with it.
struct TriMesh {
  std::vector<double> vertices;
  std::vector<dTriIndex> indices;
  dTriMeshDataID data = nullptr;
  dGeomID geom = nullptr;
  TriMesh(const cc_mesh& m, const cc_pose* pose) {
    for (unsigned i = 0; i < m.vertex_count; ++i)
      vertices.insert(vertices.end(), {m.vertices[i].x, m.vertices[i].y, m.vertices[i].z});
    for (unsigned f = 0; f < m.face_count; ++f)
      indices.insert(indices.end(), {m.faces[f][0], m.faces[f][1], m.faces[f][2]});
    // ODE's OPCODE crashes on a tree of a single triangle: such a mesh gets its face twice (as
    // face 0 and face 1; the callers map indices back modulo the face count).
    if (m.face_count == 1) indices.insert(indices.end(), {m.faces[0][0], m.faces[0][1], m.faces[0][2]});
    data = dGeomTriMeshDataCreate();
    dGeomTriMeshDataBuildDouble(data, vertices.data(), 3 * sizeof(double), static_cast<int>(m.vertex_count),
                                indices.data(), static_cast<int>(indices.size()), 3 * sizeof(dTriIndex));
    geom = dCreateTriMesh(nullptr, data, nullptr, nullptr, nullptr);
    if (pose != nullptr) {
      const dMatrix3 r = {pose->rotation[0][0], pose->rotation[0][1], pose->rotation[0][2], 0,
                          pose->rotation[1][0], pose->rotation[1][1], pose->rotation[1][2], 0,
                          pose->rotation[2][0], pose->rotation[2][1], pose->rotation[2][2], 0};
      dGeomSetRotation(geom, r);
      dGeomSetPosition(geom, pose->translation.x, pose->translation.y, pose->translation.z);
    }
  }
  TriMesh(const TriMesh&) = delete;
  TriMesh& operator=(const TriMesh&) = delete;
  ~TriMesh() {
    dGeomDestroy(geom);
    dGeomTriMeshDataDestroy(data);
  }
};

// The pairs of faces ODE's trimesh contacts name (side1 of a, side2 of b), sorted, each once.
std::vector<cc_face_pair> contact_pairs(const cc_mesh& a, const cc_pose& pose_a, const cc_mesh& b,
                                        const cc_pose& pose_b) {
  std::vector<cc_face_pair> out;
  if (a.face_count == 0 || b.face_count == 0) return out;
  TriMesh ma(a, &pose_a), mb(b, &pose_b);
  std::vector<dContactGeom> contacts(0xffff);
  const int n = dCollide(ma.geom, mb.geom, 0xffff, contacts.data(), sizeof(dContactGeom));
  for (int i = 0; i < n; ++i) {
    if (contacts[i].side1 >= 0 && contacts[i].side2 >= 0) {
      out.push_back({static_cast<unsigned>(contacts[i].side1) % a.face_count,
                     static_cast<unsigned>(contacts[i].side2) % b.face_count});
    }
  }
  std::sort(out.begin(), out.end(),
            [](const cc_face_pair& p, const cc_face_pair& q) { return p.a != q.a ? p.a < q.a : p.b < q.b; });
  out.erase(std::unique(out.begin(), out.end(),
                        [](const cc_face_pair& p, const cc_face_pair& q) { return p.a == q.a && p.b == q.b; }),
            out.end());
  return out;
}

// A ray geom for the points origin + t dir, t in [tmin, tmax], reaching `reach` past the origin
// when the range is infinite: ODE's rays start at their origin and have a length (a zero
// direction: the origin alone, a ray of length 0). The caller checks tmin <= tmax.
dGeomID ray_geom(const cc_ray& r, double reach) {
  const double speed = std::sqrt(r.dir.x * r.dir.x + r.dir.y * r.dir.y + r.dir.z * r.dir.z);
  double t0 = std::isfinite(r.tmin) ? r.tmin : -reach / speed, t1 = std::isfinite(r.tmax) ? r.tmax : reach / speed;
  if (!(speed > 0)) t0 = t1 = 0;
  dGeomID ray = dCreateRay(nullptr, (t1 - t0) * speed);
  dGeomRaySet(ray, r.origin.x + t0 * r.dir.x, r.origin.y + t0 * r.dir.y, r.origin.z + t0 * r.dir.z, r.dir.x, r.dir.y,
              r.dir.z);
  return ray;
}

double distance(const cc_vec3& a, const cc_vec3& b) { return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z); }

// A box of a broad phase: a geom of a class whose AABB is the box (ODE's spaces ask it).
struct Slot {
  cc_aabb box;
  unsigned index;
};

void slot_aabb(dGeomID g, dReal aabb[6]) {
  const cc_aabb& b = static_cast<Slot*>(dGeomGetClassData(g))->box;
  aabb[0] = b.lo.x, aabb[1] = b.hi.x, aabb[2] = b.lo.y, aabb[3] = b.hi.y, aabb[4] = b.lo.z, aabb[5] = b.hi.z;
}

dColliderFn* no_collider(int) { return nullptr; }

int slot_class() {
  static const int number = [] {
    dGeomClass c{};
    c.bytes = static_cast<int>(sizeof(Slot));
    c.collider = no_collider;
    c.aabb = slot_aabb;
    return dCreateGeomClass(&c);
  }();
  return number;
}

// The near callback: the pair kept where the boxes overlap (a narrow phase's first step).
struct Found {
  std::vector<cc_face_pair> pairs;
};

void near_pair(void* data, dGeomID a, dGeomID b) {
  const Slot& s = *static_cast<Slot*>(dGeomGetClassData(a));
  const Slot& t = *static_cast<Slot*>(dGeomGetClassData(b));
  const bool overlap = s.box.lo.x <= t.box.hi.x && t.box.lo.x <= s.box.hi.x && s.box.lo.y <= t.box.hi.y &&
                       t.box.lo.y <= s.box.hi.y && s.box.lo.z <= t.box.hi.z && t.box.lo.z <= s.box.hi.z;
  if (overlap) static_cast<Found*>(data)->pairs.push_back({std::min(s.index, t.index), std::max(s.index, t.index)});
}

}  // namespace

extern "C" {

int crosscheck_subject_version(void) { return CROSSCHECK_SUBJECT_VERSION; }

// Two axis-aligned box geoms through dCollide.
int crosscheck_aabb_aabb(const cc_aabb* a, const cc_aabb* b) {
  init();
  dGeomID ga = aabb_box(*a), gb = aabb_box(*b);
  const int hit = touches(ga, gb) ? 1 : 0;
  dGeomDestroy(ga), dGeomDestroy(gb);
  return hit;
}

// A ray geom against a box geom.
int crosscheck_ray_aabb(const cc_ray* ray, const cc_aabb* box) {
  init();
  if (!(ray->tmin <= ray->tmax)) return 0;
  const double reach =
      2 * (distance(ray->origin, box->lo) + distance(box->lo, box->hi)) + 1;  // past every point of the box
  dGeomID r = ray_geom(*ray, reach), b = aabb_box(*box);
  const int hit = touches(r, b) ? 1 : 0;
  dGeomDestroy(r), dGeomDestroy(b);
  return hit;
}

// Two box geoms through dCollide (dBoxBox).
int crosscheck_obb_obb(const cc_obb* a, const cc_obb* b) {
  init();
  dGeomID ga = obb_box(*a), gb = obb_box(*b);
  const int hit = touches(ga, gb) ? 1 : 0;
  dGeomDestroy(ga), dGeomDestroy(gb);
  return hit;
}

// Two sphere geoms through dCollide.
int crosscheck_sphere_sphere(const cc_sphere* a, const cc_sphere* b) {
  init();
  dGeomID ga = dCreateSphere(nullptr, a->radius), gb = dCreateSphere(nullptr, b->radius);
  dGeomSetPosition(ga, a->center.x, a->center.y, a->center.z);
  dGeomSetPosition(gb, b->center.x, b->center.y, b->center.z);
  const int hit = touches(ga, gb) ? 1 : 0;
  dGeomDestroy(ga), dGeomDestroy(gb);
  return hit;
}

// Two one-triangle trimeshes through dCollide.
int crosscheck_tri_tri(const cc_triangle* a, const cc_triangle* b) {
  init();
  const unsigned face[1][3] = {{0, 1, 2}};
  const cc_mesh ma{a->v, 3, face, 1}, mb{b->v, 3, face, 1};
  TriMesh ta(ma, nullptr), tb(mb, nullptr);
  return touches(ta.geom, tb.geom) ? 1 : 0;
}

// A ray geom against the mesh's trimesh, asked for its closest hit; the face of the contact.
int crosscheck_ray_mesh(const cc_ray* ray, const cc_mesh* mesh, unsigned* face) {
  init();
  if (mesh->face_count == 0 || !(ray->tmin <= ray->tmax)) return 0;
  double reach = 0;
  for (unsigned i = 0; i < mesh->vertex_count; ++i) reach = std::max(reach, distance(ray->origin, mesh->vertices[i]));
  TriMesh m(*mesh, nullptr);
  dGeomID r = ray_geom(*ray, 2 * reach + 1);
  dGeomRaySetClosestHit(r, 1);
  dContactGeom contact;
  const int n = dCollide(r, m.geom, 1, &contact, sizeof contact);
  dGeomDestroy(r);
  if (n == 0) return 0;
  const int side = contact.g1 == m.geom ? contact.side1 : contact.side2;
  if (side < 0) return 0;
  *face = static_cast<unsigned>(side) % mesh->face_count;
  return 1;
}

// The two placed trimeshes through dCollide: the pairs their contacts name.
int crosscheck_mesh_mesh(const cc_mesh* a, const cc_pose* pose_a, const cc_mesh* b, const cc_pose* pose_b,
                         cc_face_pair* pairs, unsigned capacity) {
  init();
  const std::vector<cc_face_pair> found = contact_pairs(*a, *pose_a, *b, *pose_b);
  std::copy_n(found.begin(), std::min<std::size_t>(found.size(), capacity), pairs);
  return static_cast<int>(found.size());
}

int crosscheck_mesh_mesh_first(const cc_mesh* a, const cc_pose* pose_a, const cc_mesh* b, const cc_pose* pose_b,
                               cc_face_pair* pair) {
  init();
  const std::vector<cc_face_pair> found = contact_pairs(*a, *pose_a, *b, *pose_b);
  if (found.empty()) return 0;
  *pair = found.front();
  return 1;
}

// ODE's sweep-and-prune space, driven as a user drives it: a geom added when a box appears,
// moved every frame, destroyed when the box goes; dSpaceCollide's pairs kept where the boxes overlap.
int crosscheck_broadphase(const cc_box_frames* frames, cc_face_pair* pairs, unsigned capacity, unsigned* frame_ends) {
  init();
  dSpaceID space = dSweepAndPruneSpaceCreate(nullptr, dSAP_AXES_XYZ);
  std::vector<dGeomID> geoms(frames->slots, nullptr);
  unsigned count = 0;
  for (unsigned f = 0; f < frames->frames; ++f) {
    for (unsigned i = 0; i < frames->slots; ++i) {
      const bool present = frames->present[f * frames->slots + i] != 0;
      if (present && geoms[i] == nullptr) {
        geoms[i] = dCreateGeom(slot_class());
        static_cast<Slot*>(dGeomGetClassData(geoms[i]))->index = i;
        dSpaceAdd(space, geoms[i]);
      } else if (!present && geoms[i] != nullptr) {
        dGeomDestroy(geoms[i]);
        geoms[i] = nullptr;
      }
      if (present) {
        static_cast<Slot*>(dGeomGetClassData(geoms[i]))->box = frames->boxes[f * frames->slots + i];
        dGeomSetPosition(geoms[i], 0, 0, 0);  // moved: its AABB is asked again
      }
    }
    Found found;
    dSpaceCollide(space, &found, near_pair);
    for (const cc_face_pair& p : found.pairs) {
      if (count < capacity) pairs[count] = p;
      ++count;
    }
    frame_ends[f] = std::min(count, capacity);
  }
  dSpaceDestroy(space);  // destroys the geoms still in it
  return static_cast<int>(count);
}

}  // extern "C"
