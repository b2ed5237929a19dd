/*
 * tests/bench/bench_ppm.c -- progressive photon mapping (--mode 2008) in the Cornell box:
 * hit points made per second by the ray tracing pass, and photons per second through the
 * photon passes (traced, added to every hit point around them, and the per-pass update),
 * at the mode's defaults (256 x 256, 16 eye rays a pixel, 100,000 photons a pass), over
 * BENCH_PPM_PASSES passes. Checksums: the hit points and the image's sum.
 */
#include "bench.h"

#include <stdio.h>

#include "../../src/modes/ppm2008.h"

#define BENCH_PPM_PASSES 4 /* about 5 s a run */

void bench_ppm(void)
{
    struct scene *scene = bench_scene("scenes/cornell.scene");
    if (scene == NULL)
        return;
    struct render_settings rs = render_settings_whole(scene, 1, PPM_DEFAULT_SPP, MAX_DEPTH_LIMIT);
    struct ppm_settings ps = ppm_settings_default();
    ps.progressive.passes = BENCH_PPM_PASSES;
    double hit_points_per_s[BENCH_REPEATS], photons_per_s[BENCH_REPEATS], sum = 0;
    struct ppm_stats stats;
    for (int r = 0; r < BENCH_REPEATS; r++) {
        struct render_counters counters = {0};
        struct render_result result = render_ppm(scene, &rs, &ps, &counters, &stats);
        hit_points_per_s[r] = stats.seconds_ray_pass > 0
                                  ? (double)stats.hit_points / stats.seconds_ray_pass : 0;
        photons_per_s[r] = stats.seconds_photons > 0
                               ? (double)stats.photons_emitted / stats.seconds_photons : 0;
        sum = 0;
        for (size_t i = 0; i < (size_t)result.image->width * (size_t)result.image->height; i++)
            sum += vec3_luminance(result.image->pixels[i]);
        render_result_free(&result);
    }
    printf("ppm.cornell.hit_points=%zu\n", stats.hit_points);
    printf("ppm.cornell.bytes_per_hit_point=%zu\n", stats.bytes_per_hit_point);
    printf("ppm.cornell.hit_points_per_s=%.0f\n", bench_median(hit_points_per_s, BENCH_REPEATS));
    printf("ppm.cornell.photons_per_s=%.0f\n", bench_median(photons_per_s, BENCH_REPEATS));
    printf("ppm.cornell.image_sum=%.9g\n", sum);
    fflush(stdout);
    scene_free(scene);
}
