/*
 * scene/emit.c -- emitting photons from lights (emit.h).
 *
 * Why every photon of light_emit() carries Phi_l / N: a point light's power leaves as
 * the intensity I = Phi / (4 pi) in every direction, and directions are drawn with the
 * density 1 / (4 pi), so the power each of N photons stands for is
 * (Phi / (4 pi)) / ((1 / (4 pi)) N) = Phi / N. An area light of area A emits
 * d^2 Phi = Le cos dA dw, Phi = pi Le A; an origin drawn with density 1 / A and a
 * direction with cos / pi give each photon Le cos / ((1 / A) (cos / pi) N) = Phi / N.
 *
 * Directed emission draws a direction w uniformly inside the cone of one target, picked
 * with probability proportional to the cone's solid angle Omega_t = 2 pi (1 - cos_t).
 * Cones may overlap, so the density of w is the sum over the cones that contain it:
 * pdf(w) = sum_t [w in cone_t] (Omega_t / Omega) (1 / Omega_t) = m(w) / Omega, with
 * Omega = sum_t Omega_t and m(w) the number of cones containing w. The weight is the
 * emitted density over pdf(w): (1 / (4 pi)) / pdf = Omega / (4 pi m) for a point light,
 * (cos / pi) / pdf = cos Omega / (pi m) for an area light (0 behind its front), so
 * E[weight] is the fraction of Phi_l that leaves towards the targets, and the sum of
 * the photons' powers through any direction of the cones is unbiased.
 *
 * The sky (light.h) sends radiance Le from every direction into its sphere, of centre c
 * and radius R around the scene. A photon comes from a direction w uniform over the
 * sphere of directions and starts at a point uniform on the disc of radius R about
 * c + R w facing it, travelling along -w: the sky's power reaches the sphere as Le
 * (pi R^2) dw from each dw, so the density 1 / (4 pi pi R^2) of the pair gives each of
 * N photons (Le pi R^2 4 pi) / N = Phi / N (pbrt-v4 emits its infinite lights alike).
 * The plane of the disc lies outside the sphere, so nothing of the scene stands between
 * a photon's origin and the sphere.
 *
 * Directed emission from the sky aims at a target's disc instead: w uniform again, and a
 * point uniform on the disc of radius r_t about the target's centre projected onto that
 * plane, the target picked with probability r_t^2 / sum_s r_s^2. Discs may overlap, so the
 * density of a point x of the plane is sum_t [x in disc_t] (r_t^2 / sum r^2) / (pi r_t^2)
 * = m(x) / (pi sum r^2), and the weight, the sky's own density over it, is
 * sum r^2 / (R^2 m(x)) inside the sky's disc and 0 outside it (no light of the sky starts
 * there; a target's sphere may reach past the sky's, its primitives never do).
 */
#include "emit.h"

#include "brdf.h"
#include "brdf_models.h"
#include "scene.h"

size_t specular_targets(const struct scene *scene, struct bounding_sphere *spheres)
{
    size_t n = 0;
    for (size_t i = 0; i < scene->n_materials; i++) {
        if (!brdf_split(&scene->materials[i]).has_specular)
            continue;
        struct aabb box = geometry_material_bounds(scene->geometry, (int)i);
        if (!(box.lo.x <= box.hi.x))
            continue; /* no primitive is made of it */
        spheres[n].centre = vec3_scale(vec3_add(box.lo, box.hi), 0.5);
        double half_diagonal = 0.5 * vec3_length(vec3_sub(box.hi, box.lo));
        /* a point-sized box still needs a sphere of positive radius */
        spheres[n++].radius = fmax(half_diagonal, 1e-9 * fmax(1.0, vec3_max_abs(box.lo)));
    }
    return n;
}

/* Uniform direction on the unit sphere (Archimedes: z uniform in [-1, 1]); the radius of
 * the circle at z is written 2 sqrt(u (1 - u)) = sqrt(1 - z^2) without cancellation. */
static struct vec3 uniform_sphere(double u1, double u2)
{
    double z = 1.0 - 2.0 * u1;
    double radius = 2.0 * sqrt(u1 * (1.0 - u1));
    double phi = 2.0 * PI * u2;
    return vec3(radius * cos(phi), radius * sin(phi), z);
}

/* The direction with local coordinates (x, y, z) in the frame around unit axis w. */
static struct vec3 about_axis(struct vec3 w, struct vec3 local)
{
    struct vec3 t, b;
    vec3_frame(w, &t, &b);
    return vec3_add(vec3_add(vec3_scale(t, local.x), vec3_scale(b, local.y)),
                    vec3_scale(w, local.z));
}

/* A point y on light l, uniform by area, with its unit front normal n; a point light's
 * position with n = 0. Returns 0 for a planar light with no area. */
static int light_point(const struct light *l, double u1, double u2, struct vec3 *y,
                       struct vec3 *n)
{
    switch (l->kind) {
    case LIGHT_POINT:
        *y = l->position;
        *n = vec3_zero();
        return 1;
    case LIGHT_SKY: /* no surface: its photons start on a disc (sky_emit()) */
        *y = l->position;
        *n = vec3_zero();
        return 0;
    case LIGHT_SPHERE:
        *n = uniform_sphere(u1, u2);
        *y = vec3_madd(l->position, *n, l->radius);
        return 1;
    case LIGHT_QUAD:
        *y = vec3_add(l->position, vec3_add(vec3_scale(l->e1, u1), vec3_scale(l->e2, u2)));
        break;
    case LIGHT_TRIANGLE: {
        double su = sqrt(u1); /* uniform by area (Turk 1990), as light_sample() */
        *y = vec3_add(l->position, vec3_add(vec3_scale(l->e1, su * (1.0 - u2)),
                                            vec3_scale(l->e2, u2 * su)));
        break;
    }
    }
    *n = vec3_normalize(vec3_cross(l->e1, l->e2)); /* zero when the light has no area */
    return vec3_length2(*n) > 0;
}

/* A point uniform on the disc of radius r about centre, perpendicular to unit w (the
 * disc's area is sampled by the square root of u1). */
static struct vec3 disc_point(struct vec3 centre, struct vec3 w, double r, double u1,
                              double u2)
{
    struct vec3 t, b;
    vec3_frame(w, &t, &b);
    double rho = r * sqrt(u1), phi = 2.0 * PI * u2;
    return vec3_add(centre, vec3_add(vec3_scale(t, rho * cos(phi)),
                                     vec3_scale(b, rho * sin(phi))));
}

/* The sky's photon (see the top of the file): u[0], u[1] the point of the disc, u[2], u[3]
 * the direction w the light comes from. */
static int sky_emit(const struct light *l, const double u[4], struct emission *e)
{
    struct vec3 w = uniform_sphere(u[2], u[3]);
    e->origin = disc_point(vec3_madd(l->position, w, l->radius), w, l->radius, u[0], u[1]);
    e->dir = vec3_neg(w);
    e->normal = vec3_zero(); /* it starts on no surface */
    e->weight = 1.0;
    return l->radius > 0;
}

/* A point of area light l with light_point() from u1, u2, and the side it emits from: the
 * front's normal, or for a two-sided light the back's as often, u2 telling which (the
 * half it falls in, stretched back over [0, 1) for the point). */
static int emitting_point(const struct light *l, double u1, double u2, struct vec3 *y,
                          struct vec3 *n)
{
    int back = l->two_sided && u2 >= 0.5;
    if (l->two_sided)
        u2 = back ? 2.0 * u2 - 1.0 : 2.0 * u2;
    if (!light_point(l, u1, u2, y, n))
        return 0;
    if (back)
        *n = vec3_neg(*n);
    return 1;
}

int light_emit(const struct light *l, const double u[4], struct emission *e)
{
    if (l->kind == LIGHT_SKY)
        return sky_emit(l, u, e);
    if (!emitting_point(l, u[0], u[1], &e->origin, &e->normal))
        return 0;
    e->weight = 1.0;
    if (l->kind == LIGHT_POINT)
        e->dir = uniform_sphere(u[2], u[3]);
    else
        e->dir = about_axis(e->normal, sample_cosine_local(u[2], u[3]));
    return 1;
}

/* The cone of directions from y that meet sphere s: its unit axis and 1 - cos of its
 * half-angle, sin^2 / (1 + cos) as light.c computes it (keeps its digits for small or
 * far spheres). From inside the sphere every direction meets it: 2, the whole sphere. */
static double cone_towards(const struct bounding_sphere *s, struct vec3 y, struct vec3 *axis)
{
    struct vec3 to_centre = vec3_sub(s->centre, y);
    double d2 = vec3_length2(to_centre), r2 = s->radius * s->radius;
    if (!(d2 > r2)) {
        *axis = vec3(0.0, 0.0, 1.0);
        return 2.0;
    }
    double sin2_max = r2 / d2; /* d2 > r2 >= 0 */
    *axis = vec3_scale(to_centre, 1.0 / sqrt(d2));
    return sin2_max / (1.0 + sqrt(1.0 - sin2_max));
}

/* A direction uniform in the cone about unit axis w with 1 - cos_max = one_minus_cos_max
 * in (0, 2]; 2 gives the whole sphere. */
static struct vec3 sample_cone(struct vec3 w, double one_minus_cos_max, double u1, double u2)
{
    double one_minus_cos = u1 * one_minus_cos_max;
    double sin_theta = sqrt(fmax(0.0, one_minus_cos * (2.0 - one_minus_cos)));
    double phi = 2.0 * PI * u2;
    return about_axis(w, vec3(sin_theta * cos(phi), sin_theta * sin(phi), 1.0 - one_minus_cos));
}

/* The target whose cone u (in [0, 1)) falls in, with probability proportional to its
 * 1 - cos_max; total is the sum of those over all targets (> 0). */
static size_t pick_target(const struct emission_targets *targets, struct vec3 y, double total,
                          double u)
{
    double below = u * total, cumulative = 0.0;
    size_t last = 0;
    for (size_t t = 0; t < targets->n_spheres; t++) {
        struct vec3 axis;
        double size = cone_towards(&targets->spheres[t], y, &axis);
        if (!(size > 0))
            continue;
        cumulative += size;
        last = t;
        if (below < cumulative)
            return t;
    }
    return last; /* rounding left u * total at or above the sum: the last non-empty cone */
}

/* m(w): how many targets' cones contain w. The picked target counts without a test, so
 * rounding at its rim cannot make m zero. */
static size_t cones_containing(const struct emission_targets *targets, struct vec3 y,
                               struct vec3 w, size_t picked)
{
    size_t m = 1;
    for (size_t t = 0; t < targets->n_spheres; t++) {
        struct vec3 axis;
        double size = cone_towards(&targets->spheres[t], y, &axis);
        if (t != picked && size > 0 && 1.0 - vec3_dot(w, axis) <= size)
            m++;
    }
    return m;
}

/* Directed emission from the sky (see the top of the file): u[4] picks a target by r^2,
 * u[0], u[1] the point of its disc, u[2], u[3] the direction w. */
static int sky_emit_towards(const struct light *l, const struct emission_targets *targets,
                            const double u[5], struct emission *e)
{
    double total = 0.0; /* sum_t r_t^2 */
    for (size_t t = 0; t < targets->n_spheres; t++)
        total += targets->spheres[t].radius * targets->spheres[t].radius;
    double below = u[4] * total, cumulative = 0.0;
    size_t picked = 0; /* the last when rounding left u total at or above the sum */
    for (; picked + 1 < targets->n_spheres; picked++) {
        cumulative += targets->spheres[picked].radius * targets->spheres[picked].radius;
        if (below < cumulative)
            break;
    }
    struct vec3 w = uniform_sphere(u[2], u[3]);
    struct vec3 plane = vec3_madd(l->position, w, l->radius); /* the sky disc's centre */
    const struct bounding_sphere *target = &targets->spheres[picked];
    struct vec3 across = vec3_sub(target->centre, l->position);
    struct vec3 centre = vec3_add(plane, vec3_madd(across, w, -vec3_dot(across, w)));
    e->origin = disc_point(centre, w, target->radius, u[0], u[1]);
    e->dir = vec3_neg(w);
    e->normal = vec3_zero();
    struct vec3 offset = vec3_sub(e->origin, plane);
    if (!(l->radius > 0) || vec3_length2(offset) > l->radius * l->radius)
        return 0; /* outside the sky's disc: no light of the sky starts there */
    double m = 1.0; /* m(x): the picked disc counts without a test, as cones_containing() */
    for (size_t t = 0; t < targets->n_spheres; t++) {
        struct vec3 c = vec3_sub(targets->spheres[t].centre, l->position);
        struct vec3 from_axis = vec3_sub(offset, vec3_madd(c, w, -vec3_dot(c, w)));
        double r = targets->spheres[t].radius;
        if (t != picked && vec3_length2(from_axis) <= r * r)
            m++;
    }
    e->weight = total / (l->radius * l->radius * m);
    return 1;
}

int light_emit_towards(const struct light *l, const struct emission_targets *targets,
                       const double u[5], struct emission *e)
{
    if (l->kind == LIGHT_SKY)
        return sky_emit_towards(l, targets, u, e);
    if (!emitting_point(l, u[0], u[1], &e->origin, &e->normal))
        return 0;
    double total = 0.0; /* Omega / (2 pi) */
    for (size_t t = 0; t < targets->n_spheres; t++) {
        struct vec3 axis;
        total += cone_towards(&targets->spheres[t], e->origin, &axis);
    }
    if (!(total > 0))
        return 0; /* every target subtends less than double precision can sample */
    size_t picked = pick_target(targets, e->origin, total, u[4]);
    struct vec3 axis;
    double size = cone_towards(&targets->spheres[picked], e->origin, &axis);
    e->dir = sample_cone(axis, size, u[2], u[3]);
    double m = (double)cones_containing(targets, e->origin, e->dir, picked); /* >= 1 */
    if (l->kind == LIGHT_POINT) {
        e->weight = total / (2.0 * m); /* Omega / (4 pi m) */
        return 1;
    }
    double cos_theta = vec3_dot(e->dir, e->normal);
    if (!(cos_theta > 0))
        return 0; /* behind the emitting side: no light leaves that way */
    e->weight = 2.0 * cos_theta * total / m; /* cos Omega / (pi m) */
    return 1;
}
