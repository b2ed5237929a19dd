/*
 * modes/specular_rays.c -- the specular part by recursive ray tracing, shared by modes
 * 1994 and 1996 (specular_rays.h).
 */
#include "specular_rays.h"

/* One direction bs with share of the estimate: Russian roulette on the path's throughput
 * after the bounce, then the mode's step, scaled so the estimate stays unbiased. */
static struct vec3 follow(const struct brdf_sample *bs, double share, int several,
                          struct vec3 beta, int depth, const struct specular_step *step)
{
    double q = roulette_odds(vec3_mul(beta, bs->weight), depth);
    if (q < 1 && !(rng_uniform(step->rng) < q))
        return vec3_zero(); /* absorbed (always when q = 0) */
    double scale = share / q;
    struct vec3 li = step->incoming(step, bs, scale, several);
    return vec3_mul(vec3_scale(bs->weight, scale), li);
}

struct vec3 specular_rays(const struct material *m, const struct shading_frame *frame,
                          int every_lobe, int n_rays, struct vec3 beta, int depth,
                          const struct specular_step *step)
{
    struct vec3 wo = step->s->wo, sum = vec3_zero();
    if (every_lobe && brdf_is_delta(m)) {
        struct brdf_sample lobes[2];
        int n_lobes = brdf_delta_lobes(m, frame, wo, lobes);
        for (int k = 0; k < n_lobes; k++)
            sum = vec3_add(sum, follow(&lobes[k], 1.0, 0, beta, depth, step));
        return sum;
    }
    for (int r = 0; r < n_rays; r++) {
        double u[3];
        rng_uniforms(step->rng, u, 3);
        struct brdf_sample bs;
        if (brdf_sample(m, frame, wo, u, &bs))
            sum = vec3_add(sum, follow(&bs, 1.0 / n_rays, n_rays > 1, beta, depth, step));
    }
    return sum;
}
