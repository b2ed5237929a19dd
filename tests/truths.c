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
