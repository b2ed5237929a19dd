/*
 * modes/render.c -- the shared pixel loop (render.h): sample passes, the running sums of
 * each pixel, the adaptive stopping rule, checkpoints and the progress line.
 *
 * Invariant: after pass p, pixel i has taken n[i] <= p samples, samples 0..n[i]-1, and
 * sum[3i + c] holds the sum of their channel c, added in sample order; sum2 (when kept)
 * the sum of their squares, and lum (when adaptive) their luminance's mean and summed
 * squared deviation. A pixel stops by the rule or at its target (spp, or specular_spp
 * where the camera sees a light through mirrors or glass in it), and once n[i] < p it
 * never samples again: pass p samples pixel i exactly when n[i] = p < target[i] and the
 * rule, read at n[i], does not stop it. Without the rule n[i] = min(p, target[i]).
 */
#include "render.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "../base/alloc.h"
#include "../base/progress.h"
#include "../base/sequence02.h"
#include "../image/error_image.h"
#include "pixel_error.h"
#include "surface.h"

#define SPECULAR_PROBES 16     /* a pixel's probe rays: 16 x 16, 1/16 of a pixel apart, finds
                                  a light's image 1/10 of a pixel wide                     */
#define SPECULAR_CHAIN_DEPTH 8 /* ideal specular surfaces a probe follows: a glass ball seen
                                  in a mirror ball is three                                */

struct accumulator {
    int x0, y0;              /* the window's top left pixel in the whole image           */
    int width, height;       /* of the window: rs's, grown for an error image's pool     */
    int out_x0, out_y0;      /* rs's window, the one written, within this one ...       */
    int out_width, out_height; /* ... and its size                                      */
    double *sum;             /* owned: 3 per pixel, row-major                            */
    double *sum2;            /* owned or NULL: squares, for the variance image           */
    double *batches;         /* owned or NULL: 3 ERROR_BATCHES per pixel, for the error
                                image (pixel_error.h)                                    */
    double *lum;             /* owned, or NULL when adaptive sampling is off: 2 per pixel,
                                the mean m of the samples' luminance y, and the sum of
                                their (y - m)^2                                          */
    int *n;                  /* owned: samples taken by each pixel, >= 1 after pass 1    */
    int *target;             /* owned: the samples each pixel takes at most              */
    int spp;                 /* the target of every pixel but the specular ones         */
    int most;                /* the largest target: the passes run at most               */
    size_t n_specular;       /* pixels whose target is above spp (render_settings)       */
    unsigned long long n_samples; /* sum of n[]                                          */
    unsigned long long n_target;  /* sum of target[]                                     */
    size_t n_active;         /* pixels the last pass sampled                             */
};

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
    uint64_t shift = rng_next(&pixel_shift), lens_shift = rng_next(&pixel_shift);
    double u, v, lens_u = 0, lens_v = 0;
    sequence02_point((uint32_t)s, (uint32_t)shift, (uint32_t)(shift >> 32), &u, &v);
    if (scene->camera.lens_radius > 0)
        sequence02_lens_point((uint32_t)s, (uint32_t)lens_shift, (uint32_t)(lens_shift >> 32),
                              &lens_u, &lens_v);
    *rng = rng_stream(seed, STREAM_CAMERA, pixel, (uint64_t)s);
    return camera_lens_ray(&scene->camera, x + u, y + v, lens_u, lens_v);
}

/* Point s of the (0,2)-sequence shuffled and shifted by the pixel stream's next two words
 * into u. */
static void shuffled_point(struct rng *pixel_stream, int s, double u[2])
{
    uint32_t order = (uint32_t)rng_next(pixel_stream);
    uint64_t shift = rng_next(pixel_stream);
    sequence02_point(sequence02_shuffled((uint32_t)s, order), (uint32_t)shift,
                     (uint32_t)(shift >> 32), &u[0], &u[1]);
}

struct first_bounce first_bounce_sample(const struct scene *scene, uint64_t seed, int x, int y,
                                        int s)
{
    uint64_t pixel = (uint64_t)y * (uint64_t)scene->width + (uint64_t)x;
    struct rng pixel_stream = rng_stream(seed, STREAM_PIXEL, pixel, 0);
    rng_next(&pixel_stream); /* camera_sample()'s two words */
    rng_next(&pixel_stream);
    struct first_bounce first;
    shuffled_point(&pixel_stream, s, first.direction);
    return first;
}

/* The adaptive rule of render.h for pixel i at its n = n[i] samples: whether it stops. It
 * is read only at powers of two n >= min_spp, so stopping keeps the camera points
 * stratified; it reads the pixel's own sums alone, so crops see the same decision. */
static int pixel_stops(const struct accumulator *acc, size_t i, const struct render_settings *rs)
{
    int n = acc->n[i];
    if (acc->lum == NULL || n < rs->min_spp || !is_power_of_two(n))
        return 0;
    double m = acc->lum[2 * i];
    double s2 = fmax(0.0, acc->lum[2 * i + 1]) / (n - 1.0); /* n >= min_spp >= 2 */
    return sqrt(s2 / n) <= rs->adaptive_error * fmax(m, ADAPTIVE_FLOOR);
}

/* Whether ray, followed through every lobe of each ideal mirror or glass surface (an
 * all-delta material) it meets, at most SPECULAR_CHAIN_DEPTH of them, reaches a light's
 * emitting side after bounces >= 1 of them. Its rays are counted. */
static int chain_reaches_light(const struct scene *scene, struct ray ray, int bounces,
                               struct render_counters *counters)
{
    struct surface s;
    double t;
    if (!ray_surface(scene, ray, counters, &s, &t))
        return 0;
    struct vec3 le = surface_emission(&s);
    if (bounces > 0 && (le.x > 0 || le.y > 0 || le.z > 0))
        return 1;
    if (bounces == SPECULAR_CHAIN_DEPTH || !brdf_is_delta(s.material))
        return 0;
    struct shading_frame frame = shading_frame_from_normal(s.ns, s.front, TRANSPORT_RADIANCE);
    struct brdf_sample lobes[2];
    int n_lobes = brdf_delta_lobes(s.material, &frame, s.wo, lobes);
    for (int k = 0; k < n_lobes; k++)
        if (chain_reaches_light(scene, surface_ray(&s, lobes[k].wi, lobes[k].transmitted),
                                bounces + 1, counters))
            return 1;
    return 0;
}

/* Whether the camera sees a light through mirrors or glass in pixel (x, y) of the whole
 * image (render.h): only where a ray through the pixel's centre or a corner meets such a
 * surface first, a SPECULAR_PROBES x SPECULAR_PROBES grid of rays through the pixel,
 * each followed by chain_reaches_light(), of which one must reach a light. Nothing random
 * and nothing of the pixel's own samples is read, and (x, y) alone decides, so a crop
 * takes the same counts as the whole image. */
static int pixel_sees_light_through_specular(const struct scene *scene, int x, int y,
                                             struct render_counters *counters)
{
    static const double at[5][2] = {{0.5, 0.5}, {0, 0}, {1, 0}, {0, 1}, {1, 1}};
    int specular = 0;
    for (int k = 0; k < 5 && !specular; k++) {
        struct surface s;
        double t;
        specular = ray_surface(scene, camera_ray(&scene->camera, x + at[k][0], y + at[k][1]),
                               counters, &s, &t) &&
                   brdf_is_delta(s.material);
    }
    for (int j = 0; j < SPECULAR_PROBES && specular; j++)
        for (int i = 0; i < SPECULAR_PROBES; i++) {
            double px = x + (i + 0.5) / SPECULAR_PROBES, py = y + (j + 0.5) / SPECULAR_PROBES;
            if (chain_reaches_light(scene, camera_ray(&scene->camera, px, py), 0, counters))
                return 1;
        }
    return 0;
}

/* Each pixel's target: rs->specular_spp where that is more than rs->spp and the camera
 * sees a light through mirrors or glass in the pixel, else rs->spp; and their sum and
 * largest. Nothing is probed when specular_spp is not more. */
static void set_targets(const struct scene *scene, const struct render_settings *rs,
                        struct accumulator *acc, struct render_counters *counters)
{
    acc->spp = rs->spp;
    acc->most = rs->spp;
    acc->n_specular = 0;
    acc->n_target = 0;
    for (int y = acc->y0; y < acc->y0 + acc->height; y++)
        for (int x = acc->x0; x < acc->x0 + acc->width; x++) {
            size_t i = (size_t)(y - acc->y0) * (size_t)acc->width + (size_t)(x - acc->x0);
            acc->target[i] = rs->spp;
            if (rs->specular_spp > rs->spp &&
                pixel_sees_light_through_specular(scene, x, y, counters)) {
                acc->target[i] = rs->specular_spp;
                acc->most = rs->specular_spp;
                acc->n_specular++;
            }
            acc->n_target += (unsigned long long)acc->target[i];
        }
}

/* Adds radiance l as pixel i's next sample. */
static void add_sample(struct accumulator *acc, size_t i, struct vec3 l)
{
    double v[3] = {l.x, l.y, l.z};
    for (int c = 0; c < 3; c++) {
        acc->sum[3 * i + c] += v[c];
        if (acc->sum2 != NULL)
            acc->sum2[3 * i + c] += v[c] * v[c];
    }
    if (acc->batches != NULL)
        error_batches_add(acc->batches + (size_t)3 * ERROR_BATCHES * i, ERROR_BATCHES,
                          acc->n[i], v, 3);
    if (acc->lum != NULL) {
        /* Welford's update of the luminance's mean m and M2 = sum of (y - m)^2: it does not
         * cancel as sum y^2 - n m^2 would, and leaves M2 exactly 0 while all y are equal. */
        double y = vec3_luminance(l);
        double d = y - acc->lum[2 * i];
        acc->lum[2 * i] += d / (acc->n[i] + 1.0);
        acc->lum[2 * i + 1] += d * (y - acc->lum[2 * i]);
    }
    acc->n[i]++;
    acc->n_samples++;
    acc->n_active++;
}

/* Adds sample s to every pixel in the window that is still sampling. A non-finite sample
 * (a bug upstream) counts as zero and is reported, so no NaN or Inf can reach an image. */
static void render_pass(const struct scene *scene, const struct render_settings *rs,
                        struct radiance_estimator est, int s, struct accumulator *acc,
                        struct render_counters *counters)
{
    acc->n_active = 0;
    for (int y = acc->y0; y < acc->y0 + acc->height; y++)
        for (int x = acc->x0; x < acc->x0 + acc->width; x++) {
            size_t i = (size_t)(y - acc->y0) * (size_t)acc->width + (size_t)(x - acc->x0);
            /* n[i] < s: stopped earlier (the rule, reading the same sums, would say so
             * again; this test is cheaper), or its target is reached, or the rule stops
             * it now. */
            if (acc->n[i] != s || s == acc->target[i] || pixel_stops(acc, i, rs))
                continue;
            struct rng rng;
            struct ray ray = camera_sample(scene, rs->seed, x, y, s, &rng);
            struct first_bounce first = first_bounce_sample(scene, rs->seed, x, y, s);
            struct vec3 l = est.radiance(est.mode, ray, &first, &rng, counters);
            int counted = vec3_is_finite(l);
            if (!counted) {
                counters->nonfinite_samples++;
                l = vec3_zero();
            }
            add_sample(acc, i, l);
            if (est.sample_taken != NULL)
                est.sample_taken(est.mode, i, l, counted);
        }
}

/* The index in acc of pixel k of the window written (rs's), row-major. */
static size_t written_pixel(const struct accumulator *acc, size_t k)
{
    size_t x = k % (size_t)acc->out_width, y = k / (size_t)acc->out_width;
    return (y + (size_t)acc->out_y0) * (size_t)acc->width + x + (size_t)acc->out_x0;
}

/* Each written pixel's mean over its own n[i] samples; n[i] >= 1 once a pass has run,
 * because no pixel stops before min_spp >= 2 samples. */
static void mean_image(const struct accumulator *acc, struct image *mean)
{
    for (size_t k = 0; k < (size_t)acc->out_width * (size_t)acc->out_height; k++) {
        size_t i = written_pixel(acc, k);
        int n = acc->n[i];
        mean->pixels[k] = vec3(acc->sum[3 * i] / n, acc->sum[3 * i + 1] / n,
                               acc->sum[3 * i + 2] / n);
    }
}

/* The variance of each written pixel's mean of its n = n[i] samples: s^2 / n,
 * s^2 = (sum2 - n mean^2) / (n - 1); 0 where n < 2. */
static struct image *variance_image(const struct accumulator *acc)
{
    struct image *var = image_create(acc->out_width, acc->out_height);
    for (size_t k = 0; k < (size_t)acc->out_width * (size_t)acc->out_height; k++) {
        size_t i = written_pixel(acc, k);
        int n = acc->n[i];
        if (n < 2)
            continue;
        double v[3];
        for (int c = 0; c < 3; c++) {
            double mean = acc->sum[3 * i + c] / n;
            double s2 = (acc->sum2[3 * i + c] - n * mean * mean) / (n - 1.0);
            v[c] = fmax(0.0, s2) / n; /* rounding can make s2 slightly negative */
        }
        var->pixels[k] = vec3(v[0], v[1], v[2]);
    }
    return var;
}

/* The error image of the written window (pixel_error.h), from all of acc's pixels. */
static struct image *error_image(const struct accumulator *acc, double confidence)
{
    struct pixel_sums sums = {acc->width, acc->height, acc->sum, acc->batches, acc->n};
    return pooled_error_image(&sums, acc->out_x0, acc->out_y0, acc->out_x0 + acc->out_width,
                              acc->out_y0 + acc->out_height, confidence);
}

/* The checkpoint's work (render.h): samples per pixel of the window, rounded to nearest. */
static long long samples_per_pixel(const struct accumulator *acc)
{
    unsigned long long pixels = (unsigned long long)acc->width * (unsigned long long)acc->height;
    return (long long)((2 * acc->n_samples + pixels) / (2 * pixels));
}

int target_judged_after(long p)
{
    if (p < ERROR_MIN_SPP)
        return 0;
    long step = 1;
    while (step * 16 <= p)
        step *= 2;
    return p % step == 0;
}

int target_tally(const struct image *mean, const struct stated_error *stated,
                 const struct render_settings *rs, struct render_counters *counters)
{
    struct block_count count = blocks_within(mean, stated, rs->x0, rs->y0, rs->target_error);
    counters->target_blocks = count.n_blocks;
    counters->target_within = count.within;
    counters->target_missed_x = count.missed_x;
    counters->target_missed_y = count.missed_y;
    return count.within == count.n_blocks;
}

/* Judges the window's blocks against rs->target_error, the tally into counters; whether
 * every block is within it. */
static int target_reached(const struct accumulator *acc, const struct render_settings *rs,
                          struct render_counters *counters)
{
    struct image *mean = image_create(acc->out_width, acc->out_height);
    mean_image(acc, mean);
    struct image *error = error_image(acc, rs->error_confidence);
    struct stated_error stated = {error, NULL, NULL, NULL};
    int reached = target_tally(mean, &stated, rs, counters);
    image_free(error);
    image_free(mean);
    return reached;
}

/* The progress line's words (base/progress.h adds the time, and the time left where the
 * samples to take are known). Without adaptive sampling: passes, at the rate so far per
 * sample; the pixels that see a light through mirrors or glass, when there are any, are
 * named with their own count, so that theirs is not taken for every pixel's. With it:
 * passes, and how many pixels the last pass sampled, since the time left cannot be
 * foreseen. With a target error: passes, and the blocks within it at the last judgement
 * (none before ERROR_MIN_SPP). */
static void show_progress(const struct accumulator *acc, const struct render_settings *rs,
                          const struct render_counters *counters, int passes,
                          struct progress *line)
{
    if (rs->target_error > 0)
        progress_print(line, "%d samples per pixel, %d of %d blocks within %g", passes,
                       counters->target_within, counters->target_blocks, rs->target_error);
    else if (acc->lum == NULL && acc->n_specular == 0)
        progress_print(line, "%d/%d samples per pixel", passes, acc->most);
    else if (acc->lum == NULL)
        progress_print(line, "pass %d of %d: %d samples per pixel, %d in the %zu specular "
                       "pixels", passes, acc->most, acc->spp, acc->most, acc->n_specular);
    else
        progress_print(line, "pass %d of at most %d, %zu of %zu pixels sampling", passes,
                       acc->most, acc->n_active, (size_t)acc->width * (size_t)acc->height);
}

/* Takes sample passes until every pixel has reached its target or stopped, the time limit
 * has passed or the target error is reached, calling the checkpoint after passes 1, 2, 4,
 * ... and after the last.
 * Returns the passes that sampled a pixel and the rendering seconds since start
 * (checkpoint work excluded) in *seconds. */
static int run_passes(const struct scene *scene, const struct render_settings *rs,
                      struct radiance_estimator est, struct accumulator *acc, clock_t start,
                      const struct checkpoint *checkpoint, struct render_counters *counters,
                      double *seconds)
{
    double excluded = 0.0;
    int passes = 0, checked = 0, judged = 0, reached = 0;
    struct progress line; /* the forecast's work: samples, whose count is known without
                             adaptive sampling or a target error */
    int known = acc->lum == NULL && rs->target_error <= 0;
    progress_begin(&line, rs->progress ? stderr : NULL, "sample passes",
                   known ? (double)acc->n_target : 0.0, time(NULL));
    struct image *mean = checkpoint != NULL ? image_create(acc->out_width, acc->out_height)
                                            : NULL;
    /* an error image needs ERROR_MIN_SPP samples of every pixel, time limit or not */
    int first_passes = rs->error_confidence > 0 ? ERROR_MIN_SPP : 1;
    while (passes < acc->most &&
           !(passes >= first_passes && rs->time_limit > 0 &&
             cpu_seconds(start) - excluded >= rs->time_limit)) {
        render_pass(scene, rs, est, passes, acc, counters);
        if (acc->n_active == 0)
            break; /* the adaptive rule has stopped every pixel still below its target */
        passes++;
        if (rs->target_error > 0 && target_judged_after(passes)) {
            reached = target_reached(acc, rs, counters);
            judged = passes;
        }
        *seconds = cpu_seconds(start) - excluded;
        int last = passes == acc->most || reached ||
                   (passes >= first_passes && rs->time_limit > 0 && *seconds >= rs->time_limit);
        if (progress_update(&line, (double)acc->n_samples, time(NULL)))
            show_progress(acc, rs, counters, passes, &line);
        if (mean != NULL && (is_power_of_two(passes) || last)) {
            mean_image(acc, mean);
            excluded += checkpoint->at(checkpoint->context, mean, samples_per_pixel(acc),
                                       *seconds);
            checked = passes;
        }
        if (reached)
            break;
    }
    if (rs->target_error > 0 && judged != passes)
        target_reached(acc, rs, counters); /* the tally of the image as it ends */
    if (progress_end(&line, (double)acc->n_samples, time(NULL)))
        show_progress(acc, rs, counters, passes, &line);
    if (mean != NULL && checked != passes) {
        mean_image(acc, mean);
        checkpoint->at(checkpoint->context, mean, samples_per_pixel(acc), *seconds);
    }
    image_free(mean);
    return passes;
}

struct render_result render_pixels(const struct scene *scene, const struct render_settings *rs,
                                   struct radiance_estimator estimator, int want_variance,
                                   const struct checkpoint *checkpoint,
                                   struct render_counters *counters)
{
    int adaptive = rs->adaptive_error > 0;
    assert(!adaptive || (isfinite(rs->adaptive_error) && rs->min_spp >= 2 &&
                         is_power_of_two(rs->min_spp)));
    int want_error = rs->error_confidence > 0;
    assert(!want_error || (rs->error_confidence < 1 && rs->spp >= ERROR_MIN_SPP && !adaptive));
    assert(rs->target_error == 0 || want_error);
    struct accumulator acc;
    int margin = want_error ? ERROR_POOL_RADIUS : 0; /* the pool's pixels beyond rs's window */
    acc.x0 = rs->x0 > margin ? rs->x0 - margin : 0;
    acc.y0 = rs->y0 > margin ? rs->y0 - margin : 0;
    acc.width = (rs->x1 + margin < scene->width ? rs->x1 + margin : scene->width) - acc.x0;
    acc.height = (rs->y1 + margin < scene->height ? rs->y1 + margin : scene->height) - acc.y0;
    acc.out_x0 = rs->x0 - acc.x0;
    acc.out_y0 = rs->y0 - acc.y0;
    acc.out_width = rs->x1 - rs->x0;
    acc.out_height = rs->y1 - rs->y0;
    size_t n = (size_t)acc.width * (size_t)acc.height;
    acc.sum = xcalloc(3 * n, sizeof *acc.sum, "pixel sums");
    acc.sum2 = want_variance ? xcalloc(3 * n, sizeof *acc.sum2, "pixel squares") : NULL;
    acc.batches = want_error ? xcalloc(3 * ERROR_BATCHES * n, sizeof *acc.batches,
                                       "pixel batches")
                             : NULL;
    acc.lum = adaptive ? xcalloc(2 * n, sizeof *acc.lum, "pixel luminance sums") : NULL;
    acc.n = xcalloc(n, sizeof *acc.n, "pixel sample counts");
    acc.target = xcalloc(n, sizeof *acc.target, "pixel sample targets");
    clock_t start = clock(); /* the probes of set_targets() are rendering time too */
    set_targets(scene, rs, &acc, counters);
    acc.n_samples = 0;
    acc.n_active = 0;
    struct render_result result;
    result.seconds = 0.0;
    counters->passes = run_passes(scene, rs, estimator, &acc, start, checkpoint, counters,
                                  &result.seconds);
    for (size_t k = 0; k < (size_t)acc.out_width * (size_t)acc.out_height; k++)
        counters->samples += (unsigned long long)acc.n[written_pixel(&acc, k)]; /* the
            window's, as render_counters says: the error image's margin is not its work */
    counters->specular_pixels = acc.n_specular;
    result.image = image_create(acc.out_width, acc.out_height);
    mean_image(&acc, result.image);
    result.variance = want_variance ? variance_image(&acc) : NULL;
    result.error = want_error ? error_image(&acc, rs->error_confidence) : NULL;
    result.bias = NULL; /* the mean of independent samples is unbiased */
    result.block_noise = NULL;
    result.block_bias = NULL;
    xfree(acc.target);
    xfree(acc.n);
    xfree(acc.lum);
    xfree(acc.batches);
    xfree(acc.sum2);
    xfree(acc.sum);
    return result;
}

void render_result_free(struct render_result *result)
{
    image_free(result->image);
    image_free(result->variance);
    image_free(result->error);
    image_free(result->bias);
    image_free(result->block_noise);
    image_free(result->block_bias);
    result->image = NULL;
    result->variance = NULL;
    result->error = NULL;
    result->bias = NULL;
    result->block_noise = NULL;
    result->block_bias = NULL;
}
