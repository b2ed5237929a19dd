/*
 * tests/literal_jensen1996.h -- Jensen 1996's global illumination using photon maps written
 * literally (literal_jensen1996.c): what `--mode 1996 --paper` must agree with.
 */
#ifndef PHOTON_TESTS_LITERAL_JENSEN1996_H
#define PHOTON_TESTS_LITERAL_JENSEN1996_H

#include <stddef.h>
#include <stdint.h>

#include "../src/image/image.h"
#include "../src/scene/scene.h"

/* The paper's parameters, each the mode's option of the same meaning. */
struct literal_jensen1996_settings {
    uint64_t seed;            /* --seed: the photons' and the camera samples' streams      */
    int spp;                  /* --spp: eye rays a pixel                                   */
    size_t global_photons;    /* --photons: emitted for the global map                     */
    size_t caustic_photons;   /* --caustic-photons: emitted towards the specular objects   */
    size_t global_gather;     /* --gather: N of the global map's estimates (Eq. 3)         */
    size_t caustic_gather;    /* --caustic-gather: N of the caustic map's (Eq. 5)          */
    int gather_rays;          /* --gather-rays: rays of one final gather                   */
    int glossy_rays;          /* --glossy-rays: the paper's "maximum of 6" at a glossy
                                 surface                                                   */
    double accuracy;          /* --cache-accuracy: Ward's a                                */
    double accurate_distance; /* --accurate-distance: the "small threshold", in radii of
                                 the global estimate where a gather ray ends               */
    double accurate_weight;   /* --accurate-weight: a "low" weight                         */
};

/* The image of scene (finished) with settings ls: the caller frees it with image_free().
 * NULL when the photon tracer refuses (more than MAX_PHOTONS would be stored). */
struct image *literal_jensen1996(const struct scene *scene,
                                 const struct literal_jensen1996_settings *ls);

#endif
