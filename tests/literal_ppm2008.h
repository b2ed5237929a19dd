/*
 * tests/literal_ppm2008.h -- Hachisuka, Ogaki and Jensen 2008's progressive photon mapping
 * written literally (literal_ppm2008.c): what `--mode 2008 --paper` must agree with.
 */
#ifndef PHOTON_TESTS_LITERAL_PPM2008_H
#define PHOTON_TESTS_LITERAL_PPM2008_H

#include <stddef.h>
#include <stdint.h>

#include "../src/image/image.h"
#include "../src/scene/scene.h"

/* The image of scene (finished) from spp eye rays a pixel, traced once, and `passes`
 * passes of photons_per_pass photons each, with seed's camera samples and photons: the
 * caller frees it with image_free(). */
struct image *literal_ppm2008(const struct scene *scene, uint64_t seed, int spp, long passes,
                              size_t photons_per_pass);

#endif
