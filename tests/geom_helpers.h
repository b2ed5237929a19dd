/*
 * tests/geom_helpers.h -- what the geometry and shape rooms share (test_geom.c,
 * test_geom_primitives.c, test_shapes.c, test_shapes_heightfield.c): random numbers,
 * points and directions, drawn from the STREAM_TEST streams their callers key by case and
 * index, and two checks on hits.
 */
#ifndef PHOTON_TEST_GEOM_HELPERS_H
#define PHOTON_TEST_GEOM_HELPERS_H

#include "../src/base/rng.h"
#include "../src/base/vec3.h"
#include "../src/geom/ray.h"

#define TEST_SEED 2024 /* the key of every stream in test_geom.c and test_geom_primitives.c */

/* A number uniform from lo to hi. */
double uniform(struct rng *r, double lo, double hi);

/* Uniform on the unit sphere (Archimedes: z uniform in [-1, 1]). */
struct vec3 random_unit(struct rng *r);

/* A point uniform in the cube [-half_size, half_size]^3; its coordinates are drawn in the
 * order the compiler evaluates a call's arguments, which C leaves open. */
struct vec3 random_point(struct rng *r, double half_size);

/* Whether a and b differ by at most rel of the larger magnitude. */
int relative_close(double a, double b, double rel);

/* Whether every number of the hit record is finite. */
int hit_is_finite(const struct hit *h);

#endif
