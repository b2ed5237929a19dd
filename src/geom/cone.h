/*
 * geom/cone.h -- an open cone frustum or cylinder between two points, as NFF's `c` gives it
 * (Haines, "Neutral File Format"): base point B with radius r_base, apex point A with radius
 * r_apex, and no end caps.
 *
 * The surface is the set of points at axial distance s in [0, h] from B along the unit axis
 * w = (A - B) / h, h = |A - B|, and at radial distance r(s) = r_base + k s from the axis,
 * k = (r_apex - r_base) / h; equal radii make a cylinder, a zero radius a true cone.
 * Its front side is the outside. NFF's negative radii (both <= 0: only the inside is
 * visible) give the same surface with |r| and the front side inside; our renderer's
 * surfaces reflect on both sides, so the sign changes only which side is the front.
 *
 * One procedural shape per cone (struct shape_ops), intersected exactly (cone.c); the shape
 * owns nothing but itself.
 */
#ifndef PHOTON_CONE_H
#define PHOTON_CONE_H

#include "../base/error.h"
#include "geometry.h"

struct cone;

/* Makes the shape; NULL with *err filled (file "", line 0: the caller adds its own) when a
 * number is not finite, B = A, both radii are zero, the radii have opposite signs, or the
 * slope k overflows. material is handed back in every hit. */
struct cone *cone_create(struct vec3 base, double r_base, struct vec3 apex, double r_apex,
                         int material, struct error *err);
void cone_free(struct cone *cone); /* NULL is a no-op */

/* For geometry_add_shape(g, &cone_ops, cone, material). intersect fills every field of
 * struct hit but prim: t; p on the surface; ng = ns = normalize(e - k w) on the front side
 * (e the unit radial direction at p); u = angle about the axis / 2 pi in [0, 1);
 * v = s / h in [0, 1]; material. free is cone_free. */
extern const struct shape_ops cone_ops;

#endif
