/*
 * modes/progressive.h -- what progressive photon mapping (`--mode 2008`, Hachisuka, Ogaki
 * and Jensen 2008) and its stochastic form (`--mode 2009`, Hachisuka and Jensen 2009)
 * share: the settings both read, the photon tracing pass and the loop of passes with its
 * checkpoints and progress line. Each mode hands the loop its own steps of a pass.
 */
#ifndef PHOTON_PROGRESSIVE_H
#define PHOTON_PROGRESSIVE_H

#include <stddef.h>

#include "../base/vec3.h"
#include "render.h"

#define MAX_PASSES 100000000 /* documented limit on --passes */

struct photon_event;

/* The settings both progressive modes read. */
struct progressive_settings {
    size_t photons_per_pass;          /* photons traced in each pass, 1..MAX_PHOTONS     */
    long passes;                      /* the most passes, 1..MAX_PASSES                  */
    double alpha;                     /* 2008's Eq. 7: fraction of new photons kept, (0, 1) */
    double radius;                    /* > 0: R0 in scene units; <= 0: footprints pixel
                                         footprints at the hit point (ppm_radius.c)      */
    double footprints;                /* R0 in pixel footprints, > 0                     */
    int fit_radius;                   /* 1: R0 shortened until the disc lies on the
                                         surface (ppm_radius.c)                          */
    int facing_test;                  /* 1: a photon counts only at hit points whose
                                         surface faces its own (2008; 2009's disc
                                         coverage makes its own test)                    */
    int turn_photon_directions;       /* 1: f_r sees a photon's direction turned with its
                                         surface onto the hit point's (hit_points.h)     */
    int direct_light_samples;         /* 1: the direct light by a light sample at each
                                         pass's hit points, photons only after their
                                         first bounce (a departure); 0: from photons
                                         too, the papers' way                           */
    const struct checkpoint *report;  /* borrowed or NULL: gets the image after passes 1,
                                         2, 4, ... and the last, work = photons emitted  */
    long snapshot_every;              /* > 0: call snapshot after every this many passes */
    const struct checkpoint *snapshot; /* borrowed or NULL: gets the image so far         */
};

/* What a progressive render did, for --stats. */
struct ppm_stats {
    size_t hit_points;               /* 2008: stored by the ray tracing pass; 2009: the
                                        last pass's                                     */
    size_t bytes_per_hit_point;      /* a hit point and what goes with it               */
    size_t hit_members;              /* 2008: eye rays merged hit points keep for their
                                        caustic estimates (struct hit_member each)      */
    long passes;                     /* passes done                                      */
    size_t photons_emitted;          /* N_emitted of 2008's Eq. 13                      */
    double seconds_ray_pass;         /* CPU seconds of the eye rays that make hit points */
    double seconds_photons;          /* CPU seconds of the rest of the passes            */
    double mean_radius;              /* mean R at the end                                */
    double initial_mean_radius;      /* mean R0                                          */
    unsigned long long photon_rays;  /* rays cast tracing photons                        */
};

/* A mode's steps of pass `pass` (from 0), in the order progressive_passes() calls them,
 * and what the loop asks of its state; mode is handed to each. */
struct progressive_steps {
    void *mode;
    /* before the pass's photons (2009: the distributed ray tracing pass), or NULL */
    void (*before_photons)(void *mode, long pass);
    /* a photon the tracer stored: adds it to the hit points whose discs hold it */
    void (*add_photon)(void *mode, const struct photon_event *photon);
    /* after the pass's photons (2008: the new eye ray a pixel), or NULL */
    void (*after_photons)(void *mode, long pass);
    /* the progressive update that ends the pass */
    void (*update)(void *mode, long pass);
    /* the image so far, photons_emitted photons in all */
    void (*evaluate)(const void *mode, double photons_emitted, struct image *image);
    /* the mean radius, for the progress line */
    double (*mean_radius)(const void *mode);
    /* with rs->target_error (2008, 2009), or NULL: judges the image so far, photons_emitted
     * photons in all, against the target (target_tally()), after the passes
     * target_judged_after() names and after the last; whether every block is within it */
    int (*target_reached)(void *mode, double photons_emitted);
    const struct render_counters *tally; /* with target_reached: the counters it tallies
                                            into, which the progress line shows         */
};

/* What progressive_passes() did. */
struct progressive_run {
    long passes;            /* passes done                                  */
    size_t photons_emitted; /* in all                                       */
    double seconds;         /* CPU seconds of the passes, checkpoints excluded */
};

/* Passes until ps->passes are done, rs->time_limit has passed (no pass starts after
 * it; the first always runs, and with rs->error_confidence the first ERROR_MIN_SPP, which
 * an error image needs) or steps->target_reached says so, then evaluates image. Checkpoints and the time limit count
 * seconds from `offset`, the CPU seconds spent before the first pass; checkpoint time is
 * excluded. Adds the photon tracer's rays to *photon_rays. */
struct progressive_run progressive_passes(const struct progressive_steps *steps,
                                          const struct scene *scene,
                                          const struct render_settings *rs,
                                          const struct progressive_settings *ps, double offset,
                                          struct image *image,
                                          unsigned long long *photon_rays);

#endif
