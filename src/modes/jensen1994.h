/*
 * modes/jensen1994.h -- `--mode 1994`: Jensen and Christensen 1994, "Photon maps in
 * bidirectional Monte Carlo ray tracing of complex objects" (jensen1994.c); its settings
 * and figures are in jensen1994_settings.h.
 */
#ifndef PHOTON_JENSEN1994_H
#define PHOTON_JENSEN1994_H

#include "../base/error.h"
#include "jensen1994_settings.h"
#include "render.h"

/* Renders the settings' window of the scene (finished) in two passes: the photon map,
 * then Monte Carlo ray tracing with an irradiance cache filled by a pre-pass over the
 * whole image (jensen1994.c), so a crop equals the same window of the whole render; the
 * map and the cache come from settings->work instead when it is full. Fails (result.image
 * NULL, *err filled) when more than MAX_PHOTONS photons would be stored, or settings->work
 * holds other than two maps, or illumination maps where settings asks for none or none where
 * it asks for them. The result's seconds include both passes and the pre-pass. */
struct render_result render_jensen1994(const struct scene *scene,
                                       const struct render_settings *rs,
                                       const struct jensen1994_settings *settings,
                                       int want_variance, struct render_counters *counters,
                                       struct jensen1994_stats *stats, struct error *err);

#endif
