/*
 * modes/render.h -- the pixel loop every mode shares.
 *
 * A pixel's value is the mean radiance over the pixel's square: spp camera rays through
 * uniformly jittered points of the pixel (a box filter), each estimated independently by
 * the mode. Sample s of pixel (x, y) draws every random number of its path from
 * rng_stream(seed, STREAM_CAMERA, y * width + x, s), (x, y) in the whole image, so a
 * pixel's value depends on nothing but the scene, the settings and its place: a crop
 * equals the same window of the whole image, bit for bit.
 */
#ifndef PHOTON_RENDER_H
#define PHOTON_RENDER_H

#include <stdint.h>

#include "../base/rng.h"
#include "../image/image.h"
#include "../scene/scene.h"

#define MAX_SPP (1 << 20)   /* documented limit on samples per pixel */
#define MAX_DEPTH_LIMIT 1000 /* documented limit on --max-depth */

struct render_settings {
    uint64_t seed;
    int spp;            /* camera samples per pixel, 1..MAX_SPP                      */
    int max_depth;      /* longest chain of bounces followed, 0..MAX_DEPTH_LIMIT      */
    int x0, y0, x1, y1; /* the window rendered, [x0, x1) x [y0, y1) of the whole image */
    int progress;       /* whether to print a progress line on stderr                */
};

struct render_counters {
    unsigned long long rays;              /* rays cast, camera, secondary and shadow     */
    unsigned long long nonfinite_samples; /* samples dropped for NaN or Inf: always 0
                                             unless a bug lets one through              */
};

/* Radiance arriving at the camera along ray, estimated by a mode from its own state. */
struct radiance_estimator {
    struct vec3 (*radiance)(const void *mode, struct ray ray, struct rng *rng,
                            struct render_counters *counters);
    const void *mode; /* borrowed; passed back to radiance() */
};

/* Renders the settings' window (width x1 - x0, height y1 - y0) of the scene's image. */
struct image *render_pixels(const struct scene *scene, const struct render_settings *rs,
                            struct radiance_estimator estimator,
                            struct render_counters *counters);

#endif
