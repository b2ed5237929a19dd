/*
 * photon/projection_map.c -- projection maps (projection_map.h; Jensen and Christensen
 * 1994, Sec. 3 and 3.1).
 *
 * A light is cut into patches, each a map's position (light_patches.c). Each patch has a
 * centre o, a unit normal n at o (the map's axis), the radius rho (every point of the
 * patch lies within rho of o) and the angle beta (every normal of the patch lies within
 * beta of n; 0 for flat patches). Marking an object of bounding sphere (c, r) must hold
 * from every origin y = o + delta, |delta| <= rho:
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
#include "light_patches.h"

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
    pm->patches = light_patches(scene, &pm->n_patches, &pm->power);
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

void projection_origin(const struct projection_maps *pm, const struct scene *scene, size_t map,
                       const double u[2], struct emission *e)
{
    const struct patch *p = &pm->patches[map];
    patch_origin(p, &scene->lights[p->light], u, e);
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
