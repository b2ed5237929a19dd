/*
 * tests/literal_photons.c -- the photon pass, Eq. 11 and the progressive update of the
 * literal programs (literal_photons.h).
 */
#include "literal_photons.h"

#include <math.h>
#include <string.h>

#include "../src/modes/render.h"
#include "../src/photon/trace.h"

struct kdtree *literal_photon_map(const struct scene *scene, uint64_t seed, long pass,
                                  size_t photons)
{
    struct trace_settings ts;
    struct photon_trace trace;
    struct error err;
    memset(&ts, 0, sizeof ts);
    ts.seed = seed;
    ts.pass = (uint64_t)pass;
    ts.n_emit = photons;
    ts.max_stored = MAX_PHOTONS;
    ts.store = PHOTON_MAP_GLOBAL;
    ts.max_depth = MAX_DEPTH_LIMIT;
    if (trace_photons(scene, &ts, &trace, &err) != 0)
        return NULL;
    return balance_kdtree(trace.photons, trace.n_photons); /* the map owns them now */
}

/* Eq. 11's sum as for_each_photon_within() visits the photons. */
struct gather {
    const struct material *brdf;
    const struct shading_frame *frame;
    struct vec3 wo, sum;
    double m;
};

static void add_photon(void *context, const struct photon *p, double d2)
{
    struct gather *g = context;
    (void)d2;
    struct vec3 f = brdf_eval(g->brdf, g->frame, g->wo, photon_direction(p));
    g->sum = vec3_add(g->sum, vec3_mul(f, photon_power(p)));
    g->m += 1.0;
}

struct vec3 literal_photons_within(const struct kdtree *map, struct vec3 x, double r,
                                   const struct material *brdf,
                                   const struct shading_frame *frame, struct vec3 wo,
                                   size_t photons, double *m)
{
    struct gather g = {brdf, frame, wo, {0.0, 0.0, 0.0}, 0.0};
    if (map != NULL)
        for_each_photon_within(map, x, r * r, add_photon, &g);
    *m = g.m;
    return vec3_scale(g.sum, (double)photons); /* the tracer's powers carry 1 / M */
}

void literal_update(double *n, double *radius, struct vec3 *tau, struct vec3 flux, double m)
{
    if (*n + m == 0)
        return;
    double shrink = (*n + LITERAL_ALPHA * m) / (*n + m); /* R'^2 / R^2 */
    *tau = vec3_scale(vec3_add(*tau, flux), shrink);
    *radius *= sqrt(shrink);
    *n += LITERAL_ALPHA * m;
}
