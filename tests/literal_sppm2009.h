/*
 * tests/literal_sppm2009.h -- Hachisuka and Jensen 2009's stochastic progressive photon
 * mapping written literally (literal_sppm2009.c): what `--mode 2009 --paper` must agree with.
 */
#ifndef PHOTON_TESTS_LITERAL_SPPM2009_H
#define PHOTON_TESTS_LITERAL_SPPM2009_H

#include <stddef.h>
#include <stdint.h>

#include "../src/image/image.h"
#include "../src/scene/scene.h"

/* The image of scene (finished) after `passes` passes of photons_per_pass photons each,
 * with seed's camera samples and photons: the caller frees it with image_free(). */
struct image *literal_sppm2009(const struct scene *scene, uint64_t seed, long passes,
                               size_t photons_per_pass);

#endif
