/*
 * tests/bench/bench_photons.c -- photon tracing speed in the Cornell box.
 *
 * Traces the global map of scenes/cornell.scene (every diffuse hit stored, the default
 * --max-depth of a photon mode) with 200,000 photons, BENCH_REPEATS times, and prints the
 * median rates: photons emitted per CPU second (each followed until it is absorbed or
 * leaves) and photons stored per second, with the stored count as the checksum that
 * shows every run did the same work.
 */
#include "bench.h"

#include <stdio.h>

#include "../../src/modes/render.h"
#include "../../src/photon/trace.h"

#define BENCH_PHOTONS 200000 /* emitted per run: about 0.2 s, 350,000 stored */

void bench_photons(void)
{
    struct scene *scene = bench_scene("scenes/cornell.scene");
    if (scene == NULL)
        return;
    struct trace_settings ts = {1, 0, BENCH_PHOTONS, MAX_PHOTONS, PHOTON_MAP_GLOBAL,
                                MAX_DEPTH_LIMIT, NULL, NULL, 0, NULL};
    double traced[BENCH_REPEATS], stored[BENCH_REPEATS];
    size_t n_stored = 0;
    struct error err;
    for (int r = 0; r < BENCH_REPEATS; r++) {
        struct photon_trace out;
        double start = bench_seconds();
        if (trace_photons(scene, &ts, &out, &err) < 0) {
            error_print(&err);
            break;
        }
        double seconds = bench_seconds() - start;
        n_stored = out.n_photons;
        traced[r] = seconds > 0 ? BENCH_PHOTONS / seconds : 0; /* 0: clock too coarse */
        stored[r] = seconds > 0 ? out.n_photons / seconds : 0;
        photon_trace_free(&out);
    }
    printf("photons.cornell.emitted=%d\n", BENCH_PHOTONS);
    printf("photons.cornell.stored=%zu\n", n_stored);
    printf("photons.cornell.traced_per_s=%.0f\n", bench_median(traced, BENCH_REPEATS));
    printf("photons.cornell.stored_per_s=%.0f\n", bench_median(stored, BENCH_REPEATS));
    fflush(stdout);
    scene_free(scene);
}
