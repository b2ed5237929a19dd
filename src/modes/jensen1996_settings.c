/*
 * modes/jensen1996_settings.c -- the defaults of `--mode 1996`'s settings
 * (jensen1996_settings.h).
 */
#include "jensen1996_settings.h"

#include "photons.h"

struct jensen1996_settings jensen1996_settings_default(void)
{
    struct jensen1996_settings js;
    js.global_photons = J96_DEFAULT_PHOTONS;
    js.caustic_photons = J96_DEFAULT_CAUSTIC_PHOTONS;
    js.global_gather = J96_DEFAULT_GATHER;
    js.caustic_gather = J96_DEFAULT_CAUSTIC_GATHER;
    js.max_radius = -1; /* the default */
    js.caustic_radius_fraction = CAUSTIC_RADIUS_FRACTION;
    js.cone_k = 1.0;
    js.exclude_rim = 1;
    js.gather_rays = J96_DEFAULT_GATHER_RAYS;
    js.glossy_rays = J96_DEFAULT_GLOSSY_RAYS;
    js.cache_accuracy = J96_DEFAULT_CACHE_ACCURACY;
    js.accurate_distance = J96_DEFAULT_ACCURATE_DISTANCE;
    js.accurate_weight = J96_DEFAULT_ACCURATE_WEIGHT;
    js.shadow_rays = 1;
    js.one_map = 0;
    js.precomputed_irradiance = J96_DEFAULT_PRECOMPUTED;
    js.both_lobes = 1;
    js.glossy_corner = 1;
    js.corner_photons = 1;
    js.bounded_reach = 1;
    js.gradient_limit = 1;
    js.disc_coverage = 1;
    js.report = NULL;
    js.work = NULL;
    return js;
}
