/*
 * modes/render.c -- the shared pixel loop (render.h): sample passes, the running sums of
 * each pixel, checkpoints and the progress line.
 *
 * Invariant: after pass p, sum[3i + c] holds the sum over samples 0..p-1 of pixel i's
 * channel c, added in sample order, and sum2 (when kept) the sum of their squares.
 */
#include "render.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../base/alloc.h"
#include "../base/sequence02.h"

struct accumulator {
    int width, height; /* of the window                         */
    double *sum;       /* owned: 3 per pixel, row-major          */
    double *sum2;      /* owned or NULL: squares, for variance   */
};

static double cpu_seconds(clock_t start)
{
    return (double)(clock() - start) / CLOCKS_PER_SEC;
}

struct render_settings render_settings_whole(const struct scene *scene, uint64_t seed, int spp,
                                             int max_depth)
{
    struct render_settings rs;
    memset(&rs, 0, sizeof rs);
    rs.seed = seed;
    rs.spp = spp;
    rs.max_depth = max_depth;
    rs.x1 = scene->width;
    rs.y1 = scene->height;
    return rs;
}

struct ray camera_sample(const struct scene *scene, uint64_t seed, int x, int y, int s,
                         struct rng *rng)
{
    uint64_t pixel = (uint64_t)y * (uint64_t)scene->width + (uint64_t)x;
    struct rng pixel_shift = rng_stream(seed, STREAM_PIXEL, pixel, 0);
    uint64_t shift = rng_next(&pixel_shift);
    double u, v;
    sequence02_point((uint32_t)s, (uint32_t)shift, (uint32_t)(shift >> 32), &u, &v);
    *rng = rng_stream(seed, STREAM_CAMERA, pixel, (uint64_t)s);
    return camera_ray(&scene->camera, x + u, y + v);
}

/* Adds sample s of every pixel in the window. A non-finite sample (a bug upstream) counts
 * as zero and is reported, so no NaN or Inf can reach an image. */
static void render_pass(const struct scene *scene, const struct render_settings *rs,
                        struct radiance_estimator est, int s, struct accumulator *acc,
                        struct render_counters *counters)
{
    for (int y = rs->y0; y < rs->y1; y++)
        for (int x = rs->x0; x < rs->x1; x++) {
            struct rng rng;
            struct ray ray = camera_sample(scene, rs->seed, x, y, s, &rng);
            struct vec3 l = est.radiance(est.mode, ray, &rng, counters);
            if (!vec3_is_finite(l)) {
                counters->nonfinite_samples++;
                l = vec3_zero();
            }
            size_t i = 3 * ((size_t)(y - rs->y0) * (size_t)acc->width + (size_t)(x - rs->x0));
            double v[3] = {l.x, l.y, l.z};
            for (int c = 0; c < 3; c++) {
                acc->sum[i + c] += v[c];
                if (acc->sum2 != NULL)
                    acc->sum2[i + c] += v[c] * v[c];
            }
        }
}

/* The mean of n >= 1 samples per pixel. */
static void mean_image(const struct accumulator *acc, int n, struct image *mean)
{
    for (size_t i = 0; i < (size_t)acc->width * (size_t)acc->height; i++)
        mean->pixels[i] = vec3(acc->sum[3 * i] / n, acc->sum[3 * i + 1] / n,
                               acc->sum[3 * i + 2] / n);
}

/* The variance of the mean of n samples: s^2 / n, s^2 = (sum2 - n mean^2) / (n - 1). */
static struct image *variance_image(const struct accumulator *acc, int n)
{
    struct image *var = image_create(acc->width, acc->height);
    if (n < 2)
        return var;
    for (size_t i = 0; i < (size_t)acc->width * (size_t)acc->height; i++) {
        double v[3];
        for (int c = 0; c < 3; c++) {
            double mean = acc->sum[3 * i + c] / n;
            double s2 = (acc->sum2[3 * i + c] - n * mean * mean) / (n - 1.0);
            v[c] = fmax(0.0, s2) / n; /* rounding can make s2 slightly negative */
        }
        var->pixels[i] = vec3(v[0], v[1], v[2]);
    }
    return var;
}

static void show_progress(int passes, int spp, double seconds, int done)
{
    double left = passes > 0 ? seconds * (spp - passes) / passes : 0.0;
    fprintf(stderr, "\rphoton: %d/%d samples per pixel, %.1f s, about %.0f s left   ", passes,
            spp, seconds, left);
    if (done)
        fputc('\n', stderr);
    fflush(stderr);
}

static int is_power_of_two(int n)
{
    return n > 0 && (n & (n - 1)) == 0;
}

/* Takes sample passes until spp are done or the time limit has passed, calling the
 * checkpoint after passes 1, 2, 4, ... and after the last. Returns the passes done and
 * the rendering seconds (checkpoint work excluded) in *seconds. */
static int run_passes(const struct scene *scene, const struct render_settings *rs,
                      struct radiance_estimator est, struct accumulator *acc,
                      const struct checkpoint *checkpoint, struct render_counters *counters,
                      double *seconds)
{
    clock_t start = clock();
    double excluded = 0.0, last_shown = 0.0;
    int passes = 0, checked = 0;
    struct image *mean = checkpoint != NULL ? image_create(acc->width, acc->height) : NULL;
    while (passes < rs->spp &&
           !(passes > 0 && rs->time_limit > 0 && cpu_seconds(start) - excluded >= rs->time_limit)) {
        render_pass(scene, rs, est, passes, acc, counters);
        passes++;
        *seconds = cpu_seconds(start) - excluded;
        if (rs->progress && (passes == rs->spp || *seconds - last_shown >= 0.5)) {
            show_progress(passes, rs->spp, *seconds, passes == rs->spp);
            last_shown = *seconds;
        }
        int last = passes == rs->spp ||
                   (rs->time_limit > 0 && *seconds >= rs->time_limit);
        if (mean != NULL && (is_power_of_two(passes) || last)) {
            mean_image(acc, passes, mean);
            excluded += checkpoint->at(checkpoint->context, mean, passes, *seconds);
            checked = passes;
        }
    }
    if (mean != NULL && checked != passes) {
        mean_image(acc, passes, mean);
        checkpoint->at(checkpoint->context, mean, passes, *seconds);
    }
    image_free(mean);
    return passes;
}

struct render_result render_pixels(const struct scene *scene, const struct render_settings *rs,
                                   struct radiance_estimator estimator, int want_variance,
                                   const struct checkpoint *checkpoint,
                                   struct render_counters *counters)
{
    struct accumulator acc;
    acc.width = rs->x1 - rs->x0;
    acc.height = rs->y1 - rs->y0;
    size_t n = 3 * (size_t)acc.width * (size_t)acc.height;
    acc.sum = xcalloc(n, sizeof *acc.sum, "pixel sums");
    acc.sum2 = want_variance ? xcalloc(n, sizeof *acc.sum2, "pixel squares") : NULL;
    struct render_result result;
    result.seconds = 0.0;
    counters->passes = run_passes(scene, rs, estimator, &acc, checkpoint, counters,
                                  &result.seconds);
    result.image = image_create(acc.width, acc.height);
    mean_image(&acc, counters->passes, result.image);
    result.variance = want_variance ? variance_image(&acc, counters->passes) : NULL;
    free(acc.sum2);
    free(acc.sum);
    return result;
}

void render_result_free(struct render_result *result)
{
    image_free(result->image);
    image_free(result->variance);
    result->image = NULL;
    result->variance = NULL;
}
