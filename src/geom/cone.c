/*
 * geom/cone.c -- exact ray / open cone-frustum intersection (see cone.h).
 *
 * Method. With o = O - B, the ray O + t d has the axial coordinate s(t) = s_o + t d_w
 * (s_o = o.w, d_w = d.w) and the radial vector q(t) = q_o + t q_d (q_o = o - s_o w,
 * q_d = d - d_w w). It meets the infinite double cone |q| = |r(s)| where
 *   f(t) = |q(t)|^2 - r(s(t))^2 = A t^2 + 2 B t + C = 0,
 *   A = |q_d|^2 - (k d_w)^2,  B = q_o.q_d - r_o k d_w,  C = |q_o|^2 - r_o^2,
 * r_o = r_base + k s_o being the signed radius at the origin's axial coordinate. A root is a
 * hit when 0 < t < tmax and 0 <= s(t) <= h. Both radii are >= 0, so r(s) >= 0 on [0, h]: a
 * root there lies on the frustum's own nappe, never on the mirrored one, whose points all
 * have r(s) < 0, i.e. s outside [0, h].
 *
 * Cancellation. C is formed as (|q_o| - r_o)(|q_o| + r_o). The discriminant B^2 - A C loses
 * its digits when the ray grazes the surface (B^2 ~ A C > 0); there it is taken instead as
 * -A f(t*), with f evaluated directly at the parabola's vertex t* = -B / A as
 * (|q(t*)| - r)(|q(t*)| + r): an error in t* reaches f(t*) only to second order, since
 * f'(t*) = 0. The roots are q / A and C / q with q = -(B + sign(B) sqrt(disc)), a sum of
 * terms of one sign. A = 0 -- the ray parallel to a generator, or on a cylinder to the
 * axis -- leaves the linear equation 2 B t + C = 0; if B = 0 as well the line misses the
 * surface or lies in it, and either counts as a miss.
 */
#include "cone.h"


#include "../base/alloc.h"

struct cone {
    struct vec3 base;     /* B                                                         */
    struct vec3 axis;     /* w = (A - B) / h, unit                                     */
    struct vec3 frame_t;  /* with frame_b: a unit frame about w, where u's angle is 0  */
    struct vec3 frame_b;
    double height;        /* h = |A - B| > 0                                           */
    double r_base;        /* |r_base|, >= 0                                            */
    double r_apex;        /* |r_apex|, >= 0; not both 0                                */
    double slope;         /* k = (r_apex - r_base) / h, finite                         */
    double inv_norm;      /* 1 / sqrt(1 + k^2): normalises e - k w, whose length it is */
    int inside;           /* whether the front side is the inside (negative radii)    */
    int material;
};

struct cone *cone_create(struct vec3 base, double r_base, struct vec3 apex, double r_apex,
                         int material, struct error *err)
{
    struct vec3 axis = vec3_sub(apex, base);
    double height = vec3_length(axis);
    if (!vec3_is_finite(base) || !vec3_is_finite(apex) || !isfinite(r_base) ||
        !isfinite(r_apex) || !isfinite(height)) {
        error_set(err, "", 0, "points and radii must be finite");
        return NULL;
    }
    if (!(height > 0)) {
        error_set(err, "", 0, "the base and apex points coincide");
        return NULL;
    }
    if ((r_base > 0 && r_apex < 0) || (r_base < 0 && r_apex > 0) ||
        (r_base == 0 && r_apex == 0)) {
        error_set(err, "", 0, "the radii must not be both zero or of opposite signs");
        return NULL;
    }
    double slope = (fabs(r_apex) - fabs(r_base)) / height; /* height > 0 tested above */
    if (!isfinite(slope)) {
        error_set(err, "", 0, "too short for its radii (the slope overflows)");
        return NULL;
    }
    struct cone *cone = xmalloc(1, sizeof *cone, "cone");
    cone->base = base;
    cone->axis = vec3_scale(axis, 1.0 / height);
    vec3_frame(cone->axis, &cone->frame_t, &cone->frame_b);
    cone->height = height;
    cone->r_base = fabs(r_base);
    cone->r_apex = fabs(r_apex);
    cone->slope = slope;
    cone->inv_norm = 1.0 / sqrt(1.0 + slope * slope);
    cone->inside = r_base < 0 || r_apex < 0;
    cone->material = material;
    return cone;
}

void cone_free(struct cone *cone)
{
    xfree(cone);
}

/* The ray in the cone's coordinates (see the header comment). */
struct cone_ray {
    double s_o, d_w; /* s(t) = s_o + t d_w          */
    struct vec3 q_o, q_d; /* q(t) = q_o + t q_d     */
    double r_o;      /* r_base + k s_o               */
};

static struct cone_ray cone_ray_make(const struct cone *c, struct ray ray)
{
    struct cone_ray cr;
    struct vec3 o = vec3_sub(ray.origin, c->base);
    cr.s_o = vec3_dot(o, c->axis);
    cr.d_w = vec3_dot(ray.dir, c->axis);
    cr.q_o = vec3_madd(o, c->axis, -cr.s_o);
    cr.q_d = vec3_madd(ray.dir, c->axis, -cr.d_w);
    cr.r_o = c->r_base + c->slope * cr.s_o;
    return cr;
}

/* x^2 - y^2 for x >= 0, as (x - y)(x + y): exact to a few ulps of its own size. */
static double difference_of_squares(double x, double y)
{
    return (x - y) * (x + y);
}

/* B^2 - A C, from the form that keeps its digits (header comment); may be negative. */
static double discriminant(const struct cone *c, const struct cone_ray *cr, double a, double b,
                           double cc)
{
    if (a * cc <= 0 || b * b > 2.0 * a * cc)
        return b * b - a * cc; /* the terms add, or b^2 dominates: at most a bit is lost */
    double t_vertex = -b / a;  /* a * cc > 0, so a != 0 */
    struct vec3 q = vec3_madd(cr->q_o, cr->q_d, t_vertex);
    double r = cr->r_o + c->slope * cr->d_w * t_vertex;
    return -a * difference_of_squares(vec3_length(q), r);
}

/* The real roots of f(t) = 0 in ascending order; returns how many (0, 1 or 2). */
static int cone_roots(const struct cone *c, const struct cone_ray *cr, double t[2])
{
    double k_d = c->slope * cr->d_w;
    double a = vec3_length2(cr->q_d) - k_d * k_d;
    double b = vec3_dot(cr->q_o, cr->q_d) - cr->r_o * k_d;
    double cc = difference_of_squares(vec3_length(cr->q_o), cr->r_o);
    if (a == 0) {
        if (b == 0)
            return 0;      /* parallel to a generator and no crossing: a miss */
        t[0] = -cc / (2.0 * b); /* b != 0 tested above */
        return 1;
    }
    double disc = discriminant(c, cr, a, b, cc);
    if (!(disc >= 0))
        return 0;          /* no real root, or a NaN from overflowing input */
    double q = -(b + copysign(sqrt(disc), b));
    if (q == 0)
        return 0;          /* b = 0 and disc = 0: a double root at t = 0 only */
    double t0 = q / a, t1 = cc / q; /* a != 0 and q != 0 tested above */
    t[0] = fmin(t0, t1);
    t[1] = fmax(t0, t1);
    return 2;
}

/* The nearest hit with t in (0, tmax): 1 and *t_hit, or 0. */
static int cone_hit(const struct cone *c, struct ray ray, double tmax, double *t_hit)
{
    struct cone_ray cr = cone_ray_make(c, ray);
    double t[2];
    int n = cone_roots(c, &cr, t);
    for (int i = 0; i < n; i++) {
        if (!(t[i] > 0 && t[i] < tmax))
            continue;
        double s = cr.s_o + t[i] * cr.d_w;
        if (s >= 0 && s <= c->height) {
            *t_hit = t[i];
            return 1;
        }
    }
    return 0;
}

/* Completes hit from hit->t: the point is put back onto the surface along its radial
 * direction, which removes the error t carries, as sphere_shade() does. */
static void cone_shade(const struct cone *c, struct ray ray, struct hit *hit)
{
    struct vec3 p = ray_at(ray, hit->t);
    double s = fmin(fmax(vec3_dot(vec3_sub(p, c->base), c->axis), 0.0), c->height);
    struct vec3 on_axis = vec3_madd(c->base, c->axis, s);
    struct vec3 e = vec3_normalize(vec3_sub(p, on_axis));
    if (vec3_length2(e) == 0)
        e = c->frame_t; /* p on the axis: only at a true cone's tip, where any e will do */
    hit->p = vec3_madd(on_axis, e, c->r_base + c->slope * s);
    /* The gradient of |q| - r(s) is e - k w, of length sqrt(1 + k^2). */
    struct vec3 n = vec3_scale(vec3_madd(e, c->axis, -c->slope), c->inv_norm);
    hit->ng = c->inside ? vec3_neg(n) : n;
    hit->ns = hit->ng;
    double angle = atan2(vec3_dot(e, c->frame_b), vec3_dot(e, c->frame_t));
    hit->u = angle < 0 ? angle / (2.0 * PI) + 1.0 : angle / (2.0 * PI);
    hit->u = hit->u < 1.0 ? hit->u : 0.0; /* a tiny negative angle rounds up to 1 */
    hit->v = s / c->height; /* height > 0 (cone_create) */
    hit->material = c->material;
}

static int cone_intersect(const void *shape, struct ray ray, double tmax, struct hit *hit)
{
    double t;
    if (!cone_hit(shape, ray, tmax, &t))
        return 0;
    hit->t = t;
    cone_shade(shape, ray, hit);
    return 1;
}

static int cone_occluded(const void *shape, struct ray ray, double tmax)
{
    double t;
    return cone_hit(shape, ray, tmax, &t);
}

/* The box of the two rim circles: a circle of radius r about centre m, normal w, reaches
 * r sqrt(1 - w_i^2) along axis i. The pad of 1e-12 of the coordinates' size covers the
 * rounding of a hit point (a few ulps, 1e-15), which must never fall outside the box. */
static struct aabb cone_bounds(const void *shape)
{
    const struct cone *c = shape;
    struct vec3 w = c->axis;
    struct vec3 reach = vec3(sqrt(fmax(0.0, 1.0 - w.x * w.x)), sqrt(fmax(0.0, 1.0 - w.y * w.y)),
                             sqrt(fmax(0.0, 1.0 - w.z * w.z)));
    struct vec3 apex = vec3_madd(c->base, w, c->height);
    struct vec3 base_reach = vec3_scale(reach, c->r_base);
    struct vec3 apex_reach = vec3_scale(reach, c->r_apex);
    struct aabb box;
    box.lo = vec3_min(vec3_sub(c->base, base_reach), vec3_sub(apex, apex_reach));
    box.hi = vec3_max(vec3_add(c->base, base_reach), vec3_add(apex, apex_reach));
    double size = fmax(vec3_max_abs(box.lo), vec3_max_abs(box.hi));
    struct vec3 pad = vec3(1e-12 * size, 1e-12 * size, 1e-12 * size);
    box.lo = vec3_sub(box.lo, pad);
    box.hi = vec3_add(box.hi, pad);
    return box;
}

static size_t cone_bytes(const void *shape)
{
    (void)shape;
    return sizeof(struct cone);
}

static void cone_free_shape(void *shape)
{
    cone_free(shape);
}

/* Facets a cone is cut into for renderers without an open frustum: a chord of 1/CONE_FACETS
 * of the circle stays within 1 - cos(pi / CONE_FACETS) = 0.03% of the radius of the arc. */
#define CONE_FACETS 128

/* The point at axial distance s and angle theta, and the unit front normal there. */
static struct vec3 cone_point(const struct cone *c, double s, double theta, struct vec3 *normal)
{
    struct vec3 e = vec3_add(vec3_scale(c->frame_t, cos(theta)), vec3_scale(c->frame_b, sin(theta)));
    struct vec3 outward = vec3_scale(vec3_madd(e, c->axis, -c->slope), c->inv_norm);
    *normal = c->inside ? vec3_scale(outward, -1.0) : outward;
    return vec3_madd(vec3_madd(c->base, c->axis, s), e, c->r_base + c->slope * s);
}

/* CONE_FACETS quads between the rims, each two triangles (one where a rim is a point),
 * wound so that they face the front side, with the exact surface's normals at their
 * corners. Going round by increasing theta turns about w counter-clockwise when
 * (t, b, w) is right-handed; then the corners (base i, base i+1, apex i+1) face outward. */
static void cone_primitives(const void *shape, const struct primitive_visitor *v)
{
    const struct cone *c = shape;
    int outward = vec3_dot(vec3_cross(c->frame_t, c->frame_b), c->axis) > 0;
    int flip = outward == c->inside;
    for (int i = 0; i < CONE_FACETS; i++) {
        double theta[2] = {2.0 * PI * i / CONE_FACETS, 2.0 * PI * (i + 1) / CONE_FACETS};
        struct vec3 p[4], n[4]; /* base i, base i+1, apex i+1, apex i */
        p[0] = cone_point(c, 0.0, theta[0], &n[0]);
        p[1] = cone_point(c, 0.0, theta[1], &n[1]);
        p[2] = cone_point(c, c->height, theta[1], &n[2]);
        p[3] = cone_point(c, c->height, theta[0], &n[3]);
        int tri[2][3] = {{0, 1, 2}, {0, 2, 3}};
        for (int k = 0; k < 2; k++) {
            if ((k == 0 && c->r_base == 0) || (k == 1 && c->r_apex == 0))
                continue; /* that triangle has two corners at the point */
            int a = tri[k][0], b = flip ? tri[k][2] : tri[k][1], d = flip ? tri[k][1] : tri[k][2];
            struct vec3 corner[3] = {p[a], p[b], p[d]}, normal[3] = {n[a], n[b], n[d]};
            v->triangle(v->context, corner, normal, c->material);
        }
    }
}

const struct shape_ops cone_ops = {"cone", cone_bounds, cone_intersect, cone_occluded,
                                   cone_bytes, cone_free_shape, cone_primitives,
                                   "128 flat facets with the cone's normals at their corners "
                                   "(within 0.03% of its radius)"};
