/*
 * tests/test_jensen1994.c -- `--mode 1994` (Jensen and Christensen 1994): the order-free
 * irradiance cache (a crop is the same window of the whole image), closed forms, the CP
 * photons, convergence towards the path-traced reference, finite pixels on the harder scenes,
 * the command line. The estimate itself (differential checking, normal test): test_trace.c.
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
#include "../src/modes/jensen1994_maps.h"
#include "../src/photon/estimate.h"
#include "../src/photon/kdtree.h"
#include "files.h"
#include "tests.h"
#include "truths.h"

#define OUT "build/test_jensen1994"

/* A render of path at size x size (0: the file's own size), of window (x0 y0 x1 y1, or
 * NULL for the whole image), with settings js. */
struct j94_case {
    const char *path;
    int size;
    int spp;
    uint64_t seed;
    const int *window;
    struct jensen1994_settings js;
};

/* What a render gave: the image (owned; NULL when the scene or the render failed). */
struct j94_run {
    struct image *image;
    struct jensen1994_stats stats;
    struct render_counters counters;
};

/* A small photon map and small records: photons, gather_rays rays, one sample a pixel,
 * seed 1. */
static struct j94_case small_case(const char *path, int size, size_t photons, int gather_rays)
{
    struct j94_case c;
    c.path = path;
    c.size = size;
    c.spp = 1;
    c.seed = 1;
    c.window = NULL;
    c.js = jensen1994_settings_default();
    c.js.n_photons = photons;
    c.js.gather_rays = gather_rays;
    return c;
}

static struct j94_run render_case(const struct j94_case *c)
{
    struct j94_run run;
    memset(&run, 0, sizeof run);
    run.image = NULL;
    struct scene *scene = load_test_scene(c->path, c->size, c->size);
    if (scene == NULL)
        return run;
    struct render_settings rs = case_settings(scene, c->seed, c->spp, c->window);
    struct error err;
    struct render_result r = render_jensen1994(scene, &rs, &c->js, 0, &run.counters, &run.stats,
                                               &err);
    run.image = rendered_image(r, &err);
    scene_free(scene);
    return run;
}

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
        struct j94_case c = small_case(store ? "scenes/cornell.scene"
                                             : "scenes/cornell-specular.scene", 48, 20000, 32);
        c.spp = 2;
        c.js.illumination_maps = store;
        struct j94_run whole = render_case(&c);
        struct j94_run again = render_case(&c);
        c.window = window;
        struct j94_run crop = render_case(&c);
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
    struct j94_case c = small_case("scenes/analytic/point-over-plane.scene", 0, 20000, 32);
    c.spp = 4;
    struct j94_run run = render_case(&c);
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
        struct j94_case c = small_case("scenes/analytic/point-in-sphere.scene", 16, 20000, 32);
        c.js.gather = ns[i / 2];
        c.js.differential_run = 0;
        c.js.precomputed_irradiance = i % 2 == 1 ? J94_DEFAULT_PRECOMPUTED : 0;
        struct j94_run run = render_case(&c);
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
    struct j94_case c = small_case("scenes/cornell.scene", 64, 20000, 32);
    c.spp = 4;
    c.window = ceiling;
    struct j94_run coarse = render_case(&c);
    c.js.n_photons = 200000;
    c.js.gather_rays = 256;
    struct j94_run fine = render_case(&c);
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
        struct j94_case c = small_case("scenes/cornell.scene", 64, 200000, 64);
        c.spp = 4;
        c.window = balls;
        c.js.illumination_maps = store;
        struct j94_run run = render_case(&c);
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
    struct j94_case c = small_case("scenes/cornell-specular.scene", 64, 200000, 32);
    c.spp = 4;
    c.window = window;
    struct j94_run run = render_case(&c);
    struct j94_case plain = small_case("scenes/cornell.scene", 16, 20000, 16);
    struct j94_run lambertian = render_case(&plain);
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
    struct j94_case c = small_case(path, 0, 200000, 64);
    c.spp = 16;
    struct j94_run run = render_case(&c);
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
        struct j94_case c = small_case(path, 0, 1000, 16);
        c.spp = 16;
        c.seed = (uint64_t)seed;
        c.js.lobe_lights = lobe_lights;
        struct j94_run run = render_case(&c);
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
        struct j94_case c = small_case(scenes[i], 16, 5000, 16);
        c.spp = 2;
        struct j94_run run = render_case(&c);
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
    remove(OUT "-glossy.pfm"), remove(OUT "-glossy.png"), remove(OUT "-glossy.log");
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
    RUN_TEST(t, test_caustic);
    RUN_TEST(t, test_mirror_caustic_profile);
    RUN_TEST(t, test_glossy_caustic);
    RUN_TEST(t, test_lobe_lights);
    RUN_TEST(t, test_probe_command);
    RUN_TEST(t, test_harder_scenes_are_finite);
    RUN_TEST(t, test_glossy_floor);
    RUN_TEST(t, test_command_line);
}
