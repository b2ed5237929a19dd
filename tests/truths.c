/*
 * tests/truths.c -- the closed forms and fixtures behind truths.h.
 */
#include "truths.h"

#include "files.h"
#include "../src/base/alloc.h"
#include "../src/image/error_image.h"
#include "../src/modes/pt.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

double polygon_irradiance(const struct vec3 *v, int count, struct vec3 p, struct vec3 n,
                          double le)
{
    double sum = 0;
    for (int i = 0; i < count; i++) {
        struct vec3 a = vec3_normalize(vec3_sub(v[i], p));
        struct vec3 b = vec3_normalize(vec3_sub(v[(i + 1) % count], p));
        double beta = acos(fmax(-1.0, fmin(1.0, vec3_dot(a, b))));
        sum += beta * vec3_dot(n, vec3_normalize(vec3_cross(a, b)));
    }
    return le / 2 * fabs(sum);
}

double area_over_floor(struct ray r)
{
    static const struct vec3 light[4] = {{-0.5, 1, -0.5}, {0.5, 1, -0.5}, {0.5, 1, 0.5},
                                         {-0.5, 1, 0.5}};
    if (r.dir.y > 0) {
        struct vec3 q = ray_at(r, (1 - r.origin.y) / r.dir.y);
        return fabs(q.x) <= 0.5 && fabs(q.z) <= 0.5 ? 10.0 : 0.0;
    }
    struct vec3 x = ray_at(r, -r.origin.y / r.dir.y);
    if (fabs(x.x) > 50 || fabs(x.z) > 50)
        return 0.0; /* past the floor's edge */
    return 0.5 * polygon_irradiance(light, 4, x, vec3(0, 1, 0), 10.0) / PI;
}

double sky_over_floor(struct ray r, int sphere)
{
    struct vec3 oc = vec3_sub(r.origin, vec3(SKY_X, SKY_H, 0));
    double b = vec3_dot(oc, r.dir), c = vec3_length2(oc) - SKY_A * SKY_A;
    if (sphere && b * b - c >= 0 && -b - sqrt(b * b - c) > 0)
        return 0.0;
    if (!(r.dir.y < 0))
        return SKY_LE;
    struct vec3 x = vec3_madd(r.origin, r.dir, -r.origin.y / r.dir.y);
    if (!sphere)
        return SKY_RHO * SKY_LE;
    double d = vec3_length(vec3_sub(x, vec3(SKY_X, SKY_H, 0)));
    return SKY_RHO * SKY_LE * (1.0 - SKY_A * SKY_A * SKY_H / (d * d * d));
}

struct scene *load_test_scene(const char *path, int width, int height)
{
    struct error err;
    struct scene *scene = scene_load(path, &err);
    if (scene == NULL) {
        error_print(&err);
        return NULL;
    }
    scene_finish(scene, width > 0 ? width : scene->width, height > 0 ? height : scene->height);
    return scene;
}

/* The closed form of scenes/analytic/point-over-plane.scene at image point (px, py):
 * rho = 0.5, Phi = 1000 W, the light 1 above the plane y = 0. */
static double plane_radiance(const struct scene *scene, double px, double py)
{
    struct ray r = camera_ray(&scene->camera, px, py);
    struct vec3 x = ray_at(r, -r.origin.y / r.dir.y); /* where the ray meets y = 0 */
    double d = vec3_length(vec3_sub(x, vec3(0, 1, 0)));
    return 0.5 * 1000 * 1.0 / (4 * PI * PI * d * d * d);
}

double sky_over_floor_with_sphere(struct ray r)
{
    return sky_over_floor(r, 1);
}

double point_over_plane(struct ray r)
{
    struct vec3 x = ray_at(r, -r.origin.y / r.dir.y);
    double d = vec3_length(vec3_sub(x, vec3(0, 1, 0)));
    return 0.5 * 1000 / (4 * PI * PI * d * d * d);
}

double pixel_closed_form(const struct scene *scene, int x, int y, double (*along)(struct ray))
{
    double sum = 0.0;
    for (int j = 0; j < 16; j++)
        for (int i = 0; i < 16; i++)
            sum += along(camera_ray(&scene->camera, x + (i + 0.5) / 16, y + (j + 0.5) / 16));
    return sum / 256.0;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double blocks_within_truth(const struct scene *scene, const struct image *image, double e,
                           double (*along)(struct ray), int *blocks)
{
    int within = 0;
    *blocks = 0;
    for (int by = 0; by + 16 <= image->height; by += 16)
        for (int bx = 0; bx + 16 <= image->width; bx += 16) {
            double mean = 0.0, truth = 0.0;
            for (int y = by; y < by + 16; y++)
                for (int x = bx; x < bx + 16; x++) {
                    mean += vec3_luminance(image_get(image, x, y));
                    truth += pixel_closed_form(scene, x, y, along);
                }
            if (truth < 256 * ERROR_DARK_FLOOR)
                continue;
            (*blocks)++;
            within += fabs(mean - truth) <= e * truth;
        }
    return *blocks > 0 ? (double)within / *blocks : 0.0;
}

int binomial_misses_allowed(int n, double p, double alpha)
{
    double pmf = pow(1.0 - p, n), at_most = 0.0;
    for (int k = 0; k < n; k++) {
        at_most += pmf;
        if (1.0 - at_most < alpha)
            return k;
        pmf *= (double)(n - k) / (k + 1) * p / (1.0 - p);
    }
    return n;
}

double target_outcome(struct scene *scene, struct render_result *result,
                      const struct render_counters *counters, double e,
                      double (*along)(struct ray), int *passes, int *all_within)
{
    int blocks;
    double within = blocks_within_truth(scene, result->image, e, along, &blocks);
    *passes = counters->passes;
    *all_within = counters->target_within == counters->target_blocks &&
                  counters->target_blocks == blocks && counters->target_missed_x == -1;
    render_result_free(result);
    scene_free(scene);
    return within;
}

struct coverage coverage_of(const struct scene *scene, const struct image *image,
                            const struct image *error, const struct image *without,
                            double (*along)(struct ray))
{
    struct coverage cover = {0.0, 0.0, 0.0};
    int width = image->width, height = image->height;
    int bw = (width + COVERAGE_BLOCK - 1) / COVERAGE_BLOCK;
    int bh = (height + COVERAGE_BLOCK - 1) / COVERAGE_BLOCK;
    double *block_b2 = xcalloc((size_t)(2 * bw * bh), sizeof *block_b2, "test blocks");
    double *block_e2 = block_b2 + bw * bh;
    double n = 0, within = 0, bound2 = 0, error2 = 0;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            double truth = pixel_closed_form(scene, x, y, along);
            if (truth == 0)
                continue;
            int k = y / COVERAGE_BLOCK * bw + x / COVERAGE_BLOCK;
            for (int c = 0; c < 3; c++) {
                double e = vec3_get(image_get(image, x, y), c) - truth;
                double b = vec3_get(image_get(error, x, y), c);
                if (without != NULL)
                    b -= fabs(vec3_get(image_get(without, x, y), c));
                n++;
                within += fabs(e) <= b;
                bound2 += b * b;
                error2 += e * e;
                block_b2[k] += b * b;
                block_e2[k] += e * e;
            }
        }
    int n_blocks = 0;
    for (int k = 0; k < bw * bh; k++)
        if (block_e2[k] > 0)
            block_b2[n_blocks++] = sqrt(block_b2[k] / block_e2[k]);
    qsort(block_b2, (size_t)n_blocks, sizeof *block_b2, by_value);
    cover.covered = n > 0 ? within / n : 0.0;
    cover.sharpness = n_blocks > 0 ? block_b2[n_blocks / 2] : 0.0;
    cover.rms_ratio = error2 > 0 ? sqrt(bound2 / error2) : 0.0;
    xfree(block_b2);
    return cover;
}

double point_over_plane_sample(const struct scene *scene, int x, int y)
{
    struct rng rng;
    struct ray r = camera_sample(scene, 1, x, y, 0, &rng);
    struct vec3 p = ray_at(r, -r.origin.y / r.dir.y);
    double d = vec3_length(vec3_sub(p, vec3(0, 1, 0)));
    return 0.5 * 1000 / (4 * PI * PI * d * d * d);
}

double error_before_edge(const struct scene *scene, const struct image *image, int *n)
{
    double sum = 0.0;
    *n = 0;
    for (int y = 0; y < image->height; y++)
        for (int x = 0; x < image->width; x++) {
            struct rng rng;
            struct ray r = camera_sample(scene, 1, x, y, 0, &rng);
            double foot = r.origin.x - r.origin.y / r.dir.y * r.dir.x;
            if (foot < 0.3 && foot > 0.3 - 0.29) {
                double truth = point_over_plane_sample(scene, x, y);
                sum += (image_get(image, x, y).y - truth) / truth;
                (*n)++;
            }
        }
    return *n > 0 ? sum / *n : INFINITY;
}

double mirror_caustic_irradiance(struct vec3 p)
{
    struct vec3 image = vec3(1.5, 0.8, 0);
    double t = (1 - p.x) / (image.x - p.x); /* where p -> l' crosses the mirror's plane */
    struct vec3 m = vec3_add(p, vec3_scale(vec3_sub(image, p), t));
    if (!(t > 0 && t < 1 && m.y >= 0.2 && m.y <= 0.8 && fabs(m.z) <= 0.3))
        return 0;
    struct vec3 d = vec3_sub(image, p);
    double d2 = vec3_length2(d);
    return 25 / (4 * PI) * (d.y / sqrt(d2)) / d2;
}

int within_point_over_plane(const struct scene *scene, const struct image *image)
{
    int inside = 1;
    for (int y = 0; y < image->height; y++)
        for (int x = 0; x < image->width; x++) {
            double lo = INFINITY, hi = 0;
            for (int j = 0; j <= 8; j++)
                for (int i = 0; i <= 8; i++) {
                    double l = plane_radiance(scene, x + i / 8.0, y + j / 8.0);
                    lo = fmin(lo, l);
                    hi = fmax(hi, l);
                }
            double v = image_get(image, x, y).y;
            inside = inside && v >= lo * (1 - 1e-12) && v <= hi * (1 + 1e-12);
        }
    return inside;
}

/* The window (x0 y0 x1 y1) of img as an image of its own. */
struct image *crop_image(const struct image *img, const int *window)
{
    struct image *out = image_create(window[2] - window[0], window[3] - window[1]);
    for (int y = 0; y < out->height; y++)
        for (int x = 0; x < out->width; x++)
            image_set(out, x, y, image_get(img, x + window[0], y + window[1]));
    return out;
}

/* The reference at path averaged over factor x factor blocks, cut to window (in the
 * small image's pixels); NULL when it cannot be read. */
struct image *reference_window(const char *path, int factor, const int *window)
{
    struct error err;
    struct image *ref = pfm_read(path, &err);
    if (ref == NULL) {
        error_print(&err);
        return NULL;
    }
    struct image *small = image_create(ref->width / factor, ref->height / factor);
    for (int y = 0; y < small->height; y++)
        for (int x = 0; x < small->width; x++) {
            struct vec3 sum = vec3_zero();
            for (int j = 0; j < factor; j++)
                for (int i = 0; i < factor; i++)
                    sum = vec3_add(sum, image_get(ref, x * factor + i, y * factor + j));
            image_set(small, x, y, vec3_scale(sum, 1.0 / (factor * factor)));
        }
    struct image *out = crop_image(small, window);
    image_free(small);
    image_free(ref);
    return out;
}

double mean_luminance(const struct image *img)
{
    double sum = 0;
    size_t n = (size_t)img->width * (size_t)img->height;
    for (size_t i = 0; i < n; i++)
        sum += vec3_luminance(img->pixels[i]);
    return sum / (double)n;
}

double glossy_panel(const char *path)
{
    write_text_file(path, "image 16 16\n"
                          "camera 0 0.5 -4  0 -1 0  0 1 0  40\n"
                          "material floor lambert 0.5 0.5 0.5\n"
                          "material panel ward 0 0 0 0.8 0.8 0.8 0.1 0.1\n"
                          "quad -100 0 -100 -100 0 100 100 0 100 100 0 -100 floor\n"
                          "quad -0.5 2 -0.5 0.5 2 -0.5 0.5 2 0.5 -0.5 2 0.5 panel\n"
                          "light point 0 1 0 1000 1000 1000\n");
    return pt_mean_luminance(path, 16384);
}

double pt_mean_luminance(const char *path, int spp)
{
    struct scene *scene = load_test_scene(path, 0, 0);
    if (scene == NULL)
        return -1.0;
    struct render_settings rs = render_settings_whole(scene, 1, spp, MAX_DEPTH_LIMIT);
    struct render_counters counters = {0};
    struct error err;
    struct image *img = rendered_image(render_pt(scene, &rs, 0, NULL, &counters), &err);
    double mean = img != NULL ? mean_luminance(img) : -1.0;
    image_free(img);
    scene_free(scene);
    return mean;
}

/* Whether every channel of every pixel is finite and not negative. */
int finite_and_positive(const struct image *img)
{
    size_t n = (size_t)img->width * (size_t)img->height;
    for (size_t i = 0; i < n; i++) {
        struct vec3 v = img->pixels[i];
        if (!(isfinite(v.x) && isfinite(v.y) && isfinite(v.z)) || v.x < 0 || v.y < 0 || v.z < 0)
            return 0;
    }
    return 1;
}

void tally_add(struct tally *t, double x)
{
    t->sum += x;
    t->sum2 += x * x;
}

double tally_se(const struct tally *t)
{
    if (t->n < 2)
        return 0;
    double var = (t->sum2 - t->sum * t->sum / t->n) / (t->n - 1);
    return sqrt(fmax(0.0, t->n * var));
}

int add_test_material(struct scene *scene, enum material_kind kind, struct vec3 rho,
                      struct vec3 emission)
{
    struct material m;
    memset(&m, 0, sizeof m);
    sprintf(m.name, "m%zu", scene->n_materials);
    m.kind = kind;
    m.rho = rho;
    m.ior = 1.5;
    m.emission = emission;
    return scene_add_material(scene, &m);
}

void finish_with_camera(struct scene *scene, struct vec3 from, struct vec3 at, double fov,
                        int width, int height)
{
    scene->camera.from = from;
    scene->camera.at = at;
    scene->camera.up = vec3(0, 1, 0);
    scene->camera.fov = fov;
    scene->has_camera = 1;
    scene_finish(scene, width, height);
}

void finish_test_scene(struct scene *scene)
{
    finish_with_camera(scene, vec3(0, 5, -5), vec3(0, 0, 0), 60, 8, 8);
}

int same_pixels(const struct image *a, const struct image *b)
{
    return a->width == b->width && a->height == b->height &&
           memcmp(a->pixels, b->pixels,
                  (size_t)a->width * (size_t)a->height * sizeof *a->pixels) == 0;
}

int crop_is_window(const struct image *whole, const struct image *crop, const int *window)
{
    struct image *same_window = crop_image(whole, window);
    int same = same_pixels(same_window, crop);
    image_free(same_window);
    return same;
}

int target_cut_short(const char *mode, const char *extra, const char *out)
{
    char args[1024], log[512];
    snprintf(log, sizeof log, "%s.log", out);
    snprintf(args, sizeof args, "--mode %s --target-error 0.001 --passes 16 --photons-per-pass "
             "1000 --width 32 --height 24 --no-progress --stats -o %s.pfm %s "
             "scenes/analytic/sky-over-floor.scene", mode, out, extra);
    return photon_logged("", args, log) == 0 &&
           file_contains(log, "blocks not within it after 16 passes, the first at (0, 0)") &&
           file_stat(log, "target_blocks") == 4 && file_stat(log, "target_blocks_within") == 0;
}

int refuses_options(const char *mode, const char *const (*bad)[2], size_t n_bad,
                    const char *out)
{
    char args[1024], image[512], png[512], log[512];
    snprintf(image, sizeof image, "%s.pfm", out);
    snprintf(png, sizeof png, "%s.png", out);
    snprintf(log, sizeof log, "%s.log", out);
    int failed = 0;
    for (size_t i = 0; i < n_bad; i++) {
        remove(image);
        remove(png);
        snprintf(args, sizeof args, "--mode %s %s --width 8 --height 8 -o %s "
                 "scenes/cornell.scene", mode, bad[i][0], image);
        if (photon_logged("", args, log) != 2 || !file_contains(log, bad[i][1]) ||
            file_exists(image) || !no_temporaries(image) || file_exists(png)) {
            fprintf(stderr, "refuses_options: '%s' was not refused as documented\n", bad[i][0]);
            failed++;
        }
    }
    remove(log);
    return failed;
}

struct render_settings case_settings(const struct scene *scene, uint64_t seed, int spp,
                                     const int *window)
{
    struct render_settings rs = render_settings_whole(scene, seed, spp, MAX_DEPTH_LIMIT);
    if (window != NULL) {
        rs.x0 = window[0];
        rs.y0 = window[1];
        rs.x1 = window[2];
        rs.y1 = window[3];
    }
    return rs;
}

struct image *rendered_image(struct render_result r, const struct error *err)
{
    if (r.image == NULL)
        error_print(err);
    image_free(r.variance);
    return r.image;
}

const char *mode_work_options(const char *render)
{
    static const char *const work[][2] = {
        {"photons", "--photons 20000"},
        {"1994", "--photons 20000 --gather-rays 32"},
        {"1996", "--photons 20000 --caustic-photons 20000 --gather-rays 32"},
        {"2008", "--passes 2 --photons-per-pass 20000"},
    };
    size_t n = strcspn(render, " ");
    for (size_t i = 0; i < sizeof work / sizeof work[0]; i++)
        if (strlen(work[i][0]) == n && strncmp(render, work[i][0], n) == 0)
            return work[i][1];
    return "";
}

double error_curve_record(void *context, const struct image *mean, long long work,
                          double seconds)
{
    (void)work;
    (void)seconds;
    struct error_curve *c = context;
    double sum = 0;
    int n = 0;
    for (int y = 0; y < mean->height; y++)
        for (int x = 0; x < mean->width; x++) {
            double truth = c->truth(c->scene, x, y);
            if (truth > 0) {
                sum += fabs(image_get(mean, x, y).y - truth) / truth;
                n++;
            }
        }
    if (c->n < 32)
        c->error[c->n++] = n > 0 ? sum / n : INFINITY;
    return 0;
}

double point_in_sphere_truth(const struct scene *scene, int x, int y)
{
    (void)scene;
    (void)x;
    (void)y;
    return 4.0;
}

const char phong_highlight_scene[] = "image 32 24\n"
                                     "camera 0 1.5 -3  0 0 0.5  0 1 0  40\n"
                                     "material floor phong 0.3 0.3 0.3  0.5 0.5 0.5  40\n"
                                     "quad -5 0 -5  -5 0 5  5 0 5  5 0 -5  floor\n"
                                     "light point 0 1.5 1.5  40 40 40\n";
