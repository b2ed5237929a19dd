/*
 * modes/gather_plan.h -- how a final gather of mode 1996 (Jensen 1996, Sec. 4.4) spends
 * its rays: Ward and Heckbert's m x n strata of equal projected solid angle, one ray
 * each, and the rest of the rays allotted to the strata by Jensen 1995's importance (the
 * flux of the nearest photons through each stratum, which jensen1996.c measures); and
 * the strata themselves and the direction of a ray in a stratum, which 1994's gathers (one
 * ray a stratum) and tests/literal_jensen1994.c share.
 */
#ifndef PHOTON_GATHER_PLAN_H
#define PHOTON_GATHER_PLAN_H

#include "../base/rng.h"
#include "../base/vec3.h"
#include "../scene/brdf.h"

/* A final gather's size: m x n strata (Ward and Heckbert's), one ray each, and the rest
 * of its rays spread by importance. */
struct gather_plan {
    int theta, phi; /* m rings, n sectors */
    int rays;       /* >= theta * phi     */
};

/* Ward and Heckbert's m x n strata for about `strata` rays of one each: m rings, the
 * nearest whole number to sqrt(strata / pi), and n = strata / m sectors, so that n is
 * about pi m as in their paper; at least one of each. */
void ward_strata(int strata, int *m, int *n);

/* The plan of a gather of gather_rays rays: half the rays make the strata (ward_strata(),
 * one each); the other half follow importance. At least one stratum and two rays. */
struct gather_plan gather_plan_of(int gather_rays);

/* rays_in[i] for the plan's m n strata from their importance share[0 .. m n - 1] (>= 0)
 * and its sum total (>= 0): every stratum gets one ray, so the estimate stays unbiased
 * where photons are missing and the gradients see every stratum; the other rays go in
 * proportion to importance, rounded by largest remainder (ties to the lower index, so
 * the split is deterministic), or evenly where no photon arrived (total 0). Each
 * stratum's mean is then an unbiased estimate of its own integral: importance sampling
 * by stratified allocation. share[] is used as scratch and left undefined. */
void allot_rays(const struct gather_plan *plan, double total, double *share, int *rays_in);

/* pi / (m n) times the sum of mean[0 .. m n - 1], each stratum's mean of what its rays
 * found: every stratum spans a projected solid angle of pi / (m n), so this is the
 * integral over the hemisphere of the mean times cos (the irradiance, for mean L). */
struct vec3 strata_integral(const struct gather_plan *plan, const struct vec3 *mean);

/* A gather ray's direction *wi in stratum (j, k) of m x n around frame->n (world space),
 * cosine-distributed within it by two numbers drawn from rng (stratum_direction()).
 * Returns 0 when *wi lies below the geometric surface of normal ng, where no light
 * arrives (a shading normal can lean a stratum past it), else 1. */
int gather_direction(const struct shading_frame *frame, struct vec3 ng, int m, int n, int j,
                     int k, struct rng *rng, struct vec3 *wi);

#endif
