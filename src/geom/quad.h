/*
 * geom/quad.h -- the parallelogram p0 + s e1 + t e2, s, t in [0, 1], front side along
 * e1 x e2, uv = (s, t).
 *
 * Intersected like a triangle (triangle.h): its four corners are sheared into the ray's
 * frame and the four edge functions decide inside/outside with exact signs, so quads that
 * share corners bit for bit (a box made of quads) leave no crack along their edges. The
 * projection of a parallelogram is a parallelogram, so opposite edge functions are
 * proportional to s and 1 - s (and t and 1 - t), which gives uv without another solve.
 */
#ifndef PHOTON_QUAD_H
#define PHOTON_QUAD_H

#include "ray.h"
#include "triangle.h"

struct quad {
    double corner[4][3]; /* corner[i][axis]: p0, p0 + e1, p0 + e1 + e2, p0 + e2, each rounded
                            once when the quad is made, so neighbours computing a shared
                            corner from the same numbers agree exactly                    */
    struct vec3 p0, e1, e2;
    struct vec3 ng;      /* unit e1 x e2; zero for a degenerate quad                        */
    int material;        /* handed back in struct hit                                       */
    int id;              /* primitive id from geometry_add_quad()                           */
};

struct quad quad_make(struct vec3 p0, struct vec3 e1, struct vec3 e2, int material, int id);
/* Zero area (e1 x e2 = 0): never hit, excluded from the BVH. */
int quad_is_degenerate(const struct quad *q);
struct aabb quad_bounds(const struct quad *q);

/* Hit with t in (0, tmax), from either side: 1 with hit->t, hit->u = s and hit->v = t set
 * (nothing else), or 0. */
int quad_intersect(const struct quad *q, const struct sheared_ray *ray, double tmax,
                   struct hit *hit);

/* Completes a hit from its t, u, v: p = p0 + u e1 + v e2, ng = ns, material. */
void quad_shade(const struct quad *q, struct hit *hit);

#endif
