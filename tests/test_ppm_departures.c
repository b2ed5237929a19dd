/*
 * tests/test_ppm_departures.c -- the 2008 mode's departures from the paper that shape its
 * estimate, each against a truth of its own: the initial radius fitted to an open edge,
 * merged hit points, the caustic estimate.
 */
#include <math.h>

#include "../src/image/compare.h"
#include "../src/modes/ppm2008.h"
#include "../src/photon/hit_points.h"
#include "check.h"
#include "tests.h"
#include "truths.h"

/* A whole render of scene at spp eye rays a pixel, seed 1, with ps. */
static struct image *render(const struct scene *scene, int spp, const struct ppm_settings *ps,
                            struct ppm_stats *stats)
{
    struct render_settings rs = render_settings_whole(scene, 1, spp, MAX_DEPTH_LIMIT);
    struct render_counters counters = {0};
    return render_ppm(scene, &rs, ps, &counters, stats).image;
}

/* The mean signed relative error, against the closed form, of the pixels of a 12 x 12
 * render of the plane cut off at x = 0.3 whose eye ray meets it within one footprint
 * (0.29) of the edge, the photons bringing all the light (256 passes of 64,000). */
static double error_at_edge(const struct scene *scene, int fit_radius, int *n)
{
    struct ppm_settings ps = ppm_settings_default();
    ps.progressive.photons_per_pass = 64000;
    ps.progressive.passes = 256;
    ps.progressive.direct_light_samples = 0;
    ps.progressive.fit_radius = fit_radius;
    struct ppm_stats stats;
    struct image *image = render(scene, 1, &ps, &stats);
    double error = error_before_edge(scene, image, n);
    image_free(image);
    return error;
}

/* truth: scenes/analytic/point-over-plane-edge.scene: up to the plane's open edge the
 *   closed form of point-over-plane.scene holds (point_over_plane_sample()). The pixels
 *   within one footprint of the edge, at the default R0 of 4 footprints: with the radius
 *   fitted (rim probes at twice the radius find no surface beyond the edge, and it is
 *   halved until they do) their mean signed error must be within 2%; without, the disc
 *   reaches past the edge, where no photon lands though pi R^2 counts it, and they must be
 *   more than 5% dark (so the test can tell). Measured: -0.5% fitted, -31.5% unfitted,
 *   over the 11 pixels.
 * catches: rim probes that find the plane beyond its edge (or look the wrong way along
 *   the normal), a fitted radius that is not kept, a floor that undoes the fit. */
static void test_fit_to_open_edge(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/analytic/point-over-plane-edge.scene", 12, 12);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    int n_fitted, n_whole;
    double fitted = error_at_edge(scene, 1, &n_fitted), whole = error_at_edge(scene, 0, &n_whole);
    CHECK(t, n_fitted >= 8 && fabs(fitted) <= 0.02);
    CHECK(t, n_whole == n_fitted && whole < -0.05);
    scene_free(scene);
}

/* The mean |L - 4| / 4 over an 8 x 8 render of the furnace (L = 4 everywhere) at 4 eye
 * rays a pixel, R0 2 footprints whole (256 passes of 4,000 photons). */
static double furnace_error(const struct scene *scene, int merge, size_t *hit_points)
{
    struct ppm_settings ps = ppm_settings_default();
    ps.progressive.photons_per_pass = 4000;
    ps.progressive.passes = 256;
    ps.progressive.footprints = 2;
    ps.progressive.fit_radius = 0;
    ps.merge_hit_points = merge;
    struct ppm_stats stats;
    struct image *image = render(scene, 4, &ps, &stats);
    double sum = 0.0;
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 8; x++)
            sum += fabs(image_get(image, x, y).y - 4.0) / 4.0;
    image_free(image);
    *hit_points = stats.hit_points;
    return sum / 64;
}

/* truth: scenes/analytic/point-in-sphere.scene, L = 4 everywhere (test_ppm.c): the four eye
 *   rays of a pixel all meet the sphere within a footprint of each other, so with merged
 *   hit points each pixel has exactly one, carrying the four rays' weights, and without
 *   four; either way the image must be within 1% of 4 on average after 256 passes.
 *   Measured: 0.53% merged, 0.52% not. R0 is 2 footprints (0.43) because at 4 (0.87,
 *   nearly the sphere's radius) the estimate itself is 1.5% dark here, the paper's way
 *   too: a bias of the disc on a surface this curved, which shrinks with R (1.1% at
 *   R = 0.27).
 * catches: merged weights not summed (a pixel a quarter as bright), hit points merged
 *   across pixels (fewer than 64) or not at all, a merged hit point taking a ray's weight
 *   twice. */
static void test_merged_hit_points(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/analytic/point-in-sphere.scene", 8, 8);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    size_t merged_points, points;
    double merged = furnace_error(scene, 1, &merged_points);
    double unmerged = furnace_error(scene, 0, &points);
    CHECK(t, merged_points == 64 && points == 256);
    CHECK(t, merged < 0.01 && unmerged < 0.01);
    scene_free(scene);
}

/* After the last pass: the caustic estimate's radiance against the exact caustic's at
 * the floor's hit points well inside the caustic, and the caustic flux found anywhere. */
struct caustic_check {
    long passes;                 /* the render's                                        */
    size_t photons_per_pass;     /* the render's                                        */
    double sum_estimate, sum_exact; /* over the hit points well inside the caustic      */
    double caustic_tau;          /* max |tau| of any caustic estimate                    */
    int inside;                  /* hit points well inside                              */
};

/* Whether p lies in the caustic 0.05 or more from its edges (the exact irradiance is
 * positive at p and at the four points 0.05 away along x and z). */
static int well_inside(struct vec3 p)
{
    static const double dx[4] = {0.05, -0.05, 0, 0}, dz[4] = {0, 0, 0.05, -0.05};
    if (!(mirror_caustic_irradiance(p) > 0))
        return 0;
    for (int k = 0; k < 4; k++)
        if (!(mirror_caustic_irradiance(vec3(p.x + dx[k], 0, p.z + dz[k])) > 0))
            return 0;
    return 1;
}

static void check_caustic(void *context, long pass, const struct hit_point *points, size_t n)
{
    struct caustic_check *c = context;
    if (pass < c->passes)
        return;
    double n_emitted = (double)pass * (double)c->photons_per_pass;
    for (size_t i = 0; i < n; i++) {
        const struct hit_point *hp = &points[i];
        c->caustic_tau = fmax(c->caustic_tau, vec3_max_abs(hp->caustic.tau));
        if (!(fabs(hp->x.y) < 1e-9 && well_inside(hp->x)))
            continue;
        c->sum_estimate += ppm_radiance(hp->caustic.tau, hp->caustic.radius, n_emitted).y;
        c->sum_exact += 0.8 / PI * mirror_caustic_irradiance(hp->x);
        c->inside++;
    }
}

/* Renders scenes/mirror-caustic.scene at 32 x 32 with the default settings but
 * caustic_footprints, 64 passes of 20,000 photons, into c. */
static void render_caustic(const struct scene *scene, double caustic_footprints,
                           struct caustic_check *c)
{
    struct ppm_settings ps = ppm_settings_default();
    ps.progressive.photons_per_pass = 20000;
    ps.progressive.passes = 64;
    ps.caustic_footprints = caustic_footprints;
    struct caustic_check zero = {64, 20000, 0.0, 0.0, 0.0, 0};
    *c = zero;
    struct ppm_observer observer = {check_caustic, c};
    ps.observer = &observer;
    struct ppm_stats stats;
    image_free(render(scene, 1, &ps, &stats));
}

/* truth: scenes/mirror-caustic.scene, the caustic of a flat mirror: the floor inside it is
 *   lit by the light's mirror image, E = I cos / d^2 (mirror_caustic_irradiance()), which
 *   only caustic photons (light, mirror, floor) bring. The caustic estimates of the floor's
 *   hit points at least 0.05 inside the caustic's edges (R0 one footprint, 0.03 here)
 *   must sum to the exact rho E / pi within 3%. With caustic_footprints 0 the caustic
 *   photons go to the global estimate and no caustic estimate may hold any flux.
 *   Measured: 1.0007 of the exact sum over 366 hit points; 0 with none.
 * catches: caustic photons not told apart (the caustic estimate empty) or counted in
 *   both estimates, the caustic estimate's flux not normalised by its own radius, its
 *   radius left at 0. */
static void test_caustic_estimate(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/mirror-caustic.scene", 32, 32);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    struct caustic_check c;
    render_caustic(scene, PPM_DEFAULT_CAUSTIC_FOOTPRINTS, &c);
    CHECK(t, c.inside >= 20 && fabs(c.sum_estimate / c.sum_exact - 1) <= 0.03);
    render_caustic(scene, 0, &c);
    CHECK(t, c.caustic_tau == 0 && c.sum_estimate == 0);
    scene_free(scene);
}

/* relmse of a 2008 render (32 passes, the defaults otherwise) of the window of the
 * specular box's caustic under the glass ball against the converged reference there;
 * merge: ps.merge_hit_points. -1 when the scene or reference cannot be read. */
static double caustic_window_error(int merge)
{
    static const int window[4] = {160, 216, 192, 240};
    struct scene *scene = load_test_scene("scenes/cornell-specular.scene", 0, 0);
    struct image *ref = reference_window("reference/cornell-specular-pt.pfm", 1, window);
    double error = -1;
    if (scene != NULL && ref != NULL) {
        struct ppm_settings ps = ppm_settings_default();
        ps.progressive.passes = 32;
        ps.merge_hit_points = merge;
        struct render_settings rs = case_settings(scene, 1, PPM_DEFAULT_SPP, window);
        struct render_counters counters = {0};
        struct ppm_stats stats;
        struct image *image = render_ppm(scene, &rs, &ps, &counters, &stats).image;
        error = image_compare(image, ref).relmse;
        image_free(image);
    }
    image_free(ref);
    scene_free(scene);
    return error;
}

/* truth: reference/cornell-specular-pt.pfm, the caustic under the glass ball seen directly
 *   (pixels 160..192 x 216..240), where a sharp caustic crosses pixels.
 * tolerance: merged hit points within 1.5 times the relmse of a hit point an eye ray (the
 *   paper's), which is the defaults' promise of "no worse than --paper by more than
 *   noise"; measured 1.1 times (0.00114 and 0.00103). A merged hit point whose caustic
 *   estimate sits at its one point was 13 times worse (0.0134).
 * catches: the caustic estimate centred on the hit point alone (aliasing the caustic over
 *   the pixel), members' shares not summing to one (too bright or dark), the caustic reach
 *   not widened by the members' spread (photons near the outer members lost). */
static void test_merged_caustic(struct check *t)
{
    double merged = caustic_window_error(1), paper = caustic_window_error(0);
    printf("  ppm: caustic window relmse %.3g merged, %.3g a hit point an eye ray\n", merged,
           paper);
    CHECK(t, paper > 0 && paper < 0.003);
    CHECK(t, merged > 0 && merged <= 1.5 * paper);
}

void test_ppm_departures(struct check *t)
{
    RUN_TEST(t, test_fit_to_open_edge);
    RUN_TEST(t, test_merged_hit_points);
    RUN_TEST(t, test_caustic_estimate);
    RUN_TEST(t, test_merged_caustic);
}
