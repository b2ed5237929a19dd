/*
 * scene/camera.h -- the camera: a pinhole, or a thin lens.
 *
 * Frame (the usual reading of NFF's `v` block, `angle` the full vertical field of view, so
 * our rays match other renderers' on the same file):
 * w = normalize(at - from), u = normalize(w x up), v = u x w. A point (px, py) on the
 * image plane, in pixels of the whole image with (0, 0) the top-left corner, maps to the
 * direction normalize(w + (2 px / W - 1) t (W / H) u + (1 - 2 py / H) t v), t = tan(fov / 2),
 * fov the full vertical field of view. So u points right and v up in the picture.
 *
 * A thin lens (Kolb, Mitchell & Hanrahan 1995, Sec. 2; pbrt's "perspective" camera with
 * lensradius and focaldistance) is a disc of radius lens_radius about from in the plane
 * of u and v, focused on the plane at distance focus along w. The ray through image point
 * (px, py) and lens point L leaves L towards from + focus (w + sx u + sy v), sx and sy as
 * above: the point the pinhole ray through (px, py) meets on the plane in focus. Points
 * on that plane are sharp; a point at distance z along w is seen as a disc of radius
 * lens_radius |z - focus| / z on it (the circle of confusion). lens_radius 0 is the
 * pinhole, ray for ray.
 */
#ifndef PHOTON_CAMERA_H
#define PHOTON_CAMERA_H

#include "../geom/ray.h"

struct camera {
    struct vec3 from, at, up; /* as given: position, look-at point, up hint (any length)  */
    double fov;               /* full vertical field of view in degrees, in (0, 180)       */
    double lens_radius;       /* the thin lens's radius, >= 0; 0 is the pinhole            */
    double focus;             /* distance along w of the plane in focus, > 0 with a lens   */
    /* Set by camera_setup(): */
    struct vec3 u, v, w;      /* right, up, forward: an orthonormal frame                  */
    double tan_half;          /* tan(fov / 2)                                              */
    double aspect;            /* width / height of the whole image                         */
    int width, height;        /* of the whole image, in pixels                             */
};

/* Whether from, at and up give a frame (at != from, up not parallel to at - from), the
 * field of view is in (0, 180), lens_radius >= 0, and focus > 0 where lens_radius > 0. */
int camera_is_valid(const struct camera *c);

/* Derives the frame for an image of width x height pixels; the camera must be valid. */
void camera_setup(struct camera *c, int width, int height);

/* The width of a pixel at distance 1 from the camera (at the image's centre): a surface
 * at distance d along a camera ray is seen d times this wide through one pixel. */
static inline double camera_footprint(const struct camera *c)
{
    return 2.0 * c->tan_half / c->height;
}

/* The unit-direction ray through image-plane point (px, py), in pixels from the top left,
 * from the lens's centre. */
struct ray camera_ray(const struct camera *c, double px, double py);

/* The unit-direction ray through image-plane point (px, py) from the lens point that
 * (lens_x, lens_y), uniform in [0, 1)^2, maps to: uniform on the lens's disc, by Shirley
 * and Chiu's concentric map, which keeps strata of the square strata of the disc. With
 * lens_radius 0 it is camera_ray(c, px, py), bit for bit. */
struct ray camera_lens_ray(const struct camera *c, double px, double py, double lens_x,
                           double lens_y);

#endif
