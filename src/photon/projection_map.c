/*
 * photon/projection_map.c -- projection maps (projection_map.h; Jensen and Christensen
 * 1994, Sec. 3 and 3.1).
 *
 * Emission positions. A light is cut into patches of equal area, each a map's position:
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
 * Each patch has a centre o, a unit normal n at o (the map's axis), the radius rho
 * (every point of the patch lies within rho of o) and the angle beta (every normal of the
 * patch lies within beta of n; 0 for flat patches). Marking an object of bounding sphere
 * (c, r) must hold from every origin y = o + delta, |delta| <= rho:
 *   (1) if the ray from y along w meets (c, r) at y + t w, then o + t w lies within
 *       r + rho of c: the parallel ray from o meets (c, r + rho). So from o, w lies in
 *       the cone of half-angle alpha = asin((r + rho) / |c - o|) about c - o (every
 *       direction when o is inside the widened sphere).
 *   (2) a sphere light's origin y emits about its own normal n_y, not n. Its direction
 *       is drawn in n's frame as w and turned by the least rotation taking n to n_y
 *       (turn_between()), which keeps w's angle to the axis (so the cosine density and
 *       F_c hold exactly at every y) and moves w by at most angle(n, n_y) <= beta. So the
 *       cone is widened to alpha + beta.
 *   (3) a cell is marked when the angle from the cone's axis to the cell's centre
 *       direction is below alpha + beta + h, h the largest angle from the centre
 *       direction to any direction of the cell (cell_half_diagonal()): if the cone meets
 *       the cell at w, the triangle inequality puts the centre within alpha + beta + h.
 *       The test is Sec. 3.1's "maximum radius of the circle" made exact for cells that
 *       are not circles; it marks more than the cells the cone meets, never fewer.
 * rho also holds the ray offset (ray.h) that moves the traced ray off the light, so the
 * marks hold for the rays actually traced. Objects are primitives (a procedural shape is
 * one: its whole box), each bounded by the sphere around its box, widened by the offset
 * within which hit points are computed.
 *
 * A cell's flux. With theta measured from the axis and the cell [theta0, theta1] x
 * [phi0, phi0 + dphi], the share of the patch's power leaving through it is
 *   uniform (point light):  F_c = (cos theta0 - cos theta1) dphi / (4 pi)
 *   cosine (area lights):   F_c = (sin^2 theta1 - sin^2 theta0) dphi / (2 pi)
 * written as products of sines (cell_flux()), free of cancellation. Within the cell a
 * direction is drawn by the inverse of these: cos theta (uniform) or sin^2 theta (cosine)
 * uniform between the cell's bounds, phi uniform.
 *
 * Invariants of a built struct projection_maps:
 *   (a) cells[] holds the marked cells of map 0 in cell order, then map 1's, ...; map k's
 *       are cells[first[k] .. first[k] + n_marked[k] - 1] (struct patch);
 *   (b) cells[j].cumulative is the sum of the weights lum(Phi_l) a_k F_c (1 + boost s_c)
 *       of cells[0..j], summed in that order; total is the last one (0 when none);
 *   (c) every marked cell's weight is positive (lights of zero power have no maps, and
 *       F_c > 0 for every cell).
 * Owns patches[] and cells[]; borrows nothing (the scene is passed to each call).
 */
#include "projection_map.h"

#include <assert.h>
#include <stdint.h>
#include <stdlib.h>

#include "../base/alloc.h"
#include "../scene/brdf.h"

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

enum patch_shape {
    PATCH_POINT, PATCH_PARALLELOGRAM, PATCH_TRIANGLE, PATCH_SPHERE_ZONE, PATCH_WHOLE
};

/* One emission position and its map. */
struct patch {
    int light;              /* index into scene->lights                                  */
    enum patch_shape shape;
    struct vec3 corner;     /* parallelogram: corner + s a + t b, s, t in [0, 1];
                               triangle: corner, corner + a, corner + b                  */
    struct vec3 a, b;       /* (see corner); both unused for points and sphere zones     */
    double z0, z1;          /* sphere zone: z in [z0, z1] on the unit sphere, world axes  */
    double phi0, dphi;      /* sphere zone: phi in [phi0, phi0 + dphi]                    */
    struct vec3 centre;     /* o: where the map is seen from                              */
    struct vec3 t, bt, n;   /* the map's frame: theta from n, phi from t towards bt       */
    double rho;             /* every origin lies within rho of o (ray offset included)   */
    double beta;            /* every origin's normal lies within beta of n (radians)     */
    double area_fraction;   /* a_k: the patch's area over the light's (1 for a point)    */
    size_t first, n_marked; /* its marked cells in cells[] (invariant (a))               */
};

/* A marked cell, with what picking it needs. */
struct marked_cell {
    double cumulative;  /* invariant (b)                                                 */
    double specularity; /* s_c in [0, 1]: the largest over the objects marked in it      */
    uint32_t map, cell; /* its patch, and its place row * n_phi + column in the map      */
};

struct projection_maps {
    struct projection_settings settings; /* copied at build                             */
    struct patch *patches;               /* owned; n_patches of them, lights in order   */
    size_t n_patches;
    struct marked_cell *cells;           /* owned; n_marked used of capacity            */
    size_t n_marked, capacity;
    size_t n_cells;                      /* cells over all maps, marked or not          */
    double total;                        /* invariant (b)                               */
    double marked_power, power;          /* sums of lum(Phi_l) a_k F_c over the marked
                                            cells, and of lum(Phi_l) over the lights     */
};

/* The cells of one map: n_rows x n_phi, theta in steps of d_theta from the axis. */
struct grid {
    int n_rows, n_phi;
    double d_theta, d_phi;
    int cosine; /* 1: the cosine density over a hemisphere; 0: uniform over the sphere */
};

/* An object as a map sees it. */
struct object {
    struct bounding_sphere bound;
    double specularity; /* 0 for a diffuse object */
};

/* A cone of directions from a patch towards an object, in its map's coordinates. */
struct cone {
    struct vec3 axis;   /* unit                                        */
    double alpha;       /* half-angle in radians; >= pi: every direction */
    double specularity; /* the object's                                */
};

/* The cells' centre directions and angular radii, the same in every map (a hemisphere's
 * rows are the first n_theta of a sphere's 2 n_theta), worked out once per build so that
 * marking costs a few products per cell. One block, from sin_theta on; freed by whoever
 * made it with make_cell_table(). */
struct cell_table {
    double *sin_theta, *cos_theta; /* per row (2 n_theta): of its middle theta        */
    double *half_diagonal;         /* per row: h, cell_half_diagonal()                */
    double *cos_phi, *sin_phi;     /* per column (n_phi): of its middle phi            */
};

/* The cells of a patch of this shape's map. */
static struct grid grid_of(const struct projection_settings *ps, enum patch_shape shape)
{
    struct grid g;
    g.cosine = shape != PATCH_POINT && shape != PATCH_WHOLE;
    g.n_rows = g.cosine ? ps->n_theta : 2 * ps->n_theta;
    g.n_phi = ps->n_phi;
    if (shape == PATCH_WHOLE)
        g.n_rows = g.n_phi = 1;
    g.d_theta = (g.cosine ? 0.5 * PI : PI) / g.n_rows;
    g.d_phi = 2.0 * PI / g.n_phi;
    return g;
}

/* ---- emission positions ---- */

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
static double cell_radius(double theta0, double theta1, double dphi)
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

/* Fills pm->patches with every light's patches, lights in order. */
static void make_patches(struct projection_maps *pm, const struct scene *scene)
{
    struct aabb box = geometry_bounds(scene->geometry);
    double diagonal = vec3_length(vec3_sub(box.hi, box.lo)); /* NaN when empty: 1 patch */
    size_t n = 0;
    for (size_t i = 0; i < scene->n_lights; i++) {
        int n1, n2;
        patch_grid(&scene->lights[i], diagonal, &n1, &n2);
        n += emits(&scene->lights[i]) ? (size_t)n1 * n2 : 0;
    }
    pm->patches = xmalloc(n, sizeof *pm->patches, "projection maps");
    pm->n_patches = 0;
    for (size_t i = 0; i < scene->n_lights; i++) {
        const struct light *l = &scene->lights[i];
        if (!emits(l))
            continue;
        int n1, n2;
        patch_grid(l, diagonal, &n1, &n2);
        for (int k = 0; k < n1 * n2; k++) {
            struct patch *p = &pm->patches[pm->n_patches++];
            make_patch(p, l, n1, n2, k);
            p->light = (int)i;
        }
        pm->power += vec3_luminance(light_power(l));
    }
}

/* ---- marking the maps ---- */

/* The specularity of a material: the largest channel of its specular part's reflectance
 * (brdf_split(): Jensen 1996, Eq. 2) seen at normal incidence, for a material with a
 * delta lobe: a mirror's rho, glass 1, Schlick's C for r < 1/2. 0 for the others, whose
 * directions Sec. 3 calls diffuse (they make no caustics: trace.h). */
static double specularity_of(const struct material *m)
{
    if (!brdf_has_delta(m))
        return 0.0;
    struct brdf_split split = brdf_split(m);
    struct vec3 n = vec3(0, 0, 1);
    struct shading_frame f = shading_frame_from_normal(n, 1, TRANSPORT_IMPORTANCE);
    return fmin(1.0, fmax(0.0, vec3_max_component(brdf_albedo(&split.specular, &f, n))));
}

/* Every primitive's bounding sphere and specularity, indexed by primitive id: the sphere
 * around its box (positive radius even for a point-sized box), widened by the offset
 * within which hit points are computed. Owned by the caller. The box is all geometry
 * tells of a primitive, so a sphere's bounding sphere is sqrt(3) times too large, and a
 * procedural shape's specularity is that of the material it was added with (a sphere
 * flake's top sphere's; geometry_primitive_material()): both cost photons, never
 * correctness, as Sec. 3.1's bounding spheres do. */
static struct object *scene_objects(const struct scene *scene, size_t n)
{
    struct object *objects = xmalloc(n, sizeof *objects, "projection map objects");
    for (size_t i = 0; i < n; i++) {
        struct aabb box = geometry_primitive_bounds(scene->geometry, (int)i);
        double half_diagonal = 0.5 * vec3_length(vec3_sub(box.hi, box.lo));
        objects[i].bound.centre = vec3_scale(vec3_add(box.lo, box.hi), 0.5);
        objects[i].bound.radius = half_diagonal +
            RAY_OFFSET_REL * fmax(1.0, fmax(vec3_max_abs(box.lo), vec3_max_abs(box.hi)));
        int material = geometry_primitive_material(scene->geometry, (int)i);
        objects[i].specularity = specularity_of(&scene->materials[material]);
    }
    return objects;
}

/* h: the largest angle from the centre direction of a cell of `row` to any direction of
 * the cell: cell_radius() when phi's step is at most pi, else pi (a cell that is a whole
 * ring, n_phi = 1). */
static double cell_half_diagonal(const struct grid *g, int row)
{
    if (g->d_phi > PI)
        return PI;
    double theta0 = row * g->d_theta;
    return cell_radius(theta0, theta0 + g->d_theta, g->d_phi);
}

/* The table of a point light's sphere of cells, whose first n_theta rows are an area
 * light's hemisphere. */
static struct cell_table make_cell_table(const struct projection_settings *ps)
{
    struct grid g = grid_of(ps, PATCH_POINT);
    size_t rows = (size_t)g.n_rows, columns = (size_t)g.n_phi;
    struct cell_table t;
    t.sin_theta = xmalloc(3 * rows + 2 * columns, sizeof *t.sin_theta, "projection map");
    t.cos_theta = t.sin_theta + rows;
    t.half_diagonal = t.cos_theta + rows;
    t.cos_phi = t.half_diagonal + rows;
    t.sin_phi = t.cos_phi + columns;
    for (int row = 0; row < g.n_rows; row++) {
        t.sin_theta[row] = sin((row + 0.5) * g.d_theta);
        t.cos_theta[row] = cos((row + 0.5) * g.d_theta);
        t.half_diagonal[row] = cell_half_diagonal(&g, row);
    }
    for (int column = 0; column < g.n_phi; column++) {
        t.cos_phi[column] = cos((column + 0.5) * g.d_phi);
        t.sin_phi[column] = sin((column + 0.5) * g.d_phi);
    }
    return t;
}

/* The columns a cone of half-angle alpha about (theta_a, phi_a) may reach: count of them
 * from first (wrapping around). A cone holding neither pole spans phi_a +- asin(sin alpha /
 * sin theta_a); one holding a pole spans every column. */
static void cone_columns(const struct grid *g, double theta_a, double phi_a, double alpha,
                         int *first, int *count)
{
    *first = 0;
    *count = g->n_phi;
    if (theta_a - alpha <= 0 || theta_a + alpha >= PI)
        return;
    double spread = asin(fmin(1.0, sin(alpha) / sin(theta_a))); /* 0 < theta_a < pi */
    int lo = (int)floor((phi_a - spread) / g->d_phi), hi = (int)floor((phi_a + spread) / g->d_phi);
    if (hi - lo + 1 < g->n_phi) {
        *first = lo;
        *count = hi - lo + 1;
    }
}

/* Marks in specularity[] (-1: unmarked) every cell of g that cone c may reach, by (3) at
 * the top of the file, keeping the largest specularity. Only the rows and columns the
 * cone itself can reach are tested (its directions lie within alpha of its axis in theta,
 * and within cone_columns() in phi), which keeps the marks conservative. */
static void mark_cone(const struct grid *g, const struct cell_table *cells, const struct cone *c,
                      double *specularity)
{
    struct vec3 a = c->axis;
    double theta_a = atan2(sqrt(a.x * a.x + a.y * a.y), a.z), phi_a = atan2(a.y, a.x);
    double lowest = floor((theta_a - c->alpha) / g->d_theta);
    if (lowest >= g->n_rows)
        return; /* the cone lies beyond the map (below an area light's horizon) */
    int row0 = lowest > 0 ? (int)lowest : 0;
    double highest = floor((theta_a + c->alpha) / g->d_theta);
    int row1 = highest < g->n_rows - 1 ? (int)highest : g->n_rows - 1;
    int first, count;
    cone_columns(g, theta_a, phi_a, c->alpha, &first, &count);
    for (int row = row0; row <= row1; row++) {
        double limit = c->alpha + cells->half_diagonal[row], cos_limit = cos(limit);
        double across = a.x * cells->sin_theta[row], along = a.y * cells->sin_theta[row];
        double up = a.z * cells->cos_theta[row];
        for (int k = 0; k < count; k++) {
            int column = ((first + k) % g->n_phi + g->n_phi) % g->n_phi;
            /* a . the cell's centre direction */
            double dot = across * cells->cos_phi[column] + along * cells->sin_phi[column] + up;
            double *cell = &specularity[(size_t)row * g->n_phi + column];
            if (limit >= PI || dot > cos_limit)
                *cell = fmax(*cell, c->specularity);
        }
    }
}

/* Marks object o in the map of patch p: the cone of (1) and (2) at the top of the file. */
static void mark_object(const struct grid *g, const struct cell_table *cells,
                        const struct patch *p, const struct object *o, double *specularity)
{
    struct cone c;
    c.specularity = o->specularity;
    struct vec3 to = vec3_sub(o->bound.centre, p->centre);
    double r = o->bound.radius + p->rho, d = vec3_length(to);
    if (!(d > r)) { /* o inside the widened sphere: every direction may meet it */
        c.axis = vec3(0, 0, 1);
        c.alpha = PI;
    } else {
        struct vec3 axis = vec3_scale(to, 1.0 / d); /* d > r > 0 */
        c.axis = vec3(vec3_dot(axis, p->t), vec3_dot(axis, p->bt), vec3_dot(axis, p->n));
        c.alpha = asin(r / d) + p->beta;
    }
    mark_cone(g, cells, &c, specularity);
}

/* F_c, the share of a patch's power leaving through a cell of `row` (top of the file):
 * sin^2 theta1 - sin^2 theta0 = sin(theta1 + theta0) sin(theta1 - theta0) and
 * cos theta0 - cos theta1 = 2 sin((theta0 + theta1) / 2) sin((theta1 - theta0) / 2). */
static double cell_flux(const struct grid *g, int row)
{
    double theta0 = row * g->d_theta, theta1 = theta0 + g->d_theta;
    if (g->cosine)
        return sin(theta1 + theta0) * sin(g->d_theta) * g->d_phi / (2.0 * PI);
    return 2.0 * sin(0.5 * (theta0 + theta1)) * sin(0.5 * g->d_theta) * g->d_phi / (4.0 * PI);
}

/* Appends map k's marked cells to pm->cells (invariants (a) and (b)); luminance is
 * lum(Phi_l) of its light. */
static void collect_marked(struct projection_maps *pm, size_t k, double luminance,
                           const double *specularity)
{
    struct patch *p = &pm->patches[k];
    struct grid g = grid_of(&pm->settings, p->shape);
    size_t n_cells = (size_t)g.n_rows * g.n_phi;
    p->first = pm->n_marked;
    for (size_t c = 0; c < n_cells; c++) {
        if (specularity[c] < 0)
            continue;
        if (pm->n_marked == pm->capacity) {
            pm->capacity = pm->capacity < 1024 ? 1024 : 2 * pm->capacity;
            pm->cells = xrealloc(pm->cells, pm->capacity, sizeof *pm->cells, "projection maps");
        }
        double flux = luminance * p->area_fraction * cell_flux(&g, (int)(c / g.n_phi));
        pm->marked_power += flux;
        pm->total += flux * (1.0 + pm->settings.boost * specularity[c]);
        struct marked_cell *m = &pm->cells[pm->n_marked++];
        m->cumulative = pm->total;
        m->specularity = specularity[c];
        m->map = (uint32_t)k;
        m->cell = (uint32_t)c;
    }
    p->n_marked = pm->n_marked - p->first;
    pm->n_cells += n_cells;
}

struct projection_maps *projection_maps_build(const struct scene *scene,
                                              const struct projection_settings *ps)
{
    assert(ps->n_theta >= 1 && ps->n_phi >= 1 &&
           (double)ps->n_theta * ps->n_phi <= PROJECTION_MAX_CELLS);
    assert(isfinite(ps->boost) && ps->boost >= 0);
    struct projection_maps *pm = xcalloc(1, sizeof *pm, "projection maps");
    pm->settings = *ps;
    pm->cells = NULL; /* calloc's zero bits need not be null pointers */
    make_patches(pm, scene);
    size_t n_objects = geometry_primitive_count(scene->geometry);
    struct object *objects = scene_objects(scene, n_objects);
    struct cell_table cells = make_cell_table(ps);
    double *specularity = xmalloc(2 * (size_t)ps->n_theta * ps->n_phi, sizeof *specularity,
                                  "projection map");
    for (size_t k = 0; k < pm->n_patches; k++) {
        const struct patch *p = &pm->patches[k];
        const struct light *l = &scene->lights[p->light];
        struct grid g = grid_of(ps, p->shape);
        for (size_t c = 0; c < (size_t)g.n_rows * g.n_phi; c++)
            specularity[c] = -1.0;
        if (p->shape == PATCH_WHOLE && n_objects > 0)
            specularity[0] = 0.0; /* the sky's one cell (see the top of the file) */
        for (size_t i = 0; p->shape != PATCH_WHOLE && i < n_objects; i++)
            if ((int)i != l->prim) /* the light's own surface: flat or convex */
                mark_object(&g, &cells, p, &objects[i], specularity);
        collect_marked(pm, k, vec3_luminance(light_power(l)), specularity);
    }
    xfree(specularity);
    xfree(cells.sin_theta);
    xfree(objects);
    return pm;
}

void projection_maps_free(struct projection_maps *pm)
{
    if (pm == NULL)
        return;
    xfree(pm->cells);
    xfree(pm->patches);
    xfree(pm);
}

struct projection_stats projection_maps_stats(const struct projection_maps *pm)
{
    struct projection_stats s;
    s.n_maps = pm->n_patches;
    s.n_cells = pm->n_cells;
    s.n_marked = pm->n_marked;
    s.bytes = sizeof *pm + pm->n_patches * sizeof *pm->patches +
              pm->capacity * sizeof *pm->cells;
    s.marked_fraction = pm->power > 0 ? pm->marked_power / pm->power : 0.0;
    return s;
}

/* ---- emission ---- */

/* The marked cell in which u * total falls: the first whose cumulative exceeds it
 * (zero-width cells cannot be picked; invariant (c) says there are none anyway); the last
 * when rounding put u * total at or above the total. pm->n_marked >= 1. */
static const struct marked_cell *pick_cell(const struct projection_maps *pm, double u)
{
    double x = u * pm->total;
    size_t lo = 0, hi = pm->n_marked - 1;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (pm->cells[mid].cumulative > x)
            hi = mid;
        else
            lo = mid + 1;
    }
    return &pm->cells[lo];
}

/* v turned by the least rotation taking unit `from` to unit `to` (Rodrigues' formula with
 * k = from x to = axis sin(angle), c = cos(angle)): it moves no vector by more than the
 * angle between them. from . to > -1 (a patch's normals are within beta < pi/2 of n). */
static struct vec3 turn_between(struct vec3 v, struct vec3 from, struct vec3 to)
{
    struct vec3 k = vec3_cross(from, to);
    double c = vec3_dot(from, to);
    return vec3_add(vec3_add(vec3_scale(v, c), vec3_cross(k, v)),
                    vec3_scale(k, vec3_dot(k, v) / (1.0 + c)));
}

void projection_origin(const struct projection_maps *pm, const struct scene *scene, size_t map,
                       const double u[2], struct emission *e)
{
    const struct patch *p = &pm->patches[map];
    const struct light *l = &scene->lights[p->light];
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

/* A direction in `cell` of g (map coordinates) by the density restricted to the cell,
 * from two uniform numbers: the inverse of F over theta, phi uniform. */
static struct vec3 cell_direction(const struct grid *g, uint32_t cell, double u1, double u2)
{
    int row = (int)(cell / (uint32_t)g->n_phi), column = (int)(cell % (uint32_t)g->n_phi);
    double theta0 = row * g->d_theta, theta1 = theta0 + g->d_theta;
    double cos_theta, sin_theta;
    if (g->cosine) { /* sin^2 theta uniform in [sin^2 theta0, sin^2 theta1] */
        double s0 = sin(theta0), s1 = sin(theta1);
        double sin2 = s0 * s0 + u1 * (s1 * s1 - s0 * s0);
        sin_theta = sqrt(sin2);
        cos_theta = sqrt(fmax(0.0, 1.0 - sin2));
    } else { /* cos theta uniform in [cos theta1, cos theta0] */
        double c0 = cos(theta0), c1 = cos(theta1);
        cos_theta = c0 - u1 * (c0 - c1);
        sin_theta = sqrt(fmax(0.0, (1.0 - cos_theta) * (1.0 + cos_theta)));
    }
    double phi = (column + u2) * g->d_phi;
    return vec3(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
}

int projection_emit(const struct projection_maps *pm, const struct scene *scene,
                    const double u[5], struct emission *e)
{
    if (pm->n_marked == 0)
        return -1;
    const struct marked_cell *c = pick_cell(pm, u[0]);
    const struct patch *p = &pm->patches[c->map];
    const struct light *l = &scene->lights[p->light];
    /* Phi_l a_k F_c / (P_c N) with P_c = lum(Phi_l) a_k F_c (1 + boost s_c) / total:
     * lum(Phi_l) > 0 (invariant (c)), 1 + boost s_c >= 1 */
    double weight =
        pm->total / (vec3_luminance(light_power(l)) * (1.0 + pm->settings.boost * c->specularity));
    if (p->shape == PATCH_WHOLE) { /* its one cell is the whole sphere: the light's own emission */
        if (!light_emit(l, u + 1, e))
            return -1;
        e->weight = weight;
        return p->light;
    }
    projection_origin(pm, scene, c->map, u + 1, e);
    struct grid g = grid_of(&pm->settings, p->shape);
    struct vec3 w = cell_direction(&g, c->cell, u[3], u[4]);
    e->dir = vec3_add(vec3_add(vec3_scale(p->t, w.x), vec3_scale(p->bt, w.y)),
                      vec3_scale(p->n, w.z));
    if (p->shape == PATCH_SPHERE_ZONE) /* (2) at the top of the file */
        e->dir = turn_between(e->dir, p->n, e->normal);
    e->weight = weight;
    return p->light;
}

double projection_specularity(const struct projection_maps *pm, size_t map,
                              const struct emission *e)
{
    const struct patch *p = &pm->patches[map];
    struct grid g = grid_of(&pm->settings, p->shape);
    struct vec3 w = p->shape == PATCH_SPHERE_ZONE ? turn_between(e->dir, e->normal, p->n) : e->dir;
    struct vec3 a = vec3(vec3_dot(w, p->t), vec3_dot(w, p->bt), vec3_dot(w, p->n));
    double theta = atan2(sqrt(a.x * a.x + a.y * a.y), a.z), phi = atan2(a.y, a.x);
    int row = (int)(theta / g.d_theta), column = (int)floor(phi / g.d_phi);
    if (row >= g.n_rows && g.cosine)
        return -1.0; /* behind an area light's front */
    row = row < g.n_rows ? row : g.n_rows - 1; /* theta = pi exactly, on a point light's */
    column = (column % g.n_phi + g.n_phi) % g.n_phi;
    uint32_t cell = (uint32_t)row * (uint32_t)g.n_phi + (uint32_t)column;
    size_t lo = p->first, hi = p->first + p->n_marked; /* binary search of invariant (a) */
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (pm->cells[mid].cell < cell)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < p->first + p->n_marked && pm->cells[lo].cell == cell ? pm->cells[lo].specularity
                                                                      : -1.0;
}
