/*
 * modes/ppm_direct.h -- the direct light at progressive photon mapping's hit points, by
 * light sampling (a departure from Hachisuka, Ogaki and Jensen 2008, who estimate it from
 * the photons too; ppm2008.c says why).
 */
#ifndef PHOTON_PPM_DIRECT_H
#define PHOTON_PPM_DIRECT_H

#include <stddef.h>

#include "../photon/hit_points.h"
#include "render.h"

/* The direct term of every pixel of a window: the mean over passes of its hit points'
 * light samples, each times the hit point's pixel weight. */
struct ppm_direct {
    const struct scene *scene;        /* borrowed                                        */
    const struct render_settings *rs; /* borrowed: the seed and the window               */
    struct vec3 *sum;                 /* owned: per window pixel, the sum over passes    */
    long passes;                      /* passes summed into sum                          */
};

/* An empty direct term for the window of rs (all zero, no pass yet). */
void ppm_direct_create(struct ppm_direct *d, const struct scene *scene,
                       const struct render_settings *rs);

/* Pass `pass` (from 0): the eye rays of each pixel take turns, camera sample s in the passes
 * with pass = s (mod spp): each hit point its eye path made takes one shadow-tested sample
 * of each light, f_r Li cos / pdf through its non-delta BRDF, times spp times its pixel
 * weight (so the pass's sum is the whole pixel's estimate from one eye ray), added to its
 * pixel. The hit points of one pixel must be consecutive, in the order the pixel made them
 * (ppm2008.c's ray tracing pass makes them so): the k-th of pixel (x, y) takes, at its
 * j-th turn, point j of a (0,2)-sequence for each light, shifted by words of
 * rng_stream(seed, STREAM_LIGHT, y * width + x, k), so its samples are stratified over its
 * turns and depend on nothing but the pixel and the pass. Adds the shadow rays to
 * counters->rays. */
void ppm_direct_pass(struct ppm_direct *d, const struct hit_point *points, size_t n,
                     long pass, struct render_counters *counters);

/* Window pixel i's direct term so far: the mean of its passes' sums (zero before the
 * first pass). */
struct vec3 ppm_direct_radiance(const struct ppm_direct *d, size_t i);

void ppm_direct_free(struct ppm_direct *d);

#endif
