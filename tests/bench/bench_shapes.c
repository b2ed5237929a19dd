/*
 * tests/bench/bench_shapes.c -- the procedural shapes against their expansions: a level-6
 * sphere flake (597,871 spheres) and fractal heightfields of 1024^2 and 2048^2 samples
 * (2.1M and 8.4M triangles), each cast procedurally and as plain primitives in the BVH.
 *
 * Each case runs bench_rays.c's workload (bench/README.md, rays camera, primary and secondary
 * rays, build seconds as the median of BENCH_REPEATS builds from the parameters), so its
 * figures print as rays.shapes_CASE_procedural.* and rays.shapes_CASE_expanded.*, CASE =
 * flake6, hf1024, hf2048. bvh_bytes is geometry_bytes(): the shape's own memory (plus a
 * one-leaf BVH), or the primitives and their BVH. The checksums of a pair should agree:
 * the surfaces are the same (secondary hits are random only in which rays exist).
 */
#include <stdio.h>

#include "../../src/geom/heightfield.h"
#include "../../src/geom/sphereflake.h"
#include "bench.h"
#include "bench_rays.h"

/* ---- sphere flake ---- */

/* balls.c's flake (centre 0, radius 0.5, axis +z) at level 6, seen from balls-s4's view. */
static struct sphereflake *flake6(void)
{
    struct sphereflake_params p = {{0, 0, 0}, 0.5, 6, {0, 0, 1}, {0}};
    struct error err;
    return sphereflake_create(&p, &err); /* valid parameters: never NULL */
}

static struct geometry *build_flake_procedural(void *ctx)
{
    (void)ctx;
    struct geometry *g = geometry_create();
    geometry_add_shape(g, &sphereflake_ops, flake6(), 0);
    geometry_build(g);
    return g;
}

static struct geometry *build_flake_expanded(void *ctx)
{
    (void)ctx;
    struct geometry *g = geometry_create();
    struct sphereflake *flake = flake6();
    sphereflake_expand(flake, g); /* 597,871 spheres: below MAX_PRIMITIVES */
    sphereflake_free(flake);
    geometry_build(g);
    return g;
}

/* ---- heightfield ---- */

/* A 2 x 2 landscape about the origin; the builders' ctx points at its resolution. */
static struct heightfield *landscape(int resolution)
{
    struct heightfield_params p;
    p.origin = vec3(-1, -0.1, -1);
    p.size = 2;
    p.resolution = resolution;
    p.octaves = 8;
    p.roughness = 0.5;
    p.frequency = 4;
    p.height = 0.25;
    p.seed = 1;
    p.material = 0;
    struct error err;
    return heightfield_create(&p, &err); /* valid parameters: never NULL */
}

static struct geometry *build_landscape_procedural(void *ctx)
{
    struct geometry *g = geometry_create();
    geometry_add_shape(g, &heightfield_ops, landscape(*(const int *)ctx), 0);
    geometry_build(g);
    return g;
}

static struct geometry *build_landscape_expanded(void *ctx)
{
    struct geometry *g = geometry_create();
    struct heightfield *hf = landscape(*(const int *)ctx);
    heightfield_expand(hf, g); /* at most 2 * 2047^2 triangles: below MAX_PRIMITIVES */
    heightfield_free(hf);
    geometry_build(g);
    return g;
}

/* ---- the cases ---- */

void bench_shapes(void)
{
    /* the view of SPD's balls-s4.nff (its `v` block: from, at, up, angle) */
    struct bench_camera balls = {{2.1, 1.3, 1.7}, {0, 0, 0}, {0, 0, 1}, 45.0};
    bench_ray_workload("shapes_flake6_procedural", build_flake_procedural, NULL, &balls);
    bench_ray_workload("shapes_flake6_expanded", build_flake_expanded, NULL, &balls);
    /* bench_rays.c's terrain1m view, over the same 2 x 2 square */
    struct bench_camera above = {{0.1, 0.8, 1.3}, {0.0, -0.1, -0.1}, {0.0, 1.0, 0.0}, 50.0};
    static const int resolutions[] = {1024, 2048};
    static const char *const names[][2] = {
        {"shapes_hf1024_procedural", "shapes_hf1024_expanded"},
        {"shapes_hf2048_procedural", "shapes_hf2048_expanded"}};
    for (int k = 0; k < 2; k++) {
        int n = resolutions[k];
        bench_ray_workload(names[k][0], build_landscape_procedural, &n, &above);
        bench_ray_workload(names[k][1], build_landscape_expanded, &n, &above);
    }
}
