/*
 * tests/test_lens.c -- the thin-lens camera (scene/camera.h): its sequence, its rays, and
 * the closed form of scenes/analytic/defocused-edge.scene (the lens's image of a straight
 * edge between a white and a black wall, derived in the scene file) in every mode.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/base/rng.h"
#include "../src/base/sequence02.h"
#include "../src/image/image.h"
#include "files.h"
#include "tests.h"
#include "truths.h"

#define EDGE_LIGHT 0.5  /* the light half's radiance, rho_l Le                    */
#define EDGE_DARK 0.1   /* the dark half's, rho_d Le                              */
#define EDGE_Z 10.0     /* the wall's distance from the camera ...                */
#define EDGE_D 5.0      /* ... the distance in focus ...                          */
#define EDGE_R 1.5      /* ... and the lens's radius (the scene file's numbers)   */

/* truth: the definition of a (t,k,4)-net in base 2: with sequence02_point()'s two
 *   coordinates first, the first 2^k points put exactly 2^t in every elementary box
 *   2^-d1 x 2^-d2 x 2^-d3 x 2^-d4 of volume 2^(t-k), counted by brute force for every
 *   d1 + d2 + d3 + d4 = k - t, k <= 10, t = 3 (Sobol's first four dimensions are a
 *   (3,4)-sequence: t is at most the sum of the polynomials' degrees less one, 0 + 0 +
 *   1 + 2), under several random digital shifts.
 * tolerance: none (counts).
 * catches: wrong direction numbers or a wrong recurrence (a lens point that repeats the
 *   pixel point's coordinates, or van der Corput again, fails at once), the lens point
 *   drawn from a second (0,2)-sequence with the same index, a shift applied to the index. */
static void test_lens_points_are_a_net(struct check *t)
{
    static int count[1 << 10];
    const int quality = 3;
    for (int shift = 0; shift < 4; shift++) {
        struct rng r = rng_stream(7, STREAM_TEST, (uint64_t)shift, 0);
        uint64_t a = shift == 0 ? 0 : rng_next(&r), b = shift == 0 ? 0 : rng_next(&r);
        for (int k = quality; k <= 10; k++)
            for (int d1 = 0; d1 <= k - quality; d1++)
                for (int d2 = 0; d1 + d2 <= k - quality; d2++)
                    for (int d3 = 0; d1 + d2 + d3 <= k - quality; d3++) {
                        int d4 = k - quality - d1 - d2 - d3;
                        memset(count, 0, sizeof count);
                        for (uint32_t i = 0; i < (1u << k); i++) {
                            double x[4];
                            sequence02_point(i, (uint32_t)a, (uint32_t)(a >> 32), &x[0], &x[1]);
                            sequence02_lens_point(i, (uint32_t)b, (uint32_t)(b >> 32), &x[2],
                                                  &x[3]);
                            int box = (int)(x[0] * (1 << d1));
                            box = (box << d2) + (int)(x[1] * (1 << d2));
                            box = (box << d3) + (int)(x[2] * (1 << d3));
                            box = (box << d4) + (int)(x[3] * (1 << d4));
                            count[box]++;
                        }
                        int exact = 1;
                        for (int c = 0; c < (1 << (k - quality)); c++)
                            exact &= count[c] == 1 << quality;
                        CHECK(t, exact);
                    }
    }
}

/* truth: the thin lens's geometry (camera.h): every ray through one image point, from
 *   any lens point, passes through the point where the pinhole ray through it meets the
 *   plane in focus; it starts on the lens's disc, in the plane of u and v; lens points
 *   are uniform on the disc (mean 0, E[r^2] = R^2 / 2); and lens_radius 0 gives
 *   camera_ray()'s ray bit for bit.
 * tolerance: 1e-12 relative for the geometry (a few roundings); 5 standard errors for the
 *   moments over 100,000 random lens points.
 * catches: aiming at distance focus along the ray instead of along w (points off the
 *   image's centre would miss by a cosine), a lens in the wrong plane, a radius used as a
 *   diameter, the polar map r = u (not uniform: E[r^2] = R^2 / 3), a lens ray for the
 *   pinhole that differs by a rounding. */
static void test_lens_rays_meet_in_focus(struct check *t)
{
    struct camera c;
    memset(&c, 0, sizeof c);
    c.from = vec3(1, 2, 3);
    c.at = vec3(-2, 0.5, -4);
    c.up = vec3(0.1, 1, 0);
    c.fov = 50;
    camera_setup(&c, 40, 30);
    struct rng r = rng_stream(11, STREAM_TEST, 0, 0);
    for (int k = 0; k < 100; k++) {
        double px = 40 * rng_uniform(&r), py = 30 * rng_uniform(&r);
        double lx = rng_uniform(&r), ly = rng_uniform(&r);
        struct ray pin = camera_ray(&c, px, py), lens = camera_lens_ray(&c, px, py, lx, ly);
        CHECK(t, memcmp(&pin, &lens, sizeof pin) == 0);
    }
    c.lens_radius = 0.25;
    c.focus = 7;
    const int n = 100000;
    double sum_a = 0, sum_r2 = 0, worst = 0;
    for (int k = 0; k < n; k++) {
        double px = 40 * rng_uniform(&r), py = 30 * rng_uniform(&r);
        struct ray pin = camera_ray(&c, px, py);
        struct vec3 focus_point = vec3_madd(pin.origin, pin.dir, c.focus / vec3_dot(pin.dir, c.w));
        struct ray ray = camera_lens_ray(&c, px, py, rng_uniform(&r), rng_uniform(&r));
        struct vec3 offset = vec3_sub(ray.origin, c.from);
        double s = vec3_dot(vec3_sub(focus_point, ray.origin), c.w) / vec3_dot(ray.dir, c.w);
        struct vec3 reached = vec3_madd(ray.origin, ray.dir, s);
        worst = fmax(worst, vec3_length(vec3_sub(reached, focus_point)) / c.focus);
        worst = fmax(worst, fabs(vec3_dot(offset, c.w)) / c.lens_radius);
        worst = fmax(worst, fabs(vec3_length(ray.dir) - 1));
        CHECK(t, vec3_length(offset) <= c.lens_radius * (1 + 1e-12));
        sum_a += vec3_dot(offset, c.u) / c.lens_radius;
        sum_r2 += vec3_length2(offset) / (c.lens_radius * c.lens_radius);
    }
    CHECK(t, worst <= 1e-12);
    /* a = r cos(phi): variance E[r^2] / 2 = 1/4; r^2 is uniform on [0, 1]: variance 1/12 */
    CHECK_CLOSE(t, sum_a / n, 0.0, 5 * sqrt(0.25 / n));
    CHECK_CLOSE(t, sum_r2 / n, 0.5, 5 * sqrt(1.0 / 12 / n));
}

/* The integral G of the share P(t) of the unit disc left of the chord a = t (the scene
 * file's closed form). */
static double disc_share_integral(double t)
{
    if (t <= -1)
        return 0.0;
    if (t >= 1)
        return t;
    double s = sqrt(1 - t * t);
    return t + 1 - (t * acos(t) - s + s * s * s / 3 + PI) / PI;
}

/* The closed form of column x (every row is the same): rho_d Le plus (rho_l - rho_d) Le
 * times the mean of P over the column's span of t, t = sx Z D / (R (Z - D)) linear in
 * the image x. */
static double edge_truth(const struct scene *scene, int x)
{
    const struct camera *c = &scene->camera;
    double scale = EDGE_Z * EDGE_D / (EDGE_R * (EDGE_Z - EDGE_D)) * c->tan_half * c->aspect;
    double t0 = (2.0 * x / c->width - 1) * scale, t1 = (2.0 * (x + 1) / c->width - 1) * scale;
    double share = (disc_share_integral(t1) - disc_share_integral(t0)) / (t1 - t0);
    return EDGE_DARK + (EDGE_LIGHT - EDGE_DARK) * share;
}

/* The largest difference of a column's mean (over its rows) from edge_truth(), and in
 * *ratio the image mean's ratio to the closed form's. */
static double worst_column(const struct scene *scene, const struct image *img, double *ratio)
{
    double sum = 0, truth_sum = 0, worst = 0;
    for (int x = 0; x < img->width; x++) {
        double column = 0;
        for (int y = 0; y < img->height; y++)
            column += image_get(img, x, y).y / img->height;
        sum += column;
        truth_sum += edge_truth(scene, x);
        worst = fmax(worst, fabs(column - edge_truth(scene, x)));
    }
    *ratio = sum / truth_sum;
    return worst;
}

/* truth: the closed form, against the shipped reference (pt, 65,536 samples a pixel).
 * tolerance: 1e-4 for a column and for the mean's ratio: the reference's two seeds
 *   differ by a relmse of 2e-8, a pixel's noise about 1e-4 of its value, a column's of
 *   8 pixels about 2e-5 at most.
 * catches: a reference made before a change to the lens, or one the closed form does
 *   not describe (the scene file's numbers changed without its derivation). */
static void test_defocused_edge_reference(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/analytic/defocused-edge.scene", 0, 0);
    struct error err;
    struct image *img = pfm_read("reference/defocused-edge-pt.pfm", &err);
    REQUIRE(t, scene != NULL && img != NULL);
    double ratio, worst = worst_column(scene, img, &ratio);
    printf("  lens: the reference's mean %.6f, worst column %.6f\n", ratio, worst);
    CHECK(t, fabs(ratio - 1) <= 1e-4 && worst <= 1e-4);
    image_free(img);
    scene_free(scene);
}

/* truth: the closed form of scenes/analytic/defocused-edge.scene, in every mode, at
 *   settings a few seconds long; and the blur's width: the pinhole's image of the same
 *   wall is sharp (test_zero_aperture_is_the_pinhole).
 * tolerance: the image mean within 1% and each column's mean (over its 8 rows) within
 *   0.01 = 2% of the light half's radiance. The blur spans 17 columns, across which the
 *   columns go from 0.1 to 0.5; a lens of the wrong radius, or focused at the wrong
 *   distance, moves the columns halfway across by 0.03 or more (a radius of 1.2 instead
 *   of 1.5 by 0.03), the pinhole by up to 0.2. The noise of a column at 64 samples is
 *   about 0.005 (pt: 0.001 at 256). 2009 --paper takes its eye rays as 2009 does and
 *   is not here: its light is photons alone, which leave the columns of the light half
 *   +-0.014 noisy at 1024 passes of 40,000 (9 s), far from the edge as near it.
 * catches: a lens that is not sampled in some mode (2008's fixed eye rays or 2009's new
 *   ones each pass taking the pinhole's), a lens sampled over the square, the radius or
 *   the focus read wrong. (A lens point that follows the pixel point is caught by
 *   test_lens_points_are_a_net, not here: with a pixel's own shifts it still averages
 *   close to the truth.) */
static void test_defocused_edge_in_every_mode(struct check *t)
{
    static const struct {
        const char *mode, *options;
    } modes[] = {
        {"direct", "--spp 64"},
        {"pt", "--spp 256"},
        {"photons", "--spp 64 --photons 2000000 --gather 500"},
        {"1994", "--spp 64 --photons 200000 --gather-rays 16"},
        {"1996", "--spp 64 --photons 200000 --gather-rays 16"},
        {"2008", "--spp 64 --passes 64 --photons-per-pass 20000"},
        {"2009", "--passes 256 --photons-per-pass 20000"},
        {"2008", "--paper --spp 64 --passes 64 --photons-per-pass 40000"},
    };
    const char *path = "scenes/analytic/defocused-edge.scene";
    struct scene *scene = load_test_scene(path, 0, 0);
    REQUIRE(t, scene != NULL);
    CHECK(t, scene->camera.lens_radius == EDGE_R && scene->camera.focus == EDGE_D &&
                 scene->camera.from.z == EDGE_Z);
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        char options[256];
        snprintf(options, sizeof options, "--mode %s %s", modes[m].mode, modes[m].options);
        struct image *img = photon_render("lens", options, path);
        CHECK(t, img != NULL);
        if (img != NULL) {
            double ratio, worst = worst_column(scene, img, &ratio);
            printf("  lens: defocused edge %-7s %-7s mean %.4f, worst column %.4f\n",
                   modes[m].mode, strstr(modes[m].options, "--paper") ? "--paper" : "",
                   ratio, worst);
            CHECK(t, fabs(ratio - 1) <= 0.01);
            CHECK(t, worst <= 0.01);
            image_free(img);
        }
    }
    scene_free(scene);
}

/* Removes name, a .pfm, and the PNG photon writes beside it. */
static void remove_with_png(const char *name)
{
    char png[300];
    size_t n = strlen(name);
    remove(name);
    if (n > 4 && n < sizeof png) {
        snprintf(png, sizeof png, "%.*s.png", (int)(n - 4), name);
        remove(png);
    }
}

/* Writes scene file `from` to `to` with its camera line's end, from the word "aperture"
 * on, replaced by lens (which may be ""). */
static void write_with_lens(const char *from, const char *to, const char *lens)
{
    char *text = read_text_file(from);
    char *camera = text == NULL ? NULL : strstr(text, "\ncamera ");
    char *aperture = camera == NULL ? NULL : strstr(camera, " aperture ");
    char *end = camera == NULL ? NULL : strchr(camera + 1, '\n');
    if (end == NULL || text == NULL) {
        free(text);
        return; /* to stays absent, and the render of it fails */
    }
    size_t keep = (size_t)((aperture != NULL && aperture < end ? aperture : end) - text);
    size_t size = strlen(text) + strlen(lens) + 2;
    char *out = malloc(size);
    if (out != NULL) {
        snprintf(out, size, "%.*s %s%s", (int)keep, text, lens, end);
        write_text_file(to, out);
    }
    free(out);
    free(text);
}

/* truth: a lens of radius 0 is the pinhole (camera.h): the camera line with "aperture 0
 *   focus 3" renders the bytes the line without it renders, in every mode; and the
 *   defocused edge's pinhole image is sharp (the closed form with R -> 0: rho_l Le right
 *   of the edge, rho_d Le left of it).
 * tolerance: none for the bytes; 1e-4 for the pinhole's pixels, but in the two columns
 *   beside the edge (in direct mode the wall's radiance is exact but for roundings: one
 *   light, no occluder, and a sky sample's estimate rho Le whatever its direction).
 * catches: a radius-0 lens that draws its points anyway and moves a ray by a rounding, a
 *   lens stream that shifts the pixel's (0,2)-sequence or its random numbers. */
static void test_zero_aperture_is_the_pinhole(struct check *t)
{
    static const char *modes[] = {
        "direct --spp 4",
        "pt --spp 4",
        "photons --spp 2 --photons 20000 --gather 50",
        "1994 --spp 2 --photons 20000 --gather-rays 4",
        "1996 --spp 2 --photons 20000 --gather-rays 4",
        "2008 --spp 2 --passes 2 --photons-per-pass 5000",
        "2009 --passes 4 --photons-per-pass 5000",
    };
    char pinhole[256], zero[256], a[256], b[256], log[256], args[1024];
    temp_name(pinhole, sizeof pinhole, "lens", "pinhole.scene");
    temp_name(zero, sizeof zero, "lens", "zero.scene");
    temp_name(a, sizeof a, "lens", "a.pfm");
    temp_name(b, sizeof b, "lens", "b.pfm");
    temp_name(log, sizeof log, "lens", "zero.log");
    write_with_lens("scenes/analytic/defocused-edge.scene", pinhole, "");
    write_with_lens("scenes/analytic/defocused-edge.scene", zero, "aperture 0 focus 3");
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        snprintf(args, sizeof args, "--mode %s --no-progress %s -o %s", modes[m], pinhole, a);
        CHECK(t, photon_logged("", args, log) == 0);
        snprintf(args, sizeof args, "--mode %s --no-progress %s -o %s", modes[m], zero, b);
        CHECK(t, photon_logged("", args, log) == 0);
        CHECK(t, files_equal(a, b));
        if (m == 0) {
            struct error err;
            struct image *img = pfm_read(a, &err);
            CHECK(t, img != NULL);
            int sharp = img != NULL;
            for (int y = 0; img != NULL && y < img->height; y++)
                for (int x = 0; x < img->width; x++)
                    if (x != img->width / 2 - 1 && x != img->width / 2)
                        sharp &= fabs(image_get(img, x, y).y -
                                      (x < img->width / 2 ? EDGE_DARK : EDGE_LIGHT)) <= 1e-4;
            CHECK(t, sharp);
            image_free(img);
        }
        remove_with_png(a);
        remove_with_png(b);
    }
    remove(pinhole);
    remove(zero);
    remove(log);
}

/* truth: a crop equals its window of the whole image (render.h), through the lens too:
 *   2009 and pt with --crop against the same pixels of the whole render.
 * tolerance: none (bit for bit).
 * catches: a lens point keyed by the window's pixel instead of the whole image's. */
static void test_defocused_crop_is_its_window(struct check *t)
{
    static const char *modes[] = {"pt --spp 8", "2009 --passes 8 --photons-per-pass 5000"};
    static const int window[4] = {20, 2, 44, 7};
    char whole[256], crop[256], window_file[256], log[256], args[1024];
    temp_name(whole, sizeof whole, "lens", "whole.pfm");
    temp_name(crop, sizeof crop, "lens", "crop.pfm");
    temp_name(window_file, sizeof window_file, "lens", "crop.pfm.window");
    temp_name(log, sizeof log, "lens", "crop.log");
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        const char *path = "scenes/analytic/defocused-edge.scene";
        snprintf(args, sizeof args, "--mode %s --no-progress %s -o %s", modes[m], path, whole);
        CHECK(t, photon_logged("", args, log) == 0);
        snprintf(args, sizeof args, "--mode %s --no-progress --crop %d %d %d %d %s -o %s",
                 modes[m], window[0], window[1], window[2], window[3], path, crop);
        CHECK(t, photon_logged("", args, log) == 0);
        struct error err;
        struct image *a = pfm_read(whole, &err), *b = pfm_read(crop, &err);
        CHECK(t, a != NULL && b != NULL && crop_is_window(a, b, window));
        image_free(a);
        image_free(b);
        remove_with_png(whole);
        remove_with_png(crop);
        remove(window_file);
    }
    remove(log);
}

void test_lens(struct check *t)
{
    RUN_TEST(t, test_lens_points_are_a_net);
    RUN_TEST(t, test_lens_rays_meet_in_focus);
    RUN_TEST(t, test_defocused_edge_reference);
    RUN_TEST(t, test_defocused_edge_in_every_mode);
    RUN_TEST(t, test_zero_aperture_is_the_pinhole);
    RUN_TEST(t, test_defocused_crop_is_its_window);
}
