/*
 * tests/literal_photons.h -- what the two literal programs (literal_ppm2008.c,
 * literal_sppm2009.c) do alike, as the 2008 paper writes it: the photon tracing pass, the
 * photons a hit point takes (Eq. 11) and the progressive update (Eq. 7, 9, 12).
 */
#ifndef PHOTON_TESTS_LITERAL_PHOTONS_H
#define PHOTON_TESTS_LITERAL_PHOTONS_H

#include <stddef.h>
#include <stdint.h>

#include "../src/photon/kdtree.h"
#include "../src/scene/brdf.h"
#include "../src/scene/scene.h"

#define LITERAL_ALPHA 0.7 /* the fraction of new photons kept, the paper's alpha */

/* A photon tracing pass: pass `pass`'s M = photons photons from the lights, stored
 * wherever they hit, in a photon map (NULL when the tracer refuses). kdtree_free() it. */
struct kdtree *literal_photon_map(const struct scene *scene, uint64_t seed, long pass,
                                  size_t photons);

/* Eq. 11 at a hit point x (brdf, frame, wo towards the eye) of radius r: the sum of
 * f_r(x, w, w_p) Phi_p over the map's photons within r, each Phi_p the photon's own power
 * (the tracer's, times M = photons); *m is how many there were. */
struct vec3 literal_photons_within(const struct kdtree *map, struct vec3 x, double r,
                                   const struct material *brdf,
                                   const struct shading_frame *frame, struct vec3 wo,
                                   size_t photons, double *m);

/* The progressive update with a pass's flux and m new photons: Eq. 7, 9 and 12,
 *     N' = N + alpha M,  R' = R sqrt((N + alpha M) / (N + M)),  tau' = (tau + flux) R'^2 / R^2;
 * nothing changes while N + M is 0. */
void literal_update(double *n, double *radius, struct vec3 *tau, struct vec3 flux, double m);

#endif
