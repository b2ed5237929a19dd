/*
 * geom/polygon.h -- cutting a planar polygon into triangles, for the readers of NFF
 * polygons and OBJ faces.
 */
#ifndef PHOTON_POLYGON_H
#define PHOTON_POLYGON_H

#include "ray.h"

/* Documented limit on the vertices of one polygon (NFF `p`/`pp`, OBJ `f`): ear clipping
 * costs O(n^2) per polygon, and real polygons have far fewer (SPD's largest has 144). */
#define MAX_POLYGON_VERTICES 10000

/* Splits the polygon v[0 .. n-1] (3 <= n <= MAX_POLYGON_VERTICES, in either winding) into
 * n - 2 triangles by ear clipping (in 2-D, along the largest axis of its Newell normal), so
 * concave polygons are right. Writes the triangles' corner indices to
 * triangles[0 .. 3(n-2) - 1], each triangle in the polygon's own winding, so each faces the
 * polygon's front side. For a simple polygon the triangles tile it exactly; a
 * self-intersecting or zero-area one still gets n - 2 triangles (some may overlap or have
 * no area), never an error. */
void polygon_triangulate(const struct vec3 *v, int n, int *triangles);


#endif
