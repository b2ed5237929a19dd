/*
 * photon/irradiance_cache.h -- Ward's irradiance cache (Ward, Rubinstein and Clear 1988,
 * "A ray tracing solution for diffuse interreflection") with irradiance gradients (Ward
 * and Heckbert 1992, "Irradiance gradients").
 *
 * Irradiance on diffuse surfaces changes slowly, so it is computed (by a final gather over
 * the hemisphere) at a sparse set of points and interpolated in between. A gather at p
 * samples the hemisphere in m x n strata of equal projected solid angle; the strata's mean
 * radiances give the irradiance E, their distances give R, the harmonic mean distance to
 * the surroundings (the scale over which E can change, Ward 1988's "split sphere"), and
 * the differences between neighbouring strata give how E changes as the point moves
 * (translational gradient) and as the normal turns (rotational gradient). A record (p, n,
 * E, R, gradients) is usable at a point p' with normal n' when Ward's error estimate
 *   epsilon_i(p', n') = |p' - p_i| / R_i + sqrt(1 - n' . n_i)
 * is below the accuracy a; the estimate at p' is the mean of the usable records'
 * values, each moved to (p', n') by its gradients and weighted by w_i = 1 / epsilon_i.
 *
 * Life of a cache: irradiance_cache_create() over the scene's box; a renderer asks
 * irradiance_cache_lookup() at each diffuse point and, when no record is usable, gathers,
 * makes a record with irradiance_record_make() and adds it with irradiance_cache_add();
 * lookups and additions may alternate freely. irradiance_cache_free() releases it. The
 * cache copies what it is given, so samples and records stay the caller's.
 * The spatial index (a loose octree) is described at the top of irradiance_cache.c.
 */
#ifndef PHOTON_IRRADIANCE_CACHE_H
#define PHOTON_IRRADIANCE_CACHE_H

#include <stddef.h>

#include "../base/vec3.h"
#include "../geom/ray.h" /* struct aabb */

/* Ward and Heckbert's strata: the hemisphere above a surface split into m rings of equal
 * projected solid angle (sin^2 theta from j/m to (j+1)/m) times n sectors in phi (2 pi k/n
 * to 2 pi (k+1)/n), so each stratum subtends projected solid angle pi / (m n). Local
 * coordinates: z along the normal, phi measured from x towards y.
 * STRATA_MAX: the most strata (m * n) a record may be made from, so that a renderer can
 * size its sample scratch once per render and options can refuse more. At 64 x 64 the
 * gradients are within 0.5% (translational) and 6% (rotational) of closed forms
 * (test_cache.c); finer strata buy little for the rays they cost. */
#define STRATA_MAX 4096

/* Direction in stratum (j, k) (0 <= j < m, 0 <= k < n), cosine-distributed within it,
 * from u1, u2 in [0, 1): sin^2 theta = (j + u1) / m, phi = 2 pi (k + u2) / n. Unit up to
 * rounding, z > 0 always (local coordinates). */
struct vec3 stratum_direction(int m, int n, int j, int k, double u1, double u2);

/* The stratum (*j, *k) holding a local direction with z >= 0 (need not be unit, must not
 * be zero); directions on a boundary or just outside the hemisphere are clamped into
 * range. The inverse of stratum_direction() away from stratum boundaries. */
void stratum_of(int m, int n, struct vec3 local, int *j, int *k);

/* What a final gather found in one stratum. */
struct stratum_sample {
    struct vec3 radiance; /* L_jk: mean radiance arriving through the stratum (W/(m^2 sr)) */
    double distance;      /* r_jk: distance to the nearest surface hit by its rays, >= 0;
                             INFINITY when all escaped                                    */
};

struct irradiance_record {
    struct vec3 p;         /* p_i, position                                               */
    struct vec3 n;         /* n_i, unit normal                                            */
    struct vec3 e;         /* E_i, irradiance per channel (W/m^2)                         */
    double r;              /* R_i: harmonic mean distance of the strata, bounded; > 0     */
    struct vec3 grad_r[3]; /* rotational gradient of channel c (R, G, B), world space:
                              dE_c ~ (n_i x n) . grad_r[c]; perpendicular to n_i          */
    struct vec3 grad_t[3]; /* translational gradient of channel c, world space:
                              dE_c ~ (p - p_i) . grad_t[c]; in the tangent plane of n_i   */
};

/* A record from the m x n_phi strata samples (samples[j * n_phi + k] holds stratum
 * (j, k)) gathered at p in the frame (t, b, n): orthonormal, right-handed, n the unit
 * normal; local x = t, y = b, z = n. 1 <= m, n_phi; m * n_phi <= STRATA_MAX;
 * 0 < r_min <= r_max.
 *   E = pi / (m n) sum L_jk;
 *   R = harmonic mean of r_jk (escaped strata count as infinitely far, adding 0 to the
 *       sum of 1 / r; R = r_max when all escaped), clamped to [r_min, r_max], then no
 *       more than E / |grad_t E| in luminance unless that is below r_min;
 *   the rotational and translational gradients of Ward and Heckbert 1992 (formulas in
 *   irradiance_cache.c). Allocates nothing. */
struct irradiance_record irradiance_record_make(struct vec3 p, struct vec3 t, struct vec3 b,
                                                struct vec3 n, int m, int n_phi,
                                                const struct stratum_sample *samples,
                                                double r_min, double r_max);

/* What bounds a record's R. */
struct record_reach {
    double r_min, r_max; /* R's bounds, 0 < r_min <= r_max                                */
    int gradient_limit;  /* 1: R at most E / |grad_t E| (in luminance) unless that is
                            below r_min, a departure from Ward and Heckbert (irradiance_
                            cache.c); 0: the harmonic mean distance alone, theirs         */
};

/* irradiance_record_make() with the gradient's limit on R a switch: the same record when
 * reach.gradient_limit is 1 (irradiance_record_make() is this with the limit on). */
struct irradiance_record irradiance_record_of(struct vec3 p, struct vec3 t, struct vec3 b,
                                              struct vec3 n, int m, int n_phi,
                                              const struct stratum_sample *samples,
                                              struct record_reach reach);

struct irradiance_cache; /* owns its records and its octree */

/* An empty cache over bounds (the scene's box; records outside it are accepted too, at a
 * cost: see irradiance_cache.c; an empty box, or one not finite, stands for the unit cube
 * at the origin) with Ward's accuracy a > 0 (e.g.
 * 0.15; below 1, records on surfaces facing away, n . n_i <= 0, are never usable). */
struct irradiance_cache *irradiance_cache_create(struct aabb bounds, double accuracy);
void irradiance_cache_free(struct irradiance_cache *cache); /* NULL is a no-op */

/* Adds a copy of the record (finite p, unit n, r > 0). Amortised O(depth). */
void irradiance_cache_add(struct irradiance_cache *cache,
                          const struct irradiance_record *record);

/* CACHE_FRONT_TOLERANCE: Ward 1988 leaves out a record "in front of" p, one with
 *   d_i(p) = (p - p_i) . (n + n_i) / 2 < 0,
 * since the surface it was made on may shadow p. We leave it out only when
 * d_i < -0.05 R_i: E changes over distances of order R_i (that is what R_i measures), so
 * a record that little in front errs by a few percent, less than the accuracy a the
 * cache runs at, while rounding and shading normals that differ from geometric ones
 * cannot exclude records lying on p's own surface. */
#define CACHE_FRONT_TOLERANCE 0.05

/* CACHE_EPSILON_MIN: Ward's weight 1 / epsilon_i is infinite at the record's own point
 * and normal; epsilon_i below 1e-12 counts as 1e-12. The capped weight, 1e12, is 1e11
 * times that of a record near the edge of its reach (1 / a), so the record's own E comes
 * back to 11 digits, and w E stays far from overflow for any finite E. */
#define CACHE_EPSILON_MIN 1e-12

/* Ward's interpolation at p with unit normal n:
 *   E(p, n) = sum_i w_i (E_i + (n_i x n) . grad_r + (p - p_i) . grad_t) / sum_i w_i,
 * each channel clamped to >= 0, over the records i that are usable (epsilon_i < a, with
 * a = accuracy, 0 < accuracy <= the cache's: a renderer that fills the cache asks with a
 * stricter a than it later reads with, so that records lie closer than they must,
 * w_i = 1 / max(epsilon_i, CACHE_EPSILON_MIN)) and not in front of p
 * (d_i >= -CACHE_FRONT_TOLERANCE R_i). Returns 1 with *e filled when at least one record
 * is usable, else 0 with *e untouched. Never NaN: a record at (p, n) itself has its
 * weight capped and gives its own E. The result depends only on the records and the
 * order in which they were added. Allocates nothing. */
int irradiance_cache_lookup(const struct irradiance_cache *cache, struct vec3 p,
                            struct vec3 n, double accuracy, struct vec3 *e);

size_t irradiance_cache_records(const struct irradiance_cache *cache);

/* Copies the cache's records to out[0 .. irradiance_cache_records() - 1] (the caller's
 * array) node by node, each node's records in the order they were added. Which node a
 * record goes to depends on the record, the bounds and the accuracy alone, so adding the
 * copies in this order to an empty cache of the same bounds and accuracy gives every node
 * the same records in the same order, and every lookup the same bits (a saved cache,
 * app/work_file.h). */
void irradiance_cache_copy_records(const struct irradiance_cache *cache,
                                   struct irradiance_record *out);
size_t irradiance_cache_bytes(const struct irradiance_cache *cache); /* for --stats */

/* 1 when the octree satisfies the invariants stated in irradiance_cache.c, else 0. */
int irradiance_cache_check(const struct irradiance_cache *cache);

#endif
