/*
 * modes/jensen1996.h -- `--mode 1996`: global illumination using photon maps (Jensen
 * 1996): a caustic map and a global map with shadow photons, then distribution ray
 * tracing that takes from the maps what each term of Eq. 2 needs. Its settings and
 * figures are in jensen1996_settings.h.
 */
#ifndef PHOTON_JENSEN1996_H
#define PHOTON_JENSEN1996_H

#include "../base/error.h"
#include "jensen1996_settings.h"
#include "render.h"

/* Renders the window of rs: pass 1 (the maps), the irradiance cache's pre-pass over the
 * whole image (or both from settings->work when it is full), then rs->spp camera samples per
 * pixel. On failure (more than MAX_PHOTONS photons would be stored, or settings->work holds
 * maps that do not fit the scene and settings) returns a result with image NULL and
 * *err filled. */
struct render_result render_jensen1996(const struct scene *scene,
                                       const struct render_settings *rs,
                                       const struct jensen1996_settings *settings,
                                       int want_variance, struct render_counters *counters,
                                       struct jensen1996_stats *stats, struct error *err);

#endif
