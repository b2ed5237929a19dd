/*
 * photon/hit_point_grid.c -- the hash grid over hit points (see hit_point_grid.h).
 */
#include "hit_point_grid.h"

#include <math.h>
#include <stdint.h>

#include "../base/alloc.h"

/* Cell coordinates of p: floor((p - origin) / cell), clamped far inside int64's range so
 * that a point far off the grid (a photon on a distant wall) still has a cell. */
static int64_t cell_of(double x, double origin, double cell)
{
    double c = floor((x - origin) / cell);
    return (int64_t)fmax(-1e15, fmin(1e15, c));
}

/* The bucket of cell (i, j, k): Teschner et al.'s hash of three large primes. */
static size_t bucket_of(const struct hit_point_grid *grid, int64_t i, int64_t j, int64_t k)
{
    uint64_t h = ((uint64_t)i * 73856093u) ^ ((uint64_t)j * 19349663u) ^
                 ((uint64_t)k * 83492791u);
    return (size_t)(h & (grid->n_buckets - 1));
}

/* The most cells a disc box touches: it is 2 reach <= 2 cells wide, so it spans 3 cells a
 * side, and 4 when rounding x - r or x + r moves a side exactly on a cell's boundary across
 * it (the hit point with the largest reach at the grid's origin: a photon of its disc was
 * lost when the box was cut to 27 cells, 2009 on point-in-sphere's centre pixel). */
#define MAX_CELLS 64

/* The distinct buckets of the cells that hit point hp's disc box touches, into b;
 * returns how many. */
static int buckets_of_point(const struct hit_point_grid *grid, const struct hit_point *hp,
                            size_t b[MAX_CELLS])
{
    double r = hit_point_reach(hp);
    int64_t lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        double x = vec3_get(hp->x, a), o = vec3_get(grid->origin, a);
        lo[a] = cell_of(x - r, o, grid->cell);
        hi[a] = cell_of(x + r, o, grid->cell);
    }
    int n = 0;
    for (int64_t i = lo[0]; i <= hi[0]; i++)
        for (int64_t j = lo[1]; j <= hi[1]; j++)
            for (int64_t k = lo[2]; k <= hi[2]; k++) {
                size_t bucket = bucket_of(grid, i, j, k);
                int seen = 0;
                for (int m = 0; m < n; m++)
                    seen = seen || b[m] == bucket;
                if (!seen && n < MAX_CELLS)
                    b[n++] = bucket;
            }
    return n;
}

void hit_point_grid_build(struct hit_point_grid *grid, const struct hit_point *points,
                          size_t n)
{
    grid->points = points;
    grid->n = n;
    grid->origin = vec3(0, 0, 0);
    grid->cell = 0.0;
    struct vec3 lo = vec3(INFINITY, INFINITY, INFINITY);
    for (size_t i = 0; i < n; i++) {
        grid->cell = fmax(grid->cell, hit_point_reach(&points[i]));
        lo = vec3_min(lo, points[i].x);
    }
    if (n > 0)
        grid->origin = lo;
    if (!(grid->cell > 0))
        grid->cell = 1.0; /* no disc reaches anything: any width serves */
    grid->n_buckets = 1;
    while (grid->n_buckets < 2 * n)
        grid->n_buckets *= 2;
    grid->start = xcalloc(grid->n_buckets + 1, sizeof *grid->start, "hit point grid");
    size_t b[MAX_CELLS];
    for (size_t i = 0; i < n; i++) { /* count, into start[bucket + 1] */
        int m = buckets_of_point(grid, &points[i], b);
        for (int k = 0; k < m; k++)
            grid->start[b[k] + 1]++;
    }
    for (size_t k = 0; k < grid->n_buckets; k++)
        grid->start[k + 1] += grid->start[k];
    size_t *fill = xmalloc(grid->n_buckets, sizeof *fill, "hit point grid");
    for (size_t k = 0; k < grid->n_buckets; k++)
        fill[k] = grid->start[k];
    grid->entries = xmalloc(grid->start[grid->n_buckets] + 1, sizeof *grid->entries,
                            "hit point grid");
    for (size_t i = 0; i < n; i++) {
        int m = buckets_of_point(grid, &points[i], b);
        for (int k = 0; k < m; k++)
            grid->entries[fill[b[k]]++] = i;
    }
    xfree(fill);
}

void hit_point_grid_visit(const struct hit_point_grid *grid, struct vec3 p,
                          void (*visit)(void *context, size_t i), void *context)
{
    if (grid->n == 0)
        return;
    size_t b = bucket_of(grid, cell_of(p.x, grid->origin.x, grid->cell),
                         cell_of(p.y, grid->origin.y, grid->cell),
                         cell_of(p.z, grid->origin.z, grid->cell));
    for (size_t e = grid->start[b]; e < grid->start[b + 1]; e++) {
        size_t i = grid->entries[e];
        double r = hit_point_reach(&grid->points[i]);
        if (vec3_length2(vec3_sub(p, grid->points[i].x)) <= r * r)
            visit(context, i);
    }
}

void hit_point_grid_free(struct hit_point_grid *grid)
{
    xfree(grid->start);
    xfree(grid->entries);
    grid->start = NULL;
    grid->entries = NULL;
}
