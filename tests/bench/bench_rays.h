/*
 * tests/bench/bench_rays.h -- the ray-casting workload of bench/README.md, rays, reusable for any
 * scene that can be turned into a struct geometry, and its scenes, rays and casting loop for
 * the Embree comparison (embree/bench_embree.c), which casts the same rays.
 */
#ifndef PHOTON_BENCH_RAYS_H
#define PHOTON_BENCH_RAYS_H

#include "../../src/geom/geometry.h"

/* The NFF "v" block: the image is 1024 x 1024 whatever the file says, hither is ignored. */
struct bench_camera {
    struct vec3 from, at, up;
    double angle_deg;  /* full vertical field of view, degrees */
};

/* One ray set and what casting it found. */
struct ray_set {
    struct ray *rays;   /* owned */
    size_t n_rays;
    size_t n_hits;
    double t_sum;       /* sum of the hit distances */
};

/* A workload run on one scene: build(ctx) makes a geometry from the scene's primitives and
 * calls geometry_build(); the caller frees it. */
typedef void bench_ray_scene_fn(const char *scene_name, struct geometry *(*build)(void *ctx),
                                void *ctx, const struct bench_camera *camera);

/* Times build(ctx) BENCH_REPEATS times (freeing all but the last geometry), then the
 * primary and the secondary rays of bench/README.md, rays through `camera`, and prints
 * rays.SCENE.build_s, bvh_bytes (geometry_bytes: primitives and BVH), primary_mrays,
 * secondary_mrays and the checksums primary_hits, primary_tsum, secondary_hits, with SCENE
 * = scene_name. Both ray sets are made before any timing. */
bench_ray_scene_fn bench_ray_workload;

/* Runs workload on balls-s4 and mount-s6 (from the folder PHOTON_SPD; skipped with a note
 * on stderr without it), terrain1m and cornell, in that order. */
void bench_ray_scenes(bench_ray_scene_fn *workload);

/* The primary rays through the pixel centres, and one secondary ray per primary hit
 * (bench/README.md, rays); the caller frees set.rays. */
struct ray_set bench_primary_rays(const struct bench_camera *camera);
struct ray_set bench_secondary_rays(const struct geometry *g, const struct ray_set *primary);

/* Casts every ray of the set for its closest hit, setting set->n_hits and set->t_sum;
 * returns the CPU seconds it took. */
double bench_cast_rays(const struct geometry *g, struct ray_set *set);

#endif
