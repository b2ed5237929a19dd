/*
 * photon/precomputed_irradiance.c -- irradiance at photon positions (Christensen 1999;
 * precomputed_irradiance.h).
 *
 * The estimate at a record is the map's irradiance estimate with the record's normal
 * (estimate.h): the photons arriving from the normal's side, the one on the rim left out.
 * For a Lambertian surface f_r,d times it is the radiance estimate Eq. 3 would make at
 * the record, since that estimate's photons are the same and f_r,d = rho / pi does not
 * depend on their directions. A lookup then moves the estimate from x to a record at most
 * one disc away, where the photons are nearly the same ones. Given the scene, the estimate
 * is disc_coverage.h's instead: the photons of the disc's plane over the part of the disc a
 * surface covers, so that a record by an open edge or a wall is not dark.
 */
#include "precomputed_irradiance.h"

#include <assert.h>

#include "../base/alloc.h"
#include "disc_coverage.h"

struct precomputed_irradiance *precompute_irradiance(const struct kdtree *map,
                                                     const struct kdtree *records,
                                                     const struct irradiance_settings *is,
                                                     const struct scene *coverage,
                                                     const struct work_watch *watch)
{
    assert(is->n >= 1);
    struct precomputed_irradiance *pi = xmalloc(1, sizeof *pi, "precomputed irradiance");
    pi->records = records;
    pi->value = xcalloc(records->n_photons + 1, sizeof *pi->value, "precomputed irradiance");
    pi->max_r2 = is->max_r2;
    struct nearest *nn = nearest_create(is->n);
    for (size_t i = 1; i <= records->n_photons; i++) {
        const struct photon *p = &records->photons[i];
        struct vec3 x = photon_position(p), n = photon_normal(p);
        struct vec3 e = coverage != NULL
                            ? covered_irradiance_estimate(map, coverage, x, n, is, nn)
                            : irradiance_estimate(map, x, n, is, nn);
        pi->value[i].e[0] = (float)e.x;
        pi->value[i].e[1] = (float)e.y;
        pi->value[i].e[2] = (float)e.z;
        pi->value[i].r2 = (float)nn->r2;
        if (watch != NULL && i % PRECOMPUTED_WATCH_EVERY == 0)
            watch->at(watch->context, i);
    }
    nearest_free(nn);
    return pi;
}

void precomputed_irradiance_free(struct precomputed_irradiance *pi)
{
    if (pi == NULL)
        return;
    xfree(pi->value);
    xfree(pi);
}

size_t precomputed_irradiance_bytes(const struct precomputed_irradiance *pi)
{
    return sizeof *pi + (pi->records->n_photons + 1) * sizeof *pi->value;
}

/* Whether the record of node i, at squared distance d2 from the point, can serve a
 * surface with normal n there. */
static int serves(const struct precomputed_irradiance *pi, size_t i, double d2, struct vec3 n)
{
    return d2 <= pi->value[i].r2 &&
           vec3_dot(n, photon_normal(&pi->records->photons[i])) >= PRECOMPUTED_MIN_COS;
}

/* The node of the nearest record that serves (x, n), 0 for none. On a surface away from
 * corners the nearest record serves, so it is tried alone first: a search for one record
 * costs a fraction of one for PRECOMPUTED_CANDIDATES. */
static size_t serving_record(const struct precomputed_irradiance *pi, struct vec3 x,
                             struct vec3 n, struct nearest *nn)
{
    locate_photons(pi->records, x, pi->max_r2, 1, nn);
    if (nn->found == 0)
        return 0; /* then none lies within the maximum radius */
    size_t nearest = (size_t)(nn->photon[0] - pi->records->photons);
    if (serves(pi, nearest, nn->d2[0], n))
        return nearest;
    locate_photons(pi->records, x, pi->max_r2, PRECOMPUTED_CANDIDATES, nn);
    size_t best = 0; /* node of the nearest usable record; 0: none yet */
    double best_d2 = 0.0;
    for (size_t j = 0; j < nn->found; j++) {
        size_t i = (size_t)(nn->photon[j] - pi->records->photons);
        double d2 = nn->d2[j];
        if (best != 0 && (d2 > best_d2 || (d2 == best_d2 && i > best)))
            continue; /* a nearer one is known: distance, then node, a total order */
        if (serves(pi, i, d2, n)) {
            best = i;
            best_d2 = d2;
        }
    }
    return best;
}

int precomputed_irradiance_at(const struct precomputed_irradiance *pi, struct vec3 x,
                              struct vec3 n, struct nearest *nn, struct vec3 *e, double *r2)
{
    size_t best = serving_record(pi, x, n, nn);
    if (best == 0)
        return 0;
    const struct irradiance_value *v = &pi->value[best];
    *e = vec3(v->e[0], v->e[1], v->e[2]);
    *r2 = v->r2;
    return 1;
}
