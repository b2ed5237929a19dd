/*
 * modes/sppm2009.h -- `--mode 2009`: stochastic progressive photon mapping (Hachisuka and
 * Jensen 2009).
 */
#ifndef PHOTON_SPPM2009_H
#define PHOTON_SPPM2009_H

#include "ppm2008.h"

#define SPPM_DEFAULT_PASSES 256 /* one eye path a pixel each */
/* The 2008 paper's photons a pass: an eye pass costs about as much as 50,000 photons, so
 * fewer, fuller passes reach an error sooner (src/modes/measured.md). */
#define SPPM_DEFAULT_PHOTONS_PER_PASS 100000

/* 2009's settings: what both progressive modes read, and the switch of 2009's own
 * departure. */
struct sppm_settings {
    struct progressive_settings progressive;
    int disc_coverage; /* 1: each pixel's estimate over the part of its discs a surface
                          covers, R0 fitted only to walls the surface goes on past
                          (sppm2009.c)                                                 */
    int follow_glossy_lobes; /* 1: eye paths follow glossy lobes by sampling them, the hit
                                point at a diffuse part; 0: the paper's, the hit point at
                                the first non-specular surface with its whole BRDF       */
};

/* 2009's defaults: 2008's common settings with SPPM_DEFAULT_PASSES passes of
 * SPPM_DEFAULT_PHOTONS_PER_PASS photons, the disc coverage on and glossy lobes followed. */
struct sppm_settings sppm_settings_default(void);

/* Renders the window of rs: the passes of ps->progressive (fewer when rs->time_limit
 * passes first, or, with rs->target_error, the target is reached), each one eye path
 * through every pixel and a photon tracing pass, calling its report and snapshot as 2008
 * does. stats->hit_points is the last pass's (with an error image, those of the pixels
 * kept beyond the window too); result.variance is NULL; with rs->error_confidence (and
 * ps->progressive.passes >= ERROR_MIN_SPP), result.error, .bias and .block_noise are the
 * error image and what it states of blocks (sppm_error.h). */
struct render_result render_sppm(const struct scene *scene, const struct render_settings *rs,
                                 const struct sppm_settings *ps,
                                 struct render_counters *counters, struct ppm_stats *stats);

#endif
