/*
 * modes/ppm_direct.c -- the direct term of progressive photon mapping's hit points
 * (ppm_direct.h): each pass, one light sample of each light at each hit point.
 *
 * The samples are those of `--mode direct` (light_contribution() and light_blocked(),
 * surface.h): the shadow ray is blocked by any surface, mirror and glass included, so
 * light reaching a hit point through them is left to the photons (ppm2008.c keeps the
 * caustic ones). A hit point's samples over the passes are the points of a (0,2)-sequence
 * with a digital shift of its own (sequence02.h): after 2^k passes they are stratified
 * over the light, so the term converges faster than with independent samples.
 */
#include "ppm_direct.h"

#include <stdlib.h>

#include "../base/alloc.h"
#include "../base/sequence02.h"
#include "surface.h"

void ppm_direct_create(struct ppm_direct *d, const struct scene *scene,
                       const struct render_settings *rs)
{
    size_t n_pixels = (size_t)(rs->x1 - rs->x0) * (size_t)(rs->y1 - rs->y0);
    d->scene = scene;
    d->rs = rs;
    d->sum = xcalloc(n_pixels, sizeof *d->sum, "ppm direct term");
    d->passes = 0;
}

/* The surface of hit point hp as light_contribution() reads it. */
static struct surface hit_point_surface(const struct hit_point *hp)
{
    struct surface s;
    s.p = hp->x;
    s.ng = hp->n;
    s.ns = hp->frame.n;
    s.wo = hp->wo;
    s.front = hp->frame.front;
    s.material = hp->material;
    s.prim = -1; /* unused: no emission is looked up here */
    s.u = s.v = 0.0;
    return s;
}

/* Reflected radiance at hp from sample `turn` of each light, the lights' shifts drawn
 * from shifts in light order. */
static struct vec3 sample_lights(const struct scene *scene, const struct hit_point *hp,
                                 uint32_t turn, struct rng *shifts,
                                 struct render_counters *counters)
{
    struct surface s = hit_point_surface(hp);
    struct vec3 sum = vec3_zero();
    for (size_t i = 0; i < scene->n_lights; i++) {
        uint64_t shift = rng_next(shifts); /* drawn for every light: keeps the others' */
        double u1, u2;
        sequence02_point(turn, (uint32_t)shift, (uint32_t)(shift >> 32), &u1, &u2);
        struct light_sample ls;
        struct vec3 contribution;
        if (!light_contribution(&scene->lights[i], &s, hp->material, &hp->frame, u1, u2, &ls,
                                &contribution))
            continue;
        counters->rays++;
        if (!light_blocked(scene, &s, &ls))
            sum = vec3_add(sum, contribution);
    }
    return sum;
}

/* The index in the whole image of window pixel i. */
static uint64_t whole_image_pixel(const struct ppm_direct *d, size_t i)
{
    const struct render_settings *rs = d->rs;
    size_t width = (size_t)(rs->x1 - rs->x0); /* >= 1: a window is never empty */
    uint64_t x = (uint64_t)rs->x0 + i % width, y = (uint64_t)rs->y0 + i / width;
    return y * (uint64_t)d->scene->width + x;
}

void ppm_direct_pass(struct ppm_direct *d, const struct hit_point *points, size_t n,
                     long pass, struct render_counters *counters)
{
    long turns = d->rs->spp;                  /* >= 1: the eye rays that take turns */
    uint32_t turn = (uint32_t)(pass / turns); /* turns each had before this one     */
    uint64_t k = 0;                           /* the hit point's place in its pixel */
    for (size_t i = 0; i < n; i++) {
        const struct hit_point *hp = &points[i];
        k = i > 0 && points[i - 1].pixel == hp->pixel ? k + 1 : 0;
        if (hp->sample % turns != pass % turns)
            continue;
        struct rng shifts = rng_stream(d->rs->seed, STREAM_LIGHT,
                                       whole_image_pixel(d, hp->pixel), k);
        struct vec3 l = sample_lights(d->scene, hp, turn, &shifts, counters);
        struct vec3 w = vec3_scale(hp->weight, (double)turns); /* the eye path's beta */
        d->sum[hp->pixel] = vec3_add(d->sum[hp->pixel], vec3_mul(w, l));
    }
    d->passes++;
}

struct vec3 ppm_direct_radiance(const struct ppm_direct *d, size_t i)
{
    if (d->passes == 0)
        return vec3_zero();
    return vec3_scale(d->sum[i], 1.0 / (double)d->passes);
}

void ppm_direct_free(struct ppm_direct *d)
{
    xfree(d->sum);
    d->sum = NULL;
}
