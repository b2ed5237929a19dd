/*
 * modes/cache_pass.h -- Ward's irradiance cache as the camera-driven photon modes fill
 * it: Jensen and Christensen 1994 (Sec. 4.0.3, "the irradiance gradient method") and
 * Jensen 1996 (Sec. 4.4) both cache the irradiance of their Lambertian surfaces.
 *
 * A cache filled while pixels render makes a pixel depend on which pixels came before
 * it, so a crop would differ from the same window of the whole image. Both modes
 * therefore fill their cache in a pre-pass over the whole image, in one fixed order,
 * before the final pass, which only reads it. The cache itself (records, gradients,
 * lookups) lives in photon/irradiance_cache.h.
 */
#ifndef PHOTON_CACHE_PASS_H
#define PHOTON_CACHE_PASS_H

#include "../photon/irradiance_cache.h"
#include "render.h"

#define CACHE_MIN_REACH 1.5 /* a record's R is at least what makes its reach a R this many
                               pixel footprints (Tabellion and Lamorlette 2004 bound R in
                               screen space): records never crowd into corners below
                               pixel size                                                */
#define CACHE_R_MAX 0.2     /* and at most this fraction of the scene's diagonal         */
#define CACHE_FILL_STRICTNESS 0.5 /* the pre-pass makes records where none is usable with
                                     this fraction of Ward's a, so that the final pass's
                                     samples find records made at pixel centres          */

/* Traces one camera path through the centre of every pixel of the whole image, in
 * scanline order, with estimator; path (x, y) draws from rng_stream(seed, STREAM_CACHE,
 * y * width + x, 0). The radiance is thrown away: the mode's estimator adds records to
 * cache as it goes (cache is read here only for the progress line). Through a thin lens
 * the paths leave the lens's centre; a surface only other lens points see finds no
 * usable record in the final pass and is gathered there in full. */
void fill_cache_pass(const struct scene *scene, uint64_t seed,
                     struct radiance_estimator estimator, const struct irradiance_cache *cache,
                     int progress, struct render_counters *counters);

/* Where the radius of a record at point p with unit normal n must lie. accuracy: the a
 * the cache is read with; diagonal: the scene's. The footprint is that of a pixel seen
 * straight from the camera, whatever path reached p: a pixel seen at an angle covers
 * 1 / cos more of the surface (up to 10 times). A record is read by every path that
 * reaches it, and a floor seen in a curved mirror at a grazing angle has footprints ten
 * times a direct view's: a bound from that path gives its records a reach far beyond a
 * direct view's, and one noisy gather made for the mirror then leaves a band of the floor
 * seen directly too dark (src/modes/measured.md). Fills *r_min (CACHE_MIN_REACH footprints
 * over a, and at least the ray offset at p, so positive even at the camera's own position)
 * and *r_max (CACHE_R_MAX diagonals, at least r_min). */
void record_radius_bounds(const struct camera *camera, struct vec3 p, struct vec3 n,
                          double accuracy, double diagonal, double *r_min, double *r_max);

/* A record's reach at p as a mode's switches ask. bounded 1: record_radius_bounds()'s
 * (a departure: src/modes/README.md, --bounded-reach); 0: Ward's R alone, the papers',
 * held only between the ray offset at p, below which the renderer tells no two points
 * apart, and the scene's diagonal, which no harmonic mean of distances inside the scene
 * exceeds: it binds only where every gather ray escapes, where Ward's R is infinite.
 * gradient_limit: as struct record_reach (--gradient-limit). */
struct record_reach record_reach_at(const struct camera *camera, struct vec3 p, struct vec3 n,
                                    double accuracy, double diagonal, int bounded,
                                    int gradient_limit);

#endif
