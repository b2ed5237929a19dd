/*
 * tests/bench/bench.c -- runs the benchmark workloads: all, or the one named by argv[1].
 */
#include "bench.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct workload {
    const char *name;
    void (*run)(void);
};

int main(int argc, char **argv)
{
    static const struct workload workloads[] = {
        {"rays", bench_rays}, {"knn", bench_knn}, {"shapes", bench_shapes},
        {"photons", bench_photons}, {"ppm", bench_ppm}, {"tte", bench_tte},
        {"tts", bench_tts}, {"tiles", bench_tiles}};
    const char *only = argc > 1 && argv[1][0] != '\0' ? argv[1] : NULL;
    int ran = 0;
    for (size_t i = 0; i < sizeof workloads / sizeof workloads[0]; i++) {
        if (only != NULL && strcmp(only, workloads[i].name) != 0)
            continue;
        workloads[i].run();
        ran++;
    }
    if (ran == 0) {
        fprintf(stderr, "bench: unknown workload '%s' (rays, knn, shapes, photons, ppm, tte, "
                        "tts, tiles)\n", only);
        return 2;
    }
    return 0;
}
