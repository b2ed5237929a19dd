/*
 * tests/shape_hits.h -- a procedural shape's hits against its expansion's, for the shape
 * rooms (test_shapes.c: the sphere flake; test_shapes_heightfield.c: the heightfield).
 */
#ifndef PHOTON_TEST_SHAPE_HITS_H
#define PHOTON_TEST_SHAPE_HITS_H

#include <stddef.h>
#include <stdint.h>

#include "../src/geom/geometry.h"

#define EXPANSION_RAYS 500000 /* per sphere-flake level: a million in all */

/* Two shading records of one surface point: t to rel_t, p to rel_t of the ray's scale,
 * normals to 1e-12, same material. (Distinct primitives at equal t, e.g. a ray through a
 * shared edge, may give different ng: compare_ng 0 skips it there.) */
int same_hit(const struct hit *a, const struct hit *b, struct ray ray, double rel_t,
             int compare_ng);

/* Rays make(context, q), q < n_rays, through both geometries: how many find the same hit. */
size_t geometry_agreements(const struct geometry *procedural,
                           const struct geometry *expanded,
                           struct ray (*make)(const void *context, uint64_t q),
                           const void *context, size_t n_rays, double rel_t);

#endif
