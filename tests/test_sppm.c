/*
 * tests/test_sppm.c -- `--mode 2009`, stochastic progressive photon mapping: convergence to
 * closed forms as passes grow; pixels that are means over their square (a light's outline),
 * where 2008's eye rays, traced once, keep their first error; the disc coverage at an open
 * edge and the radius fitted to a wall the surface goes on past; a point light's highlight
 * on a glossy floor the paper's way; memory flat in the
 * passes; a crop equal to the window of the whole image.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../src/base/rng.h"
#include "../src/image/compare.h"
#include "../src/modes/pt.h"
#include "../src/modes/sppm2009.h"
#include "check.h"
#include "files.h"
#include "tests.h"
#include "truths.h"

/* The paper's R0 (one footprint, whole) and the given photons, passes and direct way. */
static struct progressive_settings paper_radius(size_t photons_per_pass, long passes,
                                                int direct_light_samples)
{
    struct progressive_settings ps = sppm_settings_default().progressive;
    ps.photons_per_pass = photons_per_pass;
    ps.passes = passes;
    ps.direct_light_samples = direct_light_samples;
    ps.footprints = 1;
    ps.fit_radius = 0;
    return ps;
}

/* 2009 with paper_radius() and no disc coverage. */
static struct sppm_settings sppm_settings(size_t photons_per_pass, long passes,
                                          int direct_light_samples)
{
    struct sppm_settings ps;
    ps.progressive = paper_radius(photons_per_pass, passes, direct_light_samples);
    ps.disc_coverage = 0;
    ps.follow_glossy_lobes = 1;
    return ps;
}

/* 2008 with paper_radius() and none of its own departures. */
static struct ppm_settings ppm_paper_settings(size_t photons_per_pass, long passes,
                                              int direct_light_samples)
{
    struct ppm_settings ps = ppm_settings_default();
    ps.progressive = paper_radius(photons_per_pass, passes, direct_light_samples);
    ps.resample_emission = 0;
    ps.merge_hit_points = 0;
    ps.caustic_footprints = 0;
    return ps;
}

/* Renders path (width x width) recording the error at 1, 2, 4, ... passes. */
static void converge(const char *path, int width, long passes, size_t photons_per_pass,
                     int direct_light_samples, struct error_curve *c)
{
    struct scene *scene = load_test_scene(path, width, width);
    memset(c->error, 0, sizeof c->error);
    c->n = 0;
    if (scene == NULL)
        return;
    c->scene = scene;
    struct render_settings rs = render_settings_whole(scene, 1, (int)passes, MAX_DEPTH_LIMIT);
    struct sppm_settings ps = sppm_settings(photons_per_pass, passes, direct_light_samples);
    struct checkpoint checkpoint = {error_curve_record, c};
    ps.progressive.report = &checkpoint;
    struct render_counters counters = {0};
    struct ppm_stats stats;
    struct render_result result = render_sppm(scene, &rs, &ps, &counters, &stats);
    render_result_free(&result);
    scene_free(scene);
}

#define PLANE_PASSES 256

/* The closed form of point-over-plane, L = rho Phi h / (4 pi^2 d^3), averaged over where
 * the pixel's PLANE_PASSES eye paths (camera samples 0 on, seed 1) meet the plane: what
 * the region S of the pixel has as its mean. */
static double plane_truth(const struct scene *scene, int x, int y)
{
    double sum = 0.0;
    for (int s = 0; s < PLANE_PASSES; s++) {
        struct rng rng;
        struct ray r = camera_sample(scene, 1, x, y, s, &rng);
        struct vec3 p = ray_at(r, -r.origin.y / r.dir.y);
        double d2 = vec3_length2(vec3_sub(p, vec3(0, 1, 0)));
        sum += 0.5 * 1000.0 * 1.0 / (4 * PI * PI * d2 * sqrt(d2));
    }
    return sum / PLANE_PASSES;
}

/* truth: closed forms: the furnace of a point light in a closed Lambertian sphere (L = 4
 *   everywhere, every bounce counting), by light samples (the default) and by photons
 *   alone (the paper's); the point light over a plane by photons alone, each pixel's truth
 *   the closed form's mean over where its eye paths meet the plane.
 * tolerance: the issue's: below 1% mean relative error after 256 passes, and at 256 less
 *   than half the error after 4. Measured: furnace by light samples 2.0% after 4 passes
 *   and 0.68% after 256, by photons 2.5% and 0.76% (8,000 photons a pass; at 4,000,
 *   0.85% and 0.99%); plane 3.9% and 0.69%.
 * catches: the pass's Phi added without the eye path's weight, tau updated with the
 *   radius ratio instead of its square, N_emitted counted per pass, a pixel's statistics
 *   reset each pass (the error would not fall). */
static void test_converges_to_closed_forms(struct check *t)
{
    struct error_curve c;
    c.truth = point_in_sphere_truth;
    for (int light_samples = 0; light_samples < 2; light_samples++) {
        converge("scenes/analytic/point-in-sphere.scene", 8, 256, 8000, light_samples, &c);
        CHECK(t, c.n == 9 && c.error[8] < 0.01 && c.error[8] < 0.5 * c.error[2]);
    }
    c.truth = plane_truth;
    converge("scenes/analytic/point-over-plane.scene", 12, PLANE_PASSES, 64000, 0, &c);
    CHECK(t, c.n == 9 && c.error[8] < 0.01 && c.error[8] < 0.5 * c.error[2]);
}

#define EDGE_X 0.3     /* where point-over-plane-edge's plane ends, -wall's wall stands */
#define EDGE_BAND 0.58 /* two footprints of the 12 x 12 renders at the plane            */

/* The mean signed relative error, against plane_truth(), of the pixels of a 12 x 12 image
 * of the point-over-plane plane (seed 1, PLANE_PASSES passes) whose every eye path meets
 * it before x = EDGE_X and some within EDGE_BAND of it; *n: how many. */
static double error_before_edge_2009(const struct scene *scene, const struct image *image,
                                     int *n)
{
    double sum = 0.0;
    *n = 0;
    for (int y = 0; y < image->height; y++)
        for (int x = 0; x < image->width; x++) {
            double farthest = -INFINITY;
            for (int s = 0; s < PLANE_PASSES; s++) {
                struct rng rng;
                struct ray r = camera_sample(scene, 1, x, y, s, &rng);
                farthest = fmax(farthest, r.origin.x - r.origin.y / r.dir.y * r.dir.x);
            }
            if (farthest < EDGE_X && farthest > EDGE_X - EDGE_BAND) {
                double truth = plane_truth(scene, x, y);
                sum += (image_get(image, x, y).y - truth) / truth;
                (*n)++;
            }
        }
    return *n > 0 ? sum / *n : INFINITY;
}

/* error_before_edge_2009() of a 2009 render of path, the photons bringing all the light
 * (PLANE_PASSES passes of 64,000), R0 4 footprints, with the given departures. */
static double error_at_edge(const char *path, int disc_coverage, int fit_radius, int *n)
{
    *n = 0;
    struct scene *scene = load_test_scene(path, 12, 12);
    if (scene == NULL)
        return INFINITY;
    struct render_settings rs = render_settings_whole(scene, 1, PLANE_PASSES, MAX_DEPTH_LIMIT);
    struct sppm_settings ps = sppm_settings_default();
    ps.progressive.photons_per_pass = 64000;
    ps.progressive.passes = PLANE_PASSES;
    ps.progressive.direct_light_samples = 0;
    ps.progressive.fit_radius = fit_radius;
    ps.disc_coverage = disc_coverage;
    struct render_counters counters = {0};
    struct ppm_stats stats;
    struct render_result r = render_sppm(scene, &rs, &ps, &counters, &stats);
    double error = error_before_edge_2009(scene, r.image, n);
    render_result_free(&r);
    scene_free(scene);
    return error;
}

/* truth: point-over-plane's closed form, each pixel's mean over its eye paths
 *   (plane_truth()), which holds up to the open edge of point-over-plane-edge's plane and
 *   up to the black wall that stands on point-over-plane-wall's (whose far side is in
 *   its shadow); the pixels within two footprints of either, R0 4 footprints.
 * tolerance: mean signed error within 2% with the disc coverage and the radius fitted as
 *   it fits it, and more than 5% dark without (so the test can tell): at the open edge
 *   without the coverage (the disc reaches where no photon lands, though pi R^2 counts
 *   it); at the wall without either (the disc reaches past the wall into its shadow),
 *   and within 2% with the coverage alone, whose probes count no point behind the wall
 *   (disc_probe_beside(): the surface goes on there, and plain probes counted it, -18.3%).
 *   Measured over 24 pixels: edge +0.2% with, -18.3% without; wall -0.2% fitted, +0.2%
 *   unfitted, -18.3% neither (the same photons land before x = 0.3 in both scenes).
 * catches: probes that miss the plane or find it beyond its edge or behind a wall, a
 *   coverage divided the wrong way or never, the fit's test of a wall the surface goes on
 *   past reversed (then neither the wall nor a corner would be fitted right). */
static void test_disc_coverage(struct check *t)
{
    int n_with, n_without;
    const char *edge = "scenes/analytic/point-over-plane-edge.scene";
    double with = error_at_edge(edge, 1, 1, &n_with);
    double without = error_at_edge(edge, 0, 0, &n_without);
    CHECK(t, n_with >= 8 && n_without == n_with);
    CHECK(t, fabs(with) <= 0.02 && without < -0.05);
    const char *wall = "scenes/analytic/point-over-plane-wall.scene";
    with = error_at_edge(wall, 1, 1, &n_with);
    double unfitted = error_at_edge(wall, 1, 0, &n_without);
    without = error_at_edge(wall, 0, 0, &n_without);
    fprintf(stderr, "  sppm: disc coverage at the wall: %+.4f fitted, %+.4f unfitted, %+.4f "
            "neither\n", with, unfitted, without);
    CHECK(t, n_with >= 8 && n_without == n_with);
    CHECK(t, fabs(with) <= 0.02 && fabs(unfitted) <= 0.02 && without < -0.05);
}

#define EDGE_WIDTH 24
#define EDGE_GRID 64 /* brute-force points a side of a pixel */

/* scenes/analytic/area-over-floor.scene at EDGE_WIDTH^2: the mean of the closed form over
 * pixel (x, y)'s square by brute force, EDGE_GRID^2 rays through its points; *straddles
 * says whether some of them see the light and some do not. */
static double pixel_mean(const struct scene *scene, int x, int y, int *straddles)
{
    double sum = 0.0;
    int lit = 0;
    for (int j = 0; j < EDGE_GRID; j++)
        for (int i = 0; i < EDGE_GRID; i++) {
            struct ray r = camera_ray(&scene->camera, x + (i + 0.5) / EDGE_GRID,
                                      y + (j + 0.5) / EDGE_GRID);
            double l = area_over_floor(r);
            lit += l == 10.0;
            sum += l;
        }
    *straddles = lit > 0 && lit < EDGE_GRID * EDGE_GRID;
    return sum / (EDGE_GRID * EDGE_GRID);
}

/* The error of image over the pixels that straddle the light's outline: the sum of
 * |L - truth| over the sum of truth (a pixel the light barely touches would make a relative
 * error of its own large however close its value). *n: how many pixels. */
static double edge_error(const struct scene *scene, const struct image *image, int *n)
{
    double error = 0.0, total = 0.0;
    *n = 0;
    for (int y = 0; y < image->height; y++)
        for (int x = 0; x < image->width; x++) {
            int straddles;
            double truth = pixel_mean(scene, x, y, &straddles);
            if (straddles) {
                error += fabs(image_get(image, x, y).y - truth);
                total += truth;
                (*n)++;
            }
        }
    return total > 0 ? error / total : INFINITY;
}

/* truth: the mean radiance over each pixel's square, by brute force over a 64 x 64 grid
 *   of the closed form (area_over_floor()), in the 24 pixels on the light's outline.
 * tolerance: error (edge_error()) below 3% after 256 passes: 2009 passes, and 2008 the
 *   paper's way, its 16 eye rays a pixel traced once, does not. Measured: 2009 2.2% (256
 *   points of a (0,2)-sequence over each pixel), 2008 11.8% (its 16 points stay where
 *   they fell, however many passes follow).
 * catches: 2009 tracing the same eye path each pass, or averaging what they saw over the
 *   wrong count. */
static void test_light_outline(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/analytic/area-over-floor.scene", EDGE_WIDTH,
                                          EDGE_WIDTH);
    REQUIRE(t, scene != NULL);
    struct render_counters counters = {0};
    struct ppm_stats stats;
    struct render_settings rs = render_settings_whole(scene, 1, 256, MAX_DEPTH_LIMIT);
    struct sppm_settings sps = sppm_settings(1000, 256, 1);
    struct render_result sppm = render_sppm(scene, &rs, &sps, &counters, &stats);
    rs = render_settings_whole(scene, 1, 16, MAX_DEPTH_LIMIT);
    struct ppm_settings pps = ppm_paper_settings(1000, 256, 0);
    struct render_result ppm = render_ppm(scene, &rs, &pps, &counters, &stats);
    int n_sppm, n_ppm;
    double e_sppm = edge_error(scene, sppm.image, &n_sppm);
    double e_ppm = edge_error(scene, ppm.image, &n_ppm);
    CHECK(t, n_sppm >= 8 && n_sppm == n_ppm);
    CHECK(t, e_sppm < 0.03 && e_ppm >= 0.03);
    render_result_free(&sppm);
    render_result_free(&ppm);
    scene_free(scene);
}

/* A Ward floor (rho_d 0.2, rho_s 0.6, slopes 0.05) reflecting a square light above and
 * behind it, 16 x 16 pixels: the glossy reflection's outline crosses pixels. */
static const char glossy_floor[] =
    "image 16 16\n"
    "camera 0 1 -3  0 0 0  0 1 0  30\n"
    "material floor ward 0.2 0.2 0.2  0.6 0.6 0.6  0.05 0.05\n"
    "quad -5 0 -5  -5 0 5  5 0 5  5 0 -5  floor\n"
    "light quad -0.5 1.5 1.5  0.5 1.5 1.5  0.5 1.5 2.5  -0.5 1.5 2.5  10 10 10\n";

/* The scene of a scene file's text (written to a temporary file of group sppm, read, and
 * removed) and pt's image of it at spp samples a pixel, the truth of the cases below;
 * NULL when it does not load. */
static struct scene *scene_and_truth(const char *text, int spp, struct render_result *truth)
{
    char path[256];
    temp_name(path, sizeof path, "sppm", "text.scene");
    write_text_file(path, text);
    struct scene *scene = load_test_scene(path, 0, 0);
    remove(path);
    if (scene != NULL) {
        struct render_settings rs = render_settings_whole(scene, 1, spp, MAX_DEPTH_LIMIT);
        struct render_counters counters = {0};
        *truth = render_pt(scene, &rs, 0, NULL, &counters);
    }
    return scene;
}

/* The relmse against truth of a progressive render of scene the paper's way (photons the
 * only light, R0 one footprint, whole, no facing test): 2009, or 2008 with spp eye rays
 * traced once. */
static double paper_relmse(const struct scene *scene, const struct image *truth, int sppm,
                           int spp)
{
    struct render_counters counters = {0};
    struct ppm_stats stats;
    struct sppm_settings sps = sppm_settings(4000, 1024, 0);
    struct ppm_settings pps = ppm_paper_settings(4000, 1024, 0);
    sps.progressive.facing_test = 0;
    pps.progressive.facing_test = 0;
    struct render_settings rs = render_settings_whole(scene, 1, sppm ? 1024 : spp,
                                                      MAX_DEPTH_LIMIT);
    struct render_result r = sppm ? render_sppm(scene, &rs, &sps, &counters, &stats)
                                  : render_ppm(scene, &rs, &pps, &counters, &stats);
    double relmse = image_compare(r.image, truth).relmse;
    render_result_free(&r);
    return relmse;
}

/* truth: pt, 16,384 samples a pixel, of a glossy floor reflecting a light (glossy_floor).
 * tolerance: the paper's way (photons only) after 1,024 passes of 4,000 photons, relmse
 *   below 0.03: 2009 passes, and 2008 with its one eye ray a pixel traced once, whose
 *   pixels stay the radiance at one point of their square, does not. Measured: 2009
 *   0.0032, 2008 0.059 (0.057 after 4,096 passes). With hit points on the glossy floor
 *   instead of eye paths that sample its lobe, 2009 was 0.017: the photons' estimate
 *   behind a narrow lobe is mostly noise.
 * catches: 2009's eye paths not moving within the pixel from pass to pass, a glossy lobe
 *   estimated from photons, a surface's parts chosen without dividing by the choice's
 *   probability (the floor's diffuse or glossy light off by the odds). */
static void test_glossy_floor(struct check *t)
{
    struct render_result truth;
    struct scene *scene = scene_and_truth(glossy_floor, 16384, &truth);
    REQUIRE(t, scene != NULL);
    double sppm = paper_relmse(scene, truth.image, 1, 0);
    double ppm = paper_relmse(scene, truth.image, 0, 1);
    CHECK(t, sppm < 0.03 && ppm >= 0.03);
    render_result_free(&truth);
    scene_free(scene);
}

/* The worst 8 x 8 block's relative error against truth of 2009 the paper's way (photons
 * the only light), 64 passes of 20,000 photons, its glossy lobes followed or not. */
static double paper_highlight_error(const struct scene *scene, const struct image *truth,
                                    int follow_glossy_lobes)
{
    struct render_counters counters = {0};
    struct ppm_stats stats;
    struct sppm_settings ps = sppm_settings(20000, 64, 0);
    ps.progressive.facing_test = 0;
    ps.progressive.turn_photon_directions = 0;
    ps.follow_glossy_lobes = follow_glossy_lobes;
    struct render_settings rs = render_settings_whole(scene, 1, 64, MAX_DEPTH_LIMIT);
    struct render_result r = render_sppm(scene, &rs, &ps, &counters, &stats);
    double worst = image_worst_block(r.image, truth, NULL, 8).relative_error;
    render_result_free(&r);
    return worst;
}

/* truth: pt, 1,024 samples a pixel, of a Phong floor's highlight under a point light
 *   (phong_highlight_scene).
 * tolerance: the paper's way (--paper: photons the only light, the hit point at the first
 *   non-specular surface with its whole BRDF) within 5% in every 8 x 8 block. Measured:
 *   2.1% at worst; with the eye path following the glossy lobe instead (the departure
 *   --follow-glossy-lobes without light samples) 92%: the lobe's path cannot hit a point
 *   light and the diffuse hit point holds no highlight, so nothing finds it.
 * catches: the paper's hit point taking only a part of the BRDF, or a path that both
 *   follows the lobe and stores its light (twice the highlight). */
static void test_paper_highlight(struct check *t)
{
    struct render_result truth;
    struct scene *scene = scene_and_truth(phong_highlight_scene, 1024, &truth);
    REQUIRE(t, scene != NULL);
    double paper = paper_highlight_error(scene, truth.image, 0);
    double followed = paper_highlight_error(scene, truth.image, 1);
    printf("  sppm: a point light's highlight, the paper's way: worst 8 x 8 block %.3f off; "
           "glossy lobes followed: %.3f\n", paper, followed);
    CHECK(t, paper < 0.05 && followed > 0.5);
    render_result_free(&truth);
    scene_free(scene);
}

/* truth: the issue's: memory O(pixels) and flat in the passes: --stats' bytes_peak after
 *   10 and after 100 passes is the same, and at 256 x 256 well under 100 MB. Measured:
 *   32,119,564 bytes both.
 * catches: per-pass allocations kept (a tree not freed, hit points appended). */
static void test_memory_flat(struct check *t)
{
    char log10[256], log100[256], out[256], args[1024];
    temp_name(log10, sizeof log10, "sppm", "10.log");
    temp_name(log100, sizeof log100, "sppm", "100.log");
    temp_name(out, sizeof out, "sppm", "out.pfm");
    snprintf(args, sizeof args, "--mode 2009 --passes 10 --photons-per-pass 2000 --stats "
                                "--no-progress scenes/cornell.scene -o %s", out);
    CHECK(t, photon_logged("", args, log10) == 0);
    snprintf(args, sizeof args, "--mode 2009 --passes 100 --photons-per-pass 2000 --stats "
                                "--no-progress scenes/cornell.scene -o %s", out);
    CHECK(t, photon_logged("", args, log100) == 0);
    double peak10 = file_stat(log10, "bytes_peak"), peak100 = file_stat(log100, "bytes_peak");
    CHECK(t, peak10 > 0 && peak10 == peak100 && peak100 < 100e6);
    remove(log10);
    remove(log100);
    remove(out);
    char png[256];
    snprintf(png, sizeof png, "%.*s.png", (int)strlen(out) - 4, out);
    remove(png);
}

/* truth: the whole image, rendered once; its window equals the crop's render bit for bit.
 * catches: a pixel's statistics taking another pixel's photons, or the window's hit
 *   points changing what a pixel finds (the tree's order must not matter). */
static void test_crop_is_window(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/cornell-specular.scene", 32, 32);
    REQUIRE(t, scene != NULL);
    struct render_counters counters = {0};
    struct ppm_stats stats;
    struct sppm_settings ps = sppm_settings_default(); /* the disc probes' streams too */
    ps.progressive.photons_per_pass = 5000;
    ps.progressive.passes = 6;
    struct render_settings rs = render_settings_whole(scene, 7, 6, MAX_DEPTH_LIMIT);
    struct render_result whole = render_sppm(scene, &rs, &ps, &counters, &stats);
    static const int window[4] = {5, 9, 21, 30};
    rs.x0 = window[0];
    rs.y0 = window[1];
    rs.x1 = window[2];
    rs.y1 = window[3];
    struct render_result crop = render_sppm(scene, &rs, &ps, &counters, &stats);
    struct image *expected = crop_image(whole.image, window);
    CHECK(t, memcmp(expected->pixels, crop.image->pixels,
                    sizeof *expected->pixels * (size_t)(16 * 21)) == 0);
    image_free(expected);
    render_result_free(&whole);
    render_result_free(&crop);
    scene_free(scene);
}

void test_sppm(struct check *t)
{
    RUN_TEST(t, test_converges_to_closed_forms);
    RUN_TEST(t, test_disc_coverage);
    RUN_TEST(t, test_light_outline);
    RUN_TEST(t, test_glossy_floor);
    RUN_TEST(t, test_paper_highlight);
    RUN_TEST(t, test_memory_flat);
    RUN_TEST(t, test_crop_is_window);
}
