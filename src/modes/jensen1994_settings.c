/*
 * modes/jensen1994_settings.c -- the defaults of `--mode 1994`'s settings
 * (jensen1994_settings.h).
 */
#include "jensen1994_settings.h"

#include "../photon/estimate.h"
#include "photons.h"

struct jensen1994_settings jensen1994_settings_default(void)
{
    struct jensen1994_settings js;
    js.n_photons = J94_DEFAULT_PHOTONS;
    js.gather = J94_DEFAULT_GATHER;
    js.max_radius = -1; /* the default */
    js.differential_run = DIFFERENTIAL_RUN;
    js.exclude_rim = 1;
    js.gather_rays = J94_DEFAULT_GATHER_RAYS;
    js.cache_accuracy = J94_DEFAULT_CACHE_ACCURACY;
    js.light_samples = J94_DEFAULT_LIGHT_SAMPLES;
    js.caustic_radius_fraction = CAUSTIC_RADIUS_FRACTION;
    js.both_lobes = 1;
    js.glossy_photons = 1;
    js.lobe_lights = 1;
    js.bounded_reach = 1;
    js.gradient_limit = 1;
    js.precomputed_irradiance = J94_DEFAULT_PRECOMPUTED;
    js.projection_maps = 1;
    js.illumination_maps = 0;
    js.work = NULL;
    return js;
}
