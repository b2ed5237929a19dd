/*
 * tests/geom_helpers.c -- the random numbers, points, directions and checks behind
 * geom_helpers.h.
 */
#include "geom_helpers.h"

#include <math.h>

double uniform(struct rng *r, double lo, double hi)
{
    return lo + (hi - lo) * rng_uniform(r);
}

struct vec3 random_unit(struct rng *r)
{
    double z = uniform(r, -1.0, 1.0), phi = uniform(r, 0.0, 2.0 * PI);
    double s = sqrt(fmax(0.0, 1.0 - z * z));
    return vec3(s * cos(phi), s * sin(phi), z);
}

struct vec3 random_point(struct rng *r, double half_size)
{
    return vec3(uniform(r, -half_size, half_size), uniform(r, -half_size, half_size),
                uniform(r, -half_size, half_size));
}

int relative_close(double a, double b, double rel)
{
    return fabs(a - b) <= rel * fmax(fabs(a), fabs(b));
}

int hit_is_finite(const struct hit *h)
{
    return isfinite(h->t) && vec3_is_finite(h->p) && vec3_is_finite(h->ng)
           && vec3_is_finite(h->ns) && isfinite(h->u) && isfinite(h->v);
}
