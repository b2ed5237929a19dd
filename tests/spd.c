/*
 * tests/spd.c -- the helpers behind spd.h: the SPD views, loading a file against its census,
 * reading an NFF file's spheres, and comparing them with our sphere flake's.
 */
#include "spd.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/base/alloc.h"
#include "../src/base/hash.h"
#include "../src/geom/sphereflake.h"
#include "../src/scene/nff.h"

#define PATH_MAX_BYTES 1024
#define SPHERE_TEXT_BYTES 128 /* four %g numbers: at most 4 x 13 characters and spaces */

const char *spd_folder(void)
{
    const char *folder = getenv("PHOTON_SPD");
    return folder != NULL && folder[0] != '\0' ? folder : NULL;
}

/* The `v` block and `b` line of each generator, from its files (the same at every size
 * factor; SPD's numbers as printed, so == compares them exactly). */
const struct spd_view spd_views[] = {
    [SPD_BALLS] = {{2.1, 1.3, 1.7}, {0, 0, 0}, {0, 0, 1}, 45, 512, 512, {0.078, 0.361, 0.753}},
    [SPD_GEARS] = {{-1.1, -2.1, 2.6}, {0, 0, 0}, {0, 0, 1}, 45, 512, 512,
                   {0.078, 0.361, 0.753}},
    [SPD_MOUNT] = {{-1.6, 1.6, 1.7}, {0, 0, 0}, {0, 0, 1}, 45, 512, 512,
                   {0.078, 0.361, 0.753}},
    [SPD_RINGS] = {{-1, -2.61313, 0.5}, {-1, -1.61313, 0.5}, {0, 0, 1}, 45, 512, 512,
                   {0.078, 0.361, 0.753}},
    [SPD_TETRA] = {{1.02285, -3.17715, -2.17451}, {-0.004103, -0.004103, 0.216539},
                   {-0.816497, -0.816497, 0.816497}, 45, 512, 512, {0.078, 0.361, 0.753}},
    [SPD_TREE] = {{4.5, 0.4, 2}, {0, 0, 1.5}, {0, 0, 1}, 45, 512, 512, {0.078, 0.361, 0.753}},
    [SPD_TEAPOT] = {{4.86, 7.2, 5.4}, {0, 0, 0}, {0, 0, 1}, 45, 512, 512,
                    {0.078, 0.361, 0.753}},
    [SPD_LATTICE] = {{0.583333, 1, 0.916667}, {0.583333, -1, -1.08333}, {0.2, 1, 0}, 60, 512,
                     512, {0.078, 0.361, 0.753}},
    [SPD_SHELLS] = {{-6, -60, 35}, {0, 8, -15}, {0, 0, 1}, 45, 512, 512, {0.078, 0.361, 0.753}},
    [SPD_JACKS] = {{0, 0, -8}, {0, 0, 0}, {0, 1, 0}, 25, 256, 256, {0.2, 0.05, 0.2}},
    [SPD_SOMBRERO] = {{0, 5, -8}, {0, 0, 0}, {0, 0, 1}, 40, 512, 512, {0.078, 0.361, 0.753}},
};

static int same_vec3(struct vec3 a, struct vec3 b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

void check_spd_census(struct check *t, const char *folder, const struct spd_census *c)
{
    char path[PATH_MAX_BYTES];
    int length = snprintf(path, sizeof path, "%s/%s", folder, c->file);
    CHECK(t, length > 0 && (size_t)length < sizeof path);
    struct error err;
    struct scene *scene = nff_load(path, &err);
    CHECK(t, scene != NULL);
    if (scene == NULL) {
        error_print(&err);
        return;
    }
    const struct spd_view *v = &spd_views[c->view];
    int before = t->failures_in_test;
    CHECK(t, geometry_primitive_count(scene->geometry) == c->prims);
    CHECK(t, scene->n_lights == c->lights);
    CHECK(t, scene->n_materials == c->materials);
    CHECK(t, scene->has_camera && same_vec3(scene->camera.from, v->from) &&
                 same_vec3(scene->camera.at, v->at) && same_vec3(scene->camera.up, v->up) &&
                 scene->camera.fov == v->angle);
    CHECK(t, scene->width == v->width && scene->height == v->height);
    CHECK(t, same_vec3(scene->background, v->background));
    if (t->failures_in_test != before)
        fprintf(stderr, "SPD census: %s differs from its census\n", path);
    scene_free(scene);
}

double *nff_spheres(const char *path, size_t *n)
{
    FILE *f = fopen(path, "r");
    *n = 0;
    if (f == NULL)
        return NULL;
    size_t cap = 1024;
    double *s = xmalloc(cap, 4 * sizeof *s, "NFF spheres");
    char line[256];
    while (fgets(line, sizeof line, f) != NULL) {
        double *v = s + 4 * *n;
        if (strncmp(line, "s ", 2) != 0 ||
            sscanf(line + 2, "%lf %lf %lf %lf", &v[0], &v[1], &v[2], &v[3]) != 4)
            continue;
        if (++*n == cap) {
            cap *= 2;
            s = xrealloc(s, cap, 4 * sizeof *s, "NFF spheres");
        }
    }
    fclose(f);
    return s;
}

struct sphere_array {
    double *s; /* owned: x, y, z, r per sphere */
    size_t n, cap;
};

static void append_sphere(void *context, struct vec3 centre, double radius, int material)
{
    struct sphere_array *a = context;
    (void)material;
    if (a->n == a->cap) {
        a->cap = a->cap == 0 ? 1024 : 2 * a->cap;
        a->s = xrealloc(a->s, a->cap, 4 * sizeof *a->s, "flake spheres");
    }
    double *v = a->s + 4 * a->n++;
    v[0] = centre.x;
    v[1] = centre.y;
    v[2] = centre.z;
    v[3] = radius;
}

double *balls_spheres(int levels, size_t *n)
{
    struct sphereflake_params p;
    memset(&p, 0, sizeof p);
    p.radius = 0.5;
    p.levels = levels;
    p.orientation = vec3(0, 0, 1);
    struct error err;
    struct sphereflake *flake = sphereflake_create(&p, &err);
    struct sphere_array a = {NULL, 0, 0};
    if (flake != NULL)
        sphereflake_spheres(flake, append_sphere, &a);
    sphereflake_free(flake);
    *n = a.n;
    return a.s != NULL ? a.s : xmalloc(1, 4 * sizeof *a.s, "flake spheres");
}

/* |ours - printed| within what %g's six significant digits allow: the printed value is
 * within half a unit of the 6th digit, <= 5e-6 |x|, of balls.c's double, which differs from
 * ours by rounding only (~1e-16 of the flake's size, 1e-12 allowed; it prints e.g.
 * 1.11022e-16 for our 0). */
static int matches_printed(const double ours[4], const double printed[4])
{
    for (int k = 0; k < 4; k++)
        if (!(fabs(ours[k] - printed[k]) <= 5.0001e-6 * fabs(printed[k]) + 1e-12))
            return 0;
    return 1;
}

/* qsort order of sphere indices by centre x, ties by index: a total order. */
static const double *sorting_spheres;

static int compare_centre_x(const void *a, const void *b)
{
    size_t i = *(const size_t *)a, k = *(const size_t *)b;
    double xi = sorting_spheres[4 * i], xk = sorting_spheres[4 * k];
    if (xi != xk)
        return xi < xk ? -1 : 1;
    return (i > k) - (i < k);
}

/* The sphere of ours (by_x: indices sorted by centre x) that matches printed p, or n when
 * none does. Candidates are those with x within p's tolerance. */
static size_t match_printed(const double *ours, size_t n, const size_t *by_x, const double *p)
{
    double tolerance = 5.0001e-6 * fabs(p[0]) + 1e-12;
    size_t lo = 0, hi = n; /* first position with x >= p[0] - tolerance */
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (ours[4 * by_x[mid]] < p[0] - tolerance)
            lo = mid + 1;
        else
            hi = mid;
    }
    for (size_t k = lo; k < n && ours[4 * by_x[k]] <= p[0] + tolerance; k++)
        if (matches_printed(ours + 4 * by_x[k], p))
            return by_x[k];
    return n;
}

void check_same_spheres(struct check *t, const double *ours, size_t n_ours,
                        const double *printed, size_t n_printed)
{
    CHECK(t, n_ours == n_printed);
    size_t *by_x = xmalloc(n_ours, sizeof *by_x, "sphere order");
    for (size_t k = 0; k < n_ours; k++)
        by_x[k] = k;
    sorting_spheres = ours;
    qsort(by_x, n_ours, sizeof *by_x, compare_centre_x);
    char *matched = xcalloc(n_ours + 1, 1, "matched"); /* [n_ours]: the unmatched */
    for (size_t i = 0; i < n_printed; i++) {
        size_t k = match_printed(ours, n_ours, by_x, printed + 4 * i);
        CHECK(t, k < n_ours && !matched[k]);
        matched[k] = 1;
    }
    xfree(matched);
    xfree(by_x);
}

uint64_t spheres_digest(const double *spheres, size_t n)
{
    uint64_t sum = 0;
    for (size_t i = 0; i < n; i++) {
        double v[4];
        for (int k = 0; k < 4; k++)
            v[k] = fabs(spheres[4 * i + k]) < 1e-12 ? 0.0 : spheres[4 * i + k];
        char text[SPHERE_TEXT_BYTES];
        int length = snprintf(text, sizeof text, "%g %g %g %g", v[0], v[1], v[2], v[3]);
        sum += fnv1a(FNV1A_OFFSET_BASIS, text, (size_t)length);
    }
    return sum;
}
