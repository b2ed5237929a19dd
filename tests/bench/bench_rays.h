/*
 * tests/bench/bench_rays.h -- the ray-casting workload of bench/README.md, rays, reusable for any
 * scene that can be turned into a struct geometry.
 */
#ifndef PHOTON_BENCH_RAYS_H
#define PHOTON_BENCH_RAYS_H

#include "../../src/geom/geometry.h"

/* The NFF "v" block: the image is 1024 x 1024 whatever the file says, hither is ignored. */
struct bench_camera {
    struct vec3 from, at, up;
    double angle_deg;  /* full vertical field of view, degrees */
};

/* Times build(ctx) BENCH_REPEATS times (freeing all but the last geometry; the callback
 * makes a geometry from the scene's primitives and calls geometry_build()), then the
 * primary and the secondary rays of bench/README.md, rays through `camera`, and prints
 * rays.SCENE.build_s, bvh_bytes (geometry_bytes: primitives and BVH), primary_mrays,
 * secondary_mrays and the checksums primary_hits, primary_tsum, secondary_hits, with SCENE
 * = scene_name. Both ray sets are made before any timing. */
void bench_ray_workload(const char *scene_name, struct geometry *(*build)(void *ctx), void *ctx,
                        const struct bench_camera *camera);

#endif
