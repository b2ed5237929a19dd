/*
 * tests/bench/bench_tte.c -- time to error: how long each mode needs to reach a given
 * relmse against a scene's converged reference, beside the path tracer, on the Cornell
 * boxes whose references are in reference/.
 *
 * For each scene and each photon mode at its defaults (2008: 256 x 256, 16 eye rays, 64
 * passes of 100,000 photons; 1996: 64 samples per pixel, 256 where the camera sees a
 * mirror or glass, the maps, the irradiance cache),
 * the mode sets the target, the relmse it ends with, and its seconds to reach it; pt then
 * renders, with checkpoints after 1, 2, 4, ... samples per pixel, until it reaches the target
 * or has run four times as long. pt's time to the target is read off its checkpoints
 * (log-log interpolation between the two around it) or, when it did not get there, from
 * its last one by pt's own law, relmse ~ 1 / time (tte.pt.SCENE.extrapolated=1 says so).
 * Also printed: pt's relmse at 2008's time, and the ratio of the two relmse at equal time.
 */
#include "bench.h"

#include <math.h>
#include <stdio.h>

#include "../../src/image/compare.h"
#include "../../src/modes/jensen1996.h"
#include "../../src/modes/ppm2008.h"
#include "../../src/modes/pt.h"

#define MAX_ROWS 64

/* The error curve a render's checkpoints trace. */
struct curve {
    const struct image *reference; /* borrowed, the whole image */
    double seconds[MAX_ROWS], relmse[MAX_ROWS];
    int n;
};

static double record(void *context, const struct image *mean, long long work, double seconds)
{
    (void)work;
    double start = bench_seconds();
    struct curve *c = context;
    if (c->n < MAX_ROWS) {
        c->seconds[c->n] = seconds;
        c->relmse[c->n] = image_compare(mean, c->reference).relmse;
        c->n++;
    }
    return bench_seconds() - start;
}

/* The time at which the curve first falls to target (log-log interpolation), or -1. */
static double time_to(const struct curve *c, double target)
{
    for (int i = 0; i < c->n; i++) {
        if (c->relmse[i] > target)
            continue;
        if (i == 0)
            return c->seconds[0];
        double f = log(c->relmse[i - 1] / target) / log(c->relmse[i - 1] / c->relmse[i]);
        return exp(log(c->seconds[i - 1]) + f * log(c->seconds[i] / c->seconds[i - 1]));
    }
    return -1;
}

/* The curve's relmse at time t (log-log interpolation; the nearest end outside it). */
static double error_at(const struct curve *c, double t)
{
    if (t <= c->seconds[0])
        return c->relmse[0];
    for (int i = 1; i < c->n; i++)
        if (t <= c->seconds[i]) {
            double f = log(t / c->seconds[i - 1]) / log(c->seconds[i] / c->seconds[i - 1]);
            return exp(log(c->relmse[i - 1]) + f * log(c->relmse[i] / c->relmse[i - 1]));
        }
    return c->relmse[c->n - 1] * c->seconds[c->n - 1] / t; /* pt's 1 / time beyond its end */
}

/* Renders scene (finished) at --mode 2008's defaults, its checkpoints into at. */
static void render_2008(const struct scene *scene, const struct checkpoint *at)
{
    struct render_settings rs = render_settings_whole(scene, 1, PPM_DEFAULT_SPP, MAX_DEPTH_LIMIT);
    struct ppm_settings ps = ppm_settings_default();
    struct render_counters counters = {0, 0, 0, 0, 0};
    struct ppm_stats stats;
    ps.report = at;
    struct render_result result = render_ppm(scene, &rs, &ps, &counters, &stats);
    render_result_free(&result);
}

/* Renders scene (finished) at --mode 1996's defaults, its checkpoints into at. */
static void render_1996(const struct scene *scene, const struct checkpoint *at)
{
    struct render_settings rs = render_settings_whole(scene, 1, J96_DEFAULT_SPP, MAX_DEPTH_LIMIT);
    rs.specular_spp = SPECULAR_SPP_FACTOR * J96_DEFAULT_SPP; /* as on the command line */
    struct jensen1996_settings js = jensen1996_settings_default();
    struct render_counters counters = {0, 0, 0, 0, 0};
    struct jensen1996_stats stats;
    struct error err;
    js.report = at;
    struct render_result result = render_jensen1996(scene, &rs, &js, 0, &counters, &stats, &err);
    render_result_free(&result);
}

static void time_to_error_on(const char *mode,
                             void (*render)(const struct scene *, const struct checkpoint *),
                             const char *name, const char *scene_path,
                             const char *reference_path)
{
    struct error err;
    struct image *reference = pfm_read(reference_path, &err);
    struct scene *scene = reference != NULL ? scene_load(scene_path, &err) : NULL;
    if (scene == NULL) {
        fprintf(stderr, "bench: tte.%s.%s skipped: ", mode, name);
        error_print(&err);
        image_free(reference);
        return;
    }
    scene_finish(scene, reference->width, reference->height);
    struct curve photon = {reference, {0}, {0}, 0}, pt = {reference, {0}, {0}, 0};
    struct checkpoint at_photon = {record, &photon}, at_pt = {record, &pt};
    render(scene, &at_photon);
    double target = photon.relmse[photon.n - 1], photon_seconds = time_to(&photon, target);
    struct render_settings rs = render_settings_whole(scene, 1, MAX_SPP, MAX_DEPTH_LIMIT);
    struct render_counters counters = {0, 0, 0, 0, 0};
    rs.time_limit = 4 * photon_seconds;
    struct render_result result = render_pt(scene, &rs, 0, &at_pt, &counters);
    render_result_free(&result);
    double pt_seconds = time_to(&pt, target);
    int extrapolated = pt_seconds < 0;
    if (extrapolated)
        pt_seconds = pt.seconds[pt.n - 1] * pt.relmse[pt.n - 1] / target;
    printf("tte.%s.%s.relmse=%.6g\n", mode, name, target);
    printf("tte.%s.%s.seconds=%.3f\n", mode, name, photon_seconds);
    printf("tte.pt.%s.seconds_to_%s_relmse=%.3f\n", name, mode, pt_seconds);
    printf("tte.pt.%s.extrapolated=%d\n", name, extrapolated);
    printf("tte.%s.%s.ratio_to_pt=%.4g\n", mode, name, photon_seconds / pt_seconds);
    printf("tte.pt.%s.relmse_at_%s_seconds=%.6g\n", name, mode, error_at(&pt, photon_seconds));
    printf("tte.%s.%s.relmse_ratio_equal_time=%.4g\n", mode, name,
           target / error_at(&pt, photon_seconds));
    fflush(stdout);
    scene_free(scene);
    image_free(reference);
}

void bench_tte(void)
{
    static const char *const names[2] = {"cornell", "cornell-specular"};
    static const char *const scenes[2] = {"scenes/cornell.scene", "scenes/cornell-specular.scene"};
    static const char *const references[2] = {"reference/cornell-pt.pfm",
                                              "reference/cornell-specular-pt.pfm"};
    for (int i = 0; i < 2; i++) {
        time_to_error_on("1996", render_1996, names[i], scenes[i], references[i]);
        time_to_error_on("2008", render_2008, names[i], scenes[i], references[i]);
    }
}
