/*
 * geom/ray.h -- rays, bounding boxes and the shading record every intersection fills.
 *
 * This is the whole vocabulary modes share with geometry (one call, one record): a mode builds a
 * ray, asks geometry_intersect() for the closest hit and reads a struct hit. Nothing else
 * about an object is visible outside geom/.
 */
#ifndef PHOTON_RAY_H
#define PHOTON_RAY_H

#include "../base/vec3.h"

/* RAY_OFFSET_REL: a spawned ray starts at p + n * RAY_OFFSET_REL * max(1, max_abs(p)).
 * Hit points computed in double carry a relative error of a few ulps (~1e-15) of their
 * magnitude times the conditioning of the intersection; 1e-9 clears that by six orders of
 * magnitude while staying far below any feature a scene can resolve (1e-9 of its size). */
#define RAY_OFFSET_REL 1e-9

struct ray {
    struct vec3 origin;
    struct vec3 dir; /* need not be unit; t is in units of |dir|. Renderer rays are unit. */
};

struct aabb {
    struct vec3 lo, hi; /* lo <= hi componentwise for a non-empty box */
};

/* The smallest box holding both. */
static inline struct aabb aabb_union(struct aabb a, struct aabb b)
{
    struct aabb u;
    u.lo = vec3_min(a.lo, b.lo);
    u.hi = vec3_max(a.hi, b.hi);
    return u;
}

/* What an intersection reports: the shading record. */
struct hit {
    double t;        /* ray parameter of the hit, in (0, tmax)                              */
    struct vec3 p;   /* hit position                                                        */
    struct vec3 ng;  /* unit geometric normal on the front side (sphere: outward; triangle
                        and quad: the side from which the vertices run counter-clockwise)  */
    struct vec3 ns;  /* unit shading normal (interpolated where given), same side as ng    */
    double u, v;     /* surface parameters where defined (quad, triangle barycentrics,
                        sphere longitude/latitude in [0,1]), else 0                         */
    int material;    /* index into the scene's materials, as given when the primitive was added */
    int prim;        /* primitive id returned by geometry_add_*()                          */
};

static inline struct vec3 ray_at(struct ray r, double t) { return vec3_madd(r.origin, r.dir, t); }

static inline struct ray make_ray(struct vec3 origin, struct vec3 dir)
{
    struct ray r;
    r.origin = origin;
    r.dir = dir;
    return r;
}

/* The origin of a ray leaving surface point p on the side of the unit normal n (pass -n to
 * go through the surface): offset scaled to p's magnitude, so it works in millimetres and
 * in kilometres alike (README). */
static inline struct vec3 offset_origin(struct vec3 p, struct vec3 n)
{
    return vec3_madd(p, n, RAY_OFFSET_REL * fmax(1.0, vec3_max_abs(p)));
}

#endif
