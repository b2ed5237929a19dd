/*
 * tests/trace_fixtures.c -- the scenes' squares, traces and streams behind trace_fixtures.h.
 */
#include "trace_fixtures.h"

void add_square(struct scene *scene, struct vec3 centre, double half, int up, int m)
{
    struct vec3 p0 = vec3(centre.x - half, centre.y, centre.z - half);
    struct vec3 ex = vec3(2 * half, 0, 0), ez = vec3(0, 0, 2 * half);
    if (up)
        scene_add_quad(scene, p0, ez, ex, m); /* ez x ex = +y */
    else
        scene_add_quad(scene, p0, ex, ez, m); /* ex x ez = -y */
}

struct photon_trace trace(const struct scene *scene, size_t n, unsigned store,
                          uint64_t pass, const struct emission_targets *targets)
{
    struct trace_settings ts;
    ts.seed = SEED;
    ts.pass = pass;
    ts.n_emit = n;
    ts.max_stored = MAX_PHOTONS;
    ts.store = store;
    ts.max_depth = TEST_MAX_DEPTH;
    ts.targets = targets;
    ts.projection = NULL;
    ts.by_parts = 0;
    ts.watch = NULL;
    struct photon_trace out;
    struct error err;
    if (trace_photons(scene, &ts, &out, &err) < 0)
        error_print(&err);
    return out;
}

struct rng test_rng(uint64_t index, uint64_t sub)
{
    return rng_stream(SEED, STREAM_TEST, index, sub);
}
