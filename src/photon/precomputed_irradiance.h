/*
 * photon/precomputed_irradiance.h -- irradiance precomputed at photon positions
 * (Christensen 1999, "Faster photon map global illumination"; Jensen 2001, Realistic
 * Image Synthesis Using Photon Mapping, Ch. 11, "Optimization strategies").
 *
 * A final gather ends each of its hundreds of rays in a radiance estimate from the global
 * map: a search for the k nearest of millions of photons, then a sum over them. On a
 * Lambertian surface that estimate is f_r,d times the irradiance E, and E changes little
 * across the estimate's own disc. So E is estimated once at a subset of the photons'
 * positions (the records: in 1996, every N-th photon the global map stores, with the
 * surface normal where it landed; in 1994, whose photons hold that normal, every N-th of
 * the map's tree), and a gather ray that ends near a record reads its E
 * with one search for a few of the nearest records instead of the k nearest photons.
 *
 * The records are a kd-tree of struct photon (kdtree.h) whose direction bytes hold the
 * surface normal, as mode 1994's photons do; their power is not used. Beside the tree,
 * value[i] holds what the estimate at node i gave. The values are computed node by node
 * in the tree's order from the map and the records alone, so they are the same whatever
 * part of the image is rendered, and bit for bit the same on every run.
 */
#ifndef PHOTON_PRECOMPUTED_IRRADIANCE_H
#define PHOTON_PRECOMPUTED_IRRADIANCE_H

#include <stddef.h>

#include "../base/watch.h"
#include "../scene/scene.h"
#include "estimate.h"
#include "kdtree.h"

/* Of the records nearest to a point, how many a lookup considers (the nearest usable one
 * wins): enough that at a corner, where about half of them lie on the other wall, one on
 * the point's own surface is among them. */
#define PRECOMPUTED_CANDIDATES 8

/* A record serves a point whose surface normal n satisfies n . n_i >= this (25 degrees):
 * on the Cornell box's spheres (radius 90) the estimates' discs span a few degrees, and
 * two walls at a corner differ by 90. Christensen's test: a "similar" normal. */
#define PRECOMPUTED_MIN_COS 0.9

/* What the estimate at one record gave. Floats: the records are memory (Christensen
 * keeps his in the photon record itself); the rounding, 2^-24 relative, is far below
 * the estimate's noise. */
struct irradiance_value {
    float e[3]; /* E, irradiance in the map's units (W / m^2 per channel) */
    float r2;   /* r^2, the squared radius of the disc it was estimated over
                   (struct nearest's r2) */
};

struct precomputed_irradiance {
    const struct kdtree *records;   /* borrowed; positions and unit normals             */
    struct irradiance_value *value; /* owned; value[i] for node i of records, 1..n
                                       ([0] unused, as in the tree)                   */
    double max_r2;                  /* the estimates' maximum radius^2; no record
                                       farther from a point than this can serve it     */
};

/* Estimates E at every record of records (borrowed, and kept until the result is freed)
 * from map with irradiance_estimate() and settings is (estimate.h: 1996's global map
 * without differential checking, 1994's with it), and keeps them with each estimate's
 * r^2, the radius of the search (where differential checking stopped the sum sooner,
 * the disc the record serves is still the search's). O(n k log N).
 * coverage: NULL, or the scene the photons were traced in: then each E is divided by the
 * share of its disc that can hold photons (disc_coverage.h), so that a record by an open
 * edge or a wall is not dark by the part of pi r^2 that lies beyond.
 * watch (NULL: none) is told the records estimated so far whenever they are a positive
 * multiple of PRECOMPUTED_WATCH_EVERY (base/watch.h); the values do not depend on it.
 * Allocates its own scratch; never fails (out of memory is fatal()). */
struct precomputed_irradiance *precompute_irradiance(const struct kdtree *map,
                                                     const struct kdtree *records,
                                                     const struct irradiance_settings *is,
                                                     const struct scene *coverage,
                                                     const struct work_watch *watch);

#define PRECOMPUTED_WATCH_EVERY 256 /* records: a few milliseconds of estimates */
void precomputed_irradiance_free(struct precomputed_irradiance *pi); /* NULL: no-op */

/* Bytes the values take (the records' tree is counted with the maps: kdtree_bytes). */
size_t precomputed_irradiance_bytes(const struct precomputed_irradiance *pi);

/* Irradiance at x, on a surface with unit normal n (on the side the light is wanted
 * from), from the nearest record that can serve it: among the PRECOMPUTED_CANDIDATES
 * records nearest to x, the nearest whose normal n_i has n . n_i >= PRECOMPUTED_MIN_COS
 * and whose own estimate's disc reaches x (|x - p_i|^2 <= r_i^2); among records at the
 * same distance, the one the search keeps (deterministic: it depends on the tree alone).
 * Returns 1 with *e = its E and *r2 = its r^2, or 0 (e and r2
 * untouched) when none of them can: the caller then estimates from the map itself.
 * nn: the caller's scratch, k_max >= PRECOMPUTED_CANDIDATES. Allocates nothing. */
int precomputed_irradiance_at(const struct precomputed_irradiance *pi, struct vec3 x,
                              struct vec3 n, struct nearest *nn, struct vec3 *e, double *r2);

#endif
