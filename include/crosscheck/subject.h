/* crosscheck's subject interface: put your own collision code under test.
 *
 * A subject is a shared library exporting crosscheck_subject_version() and, for each query kind
 * it answers, a function named crosscheck_<kind> taking the kind's shapes as plain structs of
 * doubles and returning 1 when they meet (touching counts) and 0 when they do not (the mesh
 * kinds also name the faces that meet, the distance kinds give the distance and two points). Export only
 * the kinds you have; crosscheck skips and lists the others. Then
 *
 *     crosscheck campaign --subject ./libmine.so
 *
 * judges every answer against exact rational arithmetic and keeps each wrong one, shrunk, as a
 * case file. Inputs may be degenerate (zero extents, collinear triangles, zero directions),
 * touching to the last bit, huge or tiny; they are within crosscheck's own contract unless the
 * case says otherwise. A crash or a hang in a subject is a finding (the subject is asked in a
 * child process), not the end of a campaign or of any other command.
 * Plain C: no crosscheck type or library is needed to build a subject. */
#ifndef CROSSCHECK_SUBJECT_H
#define CROSSCHECK_SUBJECT_H

/* The interface's version: crosscheck_subject_version() must return it. */
#define CROSSCHECK_SUBJECT_VERSION 1

#ifdef __cplusplus
extern "C" {
#endif

typedef struct { double x, y, z; } cc_vec3;
/* The closed box lo <= p <= hi. */
typedef struct { cc_vec3 lo, hi; } cc_aabb;
/* The closed ball of the radius around the center (radius 0: a point). */
typedef struct { cc_vec3 center; double radius; } cc_sphere;
/* The closed box center + a0 axis[0] + a1 axis[1] + a2 axis[2], |ai| <= half_i; the axes
 * orthonormal to within 2^-48 (possibly a mirror-image frame), half extents >= 0. */
typedef struct { cc_vec3 center, half; cc_vec3 axis[3]; } cc_obb;
/* The closed triangle (possibly a segment or a point). */
typedef struct { cc_vec3 v[3]; } cc_triangle;
/* The points origin + t dir, tmin <= t <= tmax (tmax may be +infinity, tmin -infinity; dir may be
 * zero: then the origin alone, for any tmin <= tmax). */
typedef struct { cc_vec3 origin, dir; double tmin, tmax; } cc_ray;

/* A box moving with constant velocity over a step: at time t in [0, 1], box translated by
 * t velocity. */
typedef struct { cc_obb box; cc_vec3 velocity; } cc_moving_obb;

/* A triangle mesh: vertex_count vertices, face_count faces, each three indices of vertices (a
 * face may be degenerate: a segment or a point). */
typedef struct {
  const cc_vec3* vertices;
  unsigned vertex_count;
  const unsigned (*faces)[3];
  unsigned face_count;
} cc_mesh;
/* A rigid placement p -> rotation p + translation (rotation row by row, a proper rotation). */
typedef struct { double rotation[3][3]; cc_vec3 translation; } cc_pose;
/* A face of mesh a and a face of mesh b. */
typedef struct { unsigned a, b; } cc_face_pair;

/* Boxes frame by frame, for a sweep over many objects: frame f's box in slot i is boxes[f * slots + i] when
 * present[f * slots + i] is 1; a box absent from a frame is removed (or not yet added), and a slot
 * keeps its box's identity from frame to frame. */
typedef struct {
  const cc_aabb* boxes;
  const unsigned char* present;
  unsigned slots, frames;
} cc_box_frames;

/* Returns CROSSCHECK_SUBJECT_VERSION. */
int crosscheck_subject_version(void);

/* Each returns 1 when the two shapes share a point (two moving boxes: at some time of the step),
 * 0 otherwise. */
int crosscheck_ray_aabb(const cc_ray* ray, const cc_aabb* box);
int crosscheck_sphere_sphere(const cc_sphere* a, const cc_sphere* b);
int crosscheck_aabb_aabb(const cc_aabb* a, const cc_aabb* b);
int crosscheck_obb_obb(const cc_obb* a, const cc_obb* b);
int crosscheck_tri_aabb(const cc_triangle* tri, const cc_aabb* box);
int crosscheck_tri_obb(const cc_triangle* tri, const cc_obb* box);
int crosscheck_tri_tri(const cc_triangle* a, const cc_triangle* b);
int crosscheck_moving_obb(const cc_moving_obb* a, const cc_moving_obb* b);

/* The ray against the mesh: 1 when it meets a face, *face then the face it meets first (at the
 * least t); 0 when it meets none. */
int crosscheck_ray_mesh(const cc_ray* ray, const cc_mesh* mesh, unsigned* face);
/* The two placed meshes: every pair of faces that share a point, each once, in any order; at
 * most `capacity` written to `pairs`. Returns how many pairs meet (more than capacity: the rest
 * were not written, and crosscheck counts the answer as failed). */
int crosscheck_mesh_mesh(const cc_mesh* a, const cc_pose* pose_a, const cc_mesh* b, const cc_pose* pose_b,
                         cc_face_pair* pairs, unsigned capacity);
/* The same asked for one pair: 1 and *pair when some pair of faces meets, 0 otherwise. */
int crosscheck_mesh_mesh_first(const cc_mesh* a, const cc_pose* pose_a, const cc_mesh* b, const cc_pose* pose_b,
                               cc_face_pair* pair);
/* Many moving boxes, the frames driven through the subject's broad phase: the pairs of slots whose boxes overlap in each frame (a,
 * b the two slots, each pair once), frame after frame into `pairs` (at most `capacity`), and
 * frame_ends[f] the number written up to the end of frame f. Returns how many pairs there are in
 * all (more than capacity: crosscheck counts the answer as failed). */
int crosscheck_broadphase(const cc_box_frames* frames, cc_face_pair* pairs, unsigned capacity, unsigned* frame_ends);

/* Distances. Each writes the signed distance between the two shapes: > 0 apart (the length of a
 * shortest segment between them), < 0 overlapping (minus the penetration depth, the length of the
 * shortest translation of b that separates them; triangles have no inside), 0 touching; and a
 * point of each realising it: apart, a closest pair (any one where they are not unique);
 * overlapping, a point of each boundary with on_a - on_b that translation. Returns 1 when it
 * wrote them (anything else: crosscheck counts the call as failed). A subject that exports one
 * exports crosscheck_distance_tolerance() too. */
int crosscheck_tri_tri_distance(const cc_triangle* a, const cc_triangle* b, double* distance, cc_vec3* on_a,
                                cc_vec3* on_b);
int crosscheck_sphere_sphere_distance(const cc_sphere* a, const cc_sphere* b, double* distance, cc_vec3* on_a,
                                      cc_vec3* on_b);
int crosscheck_sphere_obb_distance(const cc_sphere* ball, const cc_obb* box, double* distance, cc_vec3* on_a,
                                   cc_vec3* on_b);
int crosscheck_obb_obb_distance(const cc_obb* a, const cc_obb* b, double* distance, cc_vec3* on_a, cc_vec3* on_b);
int crosscheck_tri_obb_distance(const cc_triangle* tri, const cc_obb* box, double* distance, cc_vec3* on_a,
                                cc_vec3* on_b);
/* The distance between the surfaces of the two placed meshes (0 where they touch or cross) and a
 * closest pair of points, on_a on a's faces and on_b on b's, in the world. Returns 1 when it wrote
 * them. */
int crosscheck_mesh_mesh_distance(const cc_mesh* a, const cc_pose* pose_a, const cc_mesh* b, const cc_pose* pose_b,
                                  double* distance, cc_vec3* on_a, cc_vec3* on_b);
/* How far the subject's distances and points may be from the exact ones, relative to the largest
 * absolute coordinate, radius or half extent of a case's shapes (e.g. 1e-12): an answer is right
 * when its distance and each point lie within this of the exact ones. At least 0, below 1. */
double crosscheck_distance_tolerance(void);

#ifdef __cplusplus
}
#endif

#endif /* CROSSCHECK_SUBJECT_H */
