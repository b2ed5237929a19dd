/*
 * tests/test_sky.c -- the background as a light (scene/light.h's sky) in every mode,
 * against the closed forms of scenes/analytic/sky-plane.scene (a floor under the sky
 * alone: L = rho Le) and scenes/analytic/sky-over-floor.scene (a black sphere hiding
 * part of the sky: L = rho Le (1 - a^2 h / d^3), derived in the scene file).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/image/image.h"
#include "files.h"
#include "tests.h"
#include "truths.h"

/* The closed form of pixel (x, y): the mean over its square, an 8 x 8 midpoint rule
 * (the sphere's outline is the only place it is not smooth). */
static double pixel_truth(const struct scene *scene, int x, int y, int sphere)
{
    double sum = 0.0;
    for (int j = 0; j < 8; j++)
        for (int i = 0; i < 8; i++)
            sum += sky_over_floor(camera_ray(&scene->camera, x + (i + 0.5) / 8,
                                             y + (j + 0.5) / 8), sphere);
    return sum / 64.0;
}

/* How a render compares with the closed form: the image mean's ratio, and the worst
 * relative error of an 8 x 8 block's mean among the blocks off the sphere. */
struct sky_score {
    double mean_ratio;
    double worst_block;
};

static struct sky_score score(const struct scene *scene, const struct image *img, int sphere)
{
    struct sky_score s = {0.0, 0.0};
    double sum = 0.0, truth_sum = 0.0;
    for (int by = 0; by + 8 <= img->height; by += 8)
        for (int bx = 0; bx + 8 <= img->width; bx += 8) {
            double b = 0.0, truth = 0.0, dark = 0.0;
            for (int y = by; y < by + 8; y++)
                for (int x = bx; x < bx + 8; x++) {
                    double exact = pixel_truth(scene, x, y, sphere);
                    b += image_get(img, x, y).y;
                    truth += exact;
                    dark += exact < 0.3 * SKY_RHO * SKY_LE;
                }
            sum += b;
            truth_sum += truth;
            if (dark == 0) /* the sphere's own pixels: the truth there is 0 */
                s.worst_block = fmax(s.worst_block, fabs(b / truth - 1.0));
        }
    s.mean_ratio = sum / truth_sum;
    return s;
}

/* truth: the closed forms above, in every mode, at settings a few seconds long.
 * tolerance: the image mean within 1% and every 8 x 8 block off the sphere within 3%,
 *   the bar make consistency holds every mode to; the sky's light is ~100% of the image,
 *   so one missing (photons, 2008, 2009 before the sky emitted photons) or counted twice
 *   (1994 or 1996 with a gather that also sees the sky) is off by 50-100%.
 * catches: the sky lighting nothing in a photon mode, counted both in a direct term and
 *   by a gather's escaped rays, its photons' power without the disc or the sphere of
 *   directions, shadow rays to the sky that ignore occluders (the sphere's shadow would
 *   be missing: 25% bright under it), a cosine sample with the wrong pdf. */
static void test_sky_in_every_mode(struct check *t)
{
    static const struct {
        const char *mode, *options;
    } modes[] = {
        {"direct", "--spp 64"},
        {"pt", "--spp 256"},
        {"photons", "--spp 4 --photons 2000000 --gather 500"},
        {"1994", "--spp 16 --photons 200000 --gather-rays 64"},
        {"1996", "--spp 16 --photons 200000 --gather-rays 64"},
        {"2008", "--spp 4 --passes 64 --photons-per-pass 20000"},
        {"2009", "--passes 256 --photons-per-pass 20000"},
        {"2008", "--paper --spp 4 --passes 128 --photons-per-pass 40000"},
        {"2009", "--paper --passes 512 --photons-per-pass 40000"},
    };
    static const char *scenes[2] = {"scenes/analytic/sky-plane.scene",
                                    "scenes/analytic/sky-over-floor.scene"};
    for (int sphere = 0; sphere < 2; sphere++) {
        struct scene *scene = load_test_scene(scenes[sphere], 0, 0);
        REQUIRE(t, scene != NULL);
        for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
            char options[256];
            snprintf(options, sizeof options, "--mode %s %s", modes[m].mode,
                     modes[m].options);
            struct image *img = photon_render("sky", options, scenes[sphere]);
            CHECK(t, img != NULL);
            if (img != NULL) {
                struct sky_score s = score(scene, img, sphere);
                printf("  sky: %-14s %-7s %-7s mean %.4f, worst block %.2f%%\n",
                       sphere ? "sky-over-floor" : "sky-plane", modes[m].mode,
                       strstr(modes[m].options, "--paper") ? "--paper" : "", s.mean_ratio,
                       100 * s.worst_block);
                CHECK(t, fabs(s.mean_ratio - 1.0) <= 0.01);
                CHECK(t, s.worst_block <= 0.03);
                image_free(img);
            }
        }
        scene_free(scene);
    }
}

void test_sky(struct check *t)
{
    RUN_TEST(t, test_sky_in_every_mode);
}
