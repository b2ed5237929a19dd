/*
 * scene/light.c -- sampling lights for direct lighting (light.h).
 */
#include "light.h"

#include "brdf_models.h"

static struct vec3 light_front_power(const struct light *l);

/* Whether a point at squared distance d2 from a sphere light's centre sees its outside.
 * Points on the sphere itself (within rounding, 1e-9 relative) do not: they see its
 * surface edge-on, and a point on its inside sees no front side at all. */
static int outside_sphere(double d2, double r2)
{
    return d2 > r2 * (1.0 + 1e-9);
}

/* The solid-angle pdf of sample_inside() for the direction from p towards q on the sphere:
 * d^2 / (A cos_l), the inner normal at q facing p. 0 where it does not (rounding). */
static double inside_pdf(const struct light *l, struct vec3 p, struct vec3 q)
{
    struct vec3 to_q = vec3_sub(q, p);
    double d2 = vec3_length2(to_q);
    struct vec3 outward = vec3_normalize(vec3_sub(q, l->position));
    double cos_light = d2 > 0 ? vec3_dot(to_q, outward) / sqrt(d2) : 0.0;
    double area = 4.0 * PI * l->radius * l->radius;
    return cos_light > 0 && area > 0 ? d2 / (area * cos_light) : 0.0;
}

/* Inside a two-sided sphere light: a point q uniform by area over the sphere, every one of
 * which faces p (its inner side), its pdf in solid angle d^2 / (A cos_l). */
static int sample_inside(const struct light *l, struct vec3 p, double u1, double u2,
                         struct light_sample *s)
{
    double z = 1.0 - 2.0 * u1, radius = 2.0 * sqrt(u1 * (1.0 - u1)), phi = 2.0 * PI * u2;
    struct vec3 q = vec3_madd(l->position, vec3(radius * cos(phi), radius * sin(phi), z),
                              l->radius);
    struct vec3 to_q = vec3_sub(q, p);
    s->distance = vec3_length(to_q);
    if (!(s->distance > 0))
        return 0;
    s->wi = vec3_scale(to_q, 1.0 / s->distance);
    s->li = l->radiance;
    s->pdf = inside_pdf(l, p, q);
    return s->pdf > 0;
}

/* A sphere of radius r seen from distance d > r subtends a cone of half-angle theta_max,
 * sin^2 theta_max = (r / d)^2. Directions are sampled uniformly in that cone, so the pdf is
 * 1 / (2 pi (1 - cos theta_max)); 1 - cos is computed as sin^2 / (1 + cos) to keep its
 * digits when the sphere is small or far. */
static int sample_sphere(const struct light *l, struct vec3 p, double u1, double u2,
                         struct light_sample *s)
{
    struct vec3 to_centre = vec3_sub(l->position, p);
    double d2 = vec3_length2(to_centre);
    double r2 = l->radius * l->radius;
    if (!outside_sphere(d2, r2))
        return l->two_sided ? sample_inside(l, p, u1, u2, s) : 0;
    double d = sqrt(d2);
    double sin2_max = r2 / d2;
    double cos_max = sqrt(fmax(0.0, 1.0 - sin2_max));
    double one_minus_cos_max = sin2_max / (1.0 + cos_max);
    if (!(one_minus_cos_max > 0))
        return 0; /* the cone is narrower than double precision can sample */
    double one_minus_cos = u1 * one_minus_cos_max;
    double cos_theta = 1.0 - one_minus_cos;
    double sin_theta = sqrt(fmax(0.0, one_minus_cos * (2.0 - one_minus_cos)));
    double phi = 2.0 * PI * u2;
    struct vec3 w = vec3_scale(to_centre, 1.0 / d), t, b;
    vec3_frame(w, &t, &b);
    s->wi = vec3_add(vec3_scale(w, cos_theta),
                     vec3_add(vec3_scale(t, sin_theta * cos(phi)),
                              vec3_scale(b, sin_theta * sin(phi))));
    /* Nearer intersection of the ray p + s wi with the sphere; at the cone's rim the root
     * is a tangent and rounding may push its radicand below zero. */
    double radicand = r2 - d2 * sin_theta * sin_theta;
    s->distance = d * cos_theta - sqrt(fmax(0.0, radicand));
    s->li = l->radiance;
    s->pdf = 1.0 / (2.0 * PI * one_minus_cos_max);
    return s->distance > 0;
}

/* Area of a planar light: |e1 x e2| for a quad, half of it for a triangle. */
static double planar_area(const struct light *l)
{
    double area = vec3_length(vec3_cross(l->e1, l->e2));
    return l->kind == LIGHT_TRIANGLE ? 0.5 * area : area;
}

/* A point q on a planar emitter of area A with unnormalised normal n (|n| = A for a quad,
 * 2A for a triangle) sampled with pdf 1/A by area: in solid angle pdf = d^2 / (A cos_l). */
static int sample_planar(const struct light *l, struct vec3 p, struct vec3 q, double area,
                         struct light_sample *s)
{
    struct vec3 n = vec3_normalize(vec3_cross(l->e1, l->e2));
    struct vec3 to_light = vec3_sub(q, p);
    double d2 = vec3_length2(to_light);
    if (!(d2 > 0) || !(area > 0))
        return 0;
    double d = sqrt(d2);
    s->wi = vec3_scale(to_light, 1.0 / d);
    double cos_light = -vec3_dot(s->wi, n);
    if (l->two_sided)
        cos_light = fabs(cos_light); /* its back emits too */
    if (!(cos_light > 0))
        return 0; /* p is behind the one-sided emitter or in its plane */
    s->distance = d;
    s->li = l->radiance;
    s->pdf = d2 / (area * cos_light);
    return 1;
}

/* The sky seen from a point with unit normal n: a direction cosine-distributed about n
 * (pdf cos / pi), along which the sky's radiance arrives unless something is in the way. */
static int sample_sky(const struct light *l, struct vec3 n, double u1, double u2,
                      struct light_sample *s)
{
    struct vec3 local = sample_cosine_local(u1, u2), t, b;
    vec3_frame(n, &t, &b);
    s->wi = vec3_add(vec3_add(vec3_scale(t, local.x), vec3_scale(b, local.y)),
                     vec3_scale(n, local.z));
    s->distance = INFINITY;
    s->li = l->radiance;
    s->pdf = local.z / PI; /* > 0: sample_cosine_local() keeps z above 0 */
    return 1;
}

int light_sample(const struct light *l, struct vec3 p, struct vec3 n, double u1, double u2,
                 struct light_sample *s)
{
    switch (l->kind) {
    case LIGHT_POINT: {
        struct vec3 to_light = vec3_sub(l->position, p);
        double d2 = vec3_length2(to_light);
        if (!(d2 > 0))
            return 0; /* shading point at the light itself */
        s->distance = sqrt(d2);
        s->wi = vec3_scale(to_light, 1.0 / s->distance);
        s->li = vec3_scale(l->power, 1.0 / (4.0 * PI * d2)); /* I / d^2, I = Phi / (4 pi) */
        s->pdf = 1.0;
        return 1;
    }
    case LIGHT_SPHERE:
        return sample_sphere(l, p, u1, u2, s);
    case LIGHT_QUAD: {
        struct vec3 q = vec3_add(l->position, vec3_add(vec3_scale(l->e1, u1),
                                                       vec3_scale(l->e2, u2)));
        return sample_planar(l, p, q, planar_area(l), s);
    }
    case LIGHT_TRIANGLE: {
        /* Uniform by area: v0 + sqrt(u1) ((1 - u2) e1 + u2 e2) (Turk 1990). */
        double su = sqrt(u1);
        struct vec3 q = vec3_add(l->position, vec3_add(vec3_scale(l->e1, su * (1.0 - u2)),
                                                       vec3_scale(l->e2, u2 * su)));
        return sample_planar(l, p, q, planar_area(l), s);
    }
    case LIGHT_SKY:
        return sample_sky(l, n, u1, u2, s);
    }
    return 0;
}

double light_pdf(const struct light *l, struct vec3 p, struct vec3 n, struct vec3 q,
                 struct vec3 wi)
{
    if (l->kind == LIGHT_POINT)
        return 0.0;
    if (l->kind == LIGHT_SKY)
        return fmax(0.0, vec3_dot(n, wi)) / PI;
    if (l->kind == LIGHT_SPHERE) {
        double d2 = vec3_length2(vec3_sub(l->position, p));
        double r2 = l->radius * l->radius;
        if (!outside_sphere(d2, r2) && l->two_sided)
            return inside_pdf(l, p, q);
        if (!outside_sphere(d2, r2))
            return 0.0;
        double sin2_max = r2 / d2;
        double one_minus_cos_max = sin2_max / (1.0 + sqrt(fmax(0.0, 1.0 - sin2_max)));
        return one_minus_cos_max > 0 ? 1.0 / (2.0 * PI * one_minus_cos_max) : 0.0;
    }
    struct vec3 front = vec3_normalize(vec3_cross(l->e1, l->e2));
    double cos_light = -vec3_dot(wi, front);
    cos_light = l->two_sided ? fabs(cos_light) : cos_light;
    double area = planar_area(l);
    if (!(cos_light > 0) || !(area > 0))
        return 0.0; /* the back of a one-sided emitter is never sampled */
    return vec3_length2(vec3_sub(q, p)) / (area * cos_light);
}

struct vec3 light_power(const struct light *l)
{
    if (l->two_sided && l->kind != LIGHT_POINT && l->kind != LIGHT_SKY)
        return vec3_scale(light_front_power(l), 2.0);
    return light_front_power(l);
}

/* light_power() of the front side alone. */
static struct vec3 light_front_power(const struct light *l)
{
    switch (l->kind) {
    case LIGHT_POINT:
        return l->power;
    case LIGHT_SPHERE:
        return vec3_scale(l->radiance, PI * 4.0 * PI * l->radius * l->radius);
    case LIGHT_QUAD:
    case LIGHT_TRIANGLE:
        return vec3_scale(l->radiance, PI * planar_area(l));
    case LIGHT_SKY:
        return vec3_scale(l->radiance, PI * l->radius * l->radius * 4.0 * PI);
    }
    return vec3_zero();
}
