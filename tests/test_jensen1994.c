/*
 * tests/test_jensen1994.c -- `--mode 1994` (Jensen and Christensen 1994): the order-free
 * irradiance cache (a crop is the same window of the whole image), closed forms,
 * convergence towards the path-traced reference, finite pixels on the harder scenes, the
 * command line; its caustics: test_jensen1994_caustics.c. The estimate itself (differential checking, normal test): test_trace.c.
 *
 * Images compared with a 256 x 256 reference are rendered at 64 x 64 and compared with
 * the reference averaged over 4 x 4 blocks (reference_window(), truths.h).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/image/compare.h"
#include "../src/modes/jensen1994.h"
#include "files.h"
#include "jensen1994_cases.h"
#include "tests.h"
#include "truths.h"

#define OUT "build/test_jensen1994"


/* ---- determinism ---- */

/* truth: the header of jensen1994.c: the irradiance cache is filled by a pre-pass over
 *   the whole image and the final pass only reads it (a fallback gather keeps nothing),
 *   so a crop of the specular box equals the same window of the whole image bit for bit,
 *   with the same records, and a second render with the same seed is identical: the
 *   specular box with photon maps, the Cornell box with illumination maps (on its two
 *   balls and the light; its walls are triangles, which keep photon maps). The window
 *   must reach a fallback gather (checked), so that path is covered.
 * tolerance: none.
 * catches: a cache filled by the final pass in pixel order, a pre-pass over the window
 *   only, a fallback record stored, scratch state carried from one pixel to the next. */
static void test_crop_is_bit_identical(struct check *t)
{
    static const int window[4] = {20, 28, 40, 48};
    for (int store = 0; store < 2; store++) {
        struct j94_case c = j94_small_case(store ? "scenes/cornell.scene"
                                             : "scenes/cornell-specular.scene", 48, 20000, 32);
        c.spp = 2;
        c.js.illumination_maps = store;
        struct j94_run whole = j94_render(&c);
        struct j94_run again = j94_render(&c);
        c.window = window;
        struct j94_run crop = j94_render(&c);
        CHECK(t, whole.image != NULL && again.image != NULL && crop.image != NULL);
        if (whole.image != NULL && again.image != NULL && crop.image != NULL) {
            CHECK(t, same_pixels(whole.image, again.image));
            CHECK(t, crop_is_window(whole.image, crop.image, window));
            CHECK(t, whole.stats.cache_records > 0 &&
                     crop.stats.cache_records == whole.stats.cache_records);
            CHECK(t, crop.stats.gather_fallbacks > 0);
            CHECK(t, whole.stats.photons_emitted > 0 && whole.counters.nonfinite_samples == 0);
            CHECK(t, store ? whole.stats.illumination_maps == 3 /* 2 balls, the light */
                           : whole.stats.photons_caustic > 0);
        }
        image_free(crop.image);
        image_free(again.image);
        image_free(whole.image);
    }
}

/* ---- closed forms ---- */

/* truth: a point light over a plane, L = rho Phi h / (4 pi^2 d^3). Nothing is specular
 *   (no CP photons) and gather rays leave the scene (no multiple diffuse reflection), so
 *   1994 is its direct term alone, stratified samples of a point light, exact per
 *   sample: every pixel lies between the least and greatest L on its square.
 * tolerance: that interval, widened by 1e-12 relative for rounding.
 * catches: the photon map's irradiance added at eye hits on top of light sampling
 *   (direct light twice), a gather that adds emission or background, the light samples'
 *   mean divided by the wrong count. */
static void test_point_light_over_plane(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/analytic/point-over-plane.scene", 0, 0);
    struct j94_case c = j94_small_case("scenes/analytic/point-over-plane.scene", 0, 20000, 32);
    c.spp = 4;
    struct j94_run run = j94_render(&c);
    CHECK(t, scene != NULL && run.image != NULL);
    CHECK(t, scene != NULL && run.image != NULL && within_point_over_plane(scene, run.image));
    CHECK(t, run.stats.photons_caustic == 0);
    image_free(run.image);
    scene_free(scene);
}

/* truth: scenes/analytic/point-in-sphere.scene, L = 4 everywhere: direct 0.8 (exact by
 *   light sampling), indirect 3.2, which the records gather from the photon map's
 *   irradiance where their rays land. Irradiance is uniform and a ball of radius r cuts
 *   exactly pi r^2 from a sphere it is centred on, and the estimate without its rim
 *   photon has no bias on a uniform density (photon/estimate.c), without differential
 *   checking: the image mean is 4 for n = 10 and n = 100, with each gather ray's end
 *   estimated (the paper's way) and read from records at every 16th photon.
 * tolerance: 0.09, as the same test of mode 1996, whose gathers read the same densities
 *   (seed 1: 4.027, 4.014; with records 3.976, 4.019). Counting the rim photon, as the
 *   paper's sum to n does, would add 3.2 / (n - 1) = 0.36 at n = 10, four tolerances:
 *   the estimate's form is tested, not only its limit. Measured with the CP estimate
 *   reading all photons: 9.03 and 8.10.
 * catches: direct photons left out of the irradiance the gather reads, or direct light
 *   counted twice (+0.8), the irradiance reflected without rho / pi, the rim photon
 *   counted, the normal test rejecting photons inside, records never made. */
static void test_point_in_sphere(struct check *t)
{
    static const size_t ns[] = {10, 100};
    for (size_t i = 0; i < 2 * sizeof ns / sizeof ns[0]; i++) {
        struct j94_case c = j94_small_case("scenes/analytic/point-in-sphere.scene", 16, 20000, 32);
        c.js.gather = ns[i / 2];
        c.js.differential_run = 0;
        c.js.precomputed_irradiance = i % 2 == 1 ? J94_DEFAULT_PRECOMPUTED : 0;
        struct j94_run run = j94_render(&c);
        CHECK(t, run.image != NULL);
        if (run.image == NULL)
            continue;
        CHECK_CLOSE(t, mean_luminance(run.image), 4.0, 0.09);
        CHECK(t, run.counters.nonfinite_samples == 0 &&
                     (run.stats.precomputed_records > 0) == (i % 2 == 1));
        image_free(run.image);
    }
}

/* ---- consistency ---- */

/* truth: the method is consistent: with more photons and more gradient rays the error
 *   against the converged reference falls. Window: the ceiling (x 4-59, y 0-6 of
 *   64 x 64), lit only indirectly. 4 samples a pixel. Measured relmse, 20,000 photons
 *   and 32 rays -> 200,000 and 256: 0.000480 -> 0.000299 (ratio 0.62).
 * tolerance: the ratio must be below 0.9.
 * catches: --gather-rays or --photons not reaching the render, a cache that keeps the
 *   first noisy record whatever the settings. */
static void test_error_falls_with_photons_and_rays(struct check *t)
{
    static const int ceiling[4] = {4, 0, 60, 7};
    struct image *ref = reference_window("reference/cornell-pt.pfm", 4, ceiling);
    struct j94_case c = j94_small_case("scenes/cornell.scene", 64, 20000, 32);
    c.spp = 4;
    c.window = ceiling;
    struct j94_run coarse = j94_render(&c);
    c.js.n_photons = 200000;
    c.js.gather_rays = 256;
    struct j94_run fine = j94_render(&c);
    CHECK(t, ref != NULL && coarse.image != NULL && fine.image != NULL);
    if (ref != NULL && coarse.image != NULL && fine.image != NULL) {
        double before = image_compare(coarse.image, ref).relmse;
        double after = image_compare(fine.image, ref).relmse;
        CHECK(t, after > 0 && after < 0.9 * before);
        CHECK(t, fine.stats.gradient_rays > 4 * coarse.stats.gradient_rays);
    }
    image_free(fine.image);
    image_free(coarse.image);
    image_free(ref);
}

/* ---- the two irradiance stores ---- */

/* truth: reference/cornell-pt.pfm (block-averaged to 64 x 64). The Cornell box's balls are
 *   the surfaces with illumination maps (its walls are triangles, which keep photons),
 *   so the two stores must give images equally close to the reference: the maps hold
 *   the same photons' energy, spread by the box kernel instead of the nearest-neighbour
 *   disc. The window: both balls' lower halves and the floor around them (x 16-50,
 *   y 36-58 of 64 x 64), where the floor's records gather from the balls; 4 samples a
 *   pixel, 200,000 light rays, 64 gather rays. Measured relmse: photon store 0.000960,
 *   illumination store 0.000955; with the DI maps' irradiance 1.5 times too large, 0.00199.
 * tolerance: each relmse below 0.002 and the two within a factor 1.3 of each other.
 * catches: illumination maps that lose or double a surface's energy (elements' areas
 *   wrong, DI read where CI was meant), the maps read where none exists. */
static void test_irradiance_stores_agree(struct check *t)
{
    static const int balls[4] = {16, 36, 50, 58}; /* both balls' lower halves, 64 x 64 */
    struct image *ref = reference_window("reference/cornell-pt.pfm", 4, balls);
    double relmse[2] = {0, 0};
    for (int store = 0; store < 2; store++) {
        struct j94_case c = j94_small_case("scenes/cornell.scene", 64, 200000, 64);
        c.spp = 4;
        c.window = balls;
        c.js.illumination_maps = store;
        struct j94_run run = j94_render(&c);
        CHECK(t, run.image != NULL && ref != NULL);
        if (run.image != NULL && ref != NULL)
            relmse[store] = image_compare(run.image, ref).relmse;
        CHECK(t, run.stats.illumination_maps == (store ? 3u : 0u));
        image_free(run.image);
    }
    CHECK(t, relmse[0] > 0 && relmse[0] < 0.002 && relmse[1] > 0 && relmse[1] < 0.002);
    CHECK(t, relmse[1] < 1.3 * relmse[0] && relmse[0] < 1.3 * relmse[1]);
    image_free(ref);
}

/* ---- hard cases ---- */

/* truth: render.h: nonfinite_samples is always 0 unless a bug lets one through; images
 *   are never NaN, Inf or negative. The glossy box, the museum (sphere flake, Schlick),
 *   the ring's caustic, the glass on a heightfield, at 16 x 16.
 * tolerance: none.
 * catches: 0/0 in a gather, an estimate over a zero radius, a glossy pdf of 0. */
static void test_harder_scenes_are_finite(struct check *t)
{
    static const char *scenes[] = {"scenes/cornell-glossy.scene", "scenes/museum.scene",
                                   "scenes/cardioid-ring.scene",
                                   "scenes/cognac-heightfield.scene"};
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++) {
        struct j94_case c = j94_small_case(scenes[i], 16, 5000, 16);
        c.spp = 2;
        struct j94_run run = j94_render(&c);
        CHECK(t, run.image != NULL);
        if (run.image != NULL) {
            CHECK(t, run.counters.nonfinite_samples == 0);
            CHECK(t, finite_and_positive(run.image));
            CHECK(t, mean_luminance(run.image) > 0);
        }
        image_free(run.image);
    }
}

/* ---- the command line ---- */

/* truth: the command-line contract (README): a bad value of a 1994 option exits 2
 *   with a message naming the option and leaves no output; a good run exits 0, writes
 *   the image and prints the paper's Fig. 9 statistics with --stats, and the mean
 *   samples per pixel of adaptive sampling (the rule itself: test_render.c).
 * catches: a limit missing from the option table, an output written before the options
 *   are checked, stats keys renamed or missing. */
static void test_command_line(struct check *t)
{
    static const char *const bad[][2] = {
        {"--differential -1", "--differential"}, {"--light-samples 0", "--light-samples"},
        {"--light-samples 1025", "--light-samples"}, {"--cache-accuracy 0", "--cache-accuracy"},
        {"--gather 0", "--gather"},              {"--gather-rays 1", "--gather-rays"},
        {"--adaptive -1", "--adaptive"},         {"--irradiance-store map", "--irradiance-store"}};
    CHECK(t, refuses_options("1994", bad, sizeof bad / sizeof bad[0], OUT) == 0);
    CHECK(t, photon_logged("", "--mode 1994 --width 16 --height 16 --spp 8 --photons 5000 "
                               "--gather-rays 16 --adaptive 1e-9 --stats --no-progress "
                               "-o " OUT ".pfm scenes/cornell-specular.scene",
                           OUT ".log") == 0);
    static const char *keys[] = {"mode=1994\n", "photons_stored=", "photons_caustic=",
                                 "photon_rays=", "bytes_per_photon=20.0\n", "gradient_rays=",
                                 "shadow_rays=", "seconds_photons=", "seconds_cache=",
                                 "seconds_final_pass=", "cache_records=", "nonfinite_samples=0\n",
                                 "spp=512\n", /* pixels that see the light in a ball
                                                  take 64 x --spp */
                                 "samples_per_pixel=", "illumination_ci_maps=",
                                 "projection_maps="};
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
        CHECK(t, file_contains(OUT ".log", keys[i]));
    struct error err;
    struct image *img = pfm_read(OUT ".pfm", &err);
    CHECK(t, img != NULL && img->width == 16 && img->height == 16);
    image_free(img);
    remove(OUT ".pfm");
    remove(OUT ".png");
    remove(OUT ".log");
}

/* truth: app/probe.h's contract: one row per sample with the header it documents, the
 *   exact caustic column equal to this file's closed form (mirror_caustic_irradiance(), truths.h) and
 *   the direct column to I cos / d^2; bad input exits 2 with a message and writes
 *   nothing.
 * tolerance: 1e-6 relative (the CSV's 9 digits).
 * catches: the image source on the wrong side of the mirror, the mirror's outline not
 *   tested, a missing cos, rows or columns out of order, a partial file on bad input. */
static void test_probe_command(struct check *t)
{
    static const char *bad[][2] = {
        {"scenes/mirror-caustic.scene --samples 5 -o " OUT ".csv", "--line"},
        {"scenes/mirror-caustic.scene --line 0 0 0 1 0 x --samples 5 -o " OUT ".csv", "--line"},
        {"scenes/mirror-caustic.scene --line 0 0 0 1 0 0 --samples 1 -o " OUT ".csv",
         "--samples"},
        {"scenes/no-such.scene --line 0 0 0 1 0 0 --samples 5 -o " OUT ".csv", "no-such"}};
    remove(OUT ".csv");
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        CHECK(t, photon_logged("probe", bad[i][0], OUT ".log") == 2 &&
                 file_contains(OUT ".log", bad[i][1]));
        CHECK(t, !file_exists(OUT ".csv") && no_temporaries(OUT ".csv"));
    }
    CHECK(t, photon_logged("probe", "--help", OUT ".log") == 0 &&
             file_contains(OUT ".log", "usage: photon probe") && !file_exists(OUT ".csv"));
    CHECK(t, photon_logged("probe", "scenes/mirror-caustic.scene --line 0.3 0 -0.9 0.3 0 0.9 "
                                    "--samples 7 --photons 20000 -o " OUT ".csv",
                           OUT ".log") == 0);
    char *csv = read_text_file(OUT ".csv");
    CHECK(t, csv != NULL);
    if (csv != NULL) {
        const char *header = "x,y,z,exact_direct,exact_caustic,caustic_photons,"
                             "caustic_photons_unchecked,all_photons,caustic_illumination\n";
        CHECK(t, strncmp(csv, header, strlen(header)) == 0);
        const char *row = csv + strlen(header);
        for (int i = 0; i < 7 && row != NULL; i++, row = strchr(row, '\n')) {
            row += *row == '\n';
            double v[9];
            CHECK(t, sscanf(row, "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2],
                            &v[3], &v[4], &v[5], &v[6], &v[7], &v[8]) == 9);
            struct vec3 p = vec3(v[0], v[1], v[2]);
            struct vec3 to_light = vec3_sub(vec3(0.5, 0.8, 0), p);
            double d2 = vec3_length2(to_light);
            CHECK_CLOSE(t, v[2], -0.9 + 0.3 * i, 1e-9);
            CHECK_CLOSE(t, v[3], 25 / (4 * PI) * (to_light.y / sqrt(d2)) / d2, 1e-6 * v[3]);
            CHECK_CLOSE(t, v[4], mirror_caustic_irradiance(p), 1e-6 * v[4] + 1e-12);
        }
        free(csv);
    }
    remove(OUT ".csv");
    remove(OUT ".log");
}

/* The worst 8 x 8 block of a 1994 render of scenes/glossy-floor.scene with these options
 * against reference/glossy-floor-pt.pfm; -1 when a file could not be made or read. */
static double glossy_floor_worst_block(const char *options)
{
    char args[512];
    snprintf(args, sizeof args, "--mode 1994 --photons 1000000 --spp 32 %s --no-progress "
                                "scenes/glossy-floor.scene -o " OUT "-glossy.pfm", options);
    struct error err;
    struct image *img = NULL, *ref = pfm_read("reference/glossy-floor-pt.pfm", &err);
    if (photon_logged("", args, OUT "-glossy.log") == 0)
        img = pfm_read(OUT "-glossy.pfm", &err);
    double worst = -1;
    if (img != NULL && ref != NULL && img->width == ref->width && img->height == ref->height)
        worst = image_worst_block(img, ref, NULL, 8).relative_error;
    image_free(img);
    image_free(ref);
    remove(OUT "-glossy.pfm");
    remove(OUT "-glossy.png");
    remove(OUT "-glossy.log");
    return worst;
}

/* truth: reference/glossy-floor-pt.pfm, pt converged (its blocks' noise below 0.3%): a
 *   Schlick floor (r = 0.6, a broad lobe) lit only by a wall in front of the camera.
 * tolerance: every 8 x 8 block within 3%, the bar of make consistency; the floor's
 *   illumination map, whose irradiance gather rays read as albedo / pi, must miss by over
 *   5% somewhere (measured: 6.9%, block (0, 0)): the check can fail.
 * catches: a non-Lambertian diffuse-like part reflecting irradiance as albedo / pi, in
 *   the final gather at the eye (the floor's blocks) or at a gather ray's end (the wall,
 *   which sees the floor at a grazing angle), and a glossy gather without the BRDF. */
static void test_glossy_floor(struct check *t)
{
    double gathered = glossy_floor_worst_block("");
    double lambertian = glossy_floor_worst_block("--irradiance-store illumination");
    printf("  1994: glossy floor, worst 8 x 8 block %.1f%% (illumination map %.1f%%)\n",
           100 * gathered, 100 * lambertian);
    CHECK(t, gathered >= 0 && gathered <= 0.03 && lambertian > 0.05);
}

void test_jensen1994(struct check *t)
{
    RUN_TEST(t, test_crop_is_bit_identical);
    RUN_TEST(t, test_point_light_over_plane);
    RUN_TEST(t, test_point_in_sphere);
    RUN_TEST(t, test_error_falls_with_photons_and_rays);
    RUN_TEST(t, test_irradiance_stores_agree);
    RUN_TEST(t, test_probe_command);
    RUN_TEST(t, test_harder_scenes_are_finite);
    RUN_TEST(t, test_glossy_floor);
    RUN_TEST(t, test_command_line);
}
