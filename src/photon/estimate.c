/*
 * photon/estimate.c -- the radiance estimates (estimate.h; Jensen 1996, Sec. 5).
 *
 * The cone filter (Eq. 4) weights photon p at distance d_p by w_p = max(0, 1 - d_p/(k r)).
 * Photons spread evenly over the disc of radius r have mean weight
 *   (1 / (pi r^2)) int_0^r (1 - s / (k r)) 2 pi s ds = 1 - 2 / (3k)
 * (Eq. 5's normalisation, for k >= 1 where no weight is clipped), so dividing by it keeps
 * the estimate of a uniform region unbiased. With k = 1 the k-th photon, the one on the
 * rim, has weight 0: the other k - 1 lie uniformly inside the disc, and for a Poisson
 * density lambda, E[(k - 1) / (pi r^2)] = lambda exactly, so the filtered estimate of a
 * uniform region has no bias. Eq. 3 as printed counts the rim photon too, and its mean
 * is lambda k / (k - 1): 1% too bright at k = 100, enough to show on a ceiling lit only
 * indirectly (src/modes/README.md, Estimates). So the plain estimate here leaves
 * out the photon on the rim (the one at d_p = r), as the cone filter does, and so does
 * the 1994 irradiance estimate with each E_j. Where fewer than k photons lie within the
 * maximum radius, r is that radius, no photon marks it, and all of them count.
 */
#include "estimate.h"

#include <assert.h>
#include <string.h>

/* Eq. 3 / Eq. 5 at at->x; with batches also each batch's share and the inner disc's
 * (estimate.h). */
static struct vec3 estimate(const struct kdtree *map, const struct estimate_point *at,
                            const struct estimate_settings *es, struct nearest *nn,
                            struct estimate_batches *batches)
{
    assert(es->cone_k == 0 || es->cone_k >= 1);
    if (batches != NULL)
        memset(batches, 0, sizeof *batches);
    struct photon_query q;
    q.x = at->x;
    q.max_r2 = es->max_r2;
    q.k = es->k;
    q.kinds = es->kinds;
    locate_photons_of_kinds(map, &q, nn); /* sets found, photon[], d2[], r2 */
    if (nn->found == 0 || !(nn->r2 > 0))
        return vec3_zero(); /* no photons, or all exactly at x: no area */
    /* Eq. 3: L = sum f_r Delta Phi_p / (pi r^2). Eq. 5 also divides by the cone's
     * normalisation 1 - 2/(3k), which is at least 1/3 because k >= 1. The inner disc, of
     * radius r / sqrt(2), has half the area, and its cone half the cone's. */
    double area = PI * nn->r2;
    if (es->cone_k > 0)
        area *= 1.0 - 2.0 / (3.0 * es->cone_k);
    struct vec3 sum = vec3_zero();
    /* A photon marks r when k were found, or when the search had no maximum radius (a
     * map of fewer than k photons): that one, on the rim, is still to be left out. */
    int rim = es->exclude_rim && nn->found >= 2 &&
              (nn->found == es->k || es->max_r2 == HUGE_VAL);
    for (size_t i = 0; i < nn->found; i++) {
        const struct photon *p = nn->photon[i];
        if (rim && nn->d2[i] == nn->r2) {
            rim = 0;
            continue; /* it marks the radius (see the top of the file) */
        }
        /* A photon on the other side of this surface (a thin wall's back, a closed
         * sphere's inside) is not this surface's: its side is the tracer's exact bit, as
         * the rounded direction and a normal turned by curvature cannot tell it (a point
         * light in a closed sphere leaked onto its outside). The direction still rejects
         * photons of a neighbouring surface that came from below this one. */
        struct vec3 wi = photon_direction(p);
        if (((p->flags & PHOTON_BACK) != 0) != (at->back != 0) || !(vec3_dot(wi, at->ng) > 0))
            continue;
        struct vec3 flux = vec3_mul(brdf_eval(at->material, at->frame, at->wo, wi),
                                    photon_power(p));
        double w = 1.0;
        if (es->cone_k > 0) /* Eq. 4: w_p = max(0, 1 - d_p / (k r)) */
            w = fmax(0.0, 1.0 - sqrt(nn->d2[i] / nn->r2) / es->cone_k);
        sum = vec3_add(sum, vec3_scale(flux, w));
        if (batches == NULL)
            continue;
        unsigned b = photon_batch(p);
        batches->disc[b] = vec3_add(batches->disc[b], vec3_scale(flux, w));
        if (2.0 * nn->d2[i] < nn->r2) {
            double w_inner = 1.0;
            if (es->cone_k > 0)
                w_inner = fmax(0.0, 1.0 - sqrt(2.0 * nn->d2[i] / nn->r2) / es->cone_k);
            batches->inner[b] = vec3_add(batches->inner[b], vec3_scale(flux, w_inner));
        }
    }
    for (int b = 0; batches != NULL && b < PHOTON_BATCHES; b++) {
        batches->disc[b] = vec3_scale(batches->disc[b], 1.0 / area);
        batches->inner[b] = vec3_scale(batches->inner[b], 2.0 / area);
    }
    return vec3_scale(sum, 1.0 / area);
}

struct vec3 radiance_estimate(const struct kdtree *map, const struct estimate_point *at,
                              const struct estimate_settings *es, struct nearest *nn)
{
    return estimate(map, at, es, nn, NULL);
}

struct vec3 radiance_estimate_in_batches(const struct kdtree *map,
                                         const struct estimate_point *at,
                                         const struct estimate_settings *es,
                                         struct nearest *nn, struct estimate_batches *batches)
{
    return estimate(map, at, es, nn, batches);
}

/* The energy photon p adds at a surface with normal n: all of it when it landed on a
 * surface facing the same way (its stored normal . n > 0), else none (Sec. 3.3's
 * rejection: a photon on the other side of a thin wall, or around a corner). Over 1996's
 * global map (precomputed irradiance) the bytes hold wi instead, and the same test keeps
 * the photons that arrived from n's side (estimate.h). */
static struct vec3 accepted_energy(const struct photon *p, struct vec3 n)
{
    return vec3_dot(photon_normal(p), n) > 0 ? photon_power(p) : vec3_zero();
}

struct vec3 irradiance_estimate(const struct kdtree *map, struct vec3 x, struct vec3 n,
                                const struct irradiance_settings *is, struct nearest *nn)
{
    struct photon_query q;
    q.x = x;
    q.max_r2 = is->max_r2;
    q.k = is->n;
    q.kinds = is->kinds;
    locate_photons_of_kinds(map, &q, nn);
    nearest_sort(nn);
    struct vec3 sum = vec3_zero(), e = vec3_zero();
    double previous = 0.0; /* luminance of E_{j-1}; 0 before the first with area */
    int rising = 0, falling = 0;
    for (size_t j = 0; j < nn->found; j++) {
        struct vec3 inside = sum; /* the photons nearer than the j-th */
        sum = vec3_add(sum, accepted_energy(nn->photon[j], n));
        if (!(nn->d2[j] > 0))
            continue; /* photons exactly at x: no disc yet */
        /* E_j = sum_{i<j} e_i / (pi r_j^2): the j-th photon marks the radius, on the rim;
         * the paper's sum_{i<=j} without exclude_rim */
        e = vec3_scale(is->exclude_rim ? inside : sum, 1.0 / (PI * nn->d2[j]));
        double now = vec3_luminance(e);
        rising = now > previous ? rising + 1 : 0;
        falling = now < previous ? falling + 1 : 0;
        previous = now;
        if (is->run > 0 && j + 1 >= 2 * (size_t)is->run &&
            (rising >= is->run || falling >= is->run))
            return e; /* differential checking: a monotonic run, an edge */
    }
    if (nn->found < is->n && is->max_r2 != HUGE_VAL && nn->r2 > 0)
        e = vec3_scale(sum, 1.0 / (PI * nn->r2)); /* fewer than n within max_r2: all of
                                                     them over its whole disc */
    return e;
}
