/*
 * geom/sphereflake.h -- Eric Haines' sphere flake ("balls" of the Standard Procedural
 * Databases, IEEE CG&A 7(11), 1987) as one procedural shape.
 *
 * A sphere of radius r carries nine child spheres of radius r/3 touching it: three leaning
 * towards its axis and six around its equator; each child does the same about its own axis
 * (the direction from its parent's centre to its own), down to `levels`. Level 0 is one
 * sphere; levels = k gives (9^(k+1) - 1) / 8 spheres. With centre (0,0,0), radius 0.5,
 * orientation (0,0,1) and levels 4 the spheres are those of balls-s4.nff.
 *
 * The shape stores no sphere: it is intersected through its implicit hierarchy
 * (sphereflake.c), so it costs the same few hundred bytes at every level.
 * sphereflake_expand() adds the same spheres, bit for bit, as plain geometry spheres.
 */
#ifndef PHOTON_SPHEREFLAKE_H
#define PHOTON_SPHEREFLAKE_H

#include "../base/error.h"
#include "geometry.h"

/* Level 10 already has 3.9e9 spheres (far more than a render resolves) and a traversal stack
 * of 81 entries; deeper flakes are refused as absurd input. */
#define SPHEREFLAKE_MAX_LEVELS 10

struct sphereflake_params {
    struct vec3 centre;      /* centre of the top-level sphere                              */
    double radius;           /* radius of the top-level sphere, > 0 and finite              */
    int levels;              /* 0..SPHEREFLAKE_MAX_LEVELS: generations of children          */
    struct vec3 orientation; /* the top sphere's axis ("up"), any non-zero finite length    */
    int materials[SPHEREFLAKE_MAX_LEVELS + 1]; /* material of the spheres at depth 0..levels
                                                  (depth 0 is the top sphere)               */
};

struct sphereflake;

/* Checks the parameters and makes the shape; NULL with *err filled (file "", line 0: the
 * caller adds its own) when radius, levels or orientation are out of range or not finite. */
struct sphereflake *sphereflake_create(const struct sphereflake_params *params,
                                       struct error *err);
void sphereflake_free(struct sphereflake *flake); /* NULL is a no-op */

/* For geometry_add_shape(g, &sphereflake_ops, flake, material): intersect fills every field
 * of struct hit but prim, exactly as the sphere hit would (sphere.h: p on the surface,
 * ng = ns outward, u and v), with material = materials[depth of that sphere]. The material
 * given to geometry_add_shape() is not used. free is sphereflake_free. */
extern const struct shape_ops sphereflake_ops;

/* (9^(levels+1) - 1) / 8, the number of spheres; levels in 0..SPHEREFLAKE_MAX_LEVELS. */
double sphereflake_sphere_count(int levels);

/* Calls visit once per sphere, parent before children, children in the order of balls.c
 * (so level 4 lists balls-s4.nff's spheres in its order), with the very doubles the
 * intersection computes. */
void sphereflake_spheres(const struct sphereflake *flake,
                         void (*visit)(void *context, struct vec3 centre, double radius,
                                       int material),
                         void *context);

/* Adds every sphere to g with geometry_add_sphere(). Returns 0, or -1 (adding nothing) when
 * the count exceeds MAX_PRIMITIVES, or (having added some) when geometry refuses one. */
int sphereflake_expand(const struct sphereflake *flake, struct geometry *g);

#endif
