/*
 * app/option_values.c -- reading the values that follow an option's name: numbers, the
 * seed, -o's file name, the mode's name, --irradiance-store's word (option_values.h);
 * and the defaults each mode gives the options left unset.
 */
#include "option_values.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../base/number.h"
#include "../modes/jensen1994.h"
#include "../modes/jensen1996.h"
#include "../modes/photons.h"
#include "../modes/sppm2009.h"

const char *mode_name(enum mode mode)
{
    switch (mode) {
    case MODE_DIRECT:
        return "direct";
    case MODE_PT:
        return "pt";
    case MODE_PHOTONS:
        return "photons";
    case MODE_JENSEN1994:
        return "1994";
    case MODE_JENSEN1996:
        return "1996";
    case MODE_PPM2008:
        return "2008";
    case MODE_SPPM2009:
        return "2009";
    }
    return "?";
}

const enum mode every_mode[] = {MODE_DIRECT, MODE_PT, MODE_PHOTONS, MODE_JENSEN1994,
                                MODE_JENSEN1996, MODE_PPM2008, MODE_SPPM2009};

/* An array of -1 chars, which does not compile, unless N_EVERY_MODE counts the list. */
typedef char every_mode_count_is_right[sizeof every_mode / sizeof every_mode[0] ==
                                       N_EVERY_MODE ? 1 : -1];

void number_range(enum number_kind kind, double min, double max, char *text, size_t size)
{
    if (kind == NUMBER_WHOLE)
        snprintf(text, size, "a whole number from %.0f to %.0f", min, max);
    else if (kind == NUMBER_REAL)
        snprintf(text, size, "a number from %g to %g", min, max);
    else if (kind == NUMBER_ABOVE)
        snprintf(text, size, "a number above %g, at most %g", min, max);
    else
        snprintf(text, size, "a number strictly between %g and %g", min, max);
}

int read_number(const char *name, const char *text, double min, double max,
                enum number_kind kind, double *value, struct error *err)
{
    int ok = number_parse(text, kind == NUMBER_WHOLE, value) && *value <= max &&
             (kind == NUMBER_WHOLE || kind == NUMBER_REAL ? *value >= min : *value > min) &&
             (kind != NUMBER_BETWEEN || *value < max);
    if (!ok) {
        char range[96];
        number_range(kind, min, max, range, sizeof range);
        return error_set(err, "", 0, "%s: expected %s, got '%s'", name, range,
                         text != NULL ? text : "nothing");
    }
    return 0;
}

int read_seed(const char *text, uint64_t *seed, struct error *err)
{
    char *end = NULL;
    if (text != NULL && text[0] >= '0' && text[0] <= '9') {
        errno = 0;
        unsigned long long v = strtoull(text, &end, 10);
        if (*end == '\0' && errno == 0 && v <= UINT64_MAX) {
            *seed = (uint64_t)v;
            return 0;
        }
    }
    return error_set(err, "", 0, "--seed: expected a whole number from 0 to 2^64-1, got '%s'",
                     text != NULL ? text : "nothing");
}

int read_store(const char *text, int *illumination, struct error *err)
{
    if (text != NULL && (strcmp(text, "photon") == 0 || strcmp(text, "illumination") == 0)) {
        *illumination = strcmp(text, "illumination") == 0;
        return 0;
    }
    return error_set(err, "", 0, "--irradiance-store: expected photon or illumination, got '%s'",
                     text != NULL ? text : "nothing");
}

int read_output(const char *text, char *output, enum display_format *display,
                struct error *err)
{
    size_t n = text != NULL ? strlen(text) : 0;
    const char *ending = n >= 5 ? text + n - 4 : ""; /* NAME is not empty */
    int ppm = strcmp(ending, display_suffix(DISPLAY_PPM)) == 0;
    int exr = strcmp(ending, ".exr") == 0;
    if (!ppm && !exr && strcmp(ending, ".pfm") != 0 &&
        strcmp(ending, display_suffix(DISPLAY_PNG)) != 0)
        return error_set(err, "", 0, "-o: expected a file name ending in .pfm, .exr, .png or "
                         ".ppm, got '%s'", text != NULL ? text : "nothing");
    if (n >= OUTPUT_PATH_MAX)
        return error_set(err, "", 0, "-o: the file name is too long");
    *display = ppm ? DISPLAY_PPM : DISPLAY_PNG;
    /* The floats are always written: to FILE.exr when named so (OpenEXR), else FILE.pfm. */
    sprintf(output, "%.*s%s", (int)(n - 4), text, exr ? ".exr" : ".pfm");
    return 0;
}

/* The default output: the scene file's name without directory and extension, + ".pfm". */
void default_output(const char *scene_path, char *output)
{
    const char *base = strrchr(scene_path, '/');
    base = base != NULL ? base + 1 : scene_path;
    const char *dot = strrchr(base, '.');
    int n = dot != NULL && dot != base ? (int)(dot - base) : (int)strlen(base);
    if (n > OUTPUT_PATH_MAX - 5)
        n = OUTPUT_PATH_MAX - 5;
    sprintf(output, "%.*s.pfm", n, base);
}

void option_defaults(struct options *o)
{
    memset(o, 0, sizeof *o);
    o->mode = MODE_PT;
    o->quality = QUALITY_DEFAULT;
    o->seed = 1;
    o->spp = 0;
    o->max_depth = -1;
    o->progress = -1;
    o->exposure = 1.0;
    o->confidence = 0.95;
    o->display = DISPLAY_PNG;
    o->photons = 0; /* the mode's default, set after parsing */
    o->gather = 0; /* the mode's default, set after parsing */
    o->passes = 0;           /* the mode's default, set after parsing */
    o->photons_per_pass = 0; /* the mode's default, set after parsing */
    o->alpha = PPM_DEFAULT_ALPHA;
    struct ppm_settings pp = ppm_settings_default();
    o->footprints = pp.progressive.footprints;
    o->fit_radius = pp.progressive.fit_radius;
    o->caustic_footprints = pp.caustic_footprints;
    o->merge_hit_points = pp.merge_hit_points;
    o->resample_emission = pp.resample_emission;
    o->facing_test = pp.progressive.facing_test;
    o->turn_photon_directions = pp.progressive.turn_photon_directions;
    o->follow_glossy_lobes = sppm_settings_default().follow_glossy_lobes;
    o->direct_light_samples = pp.progressive.direct_light_samples;
    o->cone = -1;
    o->caustic_radius_fraction = CAUSTIC_RADIUS_FRACTION;
    struct jensen1996_settings js = jensen1996_settings_default();
    o->max_radius = js.max_radius; /* -1: the default */
    o->caustic_photons = (int)js.caustic_photons;
    o->caustic_gather = (int)js.caustic_gather;
    o->gather_rays = js.gather_rays;
    o->glossy_rays = js.glossy_rays;
    o->cache_accuracy = js.cache_accuracy;
    o->accurate_distance = js.accurate_distance;
    o->accurate_weight = js.accurate_weight;
    o->exclude_rim = js.exclude_rim;
    o->shadow_rays = js.shadow_rays;
    o->precomputed_irradiance = js.precomputed_irradiance;
    o->disc_coverage = js.disc_coverage;
    o->both_lobes = js.both_lobes;
    o->glossy_corner = js.glossy_corner;
    o->corner_photons = js.corner_photons;
    o->bounded_reach = js.bounded_reach;
    o->gradient_limit = js.gradient_limit;
    struct jensen1994_settings j94 = jensen1994_settings_default();
    o->differential_run = j94.differential_run;
    o->light_samples = j94.light_samples;
    o->projection_maps = j94.projection_maps;
    o->glossy_photons = j94.glossy_photons;
    o->lobe_lights = j94.lobe_lights;
}

void mode_defaults(struct options *o)
{
    if (o->cone < 0)
        o->cone = o->mode == MODE_JENSEN1996 ? 1.0 : 0.0;
    if (o->photons == 0)
        o->photons = o->mode == MODE_JENSEN1996   ? J96_DEFAULT_PHOTONS
                     : o->mode == MODE_JENSEN1994 ? J94_DEFAULT_PHOTONS
                                                  : PHOTONS_DEFAULT_N;
    if (o->gather == 0)
        o->gather = o->mode == MODE_JENSEN1994   ? J94_DEFAULT_GATHER
                    : o->mode == MODE_JENSEN1996 ? J96_DEFAULT_GATHER
                                                 : PHOTONS_DEFAULT_GATHER;
    if (o->passes == 0) /* with a target error the target ends the render */
        o->passes = o->target_error > 0 && (o->mode == MODE_PPM2008 ||
                                            o->mode == MODE_SPPM2009) ? MAX_SPP
                    : o->mode != MODE_SPPM2009                        ? PPM_DEFAULT_PASSES
                                                                      : SPPM_DEFAULT_PASSES;
    if (o->photons_per_pass == 0)
        o->photons_per_pass = o->mode == MODE_SPPM2009 ? SPPM_DEFAULT_PHOTONS_PER_PASS
                                                       : PPM_DEFAULT_PHOTONS_PER_PASS;
    if (o->mode == MODE_SPPM2009)
        o->spp = o->passes; /* one eye path a pixel each pass (its camera samples) */
    if (o->spp == 0)
        o->spp = o->mode == MODE_PPM2008     ? PPM_DEFAULT_SPP
                 : o->mode == MODE_JENSEN1996 ? J96_DEFAULT_SPP
                 : o->mode == MODE_JENSEN1994 ? J94_DEFAULT_SPP
                                              : DEFAULT_SPP;
}
