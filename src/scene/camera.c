/*
 * scene/camera.c -- the camera of camera.h: a pinhole, or a thin lens.
 */
#include "camera.h"

#include <assert.h>

int camera_is_valid(const struct camera *c)
{
    struct vec3 forward = vec3_sub(c->at, c->from);
    struct vec3 side = vec3_cross(forward, c->up);
    /* Parallel within a relative 1e-12: the cross product is then pure rounding noise. */
    double scale = vec3_length(forward) * vec3_length(c->up);
    return scale > 0 && vec3_length(side) > 1e-12 * scale && c->fov > 0 && c->fov < 180 &&
           c->lens_radius >= 0 && (c->lens_radius == 0 || c->focus > 0);
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

/* The pinhole ray's direction through (px, py), not normalised: its w component is 1. */
static struct vec3 pinhole_direction(const struct camera *c, double px, double py)
{
    double sx = (2.0 * px / c->width - 1.0) * c->tan_half * c->aspect;
    double sy = (1.0 - 2.0 * py / c->height) * c->tan_half;
    return vec3_add(c->w, vec3_add(vec3_scale(c->u, sx), vec3_scale(c->v, sy)));
}

struct ray camera_ray(const struct camera *c, double px, double py)
{
    return make_ray(c->from, vec3_normalize(pinhole_direction(c, px, py)));
}

/* Shirley and Chiu's concentric map of (x, y) in [0, 1)^2 onto the unit disc, as (*a, *b):
 * squares about the centre go to rings, so the map keeps areas (uniform to uniform) and
 * stretches strata the least. */
static void concentric_disc(double x, double y, double *a, double *b)
{
    double sx = 2.0 * x - 1.0, sy = 2.0 * y - 1.0;
    double r, phi;
    if (sx == 0 && sy == 0) {
        *a = *b = 0;
        return;
    }
    if (fabs(sx) > fabs(sy)) {
        r = sx;
        phi = (PI / 4) * (sy / sx);
    } else {
        r = sy;
        phi = PI / 2 - (PI / 4) * (sx / sy);
    }
    *a = r * cos(phi);
    *b = r * sin(phi);
}

struct ray camera_lens_ray(const struct camera *c, double px, double py, double lens_x,
                           double lens_y)
{
    if (c->lens_radius == 0)
        return camera_ray(c, px, py);
    double a, b;
    concentric_disc(lens_x, lens_y, &a, &b);
    struct vec3 lens = vec3_add(c->from, vec3_add(vec3_scale(c->u, c->lens_radius * a),
                                                  vec3_scale(c->v, c->lens_radius * b)));
    struct vec3 in_focus = vec3_add(c->from, vec3_scale(pinhole_direction(c, px, py), c->focus));
    return make_ray(lens, vec3_normalize(vec3_sub(in_focus, lens)));
}
