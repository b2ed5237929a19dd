/*
 * tests/truths.c -- the closed forms and fixtures behind truths.h.
 */
#include "truths.h"

#include <math.h>

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
