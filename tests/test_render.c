/*
 * tests/test_render.c -- rendering with --mode direct: closed forms, crops, determinism,
 * and robustness to the scale of the scene; and the shared pixel loop's adaptive sampling
 * (render.h), driven by a synthetic mode whose samples are known.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../src/image/compare.h"
#include "../src/modes/direct.h"
#include "files.h"
#include "tests.h"
#include "truths.h"

static struct image *render(const struct scene *scene, const struct render_settings *rs)
{
    struct render_counters counters = {0};
    return render_direct(scene, rs, 0, NULL, &counters).image;
}

/* truth: the closed form L(x) = rho Phi h / (4 pi^2 d^3) for a point light over a plane.
 *   A pixel is the mean of L over its square, so it must lie between the least and the
 *   greatest L on that square (taken on a 9 x 9 grid that includes the corners; L is
 *   smooth and varies monotonically across a pixel this size, so the grid finds them).
 * tolerance: that interval, widened by 1e-12 relative for rounding.
 * catches: a missing cos, 1/(4 pi) or 1/pi; the inverse-square law wrong; the light's
 *   power read as intensity; a shadow ray blocked by the plane itself (acne). */
static void test_point_light_over_plane(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/analytic/point-over-plane.scene", 0, 0);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    struct render_settings rs = render_settings_whole(scene, 1, 4, 16);
    struct image *img = render(scene, &rs);
    CHECK(t, within_point_over_plane(scene, img));
    image_free(img);
    scene_free(scene);
}

/* truth: the light quad emits its radiance (17, 12, 4) and reflects nothing, so a pixel
 *   wholly inside its image is exactly that (pixel (128, 36) is: the light spans rows
 *   32-40 and columns 107-149 at 256 x 256).
 * tolerance: none: every sample returns Le exactly.
 * catches: the light reflecting light, emission from its back, emission lost. */
static void test_light_seen_directly(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/cornell.scene", 0, 0);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    struct render_settings rs = render_settings_whole(scene, 1, 4, 16);
    rs.x0 = 128;
    rs.y0 = 36;
    rs.x1 = 129;
    rs.y1 = 37;
    struct image *img = render(scene, &rs);
    struct vec3 v = image_get(img, 0, 0);
    CHECK(t, v.x == 17 && v.y == 12 && v.z == 4);
    image_free(img);
    scene_free(scene);
}

/* truth: render.h's promise: a crop is the same window of the whole image, bit for bit,
 *   and two renders with the same seed are identical.
 * catches: random streams keyed by the crop's own pixel numbers, state carried between
 *   pixels (a shared rng), uninitialised pixels. */
static void test_crop_matches_whole_image(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/cornell.scene", 40, 30);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    struct render_settings rs = render_settings_whole(scene, 1, 2, 16);
    struct image *whole = render(scene, &rs);
    struct image *again = render(scene, &rs);
    CHECK(t, memcmp(whole->pixels, again->pixels, 40 * 30 * sizeof *whole->pixels) == 0);
    rs.x0 = 7;
    rs.y0 = 3;
    rs.x1 = 31;
    rs.y1 = 29;
    struct image *crop = render(scene, &rs);
    for (int y = 0; y < crop->height; y++)
        for (int x = 0; x < crop->width; x++) {
            struct vec3 a = image_get(crop, x, y), b = image_get(whole, x + 7, y + 3);
            CHECK(t, a.x == b.x && a.y == b.y && a.z == b.z);
        }
    image_free(crop);
    image_free(again);
    image_free(whole);
    scene_free(scene);
}

/* truth: radiance is invariant under scaling the whole scene (solid angles and the light's
 *   radiance do not change), and the random numbers are the same, so the Cornell box in
 *   metres (x 1e-3) and in micrometres (x 1e3) must give the millimetre image.
 * tolerance: relmse 1e-6 against the unscaled image. Rounding differs between the scales
 *   (1e-3 is not a binary fraction), which can move a sample that grazes an edge; acne
 *   (surfaces shadowing themselves) or light leaking past the walls changes thousands
 *   of samples and gives a relmse above 1e-3.
 * catches: a fixed ray-offset epsilon (acne at 1e3, leaks at 1e-3), a fixed t_min, a
 *   shadow-ray end pulled in by an absolute amount. */
static void test_scale_invariance(struct check *t)
{
    static const char *scaled[] = {"scenes/cornell-1e-3.scene", "scenes/cornell-1e3.scene"};
    struct scene *scene = load_test_scene("scenes/cornell.scene", 64, 64);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    struct render_settings rs = render_settings_whole(scene, 1, 4, 16);
    struct image *reference = render(scene, &rs);
    scene_free(scene);
    for (int i = 0; i < 2; i++) {
        scene = load_test_scene(scaled[i], 64, 64);
        CHECK(t, scene != NULL);
        if (scene == NULL)
            break;
        struct image *img = render(scene, &rs);
        CHECK(t, image_compare(img, reference).relmse <= 1e-6);
        image_free(img);
        scene_free(scene);
    }
    image_free(reference);
}

/* truth: a procedural shape and its expansion into plain primitives (the `expand` word)
 *   are the same surfaces computed by the same sphere and triangle routines, so the whole
 *   pipeline -- parser, BVH, shading, lights -- must give the same image, bit for bit.
 * catches: a keyword that reads its parameters differently in the two forms, a shape that
 *   reports another normal or material than its primitives, a shadow test that treats
 *   shapes differently. */
static void test_shapes_render_as_their_expansions(struct check *t)
{
    static const char *objects[] = {
        "sphereflake 0 0 0 0.5 2  0 0 1  m n", "heightfield -1 -0.6 -1 2 17 4 0.5 2 0.3 3 m"};
    const char *path = "build/test_render_shape.scene";
    for (int i = 0; i < 2; i++) {
        struct image *img[2] = {NULL, NULL};
        for (int expand = 0; expand < 2; expand++) {
            char text[1024];
            sprintf(text, "camera 0.3 1.2 -2.5  0 0 0  0 1 0  40\n"
                          "material m lambert 0.8 0.5 0.3\nmaterial n mirror 0.9 0.9 0.9\n"
                          "%s%s\nlight point 1 3 -2  100 100 100\n"
                          "light quad -1 2 -1  1 2 -1  1 2 1  -1 2 1  3 3 3\n",
                    objects[i], expand ? " expand" : "");
            write_text_file(path, text);
            struct scene *scene = load_test_scene(path, 40, 40);
            CHECK(t, scene != NULL);
            if (scene == NULL)
                break;
            struct render_settings rs = render_settings_whole(scene, 1, 2, 16);
            img[expand] = render(scene, &rs);
            scene_free(scene);
        }
        CHECK(t, img[0] != NULL && img[1] != NULL &&
                     memcmp(img[0]->pixels, img[1]->pixels, 40 * 40 * sizeof *img[0]->pixels)
                         == 0);
        int lit = 0; /* the shape must be in the picture, lit, for the test to mean anything */
        for (int k = 0; img[0] != NULL && k < 40 * 40; k++)
            lit += img[0]->pixels[k].x > 0.01;
        CHECK(t, lit > 200);
        image_free(img[0]);
        image_free(img[1]);
    }
    remove(path);
}

/* A synthetic mode for the pixel loop: grey radiance c + a w u, u uniform in [0, 1) from
 * the sample's own stream, and w = 1, or |dir.x| of the camera ray (unit) when by_direction
 * is set, so that the noise varies across the image and pixels stop at different counts.
 * With w = 1 a pixel's samples have mean c + a/2 and variance a^2/12. */
struct synthetic {
    double c, a;
    int by_direction;
};

static struct vec3 synthetic_radiance(const void *mode, struct ray ray,
                                      const struct first_bounce *first, struct rng *rng,
                                      struct render_counters *counters)
{
    const struct synthetic *g = mode;
    (void)first;
    (void)counters;
    double w = g->by_direction ? fabs(ray.dir.x) : 1.0;
    double v = g->c + g->a * w * rng_uniform(rng);
    return vec3(v, v, v);
}

/* What the adaptive tests render: the Cornell box's camera and size (nothing else of the
 * scene is looked at), settings, and the synthetic mode. */
struct fixture {
    struct scene *scene; /* owned */
    struct render_settings rs;
    struct synthetic mode;
};

/* Loads the fixture at width x height with render_settings_whole's defaults (seed 7,
 * 64 spp, adaptive sampling off); 0 (after a failed CHECK) when the scene cannot be read. */
static int fixture_open(struct check *t, struct fixture *f, int width, int height,
                        struct synthetic mode)
{
    f->scene = load_test_scene("scenes/cornell.scene", width, height);
    CHECK(t, f->scene != NULL);
    if (f->scene == NULL)
        return 0;
    f->rs = render_settings_whole(f->scene, 7, 64, 1);
    f->mode = mode;
    return 1;
}

/* Renders f's window with its synthetic mode, the variance image included. */
static struct render_result render_synthetic(const struct fixture *f,
                                             const struct checkpoint *checkpoint,
                                             struct render_counters *counters)
{
    struct radiance_estimator estimator = {synthetic_radiance, &f->mode, NULL};
    return render_pixels(f->scene, &f->rs, estimator, 1, checkpoint, counters);
}

/* A pixel's mean, the variance of that mean, and its number of samples. */
struct pixel_value {
    struct vec3 mean, variance;
    int n;
};

static int same_vec3(struct vec3 a, struct vec3 b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

/* Pixel (x, y) rendered alone, as a 1 x 1 window, so that counters.samples is its count. */
static struct pixel_value render_one_pixel(const struct fixture *f, int x, int y)
{
    struct fixture one = *f;
    one.rs.x0 = x;
    one.rs.y0 = y;
    one.rs.x1 = x + 1;
    one.rs.y1 = y + 1;
    struct render_counters counters = {0};
    struct render_result r = render_synthetic(&one, NULL, &counters);
    struct pixel_value p = {image_get(r.image, 0, 0), image_get(r.variance, 0, 0),
                            (int)counters.samples};
    render_result_free(&r);
    return p;
}

/* Sample s of pixel (x, y) as render.h defines it: the mode's radiance along
 * camera_sample(s), with the stream camera_sample hands over. */
static struct vec3 own_sample(const struct fixture *f, int x, int y, int s)
{
    struct rng rng;
    struct ray ray = camera_sample(f->scene, f->rs.seed, x, y, s, &rng);
    return synthetic_radiance(&f->mode, ray, NULL, &rng, NULL);
}

/* Pixel (x, y)'s samples 0..n-1, each channel summed in sample order: their mean, and the
 * variance of the mean by render.h's formula (0 when n < 2). */
static struct pixel_value own_samples(const struct fixture *f, int x, int y, int n)
{
    double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0}, mean[3], var[3];
    for (int s = 0; s < n; s++) {
        struct vec3 l = own_sample(f, x, y, s);
        double v[3] = {l.x, l.y, l.z};
        for (int c = 0; c < 3; c++) {
            sum[c] += v[c];
            sum2[c] += v[c] * v[c];
        }
    }
    for (int c = 0; c < 3; c++) {
        mean[c] = sum[c] / n;
        var[c] = n < 2 ? 0.0 : fmax(0.0, (sum2[c] - n * mean[c] * mean[c]) / (n - 1.0)) / n;
    }
    struct pixel_value p = {vec3(mean[0], mean[1], mean[2]), vec3(var[0], var[1], var[2]), n};
    return p;
}

#define MAX_TEST_SPP 256 /* the most samples an adaptive test gives a pixel */

/* The count render.h's rule gives pixel (x, y), found apart from render.c: at each check
 * point n the luminance's mean and variance in two passes over samples 0..n-1, not by
 * Welford's update. *margin gets the least |se / bound - 1| over the check points read. */
static int predicted_count(const struct fixture *f, int x, int y, double *margin)
{
    const struct render_settings *rs = &f->rs;
    double lum[MAX_TEST_SPP];
    for (int s = 0; s < rs->spp && s < MAX_TEST_SPP; s++)
        lum[s] = vec3_luminance(own_sample(f, x, y, s));
    *margin = HUGE_VAL;
    for (int n = rs->min_spp; n < rs->spp && n <= MAX_TEST_SPP; n *= 2) {
        double m = 0.0, d2 = 0.0;
        for (int s = 0; s < n; s++)
            m += lum[s];
        m /= n;
        for (int s = 0; s < n; s++)
            d2 += (lum[s] - m) * (lum[s] - m);
        double se = sqrt(d2 / (n - 1.0) / n); /* n >= min_spp >= 2 */
        double bound = rs->adaptive_error * fmax(m, ADAPTIVE_FLOOR);
        *margin = fmin(*margin, fabs(se / bound - 1.0));
        if (se <= bound)
            return n;
    }
    return rs->spp;
}

/* truth: render.h without adaptive sampling, which must be what it was before: pixel i's
 *   value is the mean of its samples 0..spp-1, summed in sample order, and its variance
 *   the formula render.h states, both recomputed here from the mode's own samples;
 *   render_settings_whole leaves it off, and min_spp means nothing while it is off, not
 *   even to a constant pixel, which the rule would stop at once.
 * tolerance: none: the same doubles added in the same order.
 * catches: adaptive sampling on by default, a pixel skipped or stopped, a count left at 0
 *   or off by one, a sample other than camera_sample(s)'s, min_spp read while off. */
static void test_adaptive_off_takes_every_sample(struct check *t)
{
    struct synthetic mode = {0.2, 1.0, 1};
    struct fixture f;
    if (!fixture_open(t, &f, 12, 9, mode))
        return;
    CHECK(t, f.rs.adaptive_error == 0);
    f.rs.spp = 6;
    for (int k = 0; k < 4; k++) {
        f.rs.min_spp = k % 2 == 0 ? 0 : 4;
        f.mode.a = k < 2 ? 1.0 : 0.0;
        struct render_counters counters = {0};
        struct render_result r = render_synthetic(&f, NULL, &counters);
        CHECK(t, counters.passes == 6 && counters.samples == 6 * 12 * 9);
        for (int y = 0; y < 9; y++)
            for (int x = 0; x < 12; x++) {
                struct pixel_value p = own_samples(&f, x, y, 6);
                CHECK(t, same_vec3(image_get(r.image, x, y), p.mean));
                CHECK(t, same_vec3(image_get(r.variance, x, y), p.variance));
            }
        render_result_free(&r);
    }
    scene_free(f.scene);
}

/* truth: a pixel whose samples are all equal has s^2 = 0, so render.h's rule stops it at
 *   its first check point, min_spp (or spp if less), however small adaptive_error is
 *   (1e-300 here), black, darker than ADAPTIVE_FLOOR or bright (17, a light's radiance).
 * tolerance: none: counts.
 * catches: a variance that rounding leaves above 0 (sum y^2 - n m^2 does: 6e-17 for 0.3 at
 *   n = 16), the rule read before or after min_spp, pixels that never stop, passes run
 *   after every pixel has stopped, a pixel taking min_spp samples when spp is less. */
static void test_adaptive_constant_pixel_stops_at_min_spp(struct check *t)
{
    static const double values[] = {0.0, 1e-4, 0.3, 17.0};
    static const int min_spps[] = {2, 4, 16, 64};
    struct synthetic mode = {0.0, 0.0, 0};
    struct fixture f;
    if (!fixture_open(t, &f, 8, 6, mode))
        return;
    f.rs.spp = 32;
    f.rs.adaptive_error = 1e-300;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            f.mode.c = values[i];
            f.rs.min_spp = min_spps[j];
            int expected = min_spps[j] < 32 ? min_spps[j] : 32;
            struct render_counters counters = {0};
            struct render_result r = render_synthetic(&f, NULL, &counters);
            CHECK(t, counters.passes == expected);
            CHECK(t, counters.samples == (unsigned long long)expected * 8 * 6);
            render_result_free(&r);
        }
    scene_free(f.scene);
}

/* Checks every pixel of f's window against predicted_count(), rendered alone and in the
 * whole window; returns how many pixels took n samples. */
static int check_predicted_counts(struct check *t, const struct fixture *f, int n)
{
    int with_n = 0;
    unsigned long long predicted_total = 0;
    for (int y = f->rs.y0; y < f->rs.y1; y++)
        for (int x = f->rs.x0; x < f->rs.x1; x++) {
            double margin;
            int predicted = predicted_count(f, x, y, &margin);
            CHECK(t, margin > 1e-9);
            CHECK(t, render_one_pixel(f, x, y).n == predicted);
            predicted_total += (unsigned long long)predicted;
            with_n += predicted == n;
        }
    struct render_counters counters = {0};
    struct render_result r = render_synthetic(f, NULL, &counters);
    CHECK(t, counters.samples == predicted_total);
    render_result_free(&r);
    return with_n;
}

/* truth: (a) the rule recomputed apart from render.c (predicted_count) gives every pixel's
 *   count exactly. (b) The closed form: u uniform in [0, 1) has mean 1/2 and variance 1/12,
 *   so the standard error of n samples' mean is 1/sqrt(3 n) of it, which adaptive_error =
 *   1/sqrt(135) reaches at n = 45: most pixels stop at 64, the first check point past it.
 *   (c) The same noise times 1e-4 lies under ADAPTIVE_FLOOR, so its bound is absolute,
 *   adaptive_error * 1e-3, which n = 0.11 already meets: every pixel stops at min_spp.
 *   (d) With adaptive_error 1e-6 every pixel takes spp = 24 (not a power of two), no more.
 * tolerance: none for counts; every prediction is at least 1e-9 (relative) from its bound,
 *   so rounding cannot decide it. "Most" is more than half of the 48 pixels (the estimate
 *   of s / m at n = 32 has a spread of about 13%, against a margin of 19%).
 * catches: the rule read at every n or at n > spp, s^2 / n confused with s^2, the floor
 *   missing or applied to bright pixels, the mean of the wrong samples, a pixel taking more
 *   than spp. */
static void test_adaptive_noisy_pixel_stops_where_predicted(struct check *t)
{
    struct synthetic mode = {0.0, 1.0, 0};
    struct fixture f;
    if (!fixture_open(t, &f, 8, 6, mode))
        return;
    f.rs.spp = MAX_TEST_SPP;
    f.rs.min_spp = 4;
    f.rs.adaptive_error = 1.0 / sqrt(135.0);
    CHECK(t, check_predicted_counts(t, &f, 64) > 24);
    f.mode.a = 1e-4;
    CHECK(t, check_predicted_counts(t, &f, 4) == 48);
    f.mode.a = 1.0;
    f.rs.spp = 24;
    f.rs.adaptive_error = 1e-6;
    CHECK(t, check_predicted_counts(t, &f, 24) == 48);
    scene_free(f.scene);
}

/* truth: render.h's promise, kept with adaptive sampling on: a crop is the same window of
 *   the whole image, bit for bit, mean and variance, and takes those pixels' samples; the
 *   whole image must mix counts (more than min_spp but fewer than spp on average) for the
 *   test to mean anything.
 * tolerance: none.
 * catches: a rule that reads anything beyond the pixel (a floor or mean over the window,
 *   the share of pixels still sampling), counts indexed by the crop's own pixel numbers. */
static void test_adaptive_crop_matches_whole_image(struct check *t)
{
    struct synthetic mode = {0.2, 1.0, 1};
    struct fixture f;
    if (!fixture_open(t, &f, 24, 16, mode))
        return;
    f.rs.min_spp = 4;
    f.rs.adaptive_error = 0.05;
    struct render_counters whole_counters = {0}, crop_counters = {0};
    struct render_result whole = render_synthetic(&f, NULL, &whole_counters);
    CHECK(t, whole_counters.samples > 4 * 24 * 16 && whole_counters.samples < 64 * 24 * 16);
    struct fixture crop = f;
    crop.rs.x0 = 5;
    crop.rs.y0 = 3;
    crop.rs.x1 = 19;
    crop.rs.y1 = 11;
    struct render_result part = render_synthetic(&crop, NULL, &crop_counters);
    unsigned long long own_total = 0;
    for (int y = 3; y < 11; y++)
        for (int x = 5; x < 19; x++) {
            CHECK(t, same_vec3(image_get(part.image, x - 5, y - 3), image_get(whole.image, x, y)));
            CHECK(t, same_vec3(image_get(part.variance, x - 5, y - 3),
                               image_get(whole.variance, x, y)));
            own_total += (unsigned long long)render_one_pixel(&f, x, y).n;
        }
    CHECK(t, crop_counters.samples == own_total);
    render_result_free(&part);
    render_result_free(&whole);
    scene_free(f.scene);
}

/* truth: a pixel's value is the mean of exactly its own samples 0..n-1 (n its count, from
 *   rendering it alone), recomputed here by calling the mode along camera_sample(s), and
 *   its variance render.h's formula over those n. The window must hold at least three
 *   different counts, so that dividing by another number than the pixel's own shows.
 * tolerance: none: the same doubles added in the same order.
 * catches: dividing by spp or by the passes run instead of the pixel's count, samples added
 *   after a pixel stopped, the variance image using another count. */
static void test_adaptive_pixel_is_mean_of_own_samples(struct check *t)
{
    struct synthetic mode = {0.2, 1.0, 1};
    struct fixture f;
    if (!fixture_open(t, &f, 16, 12, mode))
        return;
    f.rs.min_spp = 2;
    f.rs.adaptive_error = 0.05;
    struct render_counters counters = {0};
    struct render_result r = render_synthetic(&f, NULL, &counters);
    int seen[MAX_TEST_SPP + 1] = {0}, distinct = 0;
    for (int y = 0; y < 12; y++)
        for (int x = 0; x < 16; x++) {
            int n = render_one_pixel(&f, x, y).n;
            struct pixel_value p = own_samples(&f, x, y, n);
            CHECK(t, same_vec3(image_get(r.image, x, y), p.mean));
            CHECK(t, same_vec3(image_get(r.variance, x, y), p.variance));
            distinct += seen[n]++ == 0;
        }
    CHECK(t, distinct >= 3);
    render_result_free(&r);
    scene_free(f.scene);
}

/* What a test's checkpoint saw: the work of each call and the last mean image. */
struct checkpoint_log {
    long long work[32];
    int n_calls;
    struct image *last; /* owned: a copy of the last mean image */
};

static double log_checkpoint(void *context, const struct image *mean, long long work,
                             double seconds)
{
    struct checkpoint_log *log = context;
    (void)seconds;
    if (log->n_calls < 32)
        log->work[log->n_calls] = work;
    log->n_calls++;
    image_free(log->last);
    log->last = image_create(mean->width, mean->height);
    memcpy(log->last->pixels, mean->pixels,
           (size_t)mean->width * (size_t)mean->height * sizeof *mean->pixels);
    return 0.0;
}

/* truth: render.h's checkpoint contract. Without adaptive sampling work is the passes run,
 *   1, 2, 4 and 6 for spp = 6, as before. With it, the last checkpoint's mean image is the
 *   render's image, bit for bit, and its work is the samples taken over the window's
 *   pixels, rounded to nearest, which here is neither the passes run nor min_spp.
 * tolerance: none.
 * catches: a checkpoint mean dividing by the passes run, work reported as passes or as
 *   all samples, a checkpoint missed when the rule ends the render. */
static void test_adaptive_checkpoint_mean_and_work(struct check *t)
{
    struct synthetic mode = {0.2, 1.0, 1};
    struct fixture f;
    if (!fixture_open(t, &f, 16, 12, mode))
        return;
    struct checkpoint_log log = {{0}, 0, NULL};
    struct checkpoint checkpoint = {log_checkpoint, &log};
    struct render_counters counters = {0};
    f.rs.spp = 6;
    struct render_result r = render_synthetic(&f, &checkpoint, &counters);
    CHECK(t, log.n_calls == 4 && log.work[0] == 1 && log.work[1] == 2 && log.work[2] == 4 &&
                 log.work[3] == 6);
    render_result_free(&r);
    log.n_calls = 0;
    f.rs.spp = 64;
    f.rs.min_spp = 2;
    f.rs.adaptive_error = 0.05;
    counters.samples = 0;
    r = render_synthetic(&f, &checkpoint, &counters);
    long long mean_spp = (long long)((2 * counters.samples + 16 * 12) / (2 * 16 * 12));
    CHECK(t, log.n_calls >= 1 && log.n_calls <= 32 && log.work[log.n_calls - 1] == mean_spp);
    CHECK(t, mean_spp != counters.passes && mean_spp != 2);
    CHECK(t, log.last != NULL &&
                 memcmp(log.last->pixels, r.image->pixels, 16 * 12 * sizeof *r.image->pixels)
                     == 0);
    image_free(log.last);
    render_result_free(&r);
    scene_free(f.scene);
}

/* The specular Cornell box's balls and light (scenes/cornell-specular.scene), for the
 * test below, which solves its rays here: nothing stands between the camera and a ball,
 * or between the mirror ball and the light but, possibly, the glass ball. */
static const double ball_centres[2][3] = {{185, 90, 169}, {368, 90, 351}}; /* glass, mirror */
#define BALL_RADIUS 90.0

/* The distance along ray (unit direction) to ball k, or 0 when it misses. */
static double ray_meets_ball(struct ray ray, int k)
{
    struct vec3 oc = vec3_sub(ray.origin, vec3(ball_centres[k][0], ball_centres[k][1],
                                               ball_centres[k][2]));
    double b = vec3_dot(oc, ray.dir), c = vec3_dot(oc, oc) - BALL_RADIUS * BALL_RADIUS;
    double disc = b * b - c;
    return b < 0 && disc > 0 ? -b - sqrt(disc) : 0.0;
}

/* Whether the ray through (px, py) of the image meets a ball first. */
static int pixel_point_meets_a_ball(const struct scene *scene, double px, double py)
{
    struct ray ray = camera_ray(&scene->camera, px, py);
    return ray_meets_ball(ray, 0) > 0 || ray_meets_ball(ray, 1) > 0;
}

/* Whether the ray through (px, py) meets the mirror ball first and, reflected there
 * (r = d - 2 (d . n) n), reaches the light's plane y = 548.7 inside its rectangle
 * [213, 343] x [227, 332] shrunk by 1 mm on every side, without meeting the glass ball. */
static int pixel_point_sees_light_in_mirror(const struct scene *scene, double px, double py)
{
    struct ray ray = camera_ray(&scene->camera, px, py);
    double t = ray_meets_ball(ray, 1), t_glass = ray_meets_ball(ray, 0);
    if (!(t > 0) || (t_glass > 0 && t_glass < t))
        return 0;
    struct vec3 p = vec3_add(ray.origin, vec3_scale(ray.dir, t));
    struct vec3 n = vec3_scale(vec3_sub(p, vec3(ball_centres[1][0], ball_centres[1][1],
                                                ball_centres[1][2])), 1.0 / BALL_RADIUS);
    struct ray out = {p, vec3_sub(ray.dir, vec3_scale(n, 2.0 * vec3_dot(ray.dir, n)))};
    if (!(out.dir.y > 0) || ray_meets_ball(out, 0) > 0)
        return 0;
    double s = (548.7 - p.y) / out.dir.y;
    double x = p.x + s * out.dir.x, z = p.z + s * out.dir.z;
    return x > 214 && x < 342 && z > 228 && z < 331;
}

/* truth: render.h's specular pixels, with the synthetic mode on the specular Cornell box's
 *   camera and geometry at 48 x 48: a pixel whose centre ray meets a ball and in which
 *   one of the 16 x 16 probe points render.c uses sees the light by one reflection in
 *   the mirror ball (solved here) takes specular_spp samples; one where no ray of a
 *   3 x 3 grid over its square (corners included) meets a ball takes spp; and every
 *   pixel, in the whole image or a 1 x 1 crop, is exactly the mean of its own samples
 *   0..n-1, n its count.
 * tolerance: none: counts, and the same doubles added in the same order; the light's
 *   rectangle is shrunk by 1 mm so that rounding cannot decide a probe at its edge.
 * catches: the count decided from the samples (or by their radiance), a pixel sampled past
 *   its target, pixels seeing only diffuse walls boosted, the light's image in a mirror
 *   missed, a crop probing the crop's own pixel numbers, passes stopping at spp. */
static void test_specular_pixels_take_specular_spp(struct check *t)
{
    struct synthetic mode = {0.2, 1.0, 1};
    struct fixture f;
    f.scene = load_test_scene("scenes/cornell-specular.scene", 48, 48);
    CHECK(t, f.scene != NULL);
    if (f.scene == NULL)
        return;
    f.rs = render_settings_whole(f.scene, 7, 2, 1);
    f.rs.specular_spp = 8;
    f.mode = mode;
    struct render_counters counters = {0};
    struct render_result whole = render_synthetic(&f, NULL, &counters);
    CHECK(t, counters.passes == 8);
    int boosted = 0, plain = 0;
    for (int y = 0; y < 48; y++)
        for (int x = 0; x < 48; x++) {
            struct pixel_value p = render_one_pixel(&f, x, y);
            int grid_meets = 0, sees_light = 0;
            for (int k = 0; k < 9; k++)
                grid_meets |= pixel_point_meets_a_ball(f.scene, x + 0.5 * (k % 3),
                                                       y + 0.5 * (k / 3));
            for (int k = 0; k < 16 * 16; k++)
                sees_light |= pixel_point_sees_light_in_mirror(f.scene, x + (k % 16 + 0.5) / 16,
                                                               y + (k / 16 + 0.5) / 16);
            if (sees_light && pixel_point_meets_a_ball(f.scene, x + 0.5, y + 0.5)) {
                CHECK(t, p.n == 8);
                boosted++;
            } else if (!grid_meets) {
                CHECK(t, p.n == 2);
                plain++;
            }
            CHECK(t, p.n == 2 || p.n == 8);
            struct pixel_value own = own_samples(&f, x, y, p.n);
            CHECK(t, same_vec3(p.mean, own.mean) &&
                         same_vec3(image_get(whole.image, x, y), own.mean));
        }
    CHECK(t, boosted >= 1 && plain >= 1500); /* both kinds are really there */
    render_result_free(&whole);
    scene_free(f.scene);
}

void test_render(struct check *t)
{
    RUN_TEST(t, test_point_light_over_plane);
    RUN_TEST(t, test_light_seen_directly);
    RUN_TEST(t, test_crop_matches_whole_image);
    RUN_TEST(t, test_scale_invariance);
    RUN_TEST(t, test_shapes_render_as_their_expansions);
    RUN_TEST(t, test_adaptive_off_takes_every_sample);
    RUN_TEST(t, test_adaptive_constant_pixel_stops_at_min_spp);
    RUN_TEST(t, test_adaptive_noisy_pixel_stops_where_predicted);
    RUN_TEST(t, test_adaptive_crop_matches_whole_image);
    RUN_TEST(t, test_adaptive_pixel_is_mean_of_own_samples);
    RUN_TEST(t, test_adaptive_checkpoint_mean_and_work);
    RUN_TEST(t, test_specular_pixels_take_specular_spp);
}
