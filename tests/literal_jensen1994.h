/*
 * tests/literal_jensen1994.h -- Jensen and Christensen 1994's bidirectional Monte Carlo
 * ray tracing with photon maps written literally (literal_jensen1994.c): what
 * `--mode 1994 --paper` must agree with.
 */
#ifndef PHOTON_TESTS_LITERAL_JENSEN1994_H
#define PHOTON_TESTS_LITERAL_JENSEN1994_H

#include <stddef.h>
#include <stdint.h>

#include "../src/image/image.h"
#include "../src/scene/scene.h"

/* The paper's parameters, each the mode's option of the same meaning. */
struct literal_jensen1994_settings {
    uint64_t seed;     /* --seed: the camera samples' and the light rays' streams        */
    int spp;           /* --spp: eye rays a pixel                                        */
    size_t photons;    /* --photons: light rays of pass 1                                */
    size_t gather;     /* --gather: n, photons in an irradiance estimate                 */
    int gather_rays;   /* --gather-rays: rays of one irradiance record (m x n strata)    */
    double accuracy;   /* --cache-accuracy: Ward's a                                     */
    int light_samples; /* --light-samples: stratified samples of an area light, k x k    */
};

/* The image of scene (finished) with settings ls: the caller frees it with image_free().
 * NULL when the photon tracer refuses (more than MAX_PHOTONS would be stored). */
struct image *literal_jensen1994(const struct scene *scene,
                                 const struct literal_jensen1994_settings *ls);

#endif
