/*
 * photon/hit_point_grid.h -- a hash grid over hit points (Hachisuka and Jensen 2009 and
 * pbrt's SPPM use one): the other way than the kd-tree of hit_points.h to find, for a
 * photon, every hit point whose disc holds it, made for hit points that change every pass.
 * Cubic cells as wide as the largest reach; each hit point is listed in every cell its
 * disc's box touches (27 at most, 64 with rounding, in practice 8 or fewer), cells are
 * hashed into buckets, and a photon reads the one bucket of its cell. Built in two passes
 * over the hit points (count, then fill), without sorting.
 */
#ifndef PHOTON_HIT_POINT_GRID_H
#define PHOTON_HIT_POINT_GRID_H

#include <stddef.h>

#include "hit_points.h"

struct hit_point_grid {
    const struct hit_point *points; /* borrowed; n of them                            */
    size_t n;
    struct vec3 origin;             /* the corner of cell (0, 0, 0)                     */
    double cell;                    /* the cells' width: the largest reach (> 0)        */
    size_t n_buckets;               /* a power of two, at least 2 n                     */
    size_t *start;                  /* owned: bucket b's hit points are
                                       entries[start[b] .. start[b + 1] - 1]           */
    size_t *entries;                /* owned: hit point indices, bucket by bucket, each
                                       in the order of the points                      */
};

/* Builds the grid over points[0 .. n-1] with their current reach (hit_point_reach()). */
void hit_point_grid_build(struct hit_point_grid *grid, const struct hit_point *points,
                          size_t n);

/* Calls visit(context, i) once for every hit point whose reach holds p, in index order
 * within p's bucket. */
void hit_point_grid_visit(const struct hit_point_grid *grid, struct vec3 p,
                          void (*visit)(void *context, size_t i), void *context);

/* Bytes the grid owns per hit point, about: two buckets' offsets and its entries in a
 * few cells. */
#define HIT_POINT_GRID_BYTES_PER_POINT (6 * sizeof(size_t))

void hit_point_grid_free(struct hit_point_grid *grid);

#endif
