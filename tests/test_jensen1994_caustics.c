/*
 * tests/test_jensen1994_caustics.c -- `--mode 1994`'s caustics (Jensen and Christensen
 * 1994): the CP photons on the specular box, the paper's Fig. 7-8 profile against the
 * exact solution, a glossy caustic, and the lights seen through glossy lobes.
 *
 * Images compared with a 256 x 256 reference are rendered at 64 x 64 and compared with
 * the reference averaged over 4 x 4 blocks (reference_window(), truths.h).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/modes/jensen1994.h"
#include "../src/modes/jensen1994_maps.h"
#include "../src/photon/estimate.h"
#include "../src/photon/kdtree.h"
#include "files.h"
#include "jensen1994_cases.h"
#include "tests.h"
#include "truths.h"

/* ---- caustics ---- */

/* truth: Sec. 3.3 and 4.0.2: the caustic is read from the CP photons, which the plain
 *   Cornell box (all Lambertian) has none of and the specular box has. In the glass
 *   sphere's caustic on the floor (x 38-47, y 54-61 of 64 x 64, 4 samples a pixel) the
 *   mean must match the specular reference's. Measured: 1.061 times the reference's
 *   mean; 0.405 without the caustic term, 1.475 with all photons read as caustic.
 * tolerance: 15% of the window's mean.
 * catches: caustics missing (the window ~40% dark), counted twice (CP photons also in
 *   the gathered light of the eye's hit), the CP bit not set. */
static void test_caustic(struct check *t)
{
    static const int window[4] = {38, 54, 48, 62};
    struct image *ref = reference_window("reference/cornell-specular-pt.pfm", 4, window);
    struct j94_case c = j94_small_case("scenes/cornell-specular.scene", 64, 200000, 32);
    c.spp = 4;
    c.window = window;
    struct j94_run run = j94_render(&c);
    struct j94_case plain = j94_small_case("scenes/cornell.scene", 16, 20000, 16);
    struct j94_run lambertian = j94_render(&plain);
    CHECK(t, ref != NULL && run.image != NULL && lambertian.image != NULL);
    if (ref != NULL && run.image != NULL && lambertian.image != NULL) {
        double ratio = mean_luminance(run.image) / mean_luminance(ref);
        CHECK_CLOSE(t, ratio, 1.0, 0.15);
        CHECK(t, run.stats.photons_caustic > 0 && lambertian.stats.photons_caustic == 0);
    }
    image_free(lambertian.image);
    image_free(run.image);
    image_free(ref);
}

/* ---- the paper's Fig. 7-8: a caustic profile against the exact solution ---- */

/* The caustic profile along x = 0.3 across the caustic (edges at z = +-0.72): the
 * relative RMS error (relative to the caustic's level inside, 1.9 W/m^2) of the CP
 * estimate (n = 200, the paper's) without and with differential checking and of the
 * caustic illumination map, over samples away from the edges (far) and within 0.1 of
 * them (near). */
struct profile_errors {
    double far[3], near[3]; /* [0]: photons unchecked, [1]: checked, [2]: CI */
};

/* The caustic irradiance at p on the floor (normal +y) by variant (as above). */
static double caustic_at(const struct scene *scene, const struct irradiance_stores *st,
                         struct vec3 p, int variant, struct nearest *nn)
{
    struct irradiance_settings is = {200, HUGE_VAL, PHOTON_CAUSTIC,
                                     variant == 1 ? DIFFERENTIAL_RUN : 0, 1};
    struct store_query q = {p, vec3(0, 1, 0), -1, 0, 0, &is, NULL};
    struct hit hit; /* the floor under p: its primitive and (u, v) */
    if (variant == 2 && scene_intersect(scene, make_ray(vec3(p.x, 1, p.z), vec3(0, -1, 0)),
                                        INFINITY, &hit)) {
        q.prim = hit.prim;
        q.u = hit.u;
        q.v = hit.v;
    }
    return vec3_luminance(stored_irradiance(st, &q, nn));
}

static struct profile_errors caustic_profile_errors(const struct scene *scene,
                                                    const struct irradiance_stores *photons,
                                                    const struct irradiance_stores *maps)
{
    struct profile_errors pe = {{0, 0, 0}, {0, 0, 0}};
    int n_far = 0, n_near = 0;
    struct nearest *nn = nearest_create(200);
    for (int i = 0; i <= 200; i++) {
        struct vec3 p = vec3(0.3, 0, -0.9 + 1.8 * i / 200.0);
        double exact = mirror_caustic_irradiance(p), edge = fabs(fabs(p.z) - 0.72);
        if (exact <= 0 && edge > 0.1)
            continue; /* outside, away from the edge: no caustic to err on */
        for (int variant = 0; variant < 3; variant++) {
            double e = caustic_at(scene, variant == 2 ? maps : photons, p, variant, nn);
            double error = (e - exact) / 1.9;
            if (edge > 0.1)
                pe.far[variant] += error * error;
            else
                pe.near[variant] += error * error;
        }
        n_far += edge > 0.1;
        n_near += edge <= 0.1;
    }
    for (int c = 0; c < 3; c++) {
        pe.far[c] = sqrt(pe.far[c] / n_far);
        pe.near[c] = sqrt(pe.near[c] / n_near);
    }
    nearest_free(nn);
    return pe;
}

/* Whether the caustic estimate from the CP photons' own tree (what stored_irradiance()
 * reads) equals the estimate from the whole map filtered to CP photons, the paper's one
 * map, along the profile (the same photons: equal up to the order of equal distances). */
static int caustic_copy_agrees(const struct irradiance_stores *st)
{
    struct nearest *nn = nearest_create(200);
    struct irradiance_settings is = {200, HUGE_VAL, PHOTON_CAUSTIC, DIFFERENTIAL_RUN, 1};
    int same = st->caustics->n_photons > 0;
    for (int i = 0; i <= 20; i++) {
        struct vec3 p = vec3(0.3, 0, -0.9 + 1.8 * i / 20.0);
        struct store_query q = {p, vec3(0, 1, 0), -1, 0, 0, &is, NULL};
        double copy = vec3_luminance(stored_irradiance(st, &q, nn));
        double filtered = vec3_luminance(irradiance_estimate(st->photons, p, q.n, &is, nn));
        same = same && fabs(copy - filtered) <= 1e-12 * fabs(filtered);
    }
    nearest_free(nn);
    return same;
}

/* truth: the exact caustic of scenes/mirror-caustic.scene (the image source through the
 *   mirror's outline, computed above from the scene's numbers, not by the code under
 *   test), the paper's Fig. 7-8. The stores: mode 1994's pass 1, 200,000 light rays, with
 *   photon maps everywhere and with illumination maps (on the Lambertian square alone:
 *   the mirror holds no photons, so it gets no map).
 * tolerance: away from the edges the CP estimate with 200 photons is within 6% RMS of
 *   the caustic's level, with checking and without (measured, seed 1: 2.8% and 1.9%;
 *   seeds 1-8 at most 3.2% and 2.4%: checking costs noise where nothing changes);
 *   within 0.1 of the edges differential checking lowers the RMS error below 0.9 times
 *   that without (seed 1: 5.2% against 6.0%, 0.87; seeds 1-8: 0.81 to 0.88). The CI map
 *   is noisier, as the paper found of its box kernel (measured: 15% away from the edges,
 *   11% near them, with CI elements of 3 x 3 per DI element from the pretrace), and must
 *   be within 30% RMS away from the edges (without its caustic photons: 44%).
 * catches: CP photons missing or weighted wrongly (the mirror's image too dim or bright),
 *   the projection maps' weights not exact, the normal test rejecting the floor's own
 *   photons, differential checking that does not stop at an edge, caustic photons not
 *   reaching the CI map or its elements' areas wrong, the CP photons' own tree holding
 *   other photons or missing some (it must agree with the filtered map). */
static void test_mirror_caustic_profile(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/mirror-caustic.scene", 0, 0);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    struct jensen1994_settings js = jensen1994_settings_default();
    js.n_photons = 200000;
    struct jensen1994_stats stats;
    struct error err;
    struct irradiance_stores photons, maps;
    int traced = jensen1994_trace(scene, 1, MAX_DEPTH_LIMIT, &js, &photons, &stats, 0, &err) == 0;
    js.illumination_maps = 1;
    traced = traced &&
             jensen1994_trace(scene, 1, MAX_DEPTH_LIMIT, &js, &maps, &stats, 0, &err) == 0;
    CHECK(t, traced);
    if (traced) {
        CHECK(t, stats.illumination_maps == 1 && stats.illumination_ci_maps > 0);
        struct profile_errors pe = caustic_profile_errors(scene, &photons, &maps);
        CHECK(t, pe.far[1] < 0.06 && pe.far[0] < 0.06);
        CHECK(t, pe.near[1] < 0.9 * pe.near[0]);
        CHECK(t, pe.far[2] < 0.3);
        CHECK(t, caustic_copy_agrees(&photons));
        irradiance_stores_free(&photons);
        irradiance_stores_free(&maps);
    }
    scene_free(scene);
}

/* ---- hard cases ---- */

/* truth: Jensen and Christensen 1994, Sec. 3.3: a caustic photon (CP) has had "only
 *   specular reflections" since the light, and the specular-like part f_r,s takes in the
 *   glossy lobes, so on the glossy panel (truths.h) the floor has the panel's light from
 *   CP photons alone (4.0.2). The truth is the path tracer: 16,384 samples, the image
 *   mean's standard error 0.1%.
 *   Measured (1994 mean / pt's), 200,000 photons, seeds 1-6: 0.986, 0.985, 0.987, 1.004,
 *   0.995, 0.991; with the glossy bounce classed DP (by_parts off) 0.874: the panel's
 *   light lost, since no gather ray can reach a point light.
 * tolerance: 5%: more than twice the largest deviation measured, and less than half the
 *   panel's 12% of the image.
 * catches: glossy bounces left out of CP (measured by breaking the code that way). */
static void test_glossy_caustic(struct check *t)
{
    char path[256];
    temp_name(path, sizeof path, "jensen1994", "panel.scene");
    double truth = glossy_panel(path);
    struct j94_case c = j94_small_case(path, 0, 200000, 64);
    c.spp = 16;
    struct j94_run run = j94_render(&c);
    remove(path);
    CHECK(t, truth > 0 && run.image != NULL && run.stats.photons_caustic > 0);
    if (truth > 0 && run.image != NULL)
        CHECK_CLOSE(t, mean_luminance(run.image) / truth, 1.0, 0.05);
    image_free(run.image);
}

#define LOBE_SEEDS 6

/* 1994's image mean of the scene at path over pt's (truth), for seeds 1..LOBE_SEEDS, into
 * ratio[]; 16 samples a pixel. Returns how many rendered. */
static int lobe_ratios(const char *path, double truth, int lobe_lights, double *ratio)
{
    int rendered = 0;
    for (int seed = 1; seed <= LOBE_SEEDS; seed++) {
        struct j94_case c = j94_small_case(path, 0, 1000, 16);
        c.spp = 16;
        c.seed = (uint64_t)seed;
        c.js.lobe_lights = lobe_lights;
        struct j94_run run = j94_render(&c);
        if (run.image != NULL)
            ratio[rendered++] = mean_luminance(run.image) / truth;
        image_free(run.image);
    }
    return rendered;
}

/* Writes to path a floor of Ward's glossy lobe alone (rho_s 0.8, alpha) whose highlight
 * is a sphere light of the given radius, nothing else; pt's image mean there, at 8,192
 * samples a pixel. */
static double highlight_truth(const char *path, double alpha, double radius)
{
    char text[512];
    snprintf(text, sizeof text,
             "image 16 16\n"
             "camera 0 1 -3  0 0 0  0 1 0  30\n"
             "material floor ward 0 0 0  0.8 0.8 0.8  %g %g\n"
             "quad -100 0 -100 -100 0 100 100 0 100 100 0 -100 floor\n"
             "light sphere 0 1 2  %g  100 100 100\n",
             alpha, alpha, radius);
    write_text_file(path, text);
    return pt_mean_luminance(path, 8192);
}

/* Writes to path a floor of a Phong lobe alone (rho_s 0.6, exponent 20) under a white
 * sky, nothing else; pt's image mean there, at 8,192 samples a pixel. */
static double sky_lobe_truth(const char *path)
{
    write_text_file(path, "image 32 24\n"
                          "background 1 1 1\n"
                          "camera 0 3.4 -2.0  0 0 0.5  0 1 0  40\n"
                          "material m phong 0 0 0  0.6 0.6 0.6  20\n"
                          "quad -4 0 -4  -4 0 4  4 0 4  4 0 -4  m\n");
    return pt_mean_luminance(path, 8192);
}

/* The sample standard deviation of x[0..n-1] (tally_se() is sqrt(n) times it). */
static double sample_sd(const double *x, int n)
{
    struct tally tl = {0, 0, n};
    for (int i = 0; i < n; i++)
        tally_add(&tl, x[i]);
    return tally_se(&tl) / sqrt(n);
}

/* truth: the path tracer (8,192 samples a pixel, multiple importance sampling between its
 *   light samples and its BRDF's rays) on a floor of Ward's glossy lobe alone whose
 *   highlight is a sphere light, nothing else (highlight_truth()). The lobe is f_r,s, so 1994
 *   finds the light only through L_r,s: with lobe_lights by light samples through the
 *   lobe weighted against the lobe's own ray (jensen1994.c, lights_through_lobe()),
 *   without by the lobe's ray alone. Both are unbiased when the two weights sum to one.
 *   A small light (radius 0.1) under a broad lobe (alpha 0.2), where the light samples
 *   carry the light, measured (1994 mean / pt's), seeds 1-6: with lobe_lights 0.9971,
 *   1.0056, 1.0009, 1.0037, 0.9962, 0.9970 (sd 0.0039); without 0.971, 1.151, 0.621,
 *   0.803, 1.349, 1.060 (sd 0.26). A large light (0.6) under a sharp lobe (0.05), where
 *   the lobe's ray carries it: with lobe_lights mean 1.0046 (sd 0.021; without 1.0091, sd
 *   0.014), and 1.46 with the light samples at weight 1. A Phong lobe under a white sky,
 *   which is sampled and found as a light too: seeds 1-4, 0.9988 to 1.0030.
 * tolerance: the small light, each seed within 2% (three times the largest deviation
 *   measured), and the spread over the seeds at most a tenth of that without (66 times
 *   smaller measured); the large light, the mean of the seeds within 3% (3.5 standard
 *   errors); the sky, each seed within 1% (three times the largest deviation).
 * catches: a light counted by both strategies at full weight (2x on the small light,
 *   1.46 on the large), the sky's escaping ray left unweighted, lobe_lights ignored. */
static void test_lobe_lights(struct check *t)
{
    char path[256];
    temp_name(path, sizeof path, "jensen1994", "highlight.scene");
    double with[LOBE_SEEDS], without[LOBE_SEEDS];
    double truth = highlight_truth(path, 0.2, 0.1);
    int ok = truth > 0 && lobe_ratios(path, truth, 1, with) == LOBE_SEEDS &&
             lobe_ratios(path, truth, 0, without) == LOBE_SEEDS;
    CHECK(t, ok);
    if (ok) {
        for (int i = 0; i < LOBE_SEEDS; i++)
            CHECK_CLOSE(t, with[i], 1.0, 0.02);
        CHECK(t, sample_sd(with, LOBE_SEEDS) < 0.1 * sample_sd(without, LOBE_SEEDS));
    }
    truth = highlight_truth(path, 0.05, 0.6);
    ok = truth > 0 && lobe_ratios(path, truth, 1, with) == LOBE_SEEDS;
    CHECK(t, ok);
    if (ok) {
        double mean = 0;
        for (int i = 0; i < LOBE_SEEDS; i++)
            mean += with[i] / LOBE_SEEDS;
        CHECK_CLOSE(t, mean, 1.0, 0.03);
    }
    truth = sky_lobe_truth(path);
    ok = truth > 0 && lobe_ratios(path, truth, 1, with) == LOBE_SEEDS;
    CHECK(t, ok);
    for (int i = 0; ok && i < LOBE_SEEDS; i++)
        CHECK_CLOSE(t, with[i], 1.0, 0.01);
    remove(path);
}

void test_jensen1994_caustics(struct check *t)
{
    RUN_TEST(t, test_caustic);
    RUN_TEST(t, test_mirror_caustic_profile);
    RUN_TEST(t, test_glossy_caustic);
    RUN_TEST(t, test_lobe_lights);
}
