/*
 * modes/gather_plan.c -- the strata of a final gather and the rays each gets
 * (gather_plan.h).
 */
#include "gather_plan.h"

#include <math.h>

#include "../photon/irradiance_cache.h"

void ward_strata(int strata, int *m, int *n)
{
    *m = (int)floor(sqrt(strata / PI) + 0.5);
    *m = *m < 1 ? 1 : *m;
    *n = strata / *m > 1 ? strata / *m : 1;
}

struct gather_plan gather_plan_of(int gather_rays)
{
    struct gather_plan plan;
    ward_strata(gather_rays / 2, &plan.theta, &plan.phi);
    plan.rays = gather_rays > 2 ? gather_rays : 2;
    return plan;
}

void allot_rays(const struct gather_plan *plan, double total, double *share, int *rays_in)
{
    int mn = plan->theta * plan->phi;
    int extra = plan->rays - mn;
    int given = 0;
    for (int i = 0; i < mn; i++) {
        double exact = total > 0 ? extra * share[i] / total : (double)extra / mn;
        rays_in[i] = (int)exact;
        share[i] = exact - rays_in[i]; /* the remainder */
        given += rays_in[i];
    }
    for (; given < extra; given++) {
        int best = 0;
        for (int i = 1; i < mn; i++)
            best = share[i] > share[best] ? i : best;
        rays_in[best]++;
        share[best] = -1.0;
    }
    for (int i = 0; i < mn; i++)
        rays_in[i]++;
}

struct vec3 strata_integral(const struct gather_plan *plan, const struct vec3 *mean)
{
    int mn = plan->theta * plan->phi;
    struct vec3 sum = vec3_zero();
    for (int i = 0; i < mn; i++)
        sum = vec3_add(sum, mean[i]);
    return vec3_scale(sum, PI / mn);
}

int gather_direction(const struct shading_frame *frame, struct vec3 ng, int m, int n, int j,
                     int k, struct rng *rng, struct vec3 *wi)
{
    double u1 = rng_uniform(rng), u2 = rng_uniform(rng);
    struct vec3 local = stratum_direction(m, n, j, k, u1, u2);
    *wi = vec3_add(vec3_add(vec3_scale(frame->t, local.x), vec3_scale(frame->b, local.y)),
                   vec3_scale(frame->n, local.z));
    return vec3_dot(*wi, ng) > 0;
}
