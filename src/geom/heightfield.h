/*
 * geom/heightfield.h -- a fractal landscape: a square grid of heights from fractal Brownian
 * motion of gradient noise (noise.h), intersected procedurally as one shape.
 *
 * The square lies in the xz plane, y up (scene convention), corner at origin:
 * sample (i, j), 0 <= i, j < n, sits at
 *   x_i = origin.x + i * spacing,  z_j = origin.z + j * spacing,  spacing = size / (n - 1),
 *   y_ij = origin.y + height * fbm2(i * c, j * c),  c = frequency / (n - 1),
 * so heights stay within origin.y +- height. Cell (i, j) is the square between samples i, i+1
 * and j, j+1, cut by its diagonal from (i, j) to (i+1, j+1) into the triangles
 *   [v(i,j), v(i,j+1), v(i+1,j+1)] and [v(i,j), v(i+1,j+1), v(i+1,j)],
 * both counter-clockwise seen from +y, so ng points up. Shading normals blend vertex
 * normals from central differences of the heights (one-sided on the border).
 *
 * No triangle is stored: the shape holds the n x n heights and a min/max pyramid over the
 * cells (heightfield.c). heightfield_expand() adds the same triangles, vertex for vertex,
 * to a geometry.
 */
#ifndef PHOTON_HEIGHTFIELD_H
#define PHOTON_HEIGHTFIELD_H

#include <stdint.h>

#include "../base/error.h"
#include "geometry.h"
#include "noise.h"

#define HEIGHTFIELD_MIN_RESOLUTION 2    /* one cell */
#define HEIGHTFIELD_MAX_RESOLUTION 8193 /* 2^13 + 1 samples a side: 0.9 GB of heights and
                                           pyramid; larger grids are refused as absurd */
#define HEIGHTFIELD_MAX_OCTAVES NOISE_MAX_OCTAVES
#define HEIGHTFIELD_MAX_FREQUENCY 1e6   /* keeps noise coordinates below 2^62 (noise2) */

struct heightfield_params {
    struct vec3 origin; /* the corner with least x and z; heights are about origin.y      */
    double size;        /* side of the square along x and z, > 0                          */
    int resolution;     /* n: samples per side, HEIGHTFIELD_MIN..MAX_RESOLUTION           */
    int octaves;        /* noise octaves summed, 1..HEIGHTFIELD_MAX_OCTAVES               */
    double roughness;   /* gain: amplitude ratio of successive octaves, in (0, 1]          */
    double frequency;   /* noise lattice cells across the square in octave 0, in (0, 1e6] */
    double height;      /* height scale: heights within origin.y +- height, >= 0          */
    uint64_t seed;      /* keys the noise: same seed, same landscape on every machine     */
    int material;
};

struct heightfield;

/* Checks the parameters, samples the heights and builds the pyramid; NULL with *err filled
 * (file "", line 0: the caller adds its own) when a parameter is out of range, not finite,
 * or the spacing is below 1e-12 of the coordinates (cells would collapse in rounding). */
struct heightfield *heightfield_create(const struct heightfield_params *params,
                                       struct error *err);
void heightfield_free(struct heightfield *hf); /* NULL is a no-op */

/* For geometry_add_shape(g, &heightfield_ops, hf, material): intersect fills every field of
 * struct hit but prim, as triangle.h would for the expanded triangle (p, ng up, ns), except
 * u, v: the hit's place on the square, ((x - origin.x) / size, (z - origin.z) / size).
 * material is params.material; the one given to geometry_add_shape() is not used. */
extern const struct shape_ops heightfield_ops;

/* Calls visit for every triangle, cell by cell (j, then i), with its vertices in the order
 * above and their shading normals: the very doubles the intersection uses. */
void heightfield_triangles(const struct heightfield *hf,
                           void (*visit)(void *context, const struct vec3 v[3],
                                         const struct vec3 normals[3], int material),
                           void *context);

/* Adds the 2 (n - 1)^2 triangles to g with geometry_add_triangle(). Returns 0, or -1 (adding
 * nothing) when their count exceeds MAX_PRIMITIVES, or (having added some) when geometry
 * refuses one. */
int heightfield_expand(const struct heightfield *hf, struct geometry *g);

/* Whether every pyramid entry holds the min and max of the heights under it: 1 or 0. */
int heightfield_check(const struct heightfield *hf);

#endif
