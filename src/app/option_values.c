/*
 * app/option_values.c -- reading the values that follow an option's name: numbers, the
 * seed, -o's file name, --irradiance-store's word (options.h, option_values.h); and
 * the defaults each mode gives the options left unset.
 */
#include "option_values.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../modes/jensen1994.h"
#include "../modes/jensen1996.h"
#include "../modes/photons.h"
#include "../modes/sppm2009.h"

int read_number(const char *name, const char *text, double min, double max, int integer,
                double *value, struct error *err)
{
    char *end = NULL;
    *value = text != NULL ? strtod(text, &end) : 0;
    int ok = text != NULL && end != text && *end == '\0' && *value >= min && *value <= max &&
             (!integer || *value == floor(*value));
    if (!ok)
        return error_set(err, "", 0, "%s: expected %s from %g to %g, got '%s'", name,
                         integer ? "a whole number" : "a number", min, max,
                         text != NULL ? text : "nothing");
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
    if (!ppm && strcmp(ending, ".pfm") != 0 && strcmp(ending, display_suffix(DISPLAY_PNG)) != 0)
        return error_set(err, "", 0, "-o: expected a file name ending in .pfm, .png or .ppm, "
                         "got '%s'", text != NULL ? text : "nothing");
    if (n >= OUTPUT_PATH_MAX)
        return error_set(err, "", 0, "-o: the file name is too long");
    *display = ppm ? DISPLAY_PPM : DISPLAY_PNG;
    sprintf(output, "%.*s.pfm", (int)(n - 4), text); /* the PFM is always written */
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
    if (o->passes == 0)
        o->passes = o->mode == MODE_SPPM2009 ? SPPM_DEFAULT_PASSES : PPM_DEFAULT_PASSES;
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
