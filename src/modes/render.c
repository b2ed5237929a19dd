/*
 * modes/render.c -- the shared pixel loop (render.h) and its progress line.
 */
#include "render.h"

#include <stdio.h>
#include <time.h>

/* Mean radiance over pixel (x, y) of the whole image: spp jittered samples, each from its
 * own stream, summed in sample order. A non-finite sample (a bug upstream) is dropped and
 * counted, so no NaN or Inf can reach an image. */
static struct vec3 render_pixel(const struct scene *scene, const struct render_settings *rs,
                                struct radiance_estimator est, int x, int y,
                                struct render_counters *counters)
{
    struct vec3 sum = vec3_zero();
    uint64_t pixel = (uint64_t)y * (uint64_t)scene->width + (uint64_t)x;
    for (int s = 0; s < rs->spp; s++) {
        struct rng rng = rng_stream(rs->seed, STREAM_CAMERA, pixel, (uint64_t)s);
        double px = x + rng_uniform(&rng);
        double py = y + rng_uniform(&rng);
        struct vec3 l = est.radiance(est.mode, camera_ray(&scene->camera, px, py), &rng,
                                     counters);
        if (vec3_is_finite(l))
            sum = vec3_add(sum, l);
        else
            counters->nonfinite_samples++;
    }
    return vec3_scale(sum, 1.0 / rs->spp); /* spp >= 1 by the options' limits */
}

static void show_progress(int rows_done, int rows, clock_t start)
{
    double seconds = (double)(clock() - start) / CLOCKS_PER_SEC;
    double left = rows_done > 0 ? seconds * (rows - rows_done) / rows_done : 0.0;
    fprintf(stderr, "\rphoton: %d/%d rows (%3.0f%%), %.0f s, about %.0f s left   ", rows_done,
            rows, 100.0 * rows_done / rows, seconds, left);
    if (rows_done == rows)
        fputc('\n', stderr);
    fflush(stderr);
}

struct image *render_pixels(const struct scene *scene, const struct render_settings *rs,
                            struct radiance_estimator estimator,
                            struct render_counters *counters)
{
    struct image *img = image_create(rs->x1 - rs->x0, rs->y1 - rs->y0);
    clock_t start = clock();
    clock_t last_shown = start;
    for (int y = rs->y0; y < rs->y1; y++) {
        for (int x = rs->x0; x < rs->x1; x++)
            image_set(img, x - rs->x0, y - rs->y0,
                      render_pixel(scene, rs, estimator, x, y, counters));
        int last_row = y + 1 == rs->y1;
        if (rs->progress && (last_row || clock() - last_shown >= CLOCKS_PER_SEC / 2)) {
            show_progress(y + 1 - rs->y0, rs->y1 - rs->y0, start);
            last_shown = clock();
        }
    }
    return img;
}
