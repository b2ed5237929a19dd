/*
 * modes/sppm2009.h -- `--mode 2009`: stochastic progressive photon mapping (Hachisuka and
 * Jensen 2009). Its settings are 2008's (struct ppm_settings), of which it reads
 * photons_per_pass, passes, alpha, radius, footprints, fit_radius, facing_test,
 * direct_photons, report, snapshot_every and snapshot.
 */
#ifndef PHOTON_SPPM2009_H
#define PHOTON_SPPM2009_H

#include "ppm2008.h"

#define SPPM_DEFAULT_PASSES 256             /* one eye path a pixel each                */
#define SPPM_DEFAULT_PHOTONS_PER_PASS 50000

/* Renders the window of rs: ps->passes passes (fewer when rs->time_limit passes first),
 * each one eye path through every pixel and ps->photons_per_pass photons, calling
 * ps->report and ps->snapshot as 2008 does. stats->hit_points is the last pass's;
 * result.variance is NULL. */
struct render_result render_sppm(const struct scene *scene, const struct render_settings *rs,
                                 const struct ppm_settings *ps,
                                 struct render_counters *counters, struct ppm_stats *stats);

#endif
