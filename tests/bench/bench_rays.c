/*
 * tests/bench/bench_rays.c -- ray casting, bench/README.md, rays: build seconds, BVH bytes,
 * primary and secondary Mrays/s, and the checksums that show the work was the same.
 *
 * bench_ray_workload() runs the workload on any scene; bench_ray_scenes() hands a workload
 * the SPD scenes balls-s4 and mount-s6 read by our NFF importer (from the folder PHOTON_SPD,
 * make bench SPD=DIR; skipped, saying so, without it), our generated scene terrain1m (a
 * 725 x 725 grid of quads over a sum of sines, two triangles each: 1,051,250 triangles) and
 * the default Cornell box; bench_rays() runs bench_ray_workload() on them, and the Embree
 * comparison (embree/bench_embree.c) its own. For files, build_s includes reading the file.
 */
#include "bench_rays.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/base/alloc.h"
#include "../../src/base/rng.h"
#include "../../src/scene/scene.h"
#include "bench.h"

#define IMAGE_SIZE 1024          /* bench/README.md: 1024 x 1024 whatever the file says          */
#define SECONDARY_NUDGE 1e-5     /* bench/README.md: origins move 1e-5 max(1, max|P|) off surface */
#define BENCH_SEED 1             /* keys the secondary directions' stream                  */
#define TERRAIN_QUADS 725        /* per side: 2 * 725^2 = 1,051,250 triangles             */

/* bench/README.md, rays camera: w = normalize(at - from), u = normalize(w x up), v = u x w, and
 * pixel (i, j), j = 0 at the top, looks along w + (2(i+1/2)/W - 1) t (W/H) u +
 * (1 - 2(j+1/2)/H) t v with t = tan(angle / 2) (here W = H). */
struct ray_set bench_primary_rays(const struct bench_camera *camera)
{
    struct vec3 w = vec3_normalize(vec3_sub(camera->at, camera->from));
    struct vec3 u = vec3_normalize(vec3_cross(w, camera->up));
    struct vec3 v = vec3_cross(u, w);
    double t = tan(camera->angle_deg * PI / 360.0);
    struct ray_set set = {NULL, (size_t)IMAGE_SIZE * IMAGE_SIZE, 0, 0.0};
    set.rays = xmalloc(set.n_rays, sizeof *set.rays, "primary rays");
    for (int j = 0; j < IMAGE_SIZE; j++) {
        for (int i = 0; i < IMAGE_SIZE; i++) {
            double x = (2.0 * (i + 0.5) / IMAGE_SIZE - 1.0) * t;
            double y = (1.0 - 2.0 * (j + 0.5) / IMAGE_SIZE) * t;
            struct vec3 d = vec3_madd(vec3_madd(w, u, x), v, y);
            set.rays[(size_t)j * IMAGE_SIZE + i] = make_ray(camera->from, vec3_normalize(d));
        }
    }
    return set;
}

/* A cosine-distributed unit direction about the unit normal n (Malley's method). */
static struct vec3 cosine_direction(struct vec3 n, struct rng *rng)
{
    double u1 = rng_uniform(rng), u2 = rng_uniform(rng);
    double r = sqrt(u1), phi = 2.0 * PI * u2;
    struct vec3 t, b;
    vec3_frame(n, &t, &b);
    struct vec3 d = vec3_scale(n, sqrt(1.0 - u1));
    return vec3_madd(vec3_madd(d, t, r * cos(phi)), b, r * sin(phi));
}

/* One secondary ray per primary hit (bench/README.md): about ng turned towards the incoming ray,
 * from the hit point nudged along it; stream (BENCH_SEED, STREAM_TEST, pixel, 0). */
struct ray_set bench_secondary_rays(const struct geometry *g, const struct ray_set *primary)
{
    struct ray_set set = {NULL, 0, 0, 0.0};
    set.rays = xmalloc(primary->n_rays, sizeof *set.rays, "secondary rays");
    for (size_t k = 0; k < primary->n_rays; k++) {
        struct hit hit;
        struct ray r = primary->rays[k];
        if (!geometry_intersect(g, r, INFINITY, &hit))
            continue;
        struct vec3 n = vec3_dot(hit.ng, r.dir) > 0 ? vec3_neg(hit.ng) : hit.ng;
        struct vec3 origin = vec3_madd(hit.p, n, SECONDARY_NUDGE * fmax(1.0, vec3_max_abs(hit.p)));
        struct rng rng = rng_stream(BENCH_SEED, STREAM_TEST, k, 0);
        set.rays[set.n_rays++] = make_ray(origin, cosine_direction(n, &rng));
    }
    return set;
}

double bench_cast_rays(const struct geometry *g, struct ray_set *set)
{
    size_t n_hits = 0;
    double t_sum = 0.0;
    double start = bench_seconds();
    for (size_t k = 0; k < set->n_rays; k++) {
        struct hit hit;
        if (geometry_intersect(g, set->rays[k], INFINITY, &hit)) {
            n_hits++;
            t_sum += hit.t;
        }
    }
    double seconds = bench_seconds() - start;
    set->n_hits = n_hits;
    set->t_sum = t_sum;
    return seconds;
}

/* Median over BENCH_REPEATS casts, in millions of rays per second. */
static double mrays_per_second(const struct geometry *g, struct ray_set *set)
{
    double seconds[BENCH_REPEATS];
    for (int r = 0; r < BENCH_REPEATS; r++)
        seconds[r] = bench_cast_rays(g, set);
    double median = bench_median(seconds, BENCH_REPEATS);
    return median > 0 ? (double)set->n_rays / median * 1e-6 : INFINITY;
}

void bench_ray_workload(const char *scene_name, struct geometry *(*build)(void *ctx), void *ctx,
                        const struct bench_camera *camera)
{
    double build_s[BENCH_REPEATS];
    struct geometry *g = NULL;
    for (int r = 0; r < BENCH_REPEATS; r++) {
        geometry_free(g);
        double start = bench_seconds();
        g = build(ctx);
        build_s[r] = bench_seconds() - start;
    }
    struct ray_set primary = bench_primary_rays(camera);
    struct ray_set secondary = bench_secondary_rays(g, &primary);
    double primary_mrays = mrays_per_second(g, &primary);
    double secondary_mrays = mrays_per_second(g, &secondary);
    printf("rays.%s.build_s=%.4f\n", scene_name, bench_median(build_s, BENCH_REPEATS));
    printf("rays.%s.bvh_bytes=%zu\n", scene_name, geometry_bytes(g));
    printf("rays.%s.primary_mrays=%.3f\n", scene_name, primary_mrays);
    printf("rays.%s.secondary_mrays=%.3f\n", scene_name, secondary_mrays);
    printf("rays.%s.primary_hits=%zu\n", scene_name, primary.n_hits);
    printf("rays.%s.primary_tsum=%.9g\n", scene_name, primary.t_sum);
    printf("rays.%s.secondary_hits=%zu\n", scene_name, secondary.n_hits);
    fflush(stdout);
    xfree(secondary.rays);
    xfree(primary.rays);
    geometry_free(g);
}

/* ---- terrain1m ---- */

/* The terrain's height over (x, z) in [-1, 1]^2: a few octaves of sines. */
static double terrain_height(double x, double z)
{
    return 0.25 * sin(2.1 * x + 0.4) * cos(1.7 * z) + 0.1 * sin(5.3 * x + 3.7 * z)
           + 0.04 * sin(13.0 * x - 11.0 * z) + 0.015 * sin(37.0 * x + 29.0 * z)
           + 0.005 * sin(97.0 * x - 83.0 * z);
}

/* The (TERRAIN_QUADS + 1)^2 grid vertices, row z-major; made once, outside the timing. */
struct terrain {
    struct vec3 *vertices;  /* owned */
    int side;               /* vertices per row */
};

static struct vec3 terrain_vertex(const struct terrain *terrain, int i, int k)
{
    return terrain->vertices[(size_t)k * terrain->side + i];
}

/* Quad (i, k) as two triangles, counter-clockwise seen from +y. */
static struct geometry *build_terrain(void *ctx)
{
    const struct terrain *terrain = ctx;
    struct geometry *g = geometry_create();
    for (int k = 0; k + 1 < terrain->side; k++) {
        for (int i = 0; i + 1 < terrain->side; i++) {
            struct vec3 a = terrain_vertex(terrain, i, k), b = terrain_vertex(terrain, i, k + 1);
            struct vec3 c = terrain_vertex(terrain, i + 1, k);
            struct vec3 d = terrain_vertex(terrain, i + 1, k + 1);
            struct vec3 lower[3] = {a, b, c}, upper[3] = {c, b, d};
            geometry_add_triangle(g, lower, NULL, 0);
            geometry_add_triangle(g, upper, NULL, 0);
        }
    }
    geometry_build(g);
    return g;
}

/* A file's scene (a scene file, or an NFF file by its .nff name); exits on bad input. */
static struct scene *load_scene_file(const char *path)
{
    struct error err;
    struct scene *scene = scene_load(path, &err);
    if (scene == NULL) {
        error_print(&err);
        exit(2);
    }
    return scene;
}

/* A file's geometry, taken from the loaded scene (which then frees the rest). */
static struct geometry *build_scene_file(void *ctx)
{
    struct scene *scene = load_scene_file(ctx);
    struct geometry *g = scene->geometry;
    scene->geometry = NULL; /* ours now: the bench frees it */
    scene_free(scene);
    geometry_build(g);
    return g;
}

/* The workload through the file's own camera, named by the file name without directory
 * and extension (bench/README.md: balls-s4, mount-s6). */
static void bench_scene_file(const char *path, bench_ray_scene_fn *workload)
{
    struct scene *scene = load_scene_file(path);
    struct bench_camera camera = {scene->camera.from, scene->camera.at, scene->camera.up,
                                  scene->camera.fov};
    scene_free(scene);
    const char *base = strrchr(path, '/');
    base = base != NULL ? base + 1 : path;
    char name[64];
    snprintf(name, sizeof name, "%.*s", (int)strcspn(base, "."), base);
    workload(name, build_scene_file, (void *)path, &camera);
}

/* The SPD files are not in the repository: they are read from the folder PHOTON_SPD
 * (make bench SPD=DIR), and without it their workloads are skipped, saying so. */
static void bench_spd_files(bench_ray_scene_fn *workload)
{
    static const char *const files[] = {"balls-s4", "mount-s6"};
    const char *folder = getenv("PHOTON_SPD");
    size_t n_files = sizeof files / sizeof files[0];
    if (folder == NULL || folder[0] == '\0') {
        fputs("bench: skipped:", stderr);
        for (size_t i = 0; i < n_files; i++)
            fprintf(stderr, "%s rays.%s", i > 0 ? "," : "", files[i]);
        fputs(" (give SPD=DIR, a folder of the SPD .nff files)\n", stderr);
        return;
    }
    for (size_t i = 0; i < n_files; i++) {
        char path[1024];
        if (snprintf(path, sizeof path, "%s/%s.nff", folder, files[i]) >= (int)sizeof path) {
            fprintf(stderr, "bench: PHOTON_SPD is too long a path\n");
            exit(2);
        }
        bench_scene_file(path, workload);
    }
}

void bench_ray_scenes(bench_ray_scene_fn *workload)
{
    bench_spd_files(workload);
    struct terrain terrain;
    terrain.side = TERRAIN_QUADS + 1;
    terrain.vertices = xmalloc((size_t)terrain.side * terrain.side, sizeof *terrain.vertices,
                               "terrain");
    for (int k = 0; k < terrain.side; k++) {
        for (int i = 0; i < terrain.side; i++) {
            double x = -1.0 + 2.0 * i / TERRAIN_QUADS, z = -1.0 + 2.0 * k / TERRAIN_QUADS;
            terrain.vertices[(size_t)k * terrain.side + i] = vec3(x, terrain_height(x, z), z);
        }
    }
    /* Looking down over the ridges: about 77% of the primary rays hit, the rest see sky. */
    struct bench_camera camera = {{0.1, 0.8, 1.3}, {0.0, -0.1, -0.1}, {0.0, 1.0, 0.0}, 50.0};
    workload("terrain1m", build_terrain, &terrain, &camera);
    xfree(terrain.vertices);
    bench_scene_file("scenes/cornell.scene", workload);
}

void bench_rays(void)
{
    bench_ray_scenes(bench_ray_workload);
}
