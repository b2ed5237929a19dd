/*
 * tests/test_error_2008.c -- 2008's error image (--error, src/modes/ppm_error.h) against
 * closed forms: coverage and sharpness per pixel (truths.h, coverage_of()) and per block
 * (block_error_image()), with and without its bias term; where the bound fails, the
 * settings the command line refuses; a crop's error image, and the image with and
 * without it; --target-error; the refusals.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/image/error_image.h"
#include "../src/modes/pixel_error.h"
#include "../src/modes/ppm2008.h"
#include "files.h"
#include "tests.h"
#include "truths.h"

#define OUT "/tmp/photon_test_error_2008"
#define PHOTONS 20000 /* photons a pass: few, so that a test case takes about a second */
#define MOST_BLOCKS 64 /* the blocks of ERROR_BLOCK pixels a case's image holds at most */

/* scenes/analytic/point-in-sphere.scene's closed form (point_in_sphere_truth()), the same
 * along every camera ray: light the photons bring after their first bounce, the only
 * closed form whose light 2008's hit points carry at its defaults. */
static double point_in_sphere(struct ray r)
{
    (void)r;
    return point_in_sphere_truth(NULL, 0, 0);
}

/* How a case departs from 2008's defaults (PHOTONS a pass aside). */
enum departure {
    DEFAULTS,        /* the direct light by light samples, hit points merged          */
    UNMERGED,        /* --no-merge-hit-points                                         */
    DIRECT_PHOTONS,  /* --no-direct-light-samples, refused with --error               */
    PHOTONS_ALONE,   /* --no-direct-light-samples --no-merge-hit-points, refused too  */
    FIXED_EMISSION   /* --no-resample-emission, refused                               */
};

struct case_2008 {
    const char *path;
    double (*along)(struct ray);
    int width, height;
    long passes;
    enum departure departure;
    uint64_t seed;
};

static struct ppm_settings error_settings(long passes, enum departure departure)
{
    struct ppm_settings ps = ppm_settings_default();
    ps.progressive.passes = passes;
    ps.progressive.photons_per_pass = PHOTONS;
    ps.progressive.direct_light_samples = departure != DIRECT_PHOTONS && departure != PHOTONS_ALONE;
    ps.merge_hit_points = departure != UNMERGED && departure != PHOTONS_ALONE;
    ps.resample_emission = departure != FIXED_EMISSION;
    return ps;
}

/* What a render did besides its result: its tally (a target error's) and statistics. */
struct done {
    struct render_counters counters;
    struct ppm_stats stats;
};

/* 2008's render of scene (path's, at the case's size) with an error image at 0.95 when
 * with_error, rendering to target_error when > 0, the window's (the whole image with
 * window NULL); what else it did into *done. */
static struct render_result render_case(const struct scene *scene, const struct case_2008 *c,
                                        const int *window, int with_error, double target_error,
                                        struct done *done)
{
    struct render_settings rs = case_settings(scene, c->seed, PPM_DEFAULT_SPP, window);
    rs.error_confidence = with_error ? 0.95 : 0.0;
    rs.target_error = target_error;
    struct ppm_settings ps = error_settings(c->passes, c->departure);
    memset(done, 0, sizeof *done);
    return render_ppm(scene, &rs, &ps, &done->counters, &done->stats);
}

/* The truth of pixel (x, y) for a block's mean: pixel_closed_form(), but where its 16 x 16
 * points disagree by more than a tenth (an edge) the mean over a Fibonacci lattice of
 * LATTICE points. The 16 x 16 rule misplaces an edge parallel to its rows by up to 1/32
 * of a pixel: area-over-floor's light, seen edge-on, 0.3 too dark a pixel along its
 * outline, puts its top 16 x 16 blocks of 32 x 32 5% too dark (pt at 1,024 samples and
 * 2008 agree with each other there, not with the rule); the lattice, one point in each
 * of its LATTICE rows and columns, misplaces such an edge by under 1/LATTICE. */
#define LATTICE 4181        /* the 19th Fibonacci number ...  */
#define LATTICE_STEP 2584   /* ... and the 18th               */
static double pixel_truth(const struct scene *scene, int x, int y, double (*along)(struct ray))
{
    double least = HUGE_VAL, most = -HUGE_VAL;
    for (int j = 0; j < 16; j++)
        for (int i = 0; i < 16; i++) {
            double l = along(camera_ray(&scene->camera, x + (i + 0.5) / 16, y + (j + 0.5) / 16));
            least = fmin(least, l);
            most = fmax(most, l);
        }
    if (most - least <= 0.1 * most)
        return pixel_closed_form(scene, x, y, along);
    double sum = 0.0;
    for (int i = 0; i < LATTICE; i++) {
        double v = (double)((long)i * LATTICE_STEP % LATTICE) + 0.5;
        sum += along(camera_ray(&scene->camera, x + (i + 0.5) / LATTICE, y + v / LATTICE));
    }
    return sum / LATTICE;
}

/* The whole blocks of ERROR_BLOCK x ERROR_BLOCK pixels of result (a render of scene) whose
 * truth (pixel_truth()) is at least ERROR_DARK_FLOOR: each one's least ratio over the channels of its
 * block statement (block_error_image(): the block's bias over its reach, the noise of the
 * block's own batches) to its mean's error against the closed form along() into
 * ratio[*n] (HUGE_VAL where the error is 0; the statement holds where the ratio is at
 * least 1), *n counting them. */
static void block_ratios(const struct scene *scene, const struct render_result *result,
                         double (*along)(struct ray), double *ratio, int *n)
{
    struct stated_error stated = {result->error, result->bias, result->block_noise,
                                  result->block_bias};
    struct image *blocks = block_error_image(result->image, &stated, 0, 0);
    const double pixels = ERROR_BLOCK * ERROR_BLOCK;
    for (int by = 0; by + ERROR_BLOCK <= result->image->height; by += ERROR_BLOCK)
        for (int bx = 0; bx + ERROR_BLOCK <= result->image->width; bx += ERROR_BLOCK) {
            struct vec3 mean = vec3_zero();
            double truth = 0.0, least = HUGE_VAL;
            for (int y = by; y < by + ERROR_BLOCK; y++)
                for (int x = bx; x < bx + ERROR_BLOCK; x++) {
                    mean = vec3_add(mean, image_get(result->image, x, y));
                    truth += pixel_truth(scene, x, y, along);
                }
            if (truth / pixels < ERROR_DARK_FLOOR || *n == MOST_BLOCKS)
                continue;
            for (int c = 0; c < 3; c++) {
                double d = fabs(vec3_get(mean, c) - truth) / pixels;
                double b = vec3_get(image_get(blocks, bx / ERROR_BLOCK, by / ERROR_BLOCK), c);
                least = fmin(least, d > 0 ? b / d : HUGE_VAL);
            }
            ratio[(*n)++] = least;
        }
    image_free(blocks);
}

static int by_value(const void *p, const void *q)
{
    double x = *(const double *)p, y = *(const double *)q;
    return (x > y) - (x < y);
}

/* How a case's error image states its error: per pixel (coverage_of(); *without, the
 * bound less its bias term), and per block, how many held (*held of *blocks) and the
 * median of their ratios of bound to error (*block_sharpness). */
struct statement {
    struct coverage pixels, without;
    int blocks, held;
    double block_sharpness;
};

static struct statement case_statement(const struct case_2008 *c)
{
    struct statement s = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0, 0, 0.0};
    struct scene *scene = load_test_scene(c->path, c->width, c->height);
    if (scene == NULL)
        return s;
    struct done done;
    struct render_result result = render_case(scene, c, NULL, 1, 0.0, &done);
    s.pixels = coverage_of(scene, result.image, result.error, NULL, c->along);
    s.without = coverage_of(scene, result.image, result.error, result.bias, c->along);
    double ratio[MOST_BLOCKS];
    block_ratios(scene, &result, c->along, ratio, &s.blocks);
    for (int k = 0; k < s.blocks; k++)
        s.held += ratio[k] >= 1;
    qsort(ratio, (size_t)s.blocks, sizeof *ratio, by_value);
    s.block_sharpness = s.blocks > 0 ? ratio[s.blocks / 2] : 0.0;
    render_result_free(&result);
    scene_free(scene);
    return s;
}

static void print_statement(const struct case_2008 *c, const char *what,
                            const struct statement *s)
{
    printf("  error: 2008 %s %dx%d, %ld passes, %s: truth within the 95%% bound in %.3f "
           "(%.3f without the bias term); rms(bound)/rms(error) %.2f, median over 8 x 8 "
           "blocks %.2f; %d of %d blocks of 16 x 16 held, median bound/error %.2f\n",
           c->path, c->width, c->height, c->passes, what, s->pixels.covered,
           s->without.covered, s->pixels.rms_ratio, s->pixels.sharpness, s->held, s->blocks,
           s->block_sharpness);
}

/* truth: the closed forms of point-over-plane (L = rho Phi h / (4 pi^2 d^3)),
 *   sky-over-floor (the sphere's soft shadow), area-over-floor (a square light's) and
 *   point-in-sphere (4 everywhere, all of it brought by photons after their first bounce
 *   to 2008's hit points), pixel means by a 16 x 16 midpoint rule, at 2008's defaults
 *   (merged hit points, the direct light by light samples: on the first three the hit
 *   points carry nothing, the photons after a bounce leaving the scene). And the one case
 *   whose hit points carry a Laplacian, so that the bias term matters: point-over-plane
 *   with the direct light from photons, one hit point an eye ray (the command line
 *   refuses that setting for its aliasing elsewhere, below; point-over-plane's light is
 *   smooth across a pixel, whose 16 stratified points alias little).
 * tolerance: the truth within the 95% bound in at least 0.95 of the pixels and channels;
 *   on the cases whose bound rests on photons (point-in-sphere, the bias case) the median
 *   over 8 x 8 blocks of rms(bound) / rms(error) at most 3 (ERROR.md); the light-sampled
 *   ones are loose, as 2009's are (sppm_error.h: their light samples are stratified over
 *   the passes and err less than the batches say); in the bias case below 0.95 without
 *   the bias term; over all cases' 16 x 16 blocks, at least 0.9 held.
 * catches: the pass values read from each estimate's whole tau instead of the pass's
 *   tau_M (while building it: the Cornell box's estimated relmse 13 where 0.16), the
 *   inner discs' flux over pi R^2 rather than pi R^2 / 2 (sharpness above 3 on the three
 *   photon cases), the bias term left out (0.891 in its case), a bound that misses
 *   where it should hold. Measured (seeds 11-30 too): at the defaults 0.98-1.00 of the
 *   pixels (0.96-0.97 unmerged); sharpness 2.1-2.8 on point-in-sphere, 3.0-8.4
 *   light-sampled; 95 of 96 blocks held. */
static void test_bound_covers_closed_forms(struct check *t)
{
    static const struct case_2008 cases[] = {
        {"scenes/analytic/point-over-plane.scene", point_over_plane, 32, 32, 64, DEFAULTS, 401},
        {"scenes/analytic/sky-over-floor.scene", sky_over_floor_with_sphere, 48, 32, 64,
         DEFAULTS, 402},
        {"scenes/analytic/area-over-floor.scene", area_over_floor, 32, 32, 64, DEFAULTS, 403},
        {"scenes/analytic/point-in-sphere.scene", point_in_sphere, 32, 32, 64, DEFAULTS, 404},
        {"scenes/analytic/point-in-sphere.scene", point_in_sphere, 16, 16, 64, UNMERGED, 405},
        {"scenes/analytic/point-over-plane.scene", point_over_plane, 32, 32, 64, PHOTONS_ALONE,
         406},
    };
    static const char *const what[] = {"defaults", "--no-merge-hit-points",
                                       "direct light from photons",
                                       "direct light from photons, unmerged", "fixed emission"};
    int blocks = 0, held = 0;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const struct case_2008 *c = &cases[k];
        struct statement s = case_statement(c);
        print_statement(c, what[c->departure], &s);
        blocks += s.blocks;
        held += s.held;
        CHECK(t, s.pixels.covered >= 0.95);
        if (c->along == point_in_sphere || c->departure == PHOTONS_ALONE)
            CHECK(t, s.pixels.sharpness <= 3.0);
        if (c->departure == PHOTONS_ALONE)
            CHECK(t, s.without.covered < 0.95);
    }
    printf("  error: 2008 blocks of 16 x 16: %d of %d held\n", held, blocks);
    CHECK(t, blocks >= 20 && held >= 0.9 * blocks);
}

/* truth: the closed forms above, under the settings option_checks.c refuses for 2008's
 *   error image (check_error_2008()): the direct light from photons at merged hit points
 *   (point-over-plane at 32 x 32, the light's gradient seen at one point a pixel), and the
 *   emission seen by the --spp eye rays alone (area-over-floor, the light's outline).
 * tolerance: the bound fails as the refusals say: under 0.9 of the pixels covered; a
 *   block of the light's outline stated under its error.
 * catches: a refusal left standing after the aliasing it names was mended (then lift the
 *   refusal), or its message's figure gone stale. */
static void test_refused_settings_miss(struct check *t)
{
    static const struct case_2008 merged = {"scenes/analytic/point-over-plane.scene",
                                            point_over_plane, 32, 32, 64, DIRECT_PHOTONS, 407};
    static const struct case_2008 fixed = {"scenes/analytic/area-over-floor.scene",
                                           area_over_floor, 32, 32, 64, FIXED_EMISSION, 408};
    struct statement m = case_statement(&merged), f = case_statement(&fixed);
    print_statement(&merged, "direct light from photons", &m);
    print_statement(&fixed, "fixed emission", &f);
    CHECK(t, m.pixels.covered > 0 && m.pixels.covered < 0.9);
    CHECK(t, f.blocks > 0 && f.held < f.blocks);
}

/* truth: the whole image's error image and bias, rendered apart, and its image rendered
 *   without an error image; on sky-over-floor, and on the specular box's caustic under
 *   the glass ball, whose merged hit points keep members for their caustic estimates.
 * tolerance: none: the crop's are its window, bit for bit (render.h's promise), and the
 *   image is the same with and without the error image.
 * catches: a window grown by the pool alone (the bias smoothed over pixels the crop never
 *   rendered), the margin's hit points written into the image, pass values summed in the
 *   tree's order (which depends on the window), the inner discs' sums changing tau. */
static void test_crop_error_is_window(struct check *t)
{
    static const struct {
        const char *path;
        int width, height, window[4];
    } scenes[] = {
        {"scenes/analytic/sky-over-floor.scene", 40, 30, {7, 5, 26, 21}},
        {"scenes/cornell-specular.scene", 64, 64, {37, 49, 51, 61}},
    };
    for (size_t k = 0; k < sizeof scenes / sizeof scenes[0]; k++) {
        struct scene *scene = load_test_scene(scenes[k].path, scenes[k].width,
                                              scenes[k].height);
        REQUIRE(t, scene != NULL);
        const struct case_2008 c = {"", NULL, 0, 0, ERROR_MIN_SPP, DEFAULTS, 5};
        struct done done;
        struct render_result a = render_case(scene, &c, NULL, 1, 0.0, &done);
        struct render_result b = render_case(scene, &c, scenes[k].window, 1, 0.0, &done);
        struct render_result plain = render_case(scene, &c, NULL, 0, 0.0, &done);
        CHECK(t, crop_is_window(a.image, b.image, scenes[k].window));
        CHECK(t, crop_is_window(a.error, b.error, scenes[k].window));
        CHECK(t, crop_is_window(a.bias, b.bias, scenes[k].window));
        CHECK(t, same_pixels(a.image, plain.image) && plain.error == NULL);
        render_result_free(&plain);
        render_result_free(&a);
        render_result_free(&b);
        scene_free(scene);
    }
}

/* Renders point-in-sphere at 48 x 48 (the defaults) with seed to target error e, at most
 * 4096 passes; the fraction of its 16 x 16 blocks whose mean is within e of the closed
 * form's, the passes in *passes, and whether every block was judged within it in
 * *all_within. */
static double target_render(double e, unsigned seed, int *passes, int *all_within)
{
    const struct case_2008 c = {"scenes/analytic/point-in-sphere.scene", point_in_sphere,
                                48, 48, 4096, DEFAULTS, seed};
    struct scene *scene = load_test_scene(c.path, c.width, c.height);
    if (scene == NULL)
        return 0.0;
    struct done done;
    struct render_result result = render_case(scene, &c, NULL, 1, e, &done);
    double within = target_outcome(scene, &result, &done.counters, e, c.along, passes,
                                   all_within);
    *passes = (int)done.stats.passes; /* counters.passes is 2008's eye rays a pixel */
    return within;
}

/* truth: point-in-sphere's closed form, block by block; a looser target against a tighter.
 * tolerance: at each target, over TARGET_SEEDS renders of 9 blocks, so few blocks outside
 *   the target of the truth that a true 95% statement of each block would leave more out
 *   with a chance of 1% or more (binomial_misses_allowed(): 5 of 36); in every render
 *   every block judged within it, the tighter target taking more passes and the looser
 *   at least ERROR_MIN_SPP, both fewer than the 4096 allowed; on the command line, a
 *   target cut short by --passes named with its passes, --spp left at 2008's 16 eye
 *   rays, the error statistics printed and the block statement written (--block-error).
 *   A render stops once every block's bound is within the target, so one block of 9 past
 *   it is what a bound as sharp as it states allows: seed 409 at 0.01 stops at 48 passes
 *   with one block 1.00% off, where its bound stated 0.84%.
 * catches: a target never judged, a bound that lets more blocks past the target than
 *   it states (blocks judged by their pixels' noise in quadrature, though they share
 *   photons, which test_bound_covers_closed_forms() catches as well), a tally left at
 *   its first judgement, --target-error taking 2008's --spp for its passes (2^20 eye
 *   rays a pixel). */
#define TARGET_SEEDS 4
static void test_target_error(struct check *t)
{
    static const double target[2] = {0.02, 0.01};
    int looser[TARGET_SEEDS];
    for (int k = 0; k < 2; k++) {
        int blocks = 0, outside = 0, passes[TARGET_SEEDS];
        for (unsigned seed = 0; seed < TARGET_SEEDS; seed++) {
            int all_within;
            double within = target_render(target[k], 409 + seed, &passes[seed], &all_within);
            printf("  error: 2008 --target-error %g, seed %u: %d passes, %.3f of blocks within "
                   "it of the truth\n", target[k], 409 + seed, passes[seed], within);
            CHECK(t, all_within && ERROR_MIN_SPP <= passes[seed] && passes[seed] < 4096);
            blocks += 9;
            outside += (int)((1.0 - within) * 9 + 0.5);
        }
        CHECK(t, outside <= binomial_misses_allowed(blocks, 0.05, 0.01));
        if (k == 1)
            for (unsigned seed = 0; seed < TARGET_SEEDS; seed++)
                CHECK(t, looser[seed] < passes[seed]);
        memcpy(looser, passes, sizeof passes);
    }
    CHECK(t, target_cut_short("2008", "--error " OUT "_e.pfm --block-error " OUT "_b.pfm",
                              OUT));
    CHECK(t, file_stat(OUT ".log", "spp") == PPM_DEFAULT_SPP &&
             file_stat(OUT ".log", "passes") == 16 &&
             file_stat(OUT ".log", "estimated_relmse") > 0 &&
             file_stat(OUT ".log", "bounded_blocks") == 4);
    struct error err;
    struct image *blocks = pfm_read(OUT "_b.pfm", &err);
    CHECK(t, blocks != NULL && blocks->width == 2 && blocks->height == 2);
    image_free(blocks);
    remove(OUT ".log");
    remove(OUT ".pfm");
    remove(OUT ".png");
    remove(OUT "_e.pfm");
    remove(OUT "_b.pfm");
}

/* truth: check_error_2008()'s refusals, measured above (test_refused_settings_miss); the
 *   rules 2008 shares with 2009 (--passes >= 16 and the like) are test_error_2009.c's.
 * tolerance: exit status 2, the message, and no file left.
 * catches: a bound stated where 2008's fixed eye rays carry the light's edges: the direct
 *   light from photons (--paper among the ways to ask for it), the emission seen by the
 *   --spp rays alone. */
static void test_error_refusals(struct check *t)
{
    static const char *const bad[][2] = {
        {"--passes 16 --paper --error " OUT "_e.pfm",
         "--error: not with --no-direct-light-samples (from --paper): the photons then bring "
         "the direct light"},
        {"--passes 16 --no-direct-light-samples --target-error 0.1",
         "--target-error: not with --no-direct-light-samples: "},
        {"--passes 16 --no-resample-emission --error " OUT "_e.pfm",
         "--error: not with --no-resample-emission: the emission seen"},
        {"--no-resample-emission --no-merge-hit-points --target-error 0.1",
         "--target-error: not with --no-resample-emission"},
    };
    CHECK(t, refuses_options("2008", bad, sizeof bad / sizeof bad[0], OUT) == 0);
    CHECK(t, !file_exists(OUT "_e.pfm"));
}

void test_error_2008(struct check *t)
{
    RUN_TEST(t, test_bound_covers_closed_forms);
    RUN_TEST(t, test_refused_settings_miss);
    RUN_TEST(t, test_crop_error_is_window);
    RUN_TEST(t, test_target_error);
    RUN_TEST(t, test_error_refusals);
}
