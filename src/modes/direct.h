/*
 * modes/direct.h -- `--mode direct`: Whitted-style ray tracing.
 */
#ifndef PHOTON_DIRECT_H
#define PHOTON_DIRECT_H

#include "render.h"

/* Default --max-depth: Whitted tracing has no roulette, so the specular chain is capped. */
#define DIRECT_MAX_DEPTH 16

struct render_result render_direct(const struct scene *scene, const struct render_settings *rs,
                                   int want_variance, const struct checkpoint *checkpoint,
                                   struct render_counters *counters);

#endif
