/*
 * geom/sphere.c -- ray/sphere intersection without cancellation (see sphere.h).
 *
 * With f = o - c, a = d.d and b = f.d (half the textbook b), the roots of
 * a t^2 + 2 b t + c = 0, c = f.f - r^2, are (-b -+ sqrt(b^2 - a c)) / a. Two steps keep
 * every digit (Ray Tracing Gems, ch. 7):
 *   (1) b^2 - a c = a (r^2 - |l|^2), where l = f - (b / a) d runs from the centre to the
 *       point of the line nearest it; |l| is computed directly, so the discriminant is
 *       exact to the ulps of r^2 even when b^2 and a c are both ~1e20 and nearly equal;
 *   (2) q = -b - sign(b) sqrt(a (r^2 - |l|^2)) adds two terms of one sign, and the roots
 *       are q / a and c / q (Vieta), so the small root is not a difference of large ones.
 */
#include "sphere.h"

struct sphere sphere_make(struct vec3 centre, double radius, int material, int id)
{
    struct sphere s;
    s.centre = centre;
    s.radius = radius;
    s.material = material;
    s.id = id;
    return s;
}

int sphere_is_degenerate(const struct sphere *s)
{
    return !(s->radius > 0);
}

struct aabb sphere_bounds(const struct sphere *s)
{
    double radius = fmax(s->radius, 0.0);   /* a degenerate sphere is its centre */
    struct vec3 r = vec3(radius, radius, radius);
    struct aabb box;
    box.lo = vec3_sub(s->centre, r);
    box.hi = vec3_add(s->centre, r);
    return box;
}

int sphere_intersect(const struct sphere *s, struct ray ray, double tmax, struct hit *hit)
{
    double a = vec3_dot(ray.dir, ray.dir);
    if (!(a > 0) || !(s->radius > 0))
        return 0;
    struct vec3 f = vec3_sub(ray.origin, s->centre);
    double b = vec3_dot(f, ray.dir);
    double r2 = s->radius * s->radius;
    double c = vec3_dot(f, f) - r2;
    if (b > 0 && c > 0)
        return 0;   /* outside and moving away: both roots q / a and c / q below 0 (q < 0) */
    struct vec3 l = vec3_madd(f, ray.dir, -b / a);     /* a > 0, tested above */
    double disc = r2 - vec3_length2(l);                  /* (b^2 - a c) / a, step (1) */
    if (disc < 0)
        return 0;
    double q = -b - copysign(sqrt(a * disc), b);        /* step (2) */
    if (q == 0)
        return 0;   /* b = 0 and disc = 0: the line touches the sphere at t = 0 only */
    double t0 = c / q;                                  /* q != 0 tested above */
    double t1 = q / a;
    if (t0 > t1) {
        double swap = t0;
        t0 = t1;
        t1 = swap;
    }
    if (t0 > 0 && t0 < tmax) {
        hit->t = t0;
        return 1;
    }
    if (t1 > 0 && t1 < tmax) {
        hit->t = t1;
        return 1;
    }
    return 0;
}

void sphere_shade(const struct sphere *s, struct ray ray, struct hit *hit)
{
    struct vec3 n = vec3_normalize(vec3_sub(ray_at(ray, hit->t), s->centre));
    if (vec3_length2(n) == 0)
        n = vec3(0.0, 1.0, 0.0);   /* p = c within rounding: only when r is near underflow */
    hit->p = vec3_madd(s->centre, n, s->radius);   /* onto the surface: removes t's error */
    hit->ng = n;
    hit->ns = n;
    double phi = atan2(n.z, n.x);
    if (phi < 0)
        phi += 2.0 * PI;
    hit->u = phi / (2.0 * PI);
    hit->v = acos(fmax(-1.0, fmin(1.0, n.y))) / PI;
    hit->material = s->material;
}
