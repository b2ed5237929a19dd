/*
 * tests/projection_fixtures.c -- the settings and traces behind projection_fixtures.h.
 */
#include "projection_fixtures.h"

struct projection_settings settings(double boost)
{
    struct projection_settings ps;
    ps.n_theta = PROJECTION_N_THETA_DEFAULT;
    ps.n_phi = PROJECTION_N_PHI_DEFAULT;
    ps.boost = boost;
    return ps;
}

void trace_into(const struct scene *scene, const struct projection_maps *pm, size_t n,
                uint64_t pass, unsigned store, const struct photon_sink *sink)
{
    struct trace_settings ts;
    ts.seed = SEED;
    ts.pass = pass;
    ts.n_emit = n;
    ts.max_stored = MAX_PHOTONS;
    ts.store = store;
    ts.max_depth = 100;
    ts.targets = NULL;
    ts.projection = pm;
    ts.by_parts = 0;
    ts.watch = NULL;
    unsigned long long rays = 0;
    trace_photons_into(scene, &ts, sink, &rays);
}
