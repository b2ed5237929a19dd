/*
 * tests/bench/bench_common.c -- what every workload shares: the CPU clock, medians, and
 * loading a scene file (bench.h). Apart from bench.c's main() so that the Embree comparison
 * (embree/bench_embree.c) links the workloads it reuses without the bench's own main().
 */
#include "bench.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "../../src/scene/scene.h"

double bench_seconds(void)
{
    return (double)clock() / CLOCKS_PER_SEC;
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double bench_median(double *values, int count)
{
    qsort(values, (size_t)count, sizeof *values, compare_doubles);
    return values[count / 2];
}

struct scene *bench_scene(const char *path)
{
    struct error err;
    struct scene *scene = scene_load(path, &err);
    if (scene == NULL) {
        error_print(&err);
        return NULL;
    }
    scene_finish(scene, scene->width, scene->height);
    return scene;
}
