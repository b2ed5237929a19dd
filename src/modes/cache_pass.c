/*
 * modes/cache_pass.c -- the irradiance cache's pre-pass and a record's radius bounds
 * (cache_pass.h).
 */
#include "cache_pass.h"

#include <math.h>
#include <stdio.h>
#include <time.h>

#include "../base/progress.h"

void fill_cache_pass(const struct scene *scene, uint64_t seed,
                     struct radiance_estimator estimator, const struct irradiance_cache *cache,
                     int progress, struct render_counters *counters)
{
    struct progress line; /* rows are the forecast's work: a rough one, rows of sky cost
                             less than rows of glass, but the only one known beforehand */
    progress_begin(&line, progress ? stderr : NULL, "irradiance cache", scene->height,
                   time(NULL));
    for (int y = 0; y < scene->height; y++) {
        for (int x = 0; x < scene->width; x++) {
            uint64_t pixel = (uint64_t)y * (uint64_t)scene->width + (uint64_t)x;
            struct rng rng = rng_stream(seed, STREAM_CACHE, pixel, 0);
            struct ray ray = camera_ray(&scene->camera, x + 0.5, y + 0.5);
            estimator.radiance(estimator.mode, ray, NULL, &rng, counters);
        }
        int shown = y + 1 == scene->height ? progress_end(&line, y + 1, time(NULL))
                                           : progress_update(&line, y + 1, time(NULL));
        if (shown)
            progress_print(&line, "row %d of %d, %zu records", y + 1, scene->height,
                           irradiance_cache_records(cache));
    }
}

/* The ray offset at p (geom/ray.h): the least distance the renderer tells apart there. */
static double resolution_at(struct vec3 p)
{
    return RAY_OFFSET_REL * fmax(1.0, vec3_max_abs(p));
}

void record_radius_bounds(const struct camera *camera, struct vec3 p, struct vec3 n,
                          double accuracy, double diagonal, double *r_min, double *r_max)
{
    struct vec3 to_camera = vec3_sub(camera->from, p);
    double distance = vec3_length(to_camera);
    double cos_view = distance > 0 ? fabs(vec3_dot(to_camera, n)) / distance : 1.0;
    double footprint = distance * camera_footprint(camera) / fmax(cos_view, 0.1);
    /* A path that comes back through the camera's own position sees no footprint there;
     * the radius still needs a positive floor: the ray offset at p. */
    *r_min = fmax(CACHE_MIN_REACH * footprint / accuracy, resolution_at(p));
    *r_max = fmax(*r_min, CACHE_R_MAX * diagonal);
}

struct record_reach record_reach_at(const struct camera *camera, struct vec3 p, struct vec3 n,
                                    double accuracy, double diagonal, int bounded,
                                    int gradient_limit)
{
    struct record_reach reach;
    reach.gradient_limit = gradient_limit;
    if (bounded) {
        record_radius_bounds(camera, p, n, accuracy, diagonal, &reach.r_min, &reach.r_max);
    } else {
        reach.r_min = resolution_at(p);
        reach.r_max = fmax(reach.r_min, diagonal);
    }
    return reach;
}
