/*
 * modes/ppm_direct.c -- the direct term of progressive photon mapping (ppm_direct.h): each
 * pass, one light sample of each light wherever that pass's eye ray meets a surface with
 * a non-delta part.
 *
 * The samples are those of `--mode direct` (light_contribution() and light_blocked(),
 * surface.h): the shadow ray is blocked by any surface, mirror and glass included, so
 * light reaching a surface through them is left to the photons (ppm2008.c keeps the
 * caustic ones). A pixel's samples at its k-th surface over the passes are the points of
 * a (0,2)-sequence with a digital shift of their own (sequence02.h): after 2^j passes
 * they are stratified over the light, so the term converges faster than with independent
 * samples; the eye rays' own points in the pixel are stratified too (render.h).
 */
#include "ppm_direct.h"

#include <stdlib.h>

#include "../base/alloc.h"
#include "../base/sequence02.h"

void ppm_direct_create(struct ppm_direct *d, const struct scene *scene,
                       const struct render_settings *rs)
{
    size_t n_pixels = (size_t)(rs->x1 - rs->x0) * (size_t)(rs->y1 - rs->y0);
    d->scene = scene;
    d->rs = rs;
    d->sum = xcalloc(n_pixels, sizeof *d->sum, "ppm direct term");
    d->passes = 0;
}

/* ppm_direct_sample() and ppm_direct_point_lights(): the lights sampled are every light,
 * or with points_only the point lights alone. */
static void sample_lights(struct ppm_direct *d, size_t pixel, uint64_t k, long pass,
                          const struct surface *s, const struct shading_frame *frame,
                          struct vec3 beta, int points_only, struct render_counters *counters)
{
    const struct scene *scene = d->scene;
    struct rng shifts =
        rng_stream(d->rs->seed, STREAM_LIGHT, image_pixel(d->rs, scene->width, pixel), k);
    struct vec3 sum = vec3_zero();
    for (size_t i = 0; i < scene->n_lights; i++) {
        uint64_t shift = rng_next(&shifts); /* drawn for every light: keeps the others' */
        uint32_t order = (uint32_t)rng_next(&shifts);
        double u1, u2;
        sequence02_point(sequence02_shuffled((uint32_t)pass, order), (uint32_t)shift,
                         (uint32_t)(shift >> 32), &u1, &u2);
        if (points_only && scene->lights[i].kind != LIGHT_POINT)
            continue;
        struct light_sample ls;
        struct vec3 contribution;
        if (!light_contribution(&scene->lights[i], s, s->material, frame, u1, u2, &ls,
                                &contribution))
            continue;
        counters->rays++;
        if (!light_blocked(scene, s, &ls))
            sum = vec3_add(sum, contribution);
    }
    d->sum[pixel] = vec3_add(d->sum[pixel], vec3_mul(beta, sum));
}

void ppm_direct_sample(struct ppm_direct *d, size_t pixel, uint64_t k, long pass,
                       const struct surface *s, const struct shading_frame *frame,
                       struct vec3 beta, struct render_counters *counters)
{
    sample_lights(d, pixel, k, pass, s, frame, beta, 0, counters);
}

void ppm_direct_point_lights(struct ppm_direct *d, size_t pixel, uint64_t k, long pass,
                             const struct surface *s, const struct shading_frame *frame,
                             struct vec3 beta, struct render_counters *counters)
{
    sample_lights(d, pixel, k, pass, s, frame, beta, 1, counters);
}

void ppm_direct_end_pass(struct ppm_direct *d)
{
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
