/*
 * geom/quad.c -- watertight ray/parallelogram intersection (see quad.h).
 *
 * Corners A = p0, B = p0 + e1, C = p0 + e1 + e2, D = p0 + e2, in order around the quad.
 * In the sheared frame (triangle.h) the hit point is the origin, and with e(P, Q) the edge
 * function of P -> Q, e(A, B) ~ t, e(C, D) ~ 1 - t, e(D, A) ~ s, e(B, C) ~ 1 - s with one
 * factor per pair (opposite edges of a parallelogram are parallel), so
 *   s = e(D, A) / (e(D, A) + e(B, C)),  t = e(A, B) / (e(A, B) + e(C, D)).
 */
#include "quad.h"

static void set_corner(struct quad *q, int i, struct vec3 p)
{
    q->corner[i][0] = p.x;
    q->corner[i][1] = p.y;
    q->corner[i][2] = p.z;
}

struct quad quad_make(struct vec3 p0, struct vec3 e1, struct vec3 e2, int material, int id)
{
    struct quad q;
    set_corner(&q, 0, p0);
    set_corner(&q, 1, vec3_add(p0, e1));
    set_corner(&q, 2, vec3_add(vec3_add(p0, e1), e2));
    set_corner(&q, 3, vec3_add(p0, e2));
    q.p0 = p0;
    q.e1 = e1;
    q.e2 = e2;
    q.ng = unit_normal(vec3_cross(e1, e2));
    q.material = material;
    q.id = id;
    return q;
}

int quad_is_degenerate(const struct quad *q)
{
    return vec3_length2(q->ng) == 0;
}

struct aabb quad_bounds(const struct quad *q)
{
    struct aabb box;
    box.lo = vec3(q->corner[0][0], q->corner[0][1], q->corner[0][2]);
    box.hi = box.lo;
    for (int i = 1; i < 4; i++) {
        struct vec3 c = vec3(q->corner[i][0], q->corner[i][1], q->corner[i][2]);
        box.lo = vec3_min(box.lo, c);
        box.hi = vec3_max(box.hi, c);
    }
    return box;
}

int quad_intersect(const struct quad *q, const struct sheared_ray *ray, double tmax,
                   struct hit *hit)
{
    const double *o = ray->origin;
    int kx = ray->kx, ky = ray->ky, kz = ray->kz;
    double x[4], y[4], z[4];
    for (int i = 0; i < 4; i++) {
        z[i] = q->corner[i][kz] - o[kz];
        x[i] = (q->corner[i][kx] - o[kx]) - ray->sx * z[i];
        y[i] = (q->corner[i][ky] - o[ky]) - ray->sy * z[i];
    }
    double e_ab = edge_fast(x[0], y[0], x[1], y[1]);
    double e_bc = edge_fast(x[1], y[1], x[2], y[2]);
    double e_cd = edge_fast(x[2], y[2], x[3], y[3]);
    double e_da = edge_fast(x[3], y[3], x[0], y[0]);
    if (((e_ab < 0) | (e_bc < 0) | (e_cd < 0) | (e_da < 0))
        & ((e_ab > 0) | (e_bc > 0) | (e_cd > 0) | (e_da > 0)))
        return 0;   /* the origin is outside an edge (one branch, as in triangle.h) */
    double sum_s = e_da + e_bc, sum_t = e_ab + e_cd;
    if (sum_s == 0 || sum_t == 0)
        return 0;   /* both terms of a sum are zero: the quad is seen edge-on */
    double s = e_da / sum_s, t = e_ab / sum_t;
    /* Depth along the ray: the bilinear blend of the corners' z, which on each edge
     * depends on that edge's corners only. */
    double depth = (1 - s) * (1 - t) * z[0] + s * (1 - t) * z[1] + s * t * z[2]
                   + (1 - s) * t * z[3];
    double t_ray = ray->sz * depth;
    if (!((t_ray > 0) & (t_ray < tmax)))
        return 0;
    hit->t = t_ray;
    hit->u = s;
    hit->v = t;
    return 1;
}

void quad_shade(const struct quad *q, struct hit *hit)
{
    hit->p = vec3_madd(vec3_madd(q->p0, q->e1, hit->u), q->e2, hit->v);
    hit->ng = q->ng;
    hit->ns = q->ng;
    hit->material = q->material;
}
