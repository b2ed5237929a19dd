/*
 * tests/test_error.c -- the error image (--error) against closed forms: how often the
 * truth lies within the stated bound (coverage) and how much wider than the error the
 * bound is (sharpness: rms(bound) / rms(image - truth)), the words of the README's "How
 * far from the truth"; a crop's error image; the refusals.
 */
#include <math.h>
#include <stdio.h>

#include "../src/image/error_image.h"
#include "../src/modes/pixel_error.h"
#include "../src/modes/pt.h"
#include "files.h"
#include "tests.h"
#include "truths.h"

#define OUT "/tmp/photon_test_error"

/* pt's image and error image at 0.95 of the scene at path, width x height, against the
 * closed form along() (coverage_of()). */
static struct coverage pt_coverage(const char *path, int width, int height, int spp,
                                   uint64_t seed, double (*along)(struct ray))
{
    struct coverage cover = {0.0, 0.0, 0.0};
    struct scene *scene = load_test_scene(path, width, height);
    if (scene == NULL)
        return cover;
    struct render_settings rs = render_settings_whole(scene, seed, spp, MAX_DEPTH_LIMIT);
    rs.error_confidence = 0.95;
    struct render_counters counters = {0};
    struct render_result result = render_pt(scene, &rs, 0, NULL, &counters);
    cover = coverage_of(scene, result.image, result.error, NULL, along);
    render_result_free(&result);
    scene_free(scene);
    return cover;
}

/* truth: the closed forms of sky-over-floor (the sky's light, a sliver of which the sphere
 *   hides: rare samples) and area-over-floor (a square light over a floor, seen in the
 *   top rows), pixel means by a 16 x 16 midpoint rule; seeds the bound was not measured
 *   on (pixel_error.h's figures are seeds 1-11).
 * tolerance: the truth within the 95% bound in at least 0.95 of the pixels and channels,
 *   and the bound at most 3 times the error's rms (ERROR.md: a bound a user can use).
 * catches: a bound from the pixel's own samples alone (0.57 of sky-over-floor's pixels at
 *   16 samples, 0.83 at 64), pooled over 3 x 3 pixels (0.95, borderline), a missing
 *   sqrt or 1/n (coverage near 1 and sharpness far above 3, or near 0), a standard
 *   error without z_c (coverage ~0.68), batches merged out of order (their spread then
 *   mixes batch sizes). */
static void test_pt_bound_covers_closed_forms(struct check *t)
{
    static const struct {
        const char *path;
        double (*along)(struct ray);
        int width, height, spp;
        uint64_t seed;
    } cases[] = {
        {"scenes/analytic/sky-over-floor.scene", sky_over_floor_with_sphere, 64, 48, 16, 101},
        {"scenes/analytic/sky-over-floor.scene", sky_over_floor_with_sphere, 64, 48, 64, 102},
        {"scenes/analytic/sky-over-floor.scene", sky_over_floor_with_sphere, 32, 24, 256, 103},
        {"scenes/analytic/area-over-floor.scene", area_over_floor, 48, 48, 16, 104},
        {"scenes/analytic/area-over-floor.scene", area_over_floor, 48, 48, 64, 105},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        struct coverage c = pt_coverage(cases[k].path, cases[k].width, cases[k].height,
                                        cases[k].spp, cases[k].seed, cases[k].along);
        printf("  error: pt %s, %d spp: truth within the 95%% bound in %.3f; "
               "rms(bound)/rms(error) %.2f, median over 8 x 8 blocks %.2f\n", cases[k].path,
               cases[k].spp, c.covered, c.rms_ratio, c.sharpness);
        CHECK(t, c.covered >= 0.95);
        CHECK(t, c.sharpness <= 3.0);
    }
}

/* truth: the whole image's error image, rendered apart.
 * tolerance: none: the crop's is its window, bit for bit (render.h's promise, which the
 *   pool of pixel_error.h must keep by sampling the pixels beyond the crop's edge).
 * catches: a pool cut at the crop's edge (its border pixels pool over fewer
 *   neighbours), a margin sampled with the wrong pixel's streams. */
static void test_crop_error_is_window(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/analytic/sky-over-floor.scene", 40, 30);
    REQUIRE(t, scene != NULL);
    static const int window[4] = {7, 5, 26, 21};
    struct render_settings whole = render_settings_whole(scene, 5, ERROR_MIN_SPP,
                                                         MAX_DEPTH_LIMIT);
    whole.error_confidence = 0.9;
    struct render_settings crop = case_settings(scene, 5, ERROR_MIN_SPP, window);
    crop.error_confidence = 0.9;
    struct render_counters counters = {0};
    struct render_result a = render_pt(scene, &whole, 0, NULL, &counters);
    struct render_result b = render_pt(scene, &crop, 0, NULL, &counters);
    CHECK(t, crop_is_window(a.image, b.image, window));
    CHECK(t, crop_is_window(a.error, b.error, window));
    render_result_free(&a);
    render_result_free(&b);
    scene_free(scene);
}

/* Renders sky-over-floor at 128 x 96 (seed 201) to target error e at most 4096 samples;
 * the fraction of its 16 x 16 blocks whose mean is within e of the closed form's, and the
 * passes it took in *passes. */
static double target_render(double e, int *passes, int *all_within)
{
    struct scene *scene = load_test_scene("scenes/analytic/sky-over-floor.scene", 128, 96);
    if (scene == NULL)
        return 0.0;
    struct render_settings rs = render_settings_whole(scene, 201, 4096, MAX_DEPTH_LIMIT);
    rs.error_confidence = 0.95;
    rs.target_error = e;
    struct render_counters counters = {0};
    struct render_result result = render_pt(scene, &rs, 0, NULL, &counters);
    return target_outcome(scene, &result, &counters, e, sky_over_floor_with_sphere, passes,
                          all_within);
}

/* truth: sky-over-floor's closed form, block by block; and a looser target against a
 *   tighter one.
 * tolerance: at least 95% of the blocks within the target of the truth (the bound's
 *   confidence), every block judged within it, the tighter target taking more passes and
 *   the looser fewer than the 4096 allowed.
 * catches: passes that stop before the blocks reach the target (a block's bound taken
 *   per pixel rather than in quadrature over its pixels would stop late; one divided by n
 *   twice, early), a target that never stops the render, a tally left at its first
 *   judgement. */
static void test_target_error(struct check *t)
{
    int passes_5, passes_1, all_5, all_1;
    double within_5 = target_render(0.05, &passes_5, &all_5);
    double within_1 = target_render(0.01, &passes_1, &all_1);
    printf("  error: --target-error 0.05: %d passes, %.3f of blocks within 5%% of the truth; "
           "0.01: %d passes, %.3f within 1%%\n", passes_5, within_5, passes_1, within_1);
    CHECK(t, all_5 && all_1);
    CHECK(t, within_5 >= 0.95 && within_1 >= 0.95);
    CHECK(t, ERROR_MIN_SPP <= passes_5 && passes_5 < passes_1 && passes_1 < 4096);
    /* cut short by --spp: the blocks that missed are named */
    CHECK(t, photon_logged("", "--mode pt --target-error 0.001 --spp 16 --width 32 --height "
                           "24 --no-progress --stats -o " OUT ".pfm "
                           "scenes/analytic/sky-over-floor.scene", OUT ".log") == 0);
    CHECK(t, file_contains(OUT ".log", "blocks not within it after 16 samples per pixel, "
                           "the first at (0, 0)"));
    CHECK(t, file_stat(OUT ".log", "target_blocks") == 4 &&
             file_stat(OUT ".log", "target_blocks_within") == 0);
    remove(OUT ".log");
    remove(OUT ".pfm");
    remove(OUT ".png");
}

/* truth: four 16 x 16 blocks worked by hand: every pixel of a has variance 0.16^2 in each
 *   channel, so a block's luminance standard error is 0.16 / 16 = 0.01 and its 95% bound
 *   B = 0.0196; a's block means exceed b's by 0.01, 0.019, 0.021 and 0.05.
 * tolerance: exact counts; the ratios to 1e-12.
 * catches: a bound taken per pixel rather than in quadrature over the block (0.16 z),
 *   the reference's noise ignored or counted against a, the median of the wrong order. */
static void test_bound_check(struct check *t)
{
    static const double d[4] = {0.01, 0.019, 0.021, 0.05};
    struct image *a = image_create(32, 32), *b = image_create(32, 32);
    struct image *var = image_create(32, 32);
    for (int y = 0; y < 32; y++)
        for (int x = 0; x < 32; x++) {
            double v = 0.5 + d[y / 16 * 2 + x / 16];
            image_set(a, x, y, vec3(v, v, v));
            image_set(b, x, y, vec3(0.5, 0.5, 0.5));
            image_set(var, x, y, vec3(0.0256, 0.0256, 0.0256));
        }
    double z = 1.959963984540054, bound = z * 0.01;
    struct bound_check c = bound_check(a, var, b, NULL, z);
    CHECK(t, c.n_blocks == 4 && c.covered == 2);
    CHECK(t, fabs(c.median_ratio - bound / 0.019) < 1e-12);
    double rms_error = sqrt((0.01 * 0.01 + 0.019 * 0.019 + 0.021 * 0.021 + 0.05 * 0.05) / 4);
    CHECK(t, fabs(c.rms_ratio - bound / rms_error) < 1e-12);
    c = bound_check(a, var, b, var, z); /* the reference as noisy: sqrt(2) B allowed */
    CHECK(t, c.n_blocks == 4 && c.covered == 3);
    image_free(var);
    image_free(b);
    image_free(a);
}

/* truth: the README's rules for --error and --confidence.
 * tolerance: exit status 2, the message, and no file left.
 * catches: a bound stated where the samples are too few to see rare values, where a
 *   rule or a depth limit biases the pixel, for a mode that states none, or a
 *   --confidence that nothing reads; a bound stated without a word where pt finds
 *   caustics only by chance (the calibration's misses), or that word where it does not. */
static void test_error_refusals(struct check *t)
{
    static const char *const bad[][2] = {
        {"--spp 8 --error " OUT "_e.pfm", "--error: needs --spp >= 16"},
        {"--spp 16 --adaptive 0.1 --error " OUT "_e.pfm", "--error: not with --adaptive"},
        {"--spp 16 --max-depth 3 --error " OUT "_e.pfm", "--error: not with --max-depth 3"},
        {"--spp 16 --confidence 0.9", "--confidence: does nothing with no --error"},
        {"--spp 8 --target-error 0.1", "--target-error: needs --spp >= 16"},
        {"--spp 16 --error " OUT "_e.pfm --confidence 1", "--confidence"},
    };
    CHECK(t, refuses_options("pt", bad, sizeof bad / sizeof bad[0], OUT) == 0);
    static const char *const not_pt[][2] = {
        {"--error " OUT "_e.pfm", "--error: --mode 1996 states no bound yet: every pixel "
                                  "shares its photon maps"},
    };
    CHECK(t, refuses_options("1996", not_pt, 1, OUT) == 0);
    CHECK(t, !file_exists(OUT "_e.pfm"));
    /* a point light's caustic pt never samples: no bound can state it */
    CHECK(t, photon_logged("", "--mode pt --spp 16 --width 8 --height 8 --error " OUT
                           "_e.pfm -o " OUT ".pfm scenes/mirror-caustic.scene",
                           OUT ".log") == 2);
    CHECK(t, file_contains(OUT ".log", "--error: pt cannot find the caustics"));
    CHECK(t, !file_exists(OUT "_e.pfm") && !file_exists(OUT ".pfm"));
    static const char *const warned[2] = {"scenes/cornell.scene",
                                          "scenes/cornell-specular.scene"};
    for (int specular = 0; specular < 2; specular++) {
        char args[512];
        snprintf(args, sizeof args, "--mode pt --spp 16 --width 8 --height 8 --no-progress "
                 "--error " OUT "_e.pfm -o " OUT ".pfm %s", warned[specular]);
        CHECK(t, photon_logged("", args, OUT ".log") == 0);
        CHECK(t, file_contains(OUT ".log", "light through mirrors and glass only by chance") ==
                     specular);
    }
    remove(OUT "_e.pfm");
    remove(OUT ".pfm");
    remove(OUT ".png");
    remove(OUT ".log");
}

void test_error(struct check *t)
{
    RUN_TEST(t, test_pt_bound_covers_closed_forms);
    RUN_TEST(t, test_crop_error_is_window);
    RUN_TEST(t, test_target_error);
    RUN_TEST(t, test_bound_check);
    RUN_TEST(t, test_error_refusals);
}
