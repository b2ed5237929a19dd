/*
 * photon/light_patches.c -- the emission positions of projection maps (light_patches.h;
 * Jensen and Christensen 1994, Sec. 3.1).
 *
 * A light is cut into patches of equal area, each a map's position:
 *   point light    one patch, its position; the map covers the whole sphere about +z
 *                  with the uniform density 1 / (4 pi) (the light's own, emit.h);
 *   quad           an n1 x n2 grid of parallelograms;
 *   triangle       n^2 triangles (the lattice of the edges cut into n: n (n + 1) / 2
 *                  upright, n (n - 1) / 2 upside down, all of area A / n^2);
 *   sphere         a grid of n_z bands of equal height in z times 2 n_z sectors in phi
 *                  about the world's z axis: equal areas (Archimedes), and a point
 *                  uniform by area is z and phi uniform.
 * A side is cut into ceil(length / (PATCH_FRACTION d)) pieces, d the diagonal of the
 * scene's box, at most MAX_PATCH_SIDE: 1 to 64 patches for a planar light, the paper's
 * "more positions for larger lights". A sphere's normal turns with its surface, so it is
 * cut into at least SPHERE_MIN_BANDS bands whatever its size (32 to 128 patches).
 *   sky and       one patch whose map is one cell, the whole sphere of directions,
 *   two-sided     marked with specularity 0 (no raise): the sky's photons start on the
 *   lights        disc that faces their direction, outside the scene (emit.c), so every
 *                  direction reaches every object from some point of the disc; a
 *                  two-sided light emits from its back too, which the front's hemisphere
 *                  does not cover. Departs from Sec. 3.1, which has neither: their
 *                  photons leave as light_emit()'s, only stratified with the other
 *                  lights' cells.
 *
 * Each patch's rho and beta bound its origins and their normals (projection_map.c
 * says what marking needs of them): a flat patch's rho is its farthest corner from o, a
 * sphere zone's the chord to its farthest corner, each with the ray offset (ray.h) that
 * moves the traced ray off the light; beta is 0 for flat patches.
 */
#include "light_patches.h"

#include <math.h>

#include "../base/alloc.h"

/* A patch's side is at most this share of the scene's diagonal (when MAX_PATCH_SIDE
 * allows): 20 patches across the scene, so that rho, which widens every object, stays
 * small beside the distances from the light to what it lights. */
#define PATCH_FRACTION 0.05
/* At most 8 pieces along a side: 64 maps for a planar light, 128 for a sphere. The maps'
 * cost grows with their number (time: maps x primitives), their benefit with 1 / rho. */
#define MAX_PATCH_SIDE 8
/* A sphere light's bands at the least: 4 bands of 8 sectors keep beta (the turn of the
 * normal over a patch, which widens every cone) at 34 degrees in the polar bands and 27
 * in the others; 8 bands of 16, at 21 and 13. */
#define SPHERE_MIN_BANDS 4

/* Whether light l's one patch is the whole sphere of directions: the sky, and a two-sided
 * light (see the top of the file). */
static int emitted_whole(const struct light *l)
{
    return l->kind == LIGHT_SKY || (l->two_sided && l->kind != LIGHT_POINT);
}

/* The pieces a side of this length is cut into (see the top of the file). */
static int side_pieces(double length, double diagonal)
{
    double pieces = ceil(length / (PATCH_FRACTION * diagonal));
    if (pieces >= MAX_PATCH_SIDE)
        return MAX_PATCH_SIDE;
    return pieces >= 1 ? (int)pieces : 1; /* also a NaN from an empty scene's diagonal */
}

/* How many patches light l is cut into: n1 x n2 (a triangle's n1 = n2 is the lattice's n,
 * its patch count n^2 all the same; a sphere's n1 bands of n2 sectors). */
static void patch_grid(const struct light *l, double diagonal, int *n1, int *n2)
{
    *n1 = *n2 = 1;
    if (emitted_whole(l))
        return;
    if (l->kind == LIGHT_QUAD) {
        *n1 = side_pieces(vec3_length(l->e1), diagonal);
        *n2 = side_pieces(vec3_length(l->e2), diagonal);
    } else if (l->kind == LIGHT_TRIANGLE) {
        double longest = fmax(vec3_length(l->e1), fmax(vec3_length(l->e2),
                                                       vec3_length(vec3_sub(l->e2, l->e1))));
        *n1 = *n2 = side_pieces(longest, diagonal);
    } else if (l->kind == LIGHT_SPHERE) {
        int bands = side_pieces(2.0 * l->radius, diagonal);
        *n1 = bands > SPHERE_MIN_BANDS ? bands : SPHERE_MIN_BANDS;
        *n2 = 2 * *n1;
    }
}

/* The offset rays leave a light's surface by (ray.h), for a light within `extent` of p. */
static double offset_bound(struct vec3 p, double extent)
{
    return RAY_OFFSET_REL * fmax(1.0, vec3_max_abs(p) + extent);
}

/* A flat patch: corner, edges a and b; a triangle when triangle is set. */
static void flat_patch(struct patch *p, struct vec3 corner, struct vec3 a, struct vec3 b,
                       int triangle)
{
    p->shape = triangle ? PATCH_TRIANGLE : PATCH_PARALLELOGRAM;
    p->corner = corner;
    p->a = a;
    p->b = b;
    p->n = vec3_normalize(vec3_cross(a, b));
    vec3_frame(p->n, &p->t, &p->bt);
    /* a convex polygon's farthest point from o is a corner */
    struct vec3 to_o = vec3_scale(vec3_add(a, b), triangle ? 1.0 / 3.0 : 0.5);
    p->centre = vec3_add(corner, to_o);
    double rho = fmax(vec3_length(to_o), fmax(vec3_length(vec3_sub(a, to_o)),
                                              vec3_length(vec3_sub(b, to_o))));
    if (!triangle)
        rho = fmax(rho, vec3_length(vec3_sub(vec3_add(a, b), to_o)));
    p->rho = rho + offset_bound(p->centre, rho);
    p->beta = 0.0;
}

/* Patch k (0 <= k < n^2) of a triangle cut n times along each edge, on the lattice
 * points v0 + (i e1 + j e2) / n: first the n (n + 1) / 2 upright triangles, corner (i, j)
 * and edges e1 / n, e2 / n, for i + j <= n - 1; then the n (n - 1) / 2 upside-down ones,
 * corner (i + 1, j + 1) and edges -e1 / n, -e2 / n (the same orientation, e1 x e2), for
 * i + j <= n - 2. Both run through i, then j. */
static void triangle_patch(struct patch *p, const struct light *l, int n, int k)
{
    struct vec3 a = vec3_scale(l->e1, 1.0 / n), b = vec3_scale(l->e2, 1.0 / n);
    int n_upright = n * (n + 1) / 2, upright = k < n_upright;
    int j = upright ? k : k - n_upright, i = 0;
    int longest = upright ? n : n - 1; /* the lattice's row i holds longest - i of them */
    while (j >= longest - i) {
        j -= longest - i;
        i++;
    }
    int up = upright ? 0 : 1;
    struct vec3 corner = vec3_add(l->position, vec3_add(vec3_scale(a, i + up),
                                                        vec3_scale(b, j + up)));
    if (upright)
        flat_patch(p, corner, a, b, 1);
    else
        flat_patch(p, corner, vec3_neg(a), vec3_neg(b), 1);
}

/* The unit vector at polar angle theta from +z and azimuth phi. */
static struct vec3 polar(double theta, double phi)
{
    return vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
}

/* The angle between unit vectors a and b, accurate near 0 and pi. */
static double angle_between(struct vec3 a, struct vec3 b)
{
    return atan2(vec3_length(vec3_cross(a, b)), vec3_dot(a, b));
}

/* The largest angle from the direction at the middle of [theta0, theta1] x [phi0, phi0 +
 * dphi] (polar angles from an axis) to any direction of that cell, dphi <= pi. It is
 * reached at a corner: along a latitude the angle grows with the distance in phi, and at
 * the largest distance, dphi / 2, its cosine is A cos theta + B sin theta with
 * B = sin theta_middle cos(dphi / 2) >= 0, which over an interval of theta is least at an
 * end. By symmetry the corners at phi0 stand for those at phi0 + dphi. */
double cell_radius(double theta0, double theta1, double dphi)
{
    struct vec3 middle = polar(0.5 * (theta0 + theta1), 0.5 * dphi);
    return fmax(angle_between(middle, polar(theta0, 0.0)),
                angle_between(middle, polar(theta1, 0.0)));
}

/* Sphere zone (band, sector) of a sphere light cut into n_bands x n_sectors (at least 8
 * sectors: dphi <= pi). o sits at the middle of the zone's theta and phi, so beta, the
 * largest angle from n to the zone's normals, is its cell_radius(). */
static void sphere_patch(struct patch *p, const struct light *l, int n_bands, int n_sectors,
                         int k)
{
    int band = k / n_sectors, sector = k % n_sectors;
    p->shape = PATCH_SPHERE_ZONE;
    p->z0 = -1.0 + 2.0 * band / n_bands;
    p->z1 = band + 1 == n_bands ? 1.0 : -1.0 + 2.0 * (band + 1) / n_bands;
    p->dphi = 2.0 * PI / n_sectors;
    p->phi0 = sector * p->dphi;
    double theta0 = acos(p->z1), theta1 = acos(p->z0);
    double phi = p->phi0 + 0.5 * p->dphi;
    p->n = polar(0.5 * (theta0 + theta1), phi);
    vec3_frame(p->n, &p->t, &p->bt);
    p->centre = vec3_madd(l->position, p->n, l->radius);
    p->beta = cell_radius(theta0, theta1, p->dphi);
    double chord = 2.0 * l->radius * sin(0.5 * p->beta); /* |y - o| grows with the angle */
    p->rho = chord + offset_bound(p->centre, chord);
}

/* Patch k of light l, cut n1 x n2 (patch_grid()). */
static void make_patch(struct patch *p, const struct light *l, int n1, int n2, int k)
{
    p->area_fraction = 1.0 / ((double)n1 * n2);
    switch (emitted_whole(l) ? LIGHT_SKY : l->kind) {
    case LIGHT_POINT:
    case LIGHT_SKY:
        p->shape = emitted_whole(l) ? PATCH_WHOLE : PATCH_POINT;
        p->centre = l->position;
        p->t = vec3(1, 0, 0);
        p->bt = vec3(0, 1, 0);
        p->n = vec3(0, 0, 1);
        p->rho = p->beta = 0.0;
        break;
    case LIGHT_QUAD: {
        struct vec3 a = vec3_scale(l->e1, 1.0 / n1), b = vec3_scale(l->e2, 1.0 / n2);
        struct vec3 corner = vec3_add(l->position, vec3_add(vec3_scale(a, k / n2),
                                                            vec3_scale(b, k % n2)));
        flat_patch(p, corner, a, b, 0);
        break;
    }
    case LIGHT_TRIANGLE:
        triangle_patch(p, l, n1, k);
        break;
    case LIGHT_SPHERE:
        sphere_patch(p, l, n1, n2, k);
        break;
    }
}

/* Whether light l gets maps: it emits some power (invariant (c)). */
static int emits(const struct light *l)
{
    return vec3_luminance(light_power(l)) > 0;
}

struct patch *light_patches(const struct scene *scene, size_t *n_patches, double *power)
{
    struct aabb box = geometry_bounds(scene->geometry);
    double diagonal = vec3_length(vec3_sub(box.hi, box.lo)); /* NaN when empty: 1 patch */
    size_t n = 0;
    for (size_t i = 0; i < scene->n_lights; i++) {
        int n1, n2;
        patch_grid(&scene->lights[i], diagonal, &n1, &n2);
        n += emits(&scene->lights[i]) ? (size_t)n1 * n2 : 0;
    }
    struct patch *patches = xmalloc(n, sizeof *patches, "projection maps");
    *n_patches = 0;
    *power = 0.0;
    for (size_t i = 0; i < scene->n_lights; i++) {
        const struct light *l = &scene->lights[i];
        if (!emits(l))
            continue;
        int n1, n2;
        patch_grid(l, diagonal, &n1, &n2);
        for (int k = 0; k < n1 * n2; k++) {
            struct patch *p = &patches[(*n_patches)++];
            make_patch(p, l, n1, n2, k);
            p->light = (int)i;
        }
        *power += vec3_luminance(light_power(l));
    }
    return patches;
}

/* v turned by the least rotation taking unit `from` to unit `to` (Rodrigues' formula with
 * k = from x to = axis sin(angle), c = cos(angle)): it moves no vector by more than the
 * angle between them. from . to > -1 (a patch's normals are within beta < pi/2 of n). */
struct vec3 turn_between(struct vec3 v, struct vec3 from, struct vec3 to)
{
    struct vec3 k = vec3_cross(from, to);
    double c = vec3_dot(from, to);
    return vec3_add(vec3_add(vec3_scale(v, c), vec3_cross(k, v)),
                    vec3_scale(k, vec3_dot(k, v) / (1.0 + c)));
}

void patch_origin(const struct patch *p, const struct light *l, const double u[2],
                  struct emission *e)
{
    switch (p->shape) {
    case PATCH_POINT:
    case PATCH_WHOLE: /* emitted as light_emit() does: the light's position stands for it */
        e->origin = p->centre;
        e->normal = vec3_zero();
        return;
    case PATCH_PARALLELOGRAM:
        e->origin = vec3_add(p->corner, vec3_add(vec3_scale(p->a, u[0]), vec3_scale(p->b, u[1])));
        break;
    case PATCH_TRIANGLE: {
        double su = sqrt(u[0]); /* uniform by area (Turk 1990), as light_emit() */
        e->origin = vec3_add(p->corner, vec3_add(vec3_scale(p->a, su * (1.0 - u[1])),
                                                 vec3_scale(p->b, u[1] * su)));
        break;
    }
    case PATCH_SPHERE_ZONE: {
        double z = p->z0 + u[0] * (p->z1 - p->z0), phi = p->phi0 + u[1] * p->dphi;
        double radius = sqrt(fmax(0.0, (1.0 - z) * (1.0 + z)));
        e->normal = vec3(radius * cos(phi), radius * sin(phi), z);
        e->origin = vec3_madd(l->position, e->normal, l->radius);
        return;
    }
    }
    e->normal = p->n;
}

