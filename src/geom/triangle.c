/*
 * geom/triangle.c -- watertight ray/triangle intersection (Woop, Benthin, Wald 2013).
 *
 * Why the sign of an edge function is exact: qx py - qy px is computed as fl(fl(qx py) -
 * fl(qy px)). Rounding is monotone, so when qx py > qy px exactly, fl(qx py) >= fl(qy px)
 * and the computed difference is >= 0: a nonzero result always has the true sign. It can
 * only be wrong by being zero, which happens exactly when the two rounded products are
 * equal; then the true value is the difference of their rounding errors, which Dekker's
 * product (Dekker 1971, "A floating-point technique for extending the available
 * precision") gives exactly. This is the paper's "recompute in double precision when an
 * edge function is zero" (Sec. 4), one level up: our edge functions are already double.
 * It requires every operation rounded once (no FMA contraction: -ffp-contract=off).
 */
#include "triangle.h"

#include <stddef.h>

/* 2^27 + 1: splits a double into two halves of 26 bits whose products are exact. */
#define DEKKER_SPLIT 134217729.0

/* The rounding error of fl(a b): a b = fl(a b) + product_error(a, b, fl(a b)) exactly. */
static double product_error(double a, double b, double p)
{
    double ca = DEKKER_SPLIT * a, cb = DEKKER_SPLIT * b;
    double a_hi = ca - (ca - a), b_hi = cb - (cb - b);
    double a_lo = a - a_hi, b_lo = b - b_hi;
    return ((a_hi * b_hi - p) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo;
}

double edge_function(double px, double py, double qx, double qy)
{
    double qx_py = qx * py, qy_px = qy * px;
    double e = qx_py - qy_px;
    if (e != 0)
        return e;
    /* The products are equal, so the exact value is the difference of their errors. */
    return product_error(qx, py, qx_py) - product_error(qy, px, qy_px);
}

struct sheared_ray shear_ray(struct ray ray)
{
    struct sheared_ray s;
    double d[3] = {ray.dir.x, ray.dir.y, ray.dir.z};
    s.origin[0] = ray.origin.x;
    s.origin[1] = ray.origin.y;
    s.origin[2] = ray.origin.z;
    /* Selections, not branches: which axis is largest, and the sign along it, are as
     * unpredictable as a scattered ray's direction, and a mispredicted branch costs more
     * than the rest of this function. */
    static const int next_axis[3] = {1, 2, 0};
    double ax = fabs(d[0]), ay = fabs(d[1]), az = fabs(d[2]);
    int kz = ay > ax ? 1 : 0;
    double amax = ay > ax ? ay : ax;
    kz = az > amax ? 2 : kz;
    int kx = next_axis[kz], ky = next_axis[kx];
    int mirrored = d[kz] < 0;   /* a mirrored frame would flip every edge function's sign */
    s.kz = kz;
    s.kx = mirrored ? ky : kx;
    s.ky = mirrored ? kx : ky;
    s.sz = 1.0 / d[s.kz];   /* d[kz] != 0: the largest |component| of a non-zero direction */
    s.sx = d[s.kx] * s.sz;
    s.sy = d[s.ky] * s.sz;
    return s;
}

struct vec3 unit_normal(struct vec3 n)
{
    double ax = fabs(n.x), ay = fabs(n.y), az = fabs(n.z);
    double m = ax > ay ? (ax > az ? ax : az) : (ay > az ? ay : az);   /* not NaN: finite input */
    if (!(m > 0))
        return vec3_zero();
    return vec3_normalize(vec3_scale(n, 1.0 / m));   /* components in [-1, 1]: no underflow */
}

struct triangle triangle_make(const struct vec3 v[3], int normals, int material, int id)
{
    struct triangle tri;
    for (int i = 0; i < 3; i++) {
        tri.v[i][0] = v[i].x;
        tri.v[i][1] = v[i].y;
        tri.v[i][2] = v[i].z;
    }
    tri.normals = normals;
    tri.material = material;
    tri.id = id;
    return tri;
}

static struct vec3 vertex(const double *const corner[3], int i)
{
    return vec3(corner[i][0], corner[i][1], corner[i][2]);
}

/* ng before normalisation: (v1 - v0) x (v2 - v0), on the counter-clockwise side. */
static struct vec3 area_normal(const double *const corner[3])
{
    struct vec3 v0 = vertex(corner, 0);
    return vec3_cross(vec3_sub(vertex(corner, 1), v0), vec3_sub(vertex(corner, 2), v0));
}

int corners_are_degenerate(const double *const corner[3])
{
    return vec3_length2(unit_normal(area_normal(corner))) == 0;
}

struct aabb corners_bounds(const double *const corner[3])
{
    struct aabb box;
    box.lo = vertex(corner, 0);
    box.hi = box.lo;
    for (int i = 1; i < 3; i++) {
        box.lo = vec3_min(box.lo, vertex(corner, i));
        box.hi = vec3_max(box.hi, vertex(corner, i));
    }
    return box;
}

/* ns: the barycentric blend of the vertex normals, normalised, and turned to ng's side
 * when it points the other way (the renderer then sees ng and ns on one side). */
void corners_shade(const double *const corner[3], int material, const struct vec3 *normals,
                   struct hit *hit)
{
    double b0 = 1.0 - hit->u - hit->v, b1 = hit->u, b2 = hit->v;
    struct vec3 p = vec3_scale(vertex(corner, 0), b0);
    p = vec3_madd(p, vertex(corner, 1), b1);
    hit->p = vec3_madd(p, vertex(corner, 2), b2);
    hit->ng = unit_normal(area_normal(corner));
    hit->ns = hit->ng;
    hit->material = material;
    if (normals == NULL)
        return;
    struct vec3 n = vec3_scale(normals[0], b0);
    n = vec3_madd(vec3_madd(n, normals[1], b1), normals[2], b2);
    n = unit_normal(n);
    if (vec3_length2(n) == 0)
        return;   /* the vertex normals cancel here: fall back to ng */
    hit->ns = vec3_dot(n, hit->ng) < 0 ? vec3_neg(n) : n;
}

/* ---- the triangle that holds its own vertices ---- */

int triangle_is_degenerate(const struct triangle *tri)
{
    const double *const corner[3] = {tri->v[0], tri->v[1], tri->v[2]};
    return corners_are_degenerate(corner);
}

struct aabb triangle_bounds(const struct triangle *tri)
{
    const double *const corner[3] = {tri->v[0], tri->v[1], tri->v[2]};
    return corners_bounds(corner);
}

int triangle_intersect(const struct triangle *tri, const struct sheared_ray *ray, double tmax,
                       struct hit *hit)
{
    const double *const corner[3] = {tri->v[0], tri->v[1], tri->v[2]};
    return corners_intersect(corner, ray, tmax, hit);
}

void triangle_shade(const struct triangle *tri, const struct vec3 *normals, struct hit *hit)
{
    const double *const corner[3] = {tri->v[0], tri->v[1], tri->v[2]};
    corners_shade(corner, tri->material, normals, hit);
}
