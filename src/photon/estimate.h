/*
 * photon/estimate.h -- radiance from a photon map (Jensen 1996, Sec. 5): the
 * nearest-neighbour estimate (Eq. 3) and its cone-filtered form (Eq. 4-5).
 *
 * The k photons nearest to x stand for the flux arriving at the disc of radius r around
 * x that contains them; each one's flux is reflected towards wo through the BRDF with
 * the direction it arrived from:
 *   L(x, wo) ~ sum_p f_r(x, wo, wi_p) Delta Phi_p / (pi r^2).
 * The estimate assumes the photons lie on the surface through x (the disc of area pi r^2);
 * it is consistent (right as N and k grow with k / N -> 0) and biased for finite k:
 * blurred where light changes over r. With r the k-th photon's distance, Eq. 3 as printed
 * overestimates a uniform density by k / (k - 1); the photon on the rim is left out here
 * (exclude_rim; 0 keeps the paper's sum), which removes that bias, as the cone filter with
 * constant 1 does by giving it weight 0 (see estimate.c). The map must not hold shadow
 * photons (trace.h).
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
    int back;                          /* 1: wo is on the primitive's back (surface.h's
                                          !front): only photons that arrived on the same
                                          side of their primitive count (PHOTON_BACK)   */
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
    int exclude_rim; /* 1: the photon on the rim only marks r (a departure); 0: it
                        counts too, as Eq. 3 is printed (the paper's, k / (k - 1) too
                        bright)                                                        */
};

/* Radiance (W / (m^2 sr) per channel, in the map's power units over length^2) leaving
 * at->x towards at->wo. nn: the caller's scratch (k_max >= es->k), made once per render;
 * this call allocates nothing. Zero when no photon lies within the radius, or all lie
 * exactly at x (no area to divide by). */
struct vec3 radiance_estimate(const struct kdtree *map, const struct estimate_point *at,
                              const struct estimate_settings *es, struct nearest *nn);

/* The estimate split by the photons' batches (photon.h, PHOTON_BATCHES), for a bound on
 * its error (modes/photons.c):
 *   disc[b]:  batch b's photons' part of the estimate: the estimate is the sum over b;
 *   inner[b]: the same over the inner disc of radius r / sqrt(2), half the area (the
 *             cone's radius scaled with it), whose density estimate's bias, Lap(L) r^2 / 16
 *             for the plain disc, is half the whole disc's, so 2 (sum disc - sum inner)
 *             estimates the estimate's bias (modes/sppm_error.h).
 * PHOTON_BATCHES times one batch's part is an estimate from that batch alone, at the
 * whole map's radius: the batches' photons are independent of each other, so the
 * spread of those estimates states the map's noise. */
struct estimate_batches {
    struct vec3 disc[PHOTON_BATCHES];
    struct vec3 inner[PHOTON_BATCHES];
};

/* radiance_estimate(), and its batches into *batches. */
struct vec3 radiance_estimate_in_batches(const struct kdtree *map,
                                         const struct estimate_point *at,
                                         const struct estimate_settings *es,
                                         struct nearest *nn, struct estimate_batches *batches);

/* ---- irradiance (Jensen and Christensen 1994, Sec. 3.3) ---- */

/* DIFFERENTIAL_RUN: the default run length of differential checking below. Measured on a
 * synthetic caustic edge (Poisson photons, density 6 : 1 across a straight edge, 200
 * photons per estimate; tests/test_trace_estimates.c's test_differential_checking_edge):
 * with runs of 10 the relative RMS error within a disc radius of the edge falls from 0.77
 * to 0.60, while far from it (x from 0.1 to 0.4, the edge at 0.5) the noise rises from
 * 0.076 to 0.105 (the early stops of a noisy estimate); runs of 8 stop too often (0.54
 * near, 0.146 far), runs of 15 too rarely (0.72 near, 0.080 far). */
#define DIFFERENTIAL_RUN 10

/* What an irradiance estimate gathers. */
struct irradiance_settings {
    size_t n;       /* photons gathered: the n nearest, 1..k_max of the scratch          */
    double max_r2;  /* photons farther than sqrt(max_r2) are not gathered; HUGE_VAL for
                       no limit; >= 0                                                   */
    unsigned kinds; /* PHOTON_CAUSTIC: the caustic estimate (CP photons only); 0: all   */
    int run;        /* differential checking's run length R >= 1; 0 turns it off        */
    int exclude_rim; /* 1: the j-th photon only marks r_j (a departure); 0: each E_j
                        counts it too, as the paper sums to n                           */
};

/* Irradiance (W / m^2 per channel in the map's units) at x on a surface with unit normal
 * n, from a map whose photons hold the SURFACE NORMAL where they landed in their
 * direction bytes (the 1994 record: position, normal, energy, caustic bit; read by
 * photon_normal()):
 *   E_x = sum_{i=1..n-1} e_i / (pi r^2),
 * r the distance of the n-th nearest photon, and only photons whose normal faces n
 * (positive dot product) adding their energy e_i. (1996's precomputed irradiance runs it
 * over its global map, whose bytes hold wi: the same test then keeps the photons that
 * arrived from n's side.) The paper sums to n; the n-th photon, on the rim, only marks r
 * here, which takes away the sum's bias of n / (n - 1) (see estimate.c), unless exclude_rim
 * is 0, the paper's sum. With fewer than n photons within max_r2, all count over that
 * disc.
 * Differential checking (run R > 0): the photons are added nearest first; E_j is the
 * estimate from the j - 1 nearest over r = the j-th distance. From the 2R-th photon on, the
 * estimate stops at the first j where each of the last R additions raised it
 * (E_i > E_{i-1}), or each lowered it, and E_j is used: near a caustic's edge the
 * estimate changes monotonically as the disc grows across it (Sec. 3.3). Zero when no
 * photon is found or all lie exactly at x. nn: the caller's scratch (k_max >= n); its
 * photons are left sorted by distance. Allocates nothing. */
struct vec3 irradiance_estimate(const struct kdtree *map, struct vec3 x, struct vec3 n,
                                const struct irradiance_settings *is, struct nearest *nn);

#endif
