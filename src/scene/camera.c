/*
 * scene/camera.c -- the pinhole camera of camera.h.
 */
#include "camera.h"

#include <assert.h>

int camera_is_valid(const struct camera *c)
{
    struct vec3 forward = vec3_sub(c->at, c->from);
    struct vec3 side = vec3_cross(forward, c->up);
    /* Parallel within a relative 1e-12: the cross product is then pure rounding noise. */
    double scale = vec3_length(forward) * vec3_length(c->up);
    return scale > 0 && vec3_length(side) > 1e-12 * scale && c->fov > 0 && c->fov < 180;
}

void camera_setup(struct camera *c, int width, int height)
{
    assert(camera_is_valid(c) && width > 0 && height > 0);
    c->w = vec3_normalize(vec3_sub(c->at, c->from));
    c->u = vec3_normalize(vec3_cross(c->w, c->up));
    c->v = vec3_cross(c->u, c->w);
    c->tan_half = tan(c->fov * PI / 360.0);
    c->width = width;
    c->height = height;
    c->aspect = (double)width / height;
}

struct ray camera_ray(const struct camera *c, double px, double py)
{
    double sx = (2.0 * px / c->width - 1.0) * c->tan_half * c->aspect;
    double sy = (1.0 - 2.0 * py / c->height) * c->tan_half;
    struct vec3 d = vec3_add(c->w, vec3_add(vec3_scale(c->u, sx), vec3_scale(c->v, sy)));
    return make_ray(c->from, vec3_normalize(d));
}
