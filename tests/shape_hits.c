/*
 * tests/shape_hits.c -- the comparisons of hits behind shape_hits.h.
 */
#include "shape_hits.h"

#include <math.h>

int same_hit(const struct hit *a, const struct hit *b, struct ray ray, double rel_t,
             int compare_ng)
{
    double scale = fmax(1.0, fmax(vec3_max_abs(ray.origin), b->t * vec3_length(ray.dir)));
    return fabs(a->t - b->t) <= rel_t * b->t &&
           vec3_max_abs(vec3_sub(a->p, b->p)) <= rel_t * scale &&
           (!compare_ng || vec3_dot(a->ng, b->ng) >= 1 - 1e-12) &&
           vec3_dot(a->ns, b->ns) >= 1 - 1e-9 && a->material == b->material;
}

size_t geometry_agreements(const struct geometry *procedural,
                           const struct geometry *expanded,
                           struct ray (*make)(const void *context, uint64_t q),
                           const void *context, size_t n_rays, double rel_t)
{
    size_t n_same = 0;
    for (uint64_t q = 0; q < n_rays; q++) {
        struct ray ray = make(context, q);
        struct hit a, b;
        int found_a = geometry_intersect(procedural, ray, INFINITY, &a);
        int found_b = geometry_intersect(expanded, ray, INFINITY, &b);
        n_same += found_a == found_b && (!found_a || same_hit(&a, &b, ray, rel_t, 0));
    }
    return n_same;
}
