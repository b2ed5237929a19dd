/*
 * geom/polygon.c -- ear clipping (Meisters 1975): repeatedly cut off a vertex whose corner
 * is convex and whose triangle holds no other vertex, until three remain. Done in 2-D, on
 * the coordinate plane most nearly parallel to the polygon (across the largest axis of its
 * Newell normal, which averages over all vertices, so slightly non-planar input is fine).
 */
#include "polygon.h"


#include "../base/alloc.h"

/* The ring of vertices not yet clipped, projected onto the polygon's plane. */
struct ring {
    double *x, *y;   /* 2-D coordinates, n each                                 */
    int *prev, *next; /* the doubly linked ring                                 */
    char *reflex;    /* whether vertex i's corner is reflex or flat now (0 once
                        clipped)                                                 */
    char *ear;       /* whether vertex i is an ear tip now (is_ear)             */
    int *candidates; /* the vertices reflex at the start: the only ones that can
                        ever block an ear (clip_ears), n_candidates of them       */
    int n_candidates;
    double sign;     /* +1 or -1: makes the polygon's own winding count positive */
};

/* Twice the signed area of the 2-D triangle (a, b, c), in the polygon's winding. */
static double orientation(const struct ring *r, int a, int b, int c)
{
    double area = (r->x[b] - r->x[a]) * (r->y[c] - r->y[a]) -
                  (r->y[b] - r->y[a]) * (r->x[c] - r->x[a]);
    return r->sign * area;
}

static int same_point(const struct ring *r, int a, int b)
{
    return r->x[a] == r->x[b] && r->y[a] == r->y[b];
}

/* Whether vertex j is inside or on triangle (a, b, c) of positive orientation. */
static int inside_or_on(const struct ring *r, int a, int b, int c, int j)
{
    return orientation(r, a, b, j) >= 0 && orientation(r, b, c, j) >= 0 &&
           orientation(r, c, a, j) >= 0;
}

/* Whether (prev, i, next) is an ear: a convex corner whose triangle holds no other vertex.
 * Only reflex (or flat) vertices need testing: if a convex corner's triangle holds any
 * vertex, it holds a reflex one. A vertex at the same place as a corner (a polygon that
 * touches itself there) does not block the ear. i's reflex flag must be current. */
static int is_ear(const struct ring *r, int i)
{
    int p = r->prev[i], q = r->next[i];
    if (r->reflex[i])
        return 0;
    for (int k = 0; k < r->n_candidates; k++) {
        int j = r->candidates[k];
        if (!r->reflex[j] || j == p || j == q)
            continue;
        if (same_point(r, j, p) || same_point(r, j, i) || same_point(r, j, q))
            continue;
        if (inside_or_on(r, p, i, q, j))
            return 0;
    }
    return 1;
}

/* Newell's normal of the polygon, from coordinates relative to v[0] (fewer digits lost):
 * its length is twice the area, its direction the side from which v runs anticlockwise. */
static struct vec3 newell_normal(const struct vec3 *v, int n)
{
    struct vec3 sum = vec3_zero();
    for (int i = 0; i < n; i++) {
        struct vec3 a = vec3_sub(v[i], v[0]), b = vec3_sub(v[(i + 1) % n], v[0]);
        sum.x += (a.y - b.y) * (a.z + b.z);
        sum.y += (a.z - b.z) * (a.x + b.x);
        sum.z += (a.x - b.x) * (a.y + b.y);
    }
    return sum;
}

/* Fills the ring with v projected along the normal's largest axis, the remaining two axes
 * taken in cyclic order so that the projected area has the sign of that component. */
static void ring_project(const struct vec3 *v, int n, struct vec3 normal, struct ring *r)
{
    double c[3] = {fabs(normal.x), fabs(normal.y), fabs(normal.z)};
    int axis = c[0] >= c[1] && c[0] >= c[2] ? 0 : c[1] >= c[2] ? 1 : 2;
    r->sign = vec3_get(normal, axis) > 0 ? 1.0 : -1.0;
    for (int i = 0; i < n; i++) {
        struct vec3 p = vec3_sub(v[i], v[0]);
        r->x[i] = vec3_get(p, (axis + 1) % 3);
        r->y[i] = vec3_get(p, (axis + 2) % 3);
        r->prev[i] = (i + n - 1) % n;
        r->next[i] = (i + 1) % n;
    }
}

static int *put_triangle(int *out, int a, int b, int c)
{
    out[0] = a;
    out[1] = b;
    out[2] = c;
    return out + 3;
}

/* Clips ears until a triangle is left, walking round the ring from the last clip. Clipping
 * ear i changes only its neighbours' corners, so only their flags are computed again: no
 * other vertex's triangle changes, and i, being convex, blocked none (only reflex vertices
 * do). A neighbour's angle shrinks by the ear's, so a corner may turn from reflex to convex
 * but never back: the blockers are always among the vertices reflex at the start. So the
 * whole costs O(n r) for r reflex vertices, O(n) for a convex polygon. A full turn without
 * an ear happens only to a polygon that crosses itself (or is flat to rounding); the vertex
 * reached is then clipped anyway, so there are always n - 2 triangles and the loop ends. */
static void set_reflex(struct ring *r, int i)
{
    r->reflex[i] = (char)!(orientation(r, r->prev[i], i, r->next[i]) > 0);
}

static void clip_ears(struct ring *r, int n, int *out)
{
    r->n_candidates = 0;
    for (int i = 0; i < n; i++) {
        set_reflex(r, i);
        if (r->reflex[i])
            r->candidates[r->n_candidates++] = i;
    }
    for (int i = 0; i < n; i++)
        r->ear[i] = (char)is_ear(r, i);
    int i = 0, remaining = n, misses = 0;
    while (remaining > 3) {
        if (misses < remaining && !r->ear[i]) {
            i = r->next[i];
            misses++;
            continue;
        }
        int p = r->prev[i], q = r->next[i];
        out = put_triangle(out, p, i, q);
        r->next[p] = q;
        r->prev[q] = p;
        r->reflex[i] = 0; /* clipped: blocks nothing any more */
        remaining--;
        misses = 0;
        set_reflex(r, p);
        set_reflex(r, q);
        r->ear[p] = (char)is_ear(r, p);
        r->ear[q] = (char)is_ear(r, q);
        i = q;
    }
    put_triangle(out, r->prev[i], i, r->next[i]);
}

void polygon_triangulate(const struct vec3 *v, int n, int *triangles)
{
    struct vec3 normal = n > 3 ? newell_normal(v, n) : vec3_zero();
    if (vec3_length2(normal) == 0) { /* a triangle; or no plane: a fan of flat triangles */
        for (int i = 1; i + 1 < n; i++)
            triangles = put_triangle(triangles, 0, i, i + 1);
        return;
    }
    struct ring r;
    r.x = xmalloc((size_t)n, sizeof *r.x, "polygon");
    r.y = xmalloc((size_t)n, sizeof *r.y, "polygon");
    r.prev = xmalloc((size_t)n, sizeof *r.prev, "polygon");
    r.next = xmalloc((size_t)n, sizeof *r.next, "polygon");
    r.reflex = xmalloc((size_t)n, sizeof *r.reflex, "polygon");
    r.ear = xmalloc((size_t)n, sizeof *r.ear, "polygon");
    r.candidates = xmalloc((size_t)n, sizeof *r.candidates, "polygon");
    ring_project(v, n, normal, &r);
    clip_ears(&r, n, triangles);
    xfree(r.candidates);
    xfree(r.ear);
    xfree(r.reflex);
    xfree(r.next);
    xfree(r.prev);
    xfree(r.y);
    xfree(r.x);
}
