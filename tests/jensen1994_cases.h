/*
 * tests/jensen1994_cases.h -- the renders test_jensen1994.c and test_jensen1994_caustics.c
 * make of `--mode 1994`: a scene at a size, a window and settings, and what it gave.
 */
#ifndef TESTS_JENSEN1994_CASES_H
#define TESTS_JENSEN1994_CASES_H

#include <stddef.h>
#include <stdint.h>

#include "../src/image/image.h"
#include "../src/modes/jensen1994.h"
#include "../src/modes/render.h"

/* A render of path at size x size (0: the file's own size), of window (x0 y0 x1 y1, or
 * NULL for the whole image), with settings js. */
struct j94_case {
    const char *path;
    int size;
    int spp;
    uint64_t seed;
    const int *window;
    struct jensen1994_settings js;
};

/* What a render gave: the image (owned; NULL when the scene or the render failed). */
struct j94_run {
    struct image *image;
    struct jensen1994_stats stats;
    struct render_counters counters;
};

/* A small photon map and small records: photons, gather_rays rays, one sample a pixel,
 * seed 1. */
struct j94_case j94_small_case(const char *path, int size, size_t photons, int gather_rays);

/* The render of c (run.image NULL when the scene or the render failed). */
struct j94_run j94_render(const struct j94_case *c);

#endif
