/*
 * tests/test_pt.c -- the path tracer against closed forms (scenes/analytic/), with
 * tolerances from the standard errors the renderer itself reports (its variance image).
 */
#include <math.h>
#include <stdio.h>

#include "../src/image/compare.h"
#include "../src/modes/direct.h"
#include "../src/modes/pt.h"
#include "files.h"
#include "tests.h"
#include "truths.h"

static struct render_result render_seed(const struct scene *scene, int pt, int spp,
                                        uint64_t seed)
{
    struct render_settings rs = render_settings_whole(scene, seed, spp,
                                                      pt ? MAX_DEPTH_LIMIT : DIRECT_MAX_DEPTH);
    struct render_counters counters = {0};
    if (pt)
        return render_pt(scene, &rs, 1, NULL, &counters);
    return render_direct(scene, &rs, 1, NULL, &counters);
}

/* truth: the white furnace, L = Le / (1 - rho) = 5 in every pixel, whatever the path.
 * tolerance: the image mean within 4 standard errors, the SE from the render's own
 *   variance image (green channel; the channels are identical, so they are not
 *   independent and only one is used). 1024 samples make the SE below 0.2% of the
 *   answer, so a bias of 1% cannot pass.
 * catches: Russian roulette without reweighting (darker), a missing 1/pi or cos in the
 *   Lambertian sampling weight, MIS weights that do not sum to one, a path cut by a
 *   depth limit (darker by rho^depth). */
static void test_furnace(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/analytic/furnace.scene", 0, 0);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    struct render_result r = render_seed(scene, 1, 1024, 7);
    double sum = 0, var = 0;
    size_t n = (size_t)r.image->width * (size_t)r.image->height;
    for (size_t i = 0; i < n; i++) {
        sum += r.image->pixels[i].y;
        var += r.variance->pixels[i].y;
    }
    double se = sqrt(var) / n;
    CHECK(t, se > 0 && se < 0.01);
    CHECK_CLOSE(t, sum / n, 5.0, 4 * se);
    render_result_free(&r);
    scene_free(scene);
}

/* truth: Lambert's polygon formula for the floor under a square light, integrated over
 *   each pixel with an 8 x 8 midpoint rule (its error is far below the noise), for both
 *   --mode direct and --mode pt (the light is black, so pt adds nothing).
 * tolerance: per pixel 5 standard errors from the variance image, plus 1% of the value
 *   for the quadrature near the light's edge; and over the floor's pixels the sum of
 *   squared z-scores must be near its expectation (within 4 sigma of a chi-square).
 * catches: area pdf not converted to solid angle, a wrong cos at the light, light picked
 *   without dividing by its probability, MIS double counting (pt brighter than direct). */
static void test_area_light_over_floor(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/analytic/area-over-floor.scene", 0, 0);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    for (int pt = 0; pt < 2; pt++) {
        struct render_result r = render_seed(scene, pt, 64, 7);
        double chi2 = 0;
        int n_floor = 0;
        for (int y = 0; y < r.image->height; y++)
            for (int x = 0; x < r.image->width; x++) {
                double exact = 0;
                for (int j = 0; j < 8; j++)
                    for (int i = 0; i < 8; i++)
                        exact += area_over_floor(camera_ray(&scene->camera, x + (i + 0.5) / 8,
                                                            y + (j + 0.5) / 8));
                exact /= 64;
                double v = image_get(r.image, x, y).y;
                double se = sqrt(image_get(r.variance, x, y).y);
                CHECK(t, fabs(v - exact) <= 5 * se + 0.01 * exact);
                if (se > 0 && exact < 1.0) {
                    chi2 += (v - exact) * (v - exact) / (se * se);
                    n_floor++;
                }
            }
        CHECK(t, n_floor > 300);
        CHECK(t, fabs(chi2 - n_floor) <= 4 * sqrt(2.0 * n_floor));
        render_result_free(&r);
    }
    scene_free(scene);
}

/* Makes every emitter of the scene brighter by factor, in its light and its material. */
static void brighten_lights(struct scene *scene, double factor)
{
    for (size_t i = 0; i < scene->n_lights; i++)
        scene->lights[i].radiance = vec3_scale(scene->lights[i].radiance, factor);
    for (size_t i = 0; i < scene->n_materials; i++)
        scene->materials[i].emission = vec3_scale(scene->materials[i].emission, factor);
}

/* truth: two renders of the same scene with different seeds estimate the same image, so
 *   the per-pixel test of image_consistency() (z with both variances, Sidak-corrected
 *   over all pixels at alpha = 0.01) must accept them; a render whose light is 2% too
 *   bright must be refused.
 * tolerance: the test's own level, alpha = 0.01, with fixed seeds.
 * catches: a variance image of single samples instead of the mean (too wide: everything
 *   passes), or of the sum (too narrow: independent renders fail), a variance that ignores
 *   the test image's noise. The biased render fails at the pixels that see the light
 *   itself, whose variance is zero: at 256 samples a 2% bias in the noisy diffuse pixels
 *   is below one standard error, which is why references are judged by relmse as well. */
static void test_independent_renders_agree(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/cornell.scene", 32, 32);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    struct render_result a = render_seed(scene, 1, 256, 1);
    struct render_result b = render_seed(scene, 1, 256, 2);
    brighten_lights(scene, 1.02);
    struct render_result biased = render_seed(scene, 1, 256, 2);
    struct consistency same = image_consistency(b.image, a.image, b.variance, a.variance, 0.01);
    struct consistency off =
        image_consistency(biased.image, a.image, biased.variance, a.variance, 0.01);
    CHECK(t, same.consistent && same.n_failed == 0);
    CHECK(t, !off.consistent && off.n_failed > 0);
    render_result_free(&biased);
    render_result_free(&b);
    render_result_free(&a);
    scene_free(scene);
}

/* The mean over pixels and channels of (a - b)^2 / (ref^2 + 1e-2), relmse's weighting
 * (compare.h) with the reference's values in the denominator whatever a and b are; with
 * var_a (a variance image) for a - b, the mean of var_a / (ref^2 + 1e-2). */
static double weighted_mean_square(const struct image *a, const struct image *b,
                                   const struct image *ref)
{
    double sum = 0;
    size_t n = (size_t)ref->width * (size_t)ref->height;
    for (size_t i = 0; i < n; i++) {
        double x[3] = {a->pixels[i].x, a->pixels[i].y, a->pixels[i].z};
        double y[3] = {0, 0, 0}, r[3] = {ref->pixels[i].x, ref->pixels[i].y, ref->pixels[i].z};
        if (b != NULL) {
            y[0] = b->pixels[i].x;
            y[1] = b->pixels[i].y;
            y[2] = b->pixels[i].z;
        }
        for (int c = 0; c < 3; c++)
            sum += (b != NULL ? (x[c] - y[c]) * (x[c] - y[c]) : x[c]) / (r[c] * r[c] + 1e-2);
    }
    return sum / (3.0 * n);
}

/* truth: reference/cornell-pt.pfm and its variance image, made by an independent run
 *   (another seed, 4096 samples). Where the renderer agrees with the reference, a short
 *   render a's relmse against it is its own noise and the reference's: half the mean
 *   square difference of a and an independent render b of the same settings (weighted
 *   as relmse is), plus the reference's variance so weighted; any bias between them adds
 *   to a's relmse alone. Measured from b rather than predicted from the reference's
 *   variance, because pt's stratified samples (render.h) make a render's noise less than
 *   independent samples' would be (16 samples: 0.0052 where they predict 0.0075).
 * tolerance: 20% of that: relmse averages 196,608 squared errors, so its own scatter is a
 *   few percent (measured: within 1%). A bias of 5% (both renders times 1.05) makes it
 *   0.00199 at 64 samples where 0.00133 is expected, and fails; at 16 samples it is lost
 *   in the noise (0.00637, 0.00575), and smaller biases are for converged comparisons.
 * catches: a renderer that drifted from the reference (any bias), a stale reference, a
 *   render equal to the reference (the same samples). */
static void test_error_against_reference(struct check *t)
{
    struct error err;
    struct image *ref = pfm_read("reference/cornell-pt.pfm", &err);
    struct image *ref_var = pfm_read("reference/cornell-pt-var.pfm", &err);
    struct scene *scene = load_test_scene("scenes/cornell.scene", 0, 0);
    CHECK(t, ref != NULL && ref_var != NULL && scene != NULL);
    if (ref != NULL && ref_var != NULL && scene != NULL) {
        for (int spp = 16; spp <= 64; spp *= 4) {
            struct render_result a = render_seed(scene, 1, spp, 1000);
            struct render_result b = render_seed(scene, 1, spp, 1001);
            double relmse = image_compare(a.image, ref).relmse;
            double expected = weighted_mean_square(a.image, b.image, ref) / 2 +
                              weighted_mean_square(ref_var, NULL, ref);
            printf("  pt: Cornell box at %d samples, relmse %.5f against the reference, "
                   "%.5f expected from its noise\n", spp, relmse, expected);
            CHECK(t, fabs(relmse - expected) <= 0.2 * expected);
            render_result_free(&b);
            render_result_free(&a);
        }
    }
    scene_free(scene);
    image_free(ref_var);
    image_free(ref);
}

/* Whether `--mode mode` warned on stderr, with text, at its start on scene. */
static int warns(const char *mode, const char *scene, const char *text)
{
    char args[1024], log[256], out[256], png[256];
    temp_name(log, sizeof log, "pt", "warn.log");
    temp_name(out, sizeof out, "pt", "warn.pfm");
    temp_name(png, sizeof png, "pt", "warn.png");
    snprintf(args, sizeof args, "--mode %s --quality preview --width 8 --height 8 "
             "--no-progress %s -o %s", mode, scene, out);
    int warned = photon_logged("", args, log) == 0 && file_contains(log, text);
    remove(log);
    remove(out);
    remove(png);
    return warned;
}

/* truth: a point light's light through a mirror onto the floor (scenes/mirror-caustic.scene)
 *   has probability zero in pt; the specular box's light is an area light, whose caustics
 *   pt finds (slowly), and the Cornell box has nothing specular.
 *   --mode photons, the photon map seen directly, is never a converged image.
 *   2008's fixed hit points on a glossy lobe (the glossy box's Ward floor) speckle, which 2009
 *   avoids; Lambertian walls, mirrors, glass and Schlick's broad r >= 1/2 (glossy-floor,
 *   where 2008 converges: reference/suite.md) have no such lobe.
 *   The photon map's estimates on a sphere flake of four levels or more count the photons
 *   of many spheres against one disc's area, bright in photons, 1994 and 1996 (the
 *   consistency table of reference/suite.md: sphereflake, sphereflake-6), where pt has no
 *   radius and 2008's and 2009's shrink; three levels render within 1% of pt in 1996.
 * tolerance: none: the warning is there or not.
 * catches: an image silently missing its caustics, a warning for area lights' caustics, or
 *   for point lights in a scene with nothing specular; a photon map shown as if it were a
 *   converged image; 2008 silently speckled by glossy lobes, or warning of mirrors, glass
 *   and Lambertian surfaces; a deep flake rendered bright in silence, or a warning for a
 *   shallow flake or for the modes whose radii shrink. */
static void test_warns_of_what_it_cannot_find(struct check *t)
{
    static const char *caustics = "warning: pt cannot find the caustics of point lights";
    CHECK(t, warns("pt", "scenes/mirror-caustic.scene", caustics));
    CHECK(t, !warns("pt", "scenes/cornell-specular.scene", caustics));
    CHECK(t, !warns("pt", "scenes/analytic/point-over-plane.scene", caustics));
    CHECK(t, warns("photons", "scenes/cornell.scene", "warning: --mode photons shows"));
    CHECK(t, !warns("1996", "scenes/cornell.scene", "warning:"));
    static const char *glossy = "warning: 2008's hit points estimate glossy lobes (the first "
                                "in material 'floor')";
    CHECK(t, warns("2008", "scenes/cornell-glossy.scene", glossy));
    CHECK(t, !warns("2009", "scenes/cornell-glossy.scene", "warning:"));
    CHECK(t, !warns("2008", "scenes/cornell.scene", "warning:"));
    CHECK(t, !warns("2008", "scenes/glossy-floor.scene", "warning:"));
    CHECK(t, !warns("2008", "scenes/cornell-specular.scene", "warning:"));
    static const char *flake = "photon estimates span many of a sphere flake's spheres";
    CHECK(t, warns("1996", "scenes/sphereflake-6.scene", flake));
    CHECK(t, warns("1994", "scenes/sphereflake.scene", flake));
    CHECK(t, warns("photons", "scenes/sphereflake.scene", flake));
    CHECK(t, !warns("2009", "scenes/sphereflake-6.scene", "warning:"));
    CHECK(t, !warns("pt", "scenes/sphereflake-6.scene", "warning:"));
    char shallow[256];
    temp_name(shallow, sizeof shallow, "pt", "flake3.scene");
    write_text_file(shallow, "camera 2.1 1.3 1.7  0 0 0  0 0 1  45\n"
                             "material flake phong 0.45 0.35 0.25  0.5 0.5 0.5  30\n"
                             "sphereflake 0 0 0 0.5 3  0 0 1  flake\n"
                             "light point 4 3 2  400 400 400\n");
    CHECK(t, !warns("1996", shallow, "warning:"));
    remove(shallow);
}

void test_pt(struct check *t)
{
    RUN_TEST(t, test_warns_of_what_it_cannot_find);
    RUN_TEST(t, test_furnace);
    RUN_TEST(t, test_area_light_over_floor);
    RUN_TEST(t, test_independent_renders_agree);
    RUN_TEST(t, test_error_against_reference);
}
