/*
 * tests/bench/bench_tte.c -- time to error: how long each photon mode needs to reach the
 * relmse it ends with against a scene's converged reference, and how long the path tracer
 * needs to reach the same relmse, on the scenes whose references are in reference/.
 *
 * Each photon mode renders at the command line's defaults (its settings_default() and
 * DEFAULT_SPP; 1994 and 1996 take SPECULAR_SPP_FACTOR times the samples where the camera
 * sees a light through a mirror or glass, as options.c gives them); its final relmse is
 * its target and its CPU seconds the time to it. pt then renders once for the scene, with
 * checkpoints after 1, 2, 4, ... samples per pixel, for PT_TIME_FACTOR times the longest
 * mode's seconds, and every mode's figure is read off that one curve: log-log
 * interpolation between the two checkpoints around the target or, past pt's last
 * checkpoint, the fit relmse = a / t + c of its checkpoints (tte_fit.h, pt_fit; c is the
 * reference's own noise, from its variance image: reference_floor()) and
 * tte.MODE.SCENE.extrapolated=1. A target at or below c is one
 * pt never reaches by the fit (extrapolated=unreachable): its pt_seconds and ratio are then
 * lower bounds, from pt's last checkpoint, which had not reached it.
 * ratio = pt's seconds / the mode's: above 1 the photon mode is faster to its error.
 *
 * PHOTON_TTE_TRIAL set and not empty makes a trial run, for trying what reads the figures
 * (scripts/figures.sh): the same steps on the TRIAL_SIZE x TRIAL_SIZE window at the
 * image's centre, with a TRIAL_SHRINK-th of the photons, TRIAL_GATHER_RAYS gather rays and
 * TRIAL_PASSES photon passes. Its figures mean nothing.
 */
#include "bench.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "../../src/base/alloc.h"
#include "../../src/image/compare.h"
#include "../../src/modes/jensen1994.h"
#include "../../src/modes/jensen1996.h"
#include "../../src/modes/ppm2008.h"
#include "../../src/modes/pt.h"
#include "../../src/modes/sppm2009.h"
#include "tte_fit.h"

#define MAX_ROWS 64
#define N_PHOTON_MODES 4
#define PT_TIME_FACTOR 4 /* pt's cap: this many times the longest mode's seconds */
#define TRIAL_SIZE 32
#define TRIAL_SHRINK 100
#define TRIAL_GATHER_RAYS 32
#define TRIAL_PASSES 4

/* The error curve a render's checkpoints trace, and its fit for past the last one. */
struct curve {
    const struct image *reference; /* borrowed, the rendered window of the reference */
    double seconds[MAX_ROWS], work[MAX_ROWS], relmse[MAX_ROWS]; /* work: samples a pixel */
    int n;
    struct tte_fit fit; /* of the n rows, in seconds, once the render is done (pt_fit) */
};

static double record(void *context, const struct image *mean, long long work, double seconds)
{
    double start = bench_seconds();
    struct curve *c = context;
    if (c->n < MAX_ROWS) {
        c->seconds[c->n] = seconds;
        c->work[c->n] = (double)work;
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

/* The curve's relmse at time t (log-log interpolation; before it, its first row; after
 * it, its fit). */
static double error_at(const struct curve *c, double t)
{
    if (t <= c->seconds[0])
        return c->relmse[0];
    for (int i = 1; i < c->n; i++)
        if (t <= c->seconds[i]) {
            double f = log(t / c->seconds[i - 1]) / log(c->seconds[i] / c->seconds[i - 1]);
            return exp(log(c->relmse[i - 1]) + f * log(c->relmse[i] / c->relmse[i - 1]));
        }
    return tte_fit_error_at(&c->fit, t);
}

/* The command line's settings at spp samples a pixel (seed 1, no time limit): the whole
 * image, or in a trial the window at its centre. */
static struct render_settings settings_at(const struct scene *scene, int spp, int trial)
{
    struct render_settings rs = render_settings_whole(scene, 1, spp, MAX_DEPTH_LIMIT);
    if (trial && scene->width >= TRIAL_SIZE && scene->height >= TRIAL_SIZE) {
        rs.x0 = (scene->width - TRIAL_SIZE) / 2;
        rs.y0 = (scene->height - TRIAL_SIZE) / 2;
        rs.x1 = rs.x0 + TRIAL_SIZE;
        rs.y1 = rs.y0 + TRIAL_SIZE;
    }
    return rs;
}

/* The settings' window of the whole image (the same size as the scene's), a new image. */
static struct image *window_of(const struct image *whole, const struct render_settings *rs)
{
    struct image *window = image_create(rs->x1 - rs->x0, rs->y1 - rs->y0);
    for (int y = rs->y0; y < rs->y1; y++)
        for (int x = rs->x0; x < rs->x1; x++)
            image_set(window, x - rs->x0, y - rs->y0, image_get(whole, x, y));
    return window;
}

/* Where a render's CPU seconds went, by the phases its --stats names. */
#define MAX_PHASES 4
struct phases {
    const char *name[MAX_PHASES]; /* the stats key, e.g. "seconds_cache" */
    double seconds[MAX_PHASES];
    int n;
};

static void phase(struct phases *ph, const char *name, double seconds)
{
    ph->name[ph->n] = name;
    ph->seconds[ph->n++] = seconds;
}

static struct render_result render_1994(const struct scene *scene, int trial, struct phases *ph,
                                        struct error *err)
{
    struct render_settings rs = settings_at(scene, J94_DEFAULT_SPP, trial);
    rs.specular_spp = SPECULAR_SPP_FACTOR * J94_DEFAULT_SPP; /* as on the command line */
    struct jensen1994_settings js = jensen1994_settings_default();
    if (trial) {
        js.n_photons /= TRIAL_SHRINK;
        js.gather_rays = TRIAL_GATHER_RAYS;
    }
    struct render_counters counters = {0};
    struct jensen1994_stats stats;
    struct render_result result = render_jensen1994(scene, &rs, &js, 0, &counters, &stats, err);
    phase(ph, "seconds_photons", stats.seconds_photons);
    phase(ph, "seconds_cache", stats.seconds_cache);
    phase(ph, "seconds_final_pass", stats.seconds_final_pass);
    return result;
}

static struct render_result render_1996(const struct scene *scene, int trial, struct phases *ph,
                                        struct error *err)
{
    struct render_settings rs = settings_at(scene, J96_DEFAULT_SPP, trial);
    rs.specular_spp = SPECULAR_SPP_FACTOR * J96_DEFAULT_SPP; /* as on the command line */
    struct jensen1996_settings js = jensen1996_settings_default();
    if (trial) {
        js.global_photons /= TRIAL_SHRINK;
        js.caustic_photons /= TRIAL_SHRINK;
        js.gather_rays = TRIAL_GATHER_RAYS;
    }
    struct render_counters counters = {0};
    struct jensen1996_stats stats;
    struct render_result result = render_jensen1996(scene, &rs, &js, 0, &counters, &stats, err);
    phase(ph, "seconds_photons", stats.seconds_photons);
    phase(ph, "seconds_cache", stats.seconds_cache);
    phase(ph, "seconds_final_pass", stats.seconds_final_pass);
    return result;
}

static struct render_result render_2008(const struct scene *scene, int trial, struct phases *ph,
                                        struct error *err)
{
    (void)err; /* render_ppm does not fail on a finished scene */
    struct render_settings rs = settings_at(scene, PPM_DEFAULT_SPP, trial);
    struct ppm_settings ps = ppm_settings_default();
    if (trial) {
        ps.progressive.photons_per_pass /= TRIAL_SHRINK;
        ps.progressive.passes = TRIAL_PASSES;
    }
    struct render_counters counters = {0};
    struct ppm_stats stats;
    struct render_result result = render_ppm(scene, &rs, &ps, &counters, &stats);
    phase(ph, "seconds_ray_pass", stats.seconds_ray_pass);
    phase(ph, "seconds_photons", stats.seconds_photons);
    return result;
}

static struct render_result render_2009(const struct scene *scene, int trial, struct phases *ph,
                                        struct error *err)
{
    (void)err; /* render_sppm does not fail on a finished scene */
    struct sppm_settings ps = sppm_settings_default();
    if (trial) {
        ps.progressive.photons_per_pass /= TRIAL_SHRINK;
        ps.progressive.passes = TRIAL_PASSES;
    }
    struct render_settings rs = settings_at(scene, (int)ps.progressive.passes, trial);
    struct render_counters counters = {0};
    struct ppm_stats stats;
    struct render_result result = render_sppm(scene, &rs, &ps, &counters, &stats);
    phase(ph, "seconds_ray_pass", stats.seconds_ray_pass);
    phase(ph, "seconds_photons", stats.seconds_photons);
    return result;
}

struct photon_mode {
    const char *name; /* the --mode and the key's MODE */
    struct render_result (*render)(const struct scene *scene, int trial, struct phases *ph,
                                   struct error *err);
};

/* One mode's render: its final relmse (the target) and its CPU seconds to it. */
struct mode_run {
    const struct photon_mode *mode; /* borrowed */
    double relmse, seconds;         /* seconds < 0: the render failed                 */
    size_t bytes_peak;              /* the render's high-water mark of our allocations,
                                       beyond the scene and reference held before it  */
    struct phases phases;           /* where its seconds went                          */
};

/* Renders with run->mode, timed, and measures the image against reference (its window). */
static void run_mode(const struct scene *scene, const struct image *reference, int trial,
                     const char *name, struct mode_run *run)
{
    fprintf(stderr, "bench: tte: %s: rendering --mode %s\n", name, run->mode->name);
    struct error err;
    alloc_restart_peak();
    size_t before = alloc_bytes_now();
    double start = bench_seconds();
    run->phases.n = 0;
    struct render_result result = run->mode->render(scene, trial, &run->phases, &err);
    run->seconds = bench_seconds() - start;
    run->bytes_peak = alloc_bytes_peak() - before;
    if (result.image == NULL) {
        fprintf(stderr, "bench: tte.%s.%s failed: ", run->mode->name, name);
        error_print(&err);
        run->seconds = -1;
        return;
    }
    run->relmse = image_compare(result.image, reference).relmse;
    fprintf(stderr, "bench: tte: %s: --mode %s: relmse %g in %.1f s\n", name, run->mode->name,
            run->relmse, run->seconds);
    render_result_free(&result);
}

/* pt's relmse = a / t + c, t in seconds, for past its last checkpoint, c the floor (< 0:
 * unknown, fitted too). The law holds in samples a pixel, but CPU seconds per sample are
 * not steady (on a shared machine the first checkpoints' samples can cost a fifth more
 * than the later ones'), and a fit in seconds takes that wander for the curve's bend. So
 * the fit is in samples, and a is turned into seconds at the pace of the last checkpoint,
 * the pace pt would go on at. */
static struct tte_fit pt_fit(const struct curve *pt, double floor)
{
    struct tte_fit fit = floor >= 0 ? tte_fit_rows_above(pt->work, pt->relmse, pt->n, floor)
                                    : tte_fit_rows(pt->work, pt->relmse, pt->n);
    fit.a *= pt->seconds[pt->n - 1] / pt->work[pt->n - 1];
    return fit;
}

/* The reference's own expected relmse against the truth, from its variance image (the
 * variance of each pixel's mean, per channel): the mean of var / (b^2 + 1e-2), the
 * relmse's own terms (image/compare.h). window: the rendered window of the reference. -1
 * (a note on stderr) when the reference has no variance image (2009 writes none) or it
 * cannot be read: the floor is then fitted. */
static double reference_floor(const char *variance_path, const struct image *window,
                              const struct render_settings *rs)
{
    if (variance_path == NULL) {
        fprintf(stderr, "bench: tte: the reference has no variance image; its noise floor is "
                        "fitted\n");
        return -1;
    }
    struct error err;
    struct image *variance = pfm_read(variance_path, &err);
    if (variance == NULL) {
        fprintf(stderr, "bench: tte: no noise floor from the reference's variance, fitted: ");
        error_print(&err);
        return -1;
    }
    double sum = 0;
    for (int y = rs->y0; y < rs->y1; y++)
        for (int x = rs->x0; x < rs->x1; x++)
            for (int c = 0; c < 3; c++) {
                double b = vec3_get(image_get(window, x - rs->x0, y - rs->y0), c);
                sum += vec3_get(image_get(variance, x, y), c) / (b * b + 1e-2);
            }
    image_free(variance);
    return sum / (3.0 * (double)(rs->x1 - rs->x0) * (double)(rs->y1 - rs->y0));
}

/* pt's curve on scene for PT_TIME_FACTOR times the longest of the modes' seconds. */
static void run_pt(const struct scene *scene, const struct mode_run *runs, int n_runs,
                   int trial, const char *name, double floor, struct curve *pt)
{
    double longest = 0;
    for (int i = 0; i < n_runs; i++)
        longest = fmax(longest, runs[i].seconds);
    struct render_settings rs = settings_at(scene, MAX_SPP, trial);
    rs.time_limit = PT_TIME_FACTOR * longest;
    fprintf(stderr, "bench: tte: %s: rendering --mode pt for %.1f s\n", name, rs.time_limit);
    struct checkpoint at = {record, pt};
    struct render_counters counters = {0};
    struct render_result result = render_pt(scene, &rs, 0, &at, &counters);
    render_result_free(&result);
    fprintf(stderr, "bench: tte: %s: --mode pt: relmse %g after %d samples, %.1f s\n", name,
            pt->relmse[pt->n - 1], counters.passes, pt->seconds[pt->n - 1]);
    pt->fit = pt_fit(pt, floor);
    if (!pt->fit.fitted)
        fprintf(stderr, "bench: tte: %s: pt's checkpoints fit no a / t + c with a > 0; "
                        "past them, relmse ~ 1 / time from the last\n", name);
    printf("tte.pt.%s.seconds=%.3f\n", name, pt->seconds[pt->n - 1]);
    printf("tte.pt.%s.relmse=%.6g\n", name, pt->relmse[pt->n - 1]);
    printf("tte.pt.%s.fit_a=%.6g\n", name, pt->fit.a);
    printf("tte.pt.%s.fit_c=%.6g\n", name, pt->fit.c);
    printf("tte.pt.%s.fitted=%d\n", name, pt->fit.fitted);
}

/* pt's seconds to relmse target, and how they were found: "0" read off its checkpoints,
 * "1" past the last by the fit, "unreachable" when the fit never gets there. Past the last
 * checkpoint they are at least its seconds, since pt had not reached target by then; that
 * lower bound is what an unreachable target gets. */
static double pt_time_to(const struct curve *pt, double target, const char **extrapolated)
{
    double seconds = time_to(pt, target);
    *extrapolated = "0";
    if (seconds < 0) {
        double beyond = tte_fit_time_to(&pt->fit, target), last = pt->seconds[pt->n - 1];
        *extrapolated = isinf(beyond) ? "unreachable" : "1";
        seconds = isinf(beyond) ? last : fmax(last, beyond);
    }
    return seconds;
}

/* The mode's figures against pt's curve. */
static void print_figures(const struct mode_run *run, const struct curve *pt, const char *name)
{
    const char *mode = run->mode->name;
    const char *extrapolated;
    double pt_seconds = pt_time_to(pt, run->relmse, &extrapolated);
    printf("tte.%s.%s.relmse=%.6g\n", mode, name, run->relmse);
    printf("tte.%s.%s.seconds=%.3f\n", mode, name, run->seconds);
    printf("tte.%s.%s.pt_seconds=%.3f\n", mode, name, pt_seconds);
    printf("tte.%s.%s.extrapolated=%s\n", mode, name, extrapolated);
    printf("tte.%s.%s.ratio=%.4g\n", mode, name, pt_seconds / run->seconds);
    printf("tte.%s.%s.pt_relmse_equal_time=%.6g\n", mode, name, error_at(pt, run->seconds));
    printf("tte.%s.%s.bytes_peak=%zu\n", mode, name, run->bytes_peak);
    for (int i = 0; i < run->phases.n; i++)
        printf("tte.%s.%s.%s=%.3f\n", mode, name, run->phases.name[i], run->phases.seconds[i]);
}

/* A scene, its reference and the photon modes measured on it. */
struct tte_case {
    const char *name, *scene_path, *reference_path;
    const char *variance_path; /* its variance image, the noise floor (NULL: none)   */
    const struct photon_mode *modes; /* borrowed: n_modes of them */
    int n_modes;                     /* 1..N_PHOTON_MODES */
};

/* Loads the case's reference and scene; NULL, with a note on stderr, when either cannot be
 * read or they differ in size. */
static struct scene *load_case(const struct tte_case *tc, struct image **reference)
{
    struct error err;
    *reference = pfm_read(tc->reference_path, &err);
    if (*reference == NULL) {
        fprintf(stderr, "bench: tte: %s skipped: ", tc->name);
        error_print(&err);
        return NULL;
    }
    struct scene *scene = bench_scene(tc->scene_path); /* which prints why it failed */
    if (scene == NULL)
        fprintf(stderr, "bench: tte: %s skipped: its scene\n", tc->name);
    else if (scene->width != (*reference)->width || scene->height != (*reference)->height) {
        fprintf(stderr, "bench: tte: %s skipped: %s is %d x %d, the scene %d x %d\n",
                tc->name, tc->reference_path, (*reference)->width, (*reference)->height,
                scene->width, scene->height);
        scene_free(scene);
        scene = NULL;
    }
    if (scene == NULL) {
        image_free(*reference);
        *reference = NULL;
    }
    return scene;
}

static void time_to_error_on(const struct tte_case *tc, int trial)
{
    struct image *whole = NULL;
    struct scene *scene = load_case(tc, &whole);
    if (scene == NULL)
        return;
    struct render_settings window = settings_at(scene, 1, trial);
    struct image *reference = window_of(whole, &window);
    struct mode_run runs[N_PHOTON_MODES];
    int n_runs = 0;
    for (int m = 0; m < tc->n_modes; m++) {
        runs[n_runs].mode = &tc->modes[m];
        run_mode(scene, reference, trial, tc->name, &runs[n_runs]);
        n_runs += runs[n_runs].seconds >= 0;
    }
    if (n_runs > 0) {
        struct curve pt = {reference, {0}, {0}, {0}, 0, {0, 0, 0}};
        run_pt(scene, runs, n_runs, trial, tc->name,
               reference_floor(tc->variance_path, reference, &window), &pt);
        for (int i = 0; i < n_runs; i++)
            print_figures(&runs[i], &pt, tc->name);
    }
    fflush(stdout);
    image_free(reference);
    image_free(whole);
    scene_free(scene);
}

void bench_tte(void)
{
    static const struct photon_mode modes[N_PHOTON_MODES] = {
        {"1994", render_1994}, {"1996", render_1996}, {"2008", render_2008},
        {"2009", render_2009}};
    static const struct tte_case cases[] = {
        {"cornell", "scenes/cornell.scene", "reference/cornell-pt.pfm",
         "reference/cornell-pt-var.pfm", modes, 4},
        {"cornell-specular", "scenes/cornell-specular.scene",
         "reference/cornell-specular-pt.pfm", "reference/cornell-specular-pt-var.pfm", modes,
         4},
        {"cornell-glossy", "scenes/cornell-glossy.scene", "reference/cornell-glossy-pt.pfm",
         "reference/cornell-glossy-pt-var.pfm", modes + 2, 2},
        {"ppm-box", "scenes/ppm-box.scene", "reference/ppm-box.pfm", "reference/ppm-box-var.pfm",
         modes + 2, 2},
        {"defocused-caustic", "scenes/defocused-caustic.scene",
         "reference/defocused-caustic-2009.pfm", NULL, modes + 2, 2}};
    const char *trial_text = getenv("PHOTON_TTE_TRIAL");
    int trial = trial_text != NULL && trial_text[0] != '\0';
    if (trial)
        fprintf(stderr, "bench: tte: PHOTON_TTE_TRIAL: a trial run, its figures mean nothing\n");
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        time_to_error_on(&cases[i], trial);
}
