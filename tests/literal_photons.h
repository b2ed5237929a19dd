/*
 * tests/literal_photons.h -- what the two literal programs (literal_ppm2008.c,
 * literal_sppm2009.c) do alike, as the 2008 paper writes it: the photon tracing pass, the
 * photons a hit point takes (Eq. 11) and the progressive update (Eq. 7, 9, 12).
 */
#ifndef PHOTON_TESTS_LITERAL_PHOTONS_H
#define PHOTON_TESTS_LITERAL_PHOTONS_H

#include <stddef.h>
#include <stdint.h>

#include "../src/photon/trace.h"
#include "../src/scene/brdf.h"
#include "../src/scene/scene.h"

#define LITERAL_ALPHA 0.7 /* the fraction of new photons kept, the paper's alpha */

/* A photon tracing pass's photons, each as the tracer stored it: position, direction and
 * power in full precision, none rounded into a photon map's record. */
struct literal_photons {
    struct photon_event *photons; /* owned; n of them, sorted by position (x first)    */
    size_t n, capacity;
};

/* A photon tracing pass: pass `pass`'s M = photons photons from the lights, each kept
 * wherever it lands on a surface with a non-specular part. literal_photons_free() them. */
struct literal_photons literal_photon_pass(const struct scene *scene, uint64_t seed, long pass,
                                           size_t photons);

void literal_photons_free(struct literal_photons *pass);

/* Eq. 11 at a hit point x (brdf, frame, wo towards the eye) of radius r: the sum of
 * f_r(x, w, w_p) Phi'_p over the pass's photons within r, w_p the photon's direction as it
 * arrived and Phi'_p its unnormalised flux (the tracer's power times M = photons); *m is
 * how many there were. */
struct vec3 literal_photons_within(const struct literal_photons *pass, struct vec3 x, double r,
                                   const struct material *brdf,
                                   const struct shading_frame *frame, struct vec3 wo,
                                   size_t photons, double *m);

/* The progressive update with a pass's flux and m new photons: Eq. 7, 9 and 12,
 *     N' = N + alpha M,  R' = R sqrt((N + alpha M) / (N + M)),
 *     tau' = (tau + flux) R'^2 / R^2;
 * nothing changes while N + M is 0. */
void literal_update(double *n, double *radius, struct vec3 *tau, struct vec3 flux, double m);

#endif
