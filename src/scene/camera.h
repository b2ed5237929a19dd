/*
 * scene/camera.h -- the pinhole camera.
 *
 * Frame (the usual reading of NFF's `v` block, `angle` the full vertical field of view, so
 * our rays match other renderers' on the same file):
 * w = normalize(at - from), u = normalize(w x up), v = u x w. A point (px, py) on the
 * image plane, in pixels of the whole image with (0, 0) the top-left corner, maps to the
 * direction normalize(w + (2 px / W - 1) t (W / H) u + (1 - 2 py / H) t v), t = tan(fov / 2),
 * fov the full vertical field of view. So u points right and v up in the picture.
 */
#ifndef PHOTON_CAMERA_H
#define PHOTON_CAMERA_H

#include "../geom/ray.h"

struct camera {
    struct vec3 from, at, up; /* as given: position, look-at point, up hint (any length)  */
    double fov;               /* full vertical field of view in degrees, in (0, 180)       */
    /* Set by camera_setup(): */
    struct vec3 u, v, w;      /* right, up, forward: an orthonormal frame                  */
    double tan_half;          /* tan(fov / 2)                                              */
    double aspect;            /* width / height of the whole image                         */
    int width, height;        /* of the whole image, in pixels                             */
};

/* Whether from, at and up give a frame: at != from and up not parallel to at - from. */
int camera_is_valid(const struct camera *c);

/* Derives the frame for an image of width x height pixels; the camera must be valid. */
void camera_setup(struct camera *c, int width, int height);

/* The width of a pixel at distance 1 from the camera (at the image's centre): a surface
 * at distance d along a camera ray is seen d times this wide through one pixel. */
static inline double camera_footprint(const struct camera *c)
{
    return 2.0 * c->tan_half / c->height;
}

/* The unit-direction ray through image-plane point (px, py), in pixels from the top left. */
struct ray camera_ray(const struct camera *c, double px, double py);

#endif
