/*
 * modes/direct.h -- `--mode direct`: Whitted-style ray tracing.
 */
#ifndef PHOTON_DIRECT_H
#define PHOTON_DIRECT_H

#include "render.h"

struct image *render_direct(const struct scene *scene, const struct render_settings *rs,
                            struct render_counters *counters);

#endif
