/*
 * geom/triangle.h -- the watertight ray/triangle test (Woop, Benthin, Wald, "Watertight
 * Ray/Triangle Intersection", JCGT 2(1), 2013) and the triangle's shading record.
 *
 * A ray is first sheared so that it becomes the +z axis through the origin (struct
 * sheared_ray); a triangle is then hit when the origin lies inside its projection onto
 * the xy plane, decided by the signs of three edge functions. Each vertex is transformed
 * by the same operations whichever triangle it belongs to, and edge_function() returns the
 * exact sign, so two triangles sharing an edge see exactly opposite values on it: a ray
 * through a shared edge or vertex of a closed mesh hits at least one of the triangles
 * around it. The guarantee needs shared vertices to be bitwise equal.
 *
 * quad.c uses the same shear and edge functions for parallelograms.
 */
#ifndef PHOTON_TRIANGLE_H
#define PHOTON_TRIANGLE_H

#include "ray.h"

struct triangle {
    double v[3][3];  /* v[i][axis]: vertex i, counter-clockwise seen from the front; arrays
                        so that the shear can pick axes by index */
    int normals;     /* index of vertex i's normal in the owner's normal array is
                        normals + i; -1 when the triangle has none */
    int material;    /* handed back in struct hit */
    int id;          /* primitive id from geometry_add_triangle() */
};

/* A ray in the frame of Woop et al., Sec. 3: axis kz is the largest component of |d|, kx and
 * ky the other two, swapped when d[kz] < 0 to keep the winding. A point P maps to
 *   x = (P - o)[kx] - sx (P - o)[kz],  y = (P - o)[ky] - sy (P - o)[kz],  z = sz (P - o)[kz]
 * and the ray to (0, 0, t). */
struct sheared_ray {
    double origin[3];
    int kx, ky, kz;
    double sx, sy, sz; /* d[kx] sz, d[ky] sz, sz = 1 / d[kz] */
};

/* ray.dir must not be the zero vector. */
struct sheared_ray shear_ray(struct ray ray);

/* The edge function of the directed edge P -> Q at the origin, qx py - qy px, with its exact
 * sign: positive when the origin is on the left of P -> Q, zero only when it is exactly on
 * the edge's line (for |coordinates| between about 1e-140 and 1e140, where the products
 * neither underflow nor overflow). e(Q, P) = -e(P, Q) exactly. */
double edge_function(double px, double py, double qx, double qy);

/* The triangle's vertices from vectors; normals as in struct triangle. */
struct triangle triangle_make(const struct vec3 v[3], int normals, int material, int id);
/* Zero area (coincident or collinear vertices): never hit, excluded from the BVH. */
int triangle_is_degenerate(const struct triangle *tri);
struct aabb triangle_bounds(const struct triangle *tri);

/* Hit with t in (0, tmax), from either side: 1 with hit->t and the barycentrics of v[1] and
 * v[2] in hit->u, hit->v set (nothing else), or 0. */
int triangle_intersect(const struct triangle *tri, const struct sheared_ray *ray, double tmax,
                       struct hit *hit);

/* Completes a hit from its t, u, v: p, ng, ns and material. normals: the triangle's three
 * vertex normals, or NULL when it has none (then ns = ng). prim is the caller's. */
void triangle_shade(const struct triangle *tri, const struct vec3 *normals, struct hit *hit);

/* The same four for a triangle whose vertices are kept elsewhere (mesh.h): corner[i] points
 * at vertex i's three coordinates. The functions above are these on tri->v. */
int corners_are_degenerate(const double *const corner[3]);
struct aabb corners_bounds(const double *const corner[3]);
void corners_shade(const double *const corner[3], int material, const struct vec3 *normals,
                   struct hit *hit);

/* edge_function() where the compiler can inline it: the rounded difference when it is not
 * zero (its sign is then exact, triangle.c), else the exact tie from edge_function(). */
static inline double edge_fast(double px, double py, double qx, double qy)
{
    double e = qx * py - qy * px;
    return e != 0 ? e : edge_function(px, py, qx, qy);
}

/* triangle_intersect() on corners (Woop et al., Fig. 1, without back-face culling), inline
 * because every leaf test runs it. Vertex i becomes (x[i], y[i]) in the sheared frame; U, V,
 * W are the edge functions of B -> C, C -> A, A -> B. */
static inline int corners_intersect(const double *const corner[3], const struct sheared_ray *ray,
                                    double tmax, struct hit *hit)
{
    const double *o = ray->origin;
    int kx = ray->kx, ky = ray->ky, kz = ray->kz;
    double x[3], y[3], z[3];
    for (int i = 0; i < 3; i++) {
        z[i] = corner[i][kz] - o[kz];
        x[i] = (corner[i][kx] - o[kx]) - ray->sx * z[i];
        y[i] = (corner[i][ky] - o[ky]) - ray->sy * z[i];
    }
    double u = edge_fast(x[1], y[1], x[2], y[2]);
    double v = edge_fast(x[2], y[2], x[0], y[0]);
    double w = edge_fast(x[0], y[0], x[1], y[1]);
    /* | and & in place of || and &&: one branch, where the result of each comparison is as
     * unpredictable as which side of an edge a ray passes. */
    if (((u < 0) | (v < 0) | (w < 0)) & ((u > 0) | (v > 0) | (w > 0)))
        return 0;   /* the origin is outside an edge */
    double det = u + v + w;
    if (det == 0)
        return 0;   /* all three zero: the triangle is seen edge-on */
    double inv_det = 1.0 / det;
    double t = ray->sz * (u * z[0] + v * z[1] + w * z[2]) * inv_det;
    if (!((t > 0) & (t < tmax)))
        return 0;
    hit->t = t;
    hit->u = v * inv_det;
    hit->v = w * inv_det;
    return 1;
}

/* The unit normal along n, computed without overflow or underflow; zero when n is zero. */
struct vec3 unit_normal(struct vec3 n);

#endif
