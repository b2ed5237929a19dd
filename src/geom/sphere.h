/*
 * geom/sphere.h -- the sphere: its box, a cancellation-free ray intersection and its
 * shading record.
 *
 * Intersection follows Haines, Guenther, Akenine-Moller, "Precision improvements for
 * ray/sphere intersection" (Ray Tracing Gems, 2019, ch. 7): the discriminant is taken from
 * the distance between the centre and the ray's line, never from b^2 - ac, and the two
 * roots from q and c / q, so neither a far origin nor a huge radius loses the hit.
 *
 * Surface parameters, y up (the scene convention): with n the unit outward normal,
 *   u = phi / (2 pi),  phi = atan2(n.z, n.x) taken in [0, 2 pi)  (longitude, from +x to +z)
 *   v = theta / pi,    theta = acos(n.y)                        (0 at the +y pole, 1 at -y)
 * A sphere with radius <= 0 is degenerate: it has no surface and is never hit.
 */
#ifndef PHOTON_SPHERE_H
#define PHOTON_SPHERE_H

#include "ray.h"

struct sphere {
    struct vec3 centre;
    double radius;   /* > 0 for a sphere that can be hit */
    int material;    /* handed back in struct hit */
    int id;          /* primitive id from geometry_add_sphere() */
};

struct sphere sphere_make(struct vec3 centre, double radius, int material, int id);
int sphere_is_degenerate(const struct sphere *s);
struct aabb sphere_bounds(const struct sphere *s);

/* Nearest root t in (0, tmax) of |o + t d - c| = r: 1 with hit->t set (nothing else), or 0. */
int sphere_intersect(const struct sphere *s, struct ray ray, double tmax, struct hit *hit);

/* Completes a hit whose t sphere_intersect() set: p (projected onto the sphere), ng = ns
 * (outward), u, v and material. prim is the caller's. */
void sphere_shade(const struct sphere *s, struct ray ray, struct hit *hit);

#endif
