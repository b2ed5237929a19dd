/*
 * modes/ppm_direct.h -- the direct light of progressive photon mapping by light sampling,
 * along a new eye ray through every pixel each pass (a departure from Hachisuka, Ogaki
 * and Jensen 2008, who estimate it from the photons too; ppm2008.c says why).
 */
#ifndef PHOTON_PPM_DIRECT_H
#define PHOTON_PPM_DIRECT_H

#include <stddef.h>
#include <stdint.h>

#include "render.h"
#include "surface.h"

/* The direct term of every pixel of a window: the mean over passes of the light samples
 * its eye rays took, each times the ray's throughput. */
struct ppm_direct {
    const struct scene *scene;        /* borrowed                                        */
    const struct render_settings *rs; /* borrowed: the seed and the window               */
    struct vec3 *sum;                 /* owned: per window pixel, the sum over passes    */
    long passes;                      /* passes summed into sum                          */
};

/* An empty direct term for the window of rs (all zero, no pass yet). */
void ppm_direct_create(struct ppm_direct *d, const struct scene *scene,
                       const struct render_settings *rs);

/* Pass `pass` (from 0) of window pixel `pixel`: the k-th surface with a non-delta part that
 * the pass's eye ray (its branches in the order traced) reached, s with its shading
 * frame, takes one shadow-tested sample of each light, f_r Li cos / pdf, which is added
 * to the pixel's sum times beta, the ray's throughput. Sample `pass` of a (0,2)-sequence
 * for each light, shifted by words of rng_stream(seed, STREAM_LIGHT, the pixel's index in
 * the whole image, k), so the pixel's samples are stratified over the passes and depend
 * on nothing but the pixel and the pass. Adds the shadow rays to counters->rays. */
void ppm_direct_sample(struct ppm_direct *d, size_t pixel, uint64_t k, long pass,
                       const struct surface *s, const struct shading_frame *frame,
                       struct vec3 beta, struct render_counters *counters);

/* As ppm_direct_sample(), the point lights alone, through s->material: at a glossy lobe an
 * eye path follows by sampling it, whose sampled directions find every other light
 * (their emission, counted along the path) but never a point light, a delta. */
void ppm_direct_point_lights(struct ppm_direct *d, size_t pixel, uint64_t k, long pass,
                             const struct surface *s, const struct shading_frame *frame,
                             struct vec3 beta, struct render_counters *counters);

/* Ends a pass: each pixel's sum now holds one more pass. */
void ppm_direct_end_pass(struct ppm_direct *d);

/* Window pixel i's direct term so far: the mean of its passes' sums (zero before the
 * first pass). */
struct vec3 ppm_direct_radiance(const struct ppm_direct *d, size_t i);

void ppm_direct_free(struct ppm_direct *d);

#endif
