/*
 * geom/geometry.h -- the scene's primitives and the BVH over them.
 *
 * A struct geometry owns every primitive (spheres, triangles, quads, and procedural
 * shapes behind struct shape_ops) and, after geometry_build(), a BVH over them.
 * Primitives are added first, then geometry_build() is called once, then the geometry
 * is only read: geometry_intersect() and geometry_occluded() are safe to call from
 * anywhere afterwards and never allocate.
 *
 * Geometry knows nothing of materials, lights or photons: a primitive carries a material
 * index that it hands back in struct hit, and an id (returned when it was added) that the
 * scene uses to find, say, the light an emitter belongs to.
 */
#ifndef PHOTON_GEOMETRY_H
#define PHOTON_GEOMETRY_H

#include <stddef.h>

#include "ray.h"

/* Documented limit on primitives in one scene: 2^28 keeps ids in an int and bounds memory
 * (each primitive costs well under 200 bytes). Beyond it geometry_add_*() returns -1. */
#define MAX_PRIMITIVES (1 << 28)

/* The plain primitives a scene is made of, handed one by one to whoever needs them as such
 * (app/export.c writes them for other renderers). Each callback gets `context`; normals is
 * NULL or a triangle's three unit vertex normals. */
struct primitive_visitor {
    void *context;
    void (*sphere)(void *context, struct vec3 centre, double radius, int material);
    void (*triangle)(void *context, const struct vec3 v[3], const struct vec3 *normals,
                     int material);
    void (*quad)(void *context, struct vec3 p0, struct vec3 e1, struct vec3 e2, int material);
    /* Called before a procedural shape's primitives with its ops' name and approximation,
     * and after them with both NULL. */
    void (*shape)(void *context, const char *name, const char *approximation);
};

/* A procedural shape (sphere flake, heightfield, ...): one BVH leaf with its own internal
 * acceleration. The shape fills every field of struct hit except prim, which geometry sets. */
struct shape_ops {
    const char *name;
    struct aabb (*bounds)(const void *shape);
    /* Closest hit with t in (0, tmax): returns 1 and fills *hit, else returns 0. */
    int (*intersect)(const void *shape, struct ray ray, double tmax, struct hit *hit);
    /* Whether any hit has t in (0, tmax). */
    int (*occluded)(const void *shape, struct ray ray, double tmax);
    size_t (*bytes)(const void *shape);  /* memory the shape holds, for --stats */
    void (*free)(void *shape);
    /* Hands the shape to v as plain spheres and triangles: exactly the surface it
     * intersects when approximation is NULL, else what approximation says. */
    void (*primitives)(const void *shape, const struct primitive_visitor *v);
    const char *approximation;
};

struct geometry;

struct geometry *geometry_create(void);
void geometry_free(struct geometry *g); /* NULL is a no-op */

/* Each add returns the new primitive's id (0, 1, 2, ... in the order of adding), or -1
 * when MAX_PRIMITIVES would be exceeded. The caller has checked the inputs are finite. */
int geometry_add_sphere(struct geometry *g, struct vec3 centre, double radius, int material);
/* v[3] counter-clockwise seen from the front; normals NULL or three unit vertex normals. */
int geometry_add_triangle(struct geometry *g, const struct vec3 v[3], const struct vec3 *normals,
                          int material);
/* The parallelogram p0 + s e1 + t e2, s, t in [0, 1]; front side along e1 x e2; uv = (s, t). */
int geometry_add_quad(struct geometry *g, struct vec3 p0, struct vec3 e1, struct vec3 e2,
                      int material);
/* Takes ownership of shape (freed with ops->free by geometry_free) when it returns an id;
 * on -1 the caller still owns it. A shape reports its own materials (a sphere flake may
 * have one per depth), so `material` is only recorded. */
int geometry_add_shape(struct geometry *g, const struct shape_ops *ops, void *shape, int material);

/* Builds the BVH over everything added so far (binned SAH). Call once, after the adds. */
void geometry_build(struct geometry *g);

/* Closest hit with t in (0, tmax) (tmax may be INFINITY): 1 and *hit filled, or 0. */
int geometry_intersect(const struct geometry *g, struct ray ray, double tmax, struct hit *hit);
/* Whether anything is hit with t in (0, tmax): the any-hit query for shadow rays. */
int geometry_occluded(const struct geometry *g, struct ray ray, double tmax);

/* Hands every primitive that can be hit (degenerate ones are left out, as the BVH leaves
 * them) to v, in the order of their ids; a procedural shape through its ops->primitives. */
void geometry_visit(const struct geometry *g, const struct primitive_visitor *v);

/* For --stats and benches. */
size_t geometry_primitive_count(const struct geometry *g);
size_t geometry_bvh_nodes(const struct geometry *g);
size_t geometry_bytes(const struct geometry *g); /* primitives + BVH + shapes' own bytes */
struct aabb geometry_bounds(const struct geometry *g); /* every primitive's box */
/* The box around the primitives added with this material (a shape counts by the material
 * it was added with); lo = +inf, hi = -inf when there is none. */
struct aabb geometry_material_bounds(const struct geometry *g, int material);

/* The box of primitive prim (an id from geometry_add_*(), 0 <= prim < the count), valid
 * before and after geometry_build(). A procedural shape is one primitive: its whole box.
 * A degenerate primitive (never hit) still has the box of its points. */
struct aabb geometry_primitive_bounds(const struct geometry *g, int prim);

/* The material primitive prim was added with. A shape's hits may report others (a sphere
 * flake has one per depth, shape_ops): this is the one it was added with. */
int geometry_primitive_material(const struct geometry *g, int prim);

/* Whether primitive prim is flat (a quad or triangle that is not degenerate); then
 * *point is one of its corners and *normal the unit normal of its front side (struct
 * hit's ng). Spheres and procedural shapes return 0. For exact solutions that reflect a
 * light in a flat mirror (`photon probe`'s image sources). */
int geometry_primitive_plane(const struct geometry *g, int prim, struct vec3 *point,
                             struct vec3 *normal);

/* The area of the part [u0, u1] x [v0, v1] (0 <= u0 <= u1 <= 1, the same for v) of
 * primitive prim's surface in the parameters struct hit reports, for illumination maps
 * over it: a quad p0 + u e1 + v e2, |e1 x e2| (u1 - u0) (v1 - v0); a sphere with
 * u = phi / (2 pi) and v = theta / pi (theta from +y), r^2 2 pi (u1 - u0)
 * (cos pi v0 - cos pi v1). -1 for triangles and procedural shapes, which have no such
 * parameters here. */
double geometry_uv_area(const struct geometry *g, int prim, double u0, double u1, double v0,
                        double v1);

/* For the same primitives, the length of the surface's longest line of constant v
 * (*length_u: a quad's |e1|, a sphere's equator) and of constant u (*length_v: |e2|, a
 * meridian), and 1; 0 for primitives without parameters. */
int geometry_uv_extent(const struct geometry *g, int prim, double *length_u, double *length_v);

#endif
