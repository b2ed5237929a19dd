/*
 * tests/truths.h -- closed forms and fixtures that several test rooms share: Lambert's
 * polygon irradiance (test_scene.c, test_pt.c), the point light over a plane, loading a
 * test scene (test_render.c, test_pt.c), and the block-averaged references the photon
 * modes are compared with.
 */
#ifndef PHOTON_TEST_TRUTHS_H
#define PHOTON_TEST_TRUTHS_H

#include "../src/image/image.h"
#include "../src/modes/render.h"
#include "../src/scene/scene.h"

/* Lambert's formula for a polygon of constant radiance le seen from p with normal n
 * (light.h's convention): E = le / 2 * | sum_i beta_i n . normalize(r_i x r_i+1) |,
 * r_i = v_i - p, beta_i the angle between r_i and r_i+1. v: count corners in order. */
double polygon_irradiance(const struct vec3 *v, int count, struct vec3 p, struct vec3 n,
                          double le);

/* The closed-form radiance camera ray r sees in scenes/analytic/area-over-floor.scene:
 * the light's Le where r meets the light square first, else rho E / pi of the floor
 * (E by polygon_irradiance()), 0 past the floor's edge (test_pt.c, test_ppm.c,
 * test_error.c). */
double area_over_floor(struct ray r);

/* scenes/analytic/sky-plane.scene (sphere 0) and sky-over-floor.scene (sphere 1): a floor
 * of albedo SKY_RHO under a sky of radiance SKY_LE, and in sky-over-floor a black sphere
 * of radius SKY_A whose centre is SKY_H above the floor's point (SKY_X, 0, 0). The closed
 * form along camera ray r: 0 where it meets the sphere (when there is one), else the
 * floor's radiance where it meets y = 0, rho Le (1 - a^2 h / d^3) with the sphere (the
 * scene file derives it), else the sky's (test_sky.c, test_error.c). */
#define SKY_RHO 0.5
#define SKY_LE 1.0
#define SKY_A 0.5
#define SKY_X 0.9
#define SKY_H 1.0
double sky_over_floor(struct ray r, int sphere);

/* sky_over_floor() with the sphere, as the scene file has it: a closed form with
 * the signature coverage_of() takes. */
double sky_over_floor_with_sphere(struct ray r);

/* scenes/analytic/point-over-plane.scene's closed form along camera ray r: where r meets
 * the plane y = 0, L = rho Phi h / (4 pi^2 d^3) (test_error_2009.c). */
double point_over_plane(struct ray r);

/* The truth of pixel (x, y): the mean of along() over its square, a 16 x 16 midpoint
 * rule (test_error.c, test_error_2009.c). */
double pixel_closed_form(const struct scene *scene, int x, int y, double (*along)(struct ray));

/* How an error image (--error) states the error of its image against a closed form, in
 * ERROR.md's words (test_error.c, test_error_2009.c). */
struct coverage {
    double covered;   /* fraction of pixels and channels with |image - truth| <= bound */
    double sharpness; /* median over COVERAGE_BLOCK-wide blocks of rms(bound) /
                         rms(image - truth) in the block (ERROR.md): rms over the whole
                         image weighs the brightest pixels alone                        */
    double rms_ratio; /* rms(bound) / rms(image - truth) over the whole image           */
};
#define COVERAGE_BLOCK 8

/* The coverage of image (a render of scene, finished, same size) by its error image
 * against the closed form along(), pixel_closed_form() per pixel; with without != NULL, of the
 * bound less |without| (a part of it, to show what that part adds). Pixels whose truth is
 * 0 (a black sphere, where the samples are all exactly 0 too) say nothing and are left
 * out. */
struct coverage coverage_of(const struct scene *scene, const struct image *image,
                            const struct image *error, const struct image *without,
                            double (*along)(struct ray));

/* The share of image's 16 x 16 blocks (image a render of scene, finished, same size; its
 * width and height multiples of 16) whose mean luminance is within e of the closed
 * form's, pixel_closed_form() per pixel, those whose truth is below ERROR_DARK_FLOOR
 * (image/error_image.h) left out as a target error leaves them; *blocks: how many were
 * judged (test_error.c, test_error_2009.c). */
double blocks_within_truth(const struct scene *scene, const struct image *image, double e,
                           double (*along)(struct ray), int *blocks);

/* The most of n statements, each true with chance 1 - p, that may fail before a test at
 * level alpha calls them untrue: the least k with P(more than k fail) < alpha, the
 * binomial's tail (make calibration's "misses" rule). */
int binomial_misses_allowed(int n, double p, double alpha);

/* What a render of scene to target error e did, against the closed form along(): the
 * share of blocks within e of it (blocks_within_truth()), the passes in *passes, and in
 * *all_within whether the render judged every one of those blocks within e. Frees result
 * and scene (test_error.c, test_error_2009.c). */
double target_outcome(struct scene *scene, struct render_result *result,
                      const struct render_counters *counters, double e,
                      double (*along)(struct ray), int *passes, int *all_within);

/* Whether every pixel of image, a render of scenes/analytic/point-over-plane.scene
 * (finished, same size), lies within the closed form L = rho Phi h / (4 pi^2 d^3) over its
 * square: a pixel is the mean of L there, so it must lie between the least and the
 * greatest L on the square (taken on a 9 x 9 grid with the corners; L is smooth and
 * monotone across a pixel), widened by 1e-12 relative for rounding (test_render.c,
 * test_jensen1996.c). */
int within_point_over_plane(const struct scene *scene, const struct image *image);

/* The closed form of scenes/analytic/point-over-plane.scene (or any scene with its plane
 * and light) where pixel (x, y)'s camera sample 0 (seed 1) meets the plane y = 0:
 * L = rho Phi h / (4 pi^2 d^3) (test_ppm.c, test_ppm_departures.c). */
double point_over_plane_sample(const struct scene *scene, int x, int y);

/* The mean signed relative error, against point_over_plane_sample(), of the pixels of
 * image (a render of a scene with point-over-plane's plane and light, seed 1) whose camera
 * sample 0 meets the plane within 0.29 (a footprint at 12 x 12) before x = 0.3, where
 * scenes/analytic/point-over-plane-wall.scene's wall stands and point-over-plane-edge's
 * plane ends; *n: how many (test_ppm.c, test_ppm_departures.c). */
double error_before_edge(const struct scene *scene, const struct image *image, int *n);

/* scenes/mirror-caustic.scene: a point light of Phi = 25 W at (0.5, 0.8, 0), a mirror
 * square of reflectance 1 at x = 1 (y 0.2..0.8, z -0.3..0.3), the Lambertian square at
 * y = 0. The exact caustic irradiance at p on the floor: the image source l' = (1.5, 0.8,
 * 0) seen through the mirror's outline, E = I cos / |p - l'|^2 with I = Phi / (4 pi)
 * (test_jensen1994_caustics.c, test_ppm_departures.c). */
double mirror_caustic_irradiance(struct vec3 p);

/* scenes/analytic/point-in-sphere.scene's radiance, 4 in every pixel: rho Phi / (4 pi^2
 * R^2 (1 - rho)) (test_ppm.c, test_sppm.c). */
double point_in_sphere_truth(const struct scene *scene, int x, int y);

/* The error of a progressive render's checkpoints against a closed form truth(scene, x,
 * y): the mean |L - truth| / truth over the pixels where truth > 0, after 1, 2, 4, ...
 * passes (test_ppm.c, test_sppm.c). */
struct error_curve {
    const struct scene *scene;
    double (*truth)(const struct scene *scene, int x, int y);
    double error[32];
    int n;
};

/* A checkpoint's at() for an error_curve: records the image's error as the next entry. */
double error_curve_record(void *context, const struct image *mean, long long work,
                          double seconds);

/* Loads and finishes the scene at path for width x height (0: the file's own size); the
 * caller frees it with scene_free. NULL, with the error printed, when it cannot be read. */
struct scene *load_test_scene(const char *path, int width, int height);

/* The window (x0 y0 x1 y1) of img as an image of its own; the caller frees it. */
struct image *crop_image(const struct image *img, const int *window);

/* The reference at path averaged over factor x factor blocks, cut to window (in the
 * small image's pixels): the reference of a render at 1/factor the size, exact in
 * expectation, since a pixel is the mean radiance over its square (render.h) and the
 * camera maps the same film to any size. NULL, with the error printed, when it cannot
 * be read (test_jensen1994.c, test_jensen1994_caustics.c, test_jensen1996.c). */
struct image *reference_window(const char *path, int factor, const int *window);

double mean_luminance(const struct image *img);

/* The glossy panel of test_jensen1994_caustics.c's and test_jensen1996.c's glossy
 * caustic, written to path (16 x 16), and its truth: the path tracer's image mean
 * (luminance) at 16,384 samples, whose standard error is 0.1%; -1 when it cannot be
 * rendered. The caller renders path too and removes it. A point light of 1000 W at (0,
 * 1, 0) lights a Lambertian floor (rho 0.5) directly and through a 1 x 1 panel of Ward's
 * glossy lobe alone (rho_s 0.8, alpha 0.1) facing down at height 2; the camera sees the
 * floor, neither the light nor the panel. No ray can hit a point light, so only photons find the panel's
 * light, as the caustic it is: about 12% of the image mean. */
double glossy_panel(const char *path);

/* The path tracer's image mean (luminance) of the scene file at path, at its own size,
 * seed 1, spp samples a pixel; -1 when it cannot be rendered. */
double pt_mean_luminance(const char *path, int spp);

/* Whether every channel of every pixel is finite and not negative. */
int finite_and_positive(const struct image *img);

/* Render settings for the whole image of scene (seed, spp, every bounce) cut to window
 * (x0 y0 x1 y1), or the whole image when window is NULL: a test case of a mode. */
struct render_settings case_settings(const struct scene *scene, uint64_t seed, int spp,
                                     const int *window);

/* A mode's result as a test keeps it: the image (NULL after a failure, whose error is
 * printed), the variance freed. */
struct image *rendered_image(struct render_result r, const struct error *err);

/* Whether a and b have the same size and the same pixels, bit for bit. */
int same_pixels(const struct image *a, const struct image *b);

/* Whether crop holds exactly the pixels of whole's window (x0 y0 x1 y1), bit for bit. */
int crop_is_window(const struct image *whole, const struct image *crop, const int *window);

/* Runs `photon --mode MODE --target-error 0.001 --passes 16 --photons-per-pass 1000 --width
 * 32 --height 24 --no-progress --stats -o OUT.pfm EXTRA scenes/analytic/sky-over-floor.scene`
 * (MODE 2008 or 2009) into OUT.log: a target no 16 passes reach. Whether it exited 0, named
 * its 4 blocks as not within it after 16 passes, the first at (0, 0), and tallied them in
 * --stats (test_error_2008.c, test_error_2009.c). OUT.log stays for more checks; the caller
 * removes it, OUT.pfm and OUT.png. */
int target_cut_short(const char *mode, const char *extra, const char *out);

/* Runs `photon --mode MODE OPTION --width 8 --height 8 -o OUT.pfm scenes/cornell.scene`
 * for each bad[i] = {OPTION, TEXT}: each must exit 2 with TEXT in its message and leave
 * no OUT.pfm, temporary of it (files.h) or OUT.png. Returns how many did not (each named on stderr). */
int refuses_options(const char *mode, const char *const (*bad)[2], size_t n_bad,
                    const char *out);

/* Sums of independent contributions, for the standard error of their total
 * (test_trace.c, test_projection.c). */
struct tally {
    double sum, sum2; /* of the contributions (zeros add nothing) */
    double n;         /* how many contributions, zeros included   */
};

void tally_add(struct tally *t, double x);

/* The standard error of the total of t->n iid contributions: sqrt(n s^2). */
double tally_se(const struct tally *t);

/* Adds a material of kind with albedo (or reflectance) rho and emission, index of
 * refraction 1.5, named m0, m1, ...; returns its index. */
int add_test_material(struct scene *scene, enum material_kind kind, struct vec3 rho,
                      struct vec3 emission);

/* Gives a scene built in code a camera (any valid one: such scenes are only traced) and
 * finishes it at 8 x 8. */
void finish_test_scene(struct scene *scene);

/* Gives a scene built in code a camera at from looking at at (up +y, fov degrees) and
 * finishes it at width x height. */
void finish_with_camera(struct scene *scene, struct vec3 from, struct vec3 at, double fov,
                        int width, int height);

/* The options that cut the work of the mode that render starts with (a mode's name, then
 * anything) to a fraction of a second on the test scenes, the counts of `make check`'s
 * determinism loop; only options that mode takes ("" for direct and pt). */
const char *mode_work_options(const char *render);

/* A Phong floor (kd 0.3, ks 0.5, n 40) under a point light, 32 x 24 pixels: the light's
 * highlight, which only the glossy lobe reflects, fills the middle of the image (a scene
 * file's text, for 2009's paper way: test_sppm.c against pt, test_literal.c). */
extern const char phong_highlight_scene[];

#endif
