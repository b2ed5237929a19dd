/*
 * modes/progressive.c -- the loop of passes that 2008 and 2009 share.
 *
 * Both papers' renders are passes repeated until the image is good enough, each ending
 * in the progressive update (2008's Eq. 7, 9 and 12); the image exists at any pass
 * (Eq. 13). A pass here is the mode's step before its photons (2009's distributed ray
 * tracing pass), its photon tracing pass, the mode's step after the photons (2008's new
 * eye ray a pixel) and the update; between passes come the checkpoints and the progress
 * line, whose time is not counted.
 *
 * With a target error (--target-error) the mode judges its image after the passes
 * target_judged_after() names, pt's schedule, and the loop ends once it is reached; with
 * an error image no time limit ends it before ERROR_MIN_SPP passes, which the image needs.
 *
 * The photon tracing pass is the same in both modes: ps->photons_per_pass photons with
 * the shared tracer, the stored photons handed to the mode in the order of where they
 * lie (photon/ordered_sink.h: the hit points a photon reads are then in the cache from
 * the photon before), all of them before the pass ends; photon i of pass p draws from
 * rng_stream(seed, STREAM_PHOTON, p, i), so a pass's photons depend on nothing but the
 * seed and p.
 */
#include "progressive.h"

#include <stdio.h>
#include <string.h>
#include <time.h>

#include "../base/progress.h"
#include "../photon/ordered_sink.h"
#include "../photon/trace.h"
#include "pixel_error.h"

/* The photons that reach hit points when a light sample takes the direct light: those
 * after a diffuse bounce, and caustics (L S+ D), which no shadow ray sees the light by. */
#define PHOTON_AFTER_FIRST_BOUNCE (PHOTON_CAUSTIC | PHOTON_INDIRECT)

/* Where the ordered photons go: the mode adds each to its hit points; the tracer goes
 * on. */
static int hand_to_mode(void *context, const struct photon_event *photon)
{
    const struct progressive_steps *steps = context;
    steps->add_photon(steps->mode, photon);
    return 0;
}

/* Photon tracing pass `pass`: with ps->direct_light_samples the photons after their first
 * bounce (the light samples bring the first), else every photon, the papers' way, into
 * in_order, which hands them all on before the pass ends. Returns the photons emitted. */
static size_t photon_tracing_pass(struct ordered_sink *in_order, const struct scene *scene,
                                  const struct render_settings *rs,
                                  const struct progressive_settings *ps, long pass,
                                  unsigned long long *photon_rays)
{
    struct trace_settings ts;
    memset(&ts, 0, sizeof ts);
    ts.seed = rs->seed;
    ts.pass = (uint64_t)pass;
    ts.n_emit = ps->photons_per_pass; /* max_stored: unused, nothing is stored */
    ts.store = ps->direct_light_samples ? PHOTON_AFTER_FIRST_BOUNCE : PHOTON_MAP_GLOBAL;
    ts.max_depth = rs->max_depth;
    ts.targets = NULL;
    ts.projection = NULL;
    struct photon_sink sink = ordered_sink_of(in_order);
    trace_photons_into(scene, &ts, &sink, photon_rays); /* the sinks never stop it */
    ordered_sink_flush(in_order);
    return ts.n_emit;
}

/* The progress line's words (base/progress.h adds the time); with a target error, the
 * blocks within it at the last judgement (none before ERROR_MIN_SPP passes), and no
 * forecast, since the passes it takes are not known. */
static void show_progress(const struct progressive_steps *steps,
                          const struct render_settings *rs, struct progress *line, long pass,
                          long passes, double photons)
{
    double mean_radius = steps->mean_radius(steps->mode);
    if (steps->target_reached != NULL)
        progress_print(line, "pass %ld, %d of %d blocks within %g, %.3g photons, mean "
                       "radius %.3g", pass, steps->tally->target_within,
                       steps->tally->target_blocks, rs->target_error, photons, mean_radius);
    else
        progress_print(line, "pass %ld/%ld, %.3g photons, mean radius %.3g", pass, passes,
                       photons, mean_radius);
}

/* Calls checkpoint with the image so far; returns the CPU seconds it took. */
static double call_checkpoint(const struct progressive_steps *steps,
                              const struct checkpoint *checkpoint, size_t photons_emitted,
                              struct image *image, double seconds)
{
    steps->evaluate(steps->mode, (double)photons_emitted, image);
    return checkpoint->at(checkpoint->context, image, (long long)photons_emitted, seconds);
}

struct progressive_run progressive_passes(const struct progressive_steps *steps,
                                          const struct scene *scene,
                                          const struct render_settings *rs,
                                          const struct progressive_settings *ps, double offset,
                                          struct image *image, unsigned long long *photon_rays)
{
    struct progressive_run run = {0, 0, 0.0};
    double limit = rs->time_limit;
    clock_t start = clock();
    double excluded = 0.0;
    struct progress line;
    struct ordered_sink in_order;
    struct photon_sink to_mode = {hand_to_mode, (void *)steps};
    ordered_sink_create(&in_order, geometry_bounds(scene->geometry), to_mode);
    progress_begin(&line, rs->progress ? stderr : NULL, "passes",
                   steps->target_reached != NULL ? 0.0 : (double)ps->passes, time(NULL));
    long first_passes = rs->error_confidence > 0 ? ERROR_MIN_SPP : 1, judged = 0;
    int reached = 0;
    while (run.passes < ps->passes && !reached &&
           !(run.passes >= first_passes && limit > 0 && offset + run.seconds >= limit)) {
        long pass = run.passes;
        if (steps->before_photons != NULL)
            steps->before_photons(steps->mode, pass);
        run.photons_emitted += photon_tracing_pass(&in_order, scene, rs, ps, pass, photon_rays);
        if (steps->after_photons != NULL)
            steps->after_photons(steps->mode, pass);
        steps->update(steps->mode, pass);
        run.passes++;
        if (steps->target_reached != NULL && target_judged_after(run.passes)) {
            reached = steps->target_reached(steps->mode, (double)run.photons_emitted);
            judged = run.passes;
        }
        run.seconds = cpu_seconds(start) - excluded;
        double at = offset + run.seconds;
        int last = run.passes == ps->passes || reached ||
                   (run.passes >= first_passes && limit > 0 && at >= limit);
        if (ps->report != NULL && (is_power_of_two(run.passes) || last))
            excluded += call_checkpoint(steps, ps->report, run.photons_emitted, image, at);
        if (ps->snapshot != NULL && ps->snapshot_every > 0 &&
            run.passes % ps->snapshot_every == 0)
            excluded += call_checkpoint(steps, ps->snapshot, run.photons_emitted, image, at);
        if (progress_update(&line, (double)run.passes, time(NULL)))
            show_progress(steps, rs, &line, run.passes, ps->passes, (double)run.photons_emitted);
    }
    if (steps->target_reached != NULL && judged != run.passes)
        steps->target_reached(steps->mode, (double)run.photons_emitted); /* the last tally */
    if (progress_end(&line, (double)run.passes, time(NULL)))
        show_progress(steps, rs, &line, run.passes, ps->passes, (double)run.photons_emitted);
    steps->evaluate(steps->mode, (double)run.photons_emitted, image);
    ordered_sink_free(&in_order);
    return run;
}
