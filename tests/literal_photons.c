/*
 * tests/literal_photons.c -- the photon pass, Eq. 11 and the progressive update of the
 * literal programs (literal_photons.h).
 *
 * The photons are kept as the tracer stores them, not in the photon map's 20-byte records
 * (Jensen 1996, Sec. 3): those round a direction to 256 steps of theta and of phi, up to a
 * degree off, as wide as a sharp glossy lobe (cornell-glossy's Ward floor, alpha_x = 0.02
 * radians), and Eq. 11's f_r at the rounded directions moved 8 x 8 blocks of that floor by
 * up to 11%. The 2008 paper's photons live for one pass, so nothing asks for the rounding.
 * A hit point finds its photons within R among those whose x lies within R of its own,
 * the pass's photons being sorted by x: the simplest search that keeps a test quick.
 */
#include "literal_photons.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../src/base/alloc.h"
#include "../src/modes/render.h"

/* The tracer's sink: keeps every photon it stores. */
static int keep_photon(void *context, const struct photon_event *photon)
{
    struct literal_photons *pass = context;
    if (pass->n == pass->capacity) {
        pass->capacity = pass->capacity > 0 ? 2 * pass->capacity : 4096;
        pass->photons = xrealloc(pass->photons, pass->capacity, sizeof *pass->photons,
                                 "literal photons");
    }
    pass->photons[pass->n++] = *photon;
    return 0;
}

/* qsort()'s order of photons: by x, then y, then z. */
static int by_position(const void *a, const void *b)
{
    struct vec3 p = ((const struct photon_event *)a)->position;
    struct vec3 q = ((const struct photon_event *)b)->position;
    if (p.x != q.x)
        return p.x < q.x ? -1 : 1;
    if (p.y != q.y)
        return p.y < q.y ? -1 : 1;
    return p.z < q.z ? -1 : p.z > q.z;
}

/* The first of the pass's photons (sorted by x) whose x is x_min or more. */
static size_t first_at_or_after(const struct literal_photons *pass, double x_min)
{
    size_t lo = 0, hi = pass->n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (pass->photons[mid].position.x < x_min)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

struct literal_photons literal_photon_pass(const struct scene *scene, uint64_t seed, long pass,
                                           size_t photons)
{
    struct literal_photons out = {NULL, 0, 0};
    struct trace_settings ts;
    unsigned long long rays = 0;
    memset(&ts, 0, sizeof ts);
    ts.seed = seed;
    ts.pass = (uint64_t)pass;
    ts.n_emit = photons;
    ts.store = PHOTON_MAP_GLOBAL;
    ts.max_depth = MAX_DEPTH_LIMIT;
    struct photon_sink sink = {keep_photon, &out};
    trace_photons_into(scene, &ts, &sink, &rays); /* keep_photon() never stops it */
    if (out.n > 0)
        qsort(out.photons, out.n, sizeof *out.photons, by_position);
    return out;
}

void literal_photons_free(struct literal_photons *pass)
{
    xfree(pass->photons);
    pass->photons = NULL;
    pass->n = pass->capacity = 0;
}

struct vec3 literal_photons_within(const struct literal_photons *pass, struct vec3 x, double r,
                                   const struct material *brdf,
                                   const struct shading_frame *frame, struct vec3 wo,
                                   size_t photons, double *m)
{
    struct vec3 sum = vec3_zero();
    *m = 0.0;
    for (size_t i = first_at_or_after(pass, x.x - r);
         i < pass->n && pass->photons[i].position.x <= x.x + r; i++) {
        const struct photon_event *p = &pass->photons[i];
        if (vec3_length2(vec3_sub(p->position, x)) > r * r)
            continue;
        struct vec3 f = brdf_eval(brdf, frame, wo, p->wi);
        sum = vec3_add(sum, vec3_mul(f, vec3_scale(p->power, (double)photons))); /* Phi'_p */
        *m += 1.0;
    }
    return sum;
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
