/*
 * photon/estimate.h -- radiance from a photon map (Jensen 1996, Sec. 5): the
 * nearest-neighbour estimate (Eq. 3) and its cone-filtered form (Eq. 4-5).
 *
 * The k photons nearest to x stand for the flux arriving at the disc of radius r around
 * x that contains them; each one's flux is reflected towards wo through the BRDF with
 * the direction it arrived from:
 *   L(x, wo) ~ sum_p f_r(x, wo, wi_p) Delta Phi_p / (pi r^2).
 * The estimate assumes the photons lie on the surface through x (the disc of area
 * pi r^2); it is consistent (right as N and k grow with k / N -> 0) and biased for finite
 * k: blurred where light changes over r, and with r the k-th photon's distance it
 * overestimates a uniform density by k / (k - 1); the cone filter with constant 1 has
 * no such bias (see estimate.c). The map must not hold shadow photons (trace.h).
 */
#ifndef PHOTON_ESTIMATE_H
#define PHOTON_ESTIMATE_H

#include <stddef.h>

#include "../scene/brdf.h"
#include "kdtree.h"

/* Where radiance is estimated and how the surface reflects there. */
struct estimate_point {
    struct vec3 x;                     /* the point on the surface                      */
    struct vec3 ng;                    /* unit geometric normal on the side of wo: only
                                          photons that arrived from this side count     */
    struct vec3 wo;                    /* unit, from x towards the viewer               */
    const struct material *material;   /* borrowed                                      */
    const struct shading_frame *frame; /* borrowed; around the shading normal, on wo's
                                          side, with TRANSPORT_RADIANCE                 */
};

/* How many photons, how far, and which filter. */
struct estimate_settings {
    size_t k;      /* photons gathered, 1..k_max of the scratch                         */
    double max_r2; /* photons farther than sqrt(max_r2) are not gathered; HUGE_VAL for
                      no limit; >= 0                                                    */
    double cone_k; /* 0: the plain estimate (Eq. 3); >= 1: the cone filter's constant k
                      (Eq. 4-5; Jensen 1996 uses 1). Values in (0, 1) are refused by
                      whoever reads them: the normalisation would not be the cone's.   */
    unsigned kinds; /* only photons with one of these PHOTON_* flags; 0: all         */
};

/* Radiance (W / (m^2 sr) per channel, in the map's power units over length^2) leaving
 * at->x towards at->wo. nn: the caller's scratch (k_max >= es->k), made once per render;
 * this call allocates nothing. Zero when no photon lies within the radius, or all lie
 * exactly at x (no area to divide by). */
struct vec3 radiance_estimate(const struct kdtree *map, const struct estimate_point *at,
                              const struct estimate_settings *es, struct nearest *nn);

#endif
