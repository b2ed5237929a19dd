/*
 * modes/sppm2009.h -- `--mode 2009`: stochastic progressive photon mapping (Hachisuka and
 * Jensen 2009). Its settings are 2008's (struct ppm_settings), of which it reads
 * photons_per_pass, passes, alpha, radius, footprints, fit_radius, disc_coverage,
 * facing_test, direct_photons, report, snapshot_every and snapshot.
 */
#ifndef PHOTON_SPPM2009_H
#define PHOTON_SPPM2009_H

#include "ppm2008.h"

#define SPPM_DEFAULT_PASSES 256 /* one eye path a pixel each */
/* The 2008 paper's photons a pass. On the Cornell box 128 passes of 100,000 reached relmse
 * 0.00061 in 27 CPU s, 256 of 50,000 0.00063 in 36 s: an eye pass costs about as much as
 * 50,000 photons, so fewer, fuller passes reach an error sooner. */
#define SPPM_DEFAULT_PHOTONS_PER_PASS 100000

/* 2009's defaults: ppm_settings_default() with SPPM_DEFAULT_PASSES passes of
 * SPPM_DEFAULT_PHOTONS_PER_PASS photons and the disc coverage on. */
struct ppm_settings sppm_settings_default(void);

/* Renders the window of rs: ps->passes passes (fewer when rs->time_limit passes first),
 * each one eye path through every pixel and ps->photons_per_pass photons, calling
 * ps->report and ps->snapshot as 2008 does. stats->hit_points is the last pass's;
 * result.variance is NULL. */
struct render_result render_sppm(const struct scene *scene, const struct render_settings *rs,
                                 const struct ppm_settings *ps,
                                 struct render_counters *counters, struct ppm_stats *stats);

#endif
