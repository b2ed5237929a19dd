/*
 * tests/test_projection_cells.c -- the cells of projection maps (Jensen and Christensen
 * 1994, Sec. 3.1): photons spread over a point light's cells in proportion to each cell's
 * flux raised by its specularity, the tracer's stratification over them, and the maps at
 * their edges (nothing to reach, a black light, no lights, every cell marked).
 *
 * Photons are counted cell by cell against each cell's exact flux, computed here; the
 * strata bound every count to within 2 of N times its probability.
 */
#include <math.h>
#include <string.h>

#include "../src/base/rng.h"
#include "../src/photon/projection_map.h"
#include "../src/photon/trace.h"
#include "check.h"
#include "projection_fixtures.h"
#include "tests.h"
#include "truths.h"

/* ---- the raise and the strata ---- */

#define ROWS (2 * PROJECTION_N_THETA_DEFAULT) /* a point light's map over the sphere */
#define COLUMNS PROJECTION_N_PHI_DEFAULT

/* Photons of a point light's map, cell by cell (theta from +z, phi from +x to +y). */
struct cell_counts {
    long count[ROWS * COLUMNS];
    double weight[ROWS * COLUMNS];     /* of the cell's last photon              */
    double specularity[ROWS * COLUMNS]; /* of its cell, projection_specularity() */
    int weights_agree;                 /* whether a cell's photons share one weight */
};

/* The point light map's cell of unit direction w. */
static int cell_of(struct vec3 w)
{
    double theta = atan2(sqrt(w.x * w.x + w.y * w.y), w.z), phi = atan2(w.y, w.x);
    int row = (int)(theta / (PI / ROWS)), column = (int)floor(phi / (2 * PI / COLUMNS));
    row = row < ROWS ? row : ROWS - 1;
    return row * COLUMNS + (column + COLUMNS) % COLUMNS;
}

/* Emits n photons through pm, photon i with the stratified (i + xi) / n as trace.c does. */
static void count_cells(const struct scene *scene, const struct projection_maps *pm, size_t n,
                        struct cell_counts *c)
{
    memset(c, 0, sizeof *c);
    c->weights_agree = 1;
    for (size_t i = 0; i < n; i++) {
        struct rng r = rng_stream(SEED, STREAM_TEST, 200, i);
        double u[5];
        for (int k = 0; k < 5; k++)
            u[k] = rng_uniform(&r);
        u[0] = ((double)i + u[0]) / (double)n;
        struct emission e;
        if (projection_emit(pm, scene, u, &e) != 0)
            continue;
        int cell = cell_of(e.dir);
        c->weights_agree &= c->count[cell] == 0 || c->weight[cell] == e.weight;
        c->count[cell]++;
        c->weight[cell] = e.weight;
        c->specularity[cell] = projection_specularity(pm, 0, &e);
    }
}

/* F_c of a point light's cell in `row`: (cos theta0 - cos theta1) dphi / (4 pi). */
static double uniform_cell_flux(int row)
{
    return (cos(row * PI / ROWS) - cos((row + 1) * PI / ROWS)) / (2.0 * COLUMNS);
}

/* A point light at the origin and three spheres of radius 0.3 in different directions:
 * a mirror (rho 0.8), glass (specularity 1) and a diffuse one. */
static struct scene *three_spheres_scene(void)
{
    struct scene *scene = scene_create();
    int diffuse = add_test_material(scene, MATERIAL_LAMBERT, vec3(0.5, 0.5, 0.5), vec3_zero());
    int mirror = add_test_material(scene, MATERIAL_MIRROR, vec3(0.8, 0.5, 0.2), vec3_zero());
    int glass = add_test_material(scene, MATERIAL_GLASS, vec3_zero(), vec3_zero());
    scene_add_point_light(scene, vec3_zero(), vec3(1, 1, 1));
    scene_add_sphere(scene, vec3(2, 1, 1.2), 0.3, mirror);
    scene_add_sphere(scene, vec3(-2, 1, -0.5), 0.3, glass);
    scene_add_sphere(scene, vec3(0.5, -2, 0.3), 0.3, diffuse);
    finish_test_scene(scene);
    return scene;
}

/* Whether every cell that received photons received N F_c (1 + boost s_c) / T of them
 * within 2 (T the sum of F_c (1 + boost s_c) over those cells), each carrying the weight
 * T / (1 + boost s_c) (the point light's lum(Phi) cancels). *n_specular, *n_diffuse:
 * photons per unit of flux in cells of specularity 0.8 and 0. */
static int strata_exact(const struct cell_counts *c, size_t n, double boost,
                        double *n_specular, double *n_diffuse)
{
    double total = 0, flux[2] = {0, 0}, photons[2] = {0, 0};
    for (int k = 0; k < ROWS * COLUMNS; k++)
        if (c->count[k] > 0)
            total += uniform_cell_flux(k / COLUMNS) * (1 + boost * c->specularity[k]);
    int exact = c->weights_agree;
    for (int k = 0; k < ROWS * COLUMNS; k++) {
        if (c->count[k] == 0)
            continue;
        double raise = 1 + boost * c->specularity[k];
        double expected = (double)n * uniform_cell_flux(k / COLUMNS) * raise / total;
        exact &= fabs((double)c->count[k] - expected) <= 2;
        exact &= fabs(c->weight[k] - total / raise) <= 1e-9 * total;
        int kind = c->specularity[k] == 0.8 ? 0 : c->specularity[k] == 0 ? 1 : -1;
        if (kind >= 0) {
            flux[kind] += uniform_cell_flux(k / COLUMNS);
            photons[kind] += (double)c->count[k];
        }
    }
    *n_specular = photons[0] / flux[0];
    *n_diffuse = photons[1] / flux[1];
    return exact;
}

/* truth: Sec. 3's rule as projection_map.h states it: each marked cell c receives photons
 *   in proportion to F_c (1 + boost s_c), its exact flux F_c = (cos theta0 - cos theta1)
 *   dphi / (4 pi) computed here, and stratification puts within 2 of N times its
 *   probability into it; photons towards the mirror (s = 0.8, its largest channel) come
 *   1 + 0.8 boost times as densely per unit of flux as towards the diffuse sphere, the
 *   glass's cells have s = 1; with boost 0 all come equally densely.
 * tolerance: 2 photons per cell (the strata's bound); weights to 1e-9 relative; the
 *   density ratio to 1%.
 * catches: u not stratified (a cell's count then strays by sqrt(N P_c), about 50), the
 *   raise missing or applied to the weight twice, specularity from the mean channel or
 *   the last object, a cell's flux taken as its solid angle for a cosine light or as
 *   equal for all cells, weights that differ within a cell. */
static void test_specular_cells_get_more(struct check *t)
{
    struct scene *scene = three_spheres_scene();
    static struct cell_counts counts; /* 96 kB: off the stack */
    for (int boosted = 0; boosted < 2; boosted++) {
        double boost = boosted ? PROJECTION_BOOST_DEFAULT : 0;
        struct projection_settings ps = settings(boost);
        struct projection_maps *pm = projection_maps_build(scene, &ps);
        size_t n = 200000;
        count_cells(scene, pm, n, &counts);
        double n_specular, n_diffuse;
        CHECK(t, strata_exact(&counts, n, boost, &n_specular, &n_diffuse));
        CHECK_CLOSE(t, n_specular / n_diffuse, 1 + 0.8 * boost, 0.01 * (1 + 0.8 * boost));
        struct emission e = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, 0};
        e.dir = vec3_normalize(vec3(-2, 1, -0.5));
        CHECK(t, projection_specularity(pm, 0, &e) == 1.0);
        e.dir = vec3_normalize(vec3(0.5, -2, 0.3));
        CHECK(t, projection_specularity(pm, 0, &e) == 0.0);
        e.dir = vec3(0, 0, 1);
        CHECK(t, projection_specularity(pm, 0, &e) == -1.0);
        projection_maps_free(pm);
    }
    scene_free(scene);
}

/* trace_photons_into()'s sink: each direct photon's cell of emission (its wi reversed). */
static int count_direct_cells(void *context, const struct photon_event *e)
{
    struct cell_counts *c = context;
    c->count[cell_of(vec3_neg(e->wi))]++;
    return 0;
}

/* truth: the tracer stratifies: photon i of N takes the cell at (i + xi) / N (trace.c),
 *   so with a point light inside a closed diffuse box (every cell marked, specularity 0,
 *   every photon stored once as direct) each cell receives within 2 of N F_c photons,
 *   F_c = (cos theta0 - cos theta1) dphi / (4 pi).
 * tolerance: 2 photons per cell, the strata's bound; N = 40960 is 10 photons per cell on
 *   average, so independent photons would stray by about 3 in most cells.
 * catches: the tracer passing xi instead of (i + xi) / N, or i / N without xi (still
 *   within 2, but then not caught: the bound holds for any point of each stratum). */
static void test_trace_stratifies(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/analytic/closed-box.scene", 0, 0);
    CHECK(t, scene != NULL && scene->lights[0].kind == LIGHT_POINT);
    if (scene == NULL)
        return;
    struct projection_settings ps = settings(PROJECTION_BOOST_DEFAULT);
    struct projection_maps *pm = projection_maps_build(scene, &ps);
    static struct cell_counts counts; /* 96 kB: off the stack */
    memset(&counts, 0, sizeof counts);
    size_t n = 40960;
    struct photon_sink sink = {count_direct_cells, &counts};
    trace_into(scene, pm, n, 0, PHOTON_DIRECT, &sink);
    int within = 1;
    long total = 0;
    for (int k = 0; k < ROWS * COLUMNS; k++) {
        within &= fabs((double)counts.count[k] - (double)n * uniform_cell_flux(k / COLUMNS)) <= 2;
        total += counts.count[k];
    }
    CHECK(t, within && total == (long)n);
    projection_maps_free(pm);
    scene_free(scene);
}

/* ---- boundaries ---- */

static int count_photons(void *context, const struct photon_event *e)
{
    (void)e;
    ++*(long *)context;
    return 0;
}

/* truth: the contract at its edges: a light with nothing to reach marks nothing and
 *   emits nothing (projection_emit() -1, a trace stores nothing); a black light gets no
 *   map; no lights, no maps; a point light inside a closed box marks every cell, and
 *   every photon then carries exactly Phi / N, as with plain emission.
 * tolerance: weights to 1e-12 relative (a sum of 4096 cell fluxes).
 * catches: a division by a zero total, maps for black lights (a zero in a weight's
 *   denominator), cell fluxes that do not sum to 1. */
static void test_projection_boundaries(struct check *t)
{
    struct projection_settings ps = settings(PROJECTION_BOOST_DEFAULT);
    struct scene *scene = scene_create();
    int black = add_test_material(scene, MATERIAL_LAMBERT, vec3_zero(), vec3_zero());
    scene_add_point_light(scene, vec3_zero(), vec3(1, 1, 1));
    scene_add_point_light(scene, vec3(1, 0, 0), vec3_zero());
    scene_add_sphere(scene, vec3(0, 0, -5), 1, black); /* behind nothing: it is marked */
    finish_test_scene(scene);
    struct projection_maps *pm = projection_maps_build(scene, &ps);
    struct projection_stats s = projection_maps_stats(pm);
    CHECK(t, s.n_maps == 1 && s.n_cells == (size_t)ROWS * COLUMNS && s.n_marked > 0);
    projection_maps_free(pm);
    projection_maps_free(NULL);
    scene_free(scene);

    scene = scene_create();
    scene_add_point_light(scene, vec3_zero(), vec3(1, 1, 1));
    finish_test_scene(scene);
    pm = projection_maps_build(scene, &ps);
    s = projection_maps_stats(pm);
    double u[5] = {0.5, 0.5, 0.5, 0.5, 0.5};
    struct emission e;
    CHECK(t, s.n_maps == 1 && s.n_marked == 0 && s.marked_fraction == 0);
    CHECK(t, projection_emit(pm, scene, u, &e) == -1);
    long stored = 0;
    struct photon_sink sink = {count_photons, &stored};
    trace_into(scene, pm, 100, 0, PHOTON_MAP_GLOBAL, &sink);
    CHECK(t, stored == 0);
    projection_maps_free(pm);
    scene_free(scene);

    scene = load_test_scene("scenes/analytic/closed-box.scene", 0, 0);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    pm = projection_maps_build(scene, &ps);
    s = projection_maps_stats(pm);
    CHECK(t, s.n_marked == s.n_cells && fabs(s.marked_fraction - 1) <= 1e-12);
    int exact = 1;
    for (int i = 0; i < 100; i++) {
        u[0] = (i + 0.5) / 100;
        exact &= projection_emit(pm, scene, u, &e) == 0 && fabs(e.weight - 1) <= 1e-12;
    }
    CHECK(t, exact);
    projection_maps_free(pm);
    scene_free(scene);
}

void test_projection_cells(struct check *t)
{
    RUN_TEST(t, test_projection_boundaries);
    RUN_TEST(t, test_specular_cells_get_more);
    RUN_TEST(t, test_trace_stratifies);
}
