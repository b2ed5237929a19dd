/*
 * geom/mesh.h -- the scene's triangles, sharing their corners: each distinct point is
 * stored once, and a triangle is three indices into the points.
 *
 * A mesh's triangles meet at their corners (in a grid every point is a corner of six), so
 * keeping each point once stores a triangle in 24 bytes and, on average, half a point of 24
 * bytes, where three points of its own take 72. Points are the same when they are equal bit
 * for bit; a point is looked up in a hash table (open addressing, linear probing) while
 * triangles are added. Invariants:
 *   (1) points[0 .. n_points) are distinct bit patterns, and every corner of every triangle
 *       is below n_points;
 *   (2) while the table exists it holds every point's index once, at its hash's probe
 *       sequence, and is at most half full; mesh_finish() drops it (no adds are expected
 *       after a build) and the next add rebuilds it.
 * The intersection and shading are triangle.h's, on the three points. Owns points[],
 * triangles[] and the table. geometry.c permutes triangles[] into the BVH's leaf order;
 * mesh_finish() then renumbers the points in the order the triangles first use them, so a
 * leaf's corners lie side by side.
 */
#ifndef PHOTON_MESH_H
#define PHOTON_MESH_H

#include <stddef.h>
#include <stdint.h>

#include "ray.h"
#include "triangle.h"

/* 24 bytes. */
struct mesh_triangle {
    uint32_t corner[3]; /* indices into points[], counter-clockwise seen from the front    */
    int normals;        /* vertex i's normal is the owner's normals[normals + i]; -1: none */
    int material;       /* handed back in struct hit                                      */
    int id;             /* primitive id from geometry_add_triangle()                      */
};

struct mesh {
    double (*points)[3];              /* owned; n_points used of cap_points              */
    size_t n_points, cap_points;
    struct mesh_triangle *triangles;  /* owned; n_triangles used of cap_triangles        */
    size_t n_triangles, cap_triangles;
    uint32_t *table;                  /* owned: point index + 1 per slot, 0 for empty;
                                         table_size slots, a power of 2; NULL when none */
    size_t table_size;
};

void mesh_init(struct mesh *m);   /* empty */
void mesh_free(struct mesh *m);   /* releases the arrays; the struct is the caller's */

/* Appends the triangle over v[0..2]; returns its index in triangles[]. */
size_t mesh_add(struct mesh *m, const struct vec3 v[3], int normals, int material, int id);

/* The triangle's corners as points. */
void mesh_corners(const struct mesh *m, const struct mesh_triangle *tri, struct vec3 v[3]);
int mesh_is_degenerate(const struct mesh *m, const struct mesh_triangle *tri);
struct aabb mesh_bounds(const struct mesh *m, const struct mesh_triangle *tri);

/* triangle_intersect() and triangle_shade() on the triangle's corners; the test inline, as
 * every leaf test runs it. */
static inline int mesh_intersect(const struct mesh *m, const struct mesh_triangle *tri,
                                 const struct sheared_ray *ray, double tmax, struct hit *hit)
{
    const double *const corner[3] = {m->points[tri->corner[0]], m->points[tri->corner[1]],
                                     m->points[tri->corner[2]]};
    return corners_intersect(corner, ray, tmax, hit);
}
void mesh_shade(const struct mesh *m, const struct mesh_triangle *tri,
                const struct vec3 *normals, struct hit *hit);

/* After the triangles were put in their final order: renumbers the points in the order the
 * triangles first use them, fits both arrays to their counts and drops the table. */
void mesh_finish(struct mesh *m);

size_t mesh_bytes(const struct mesh *m);

#endif
