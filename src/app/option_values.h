/*
 * app/option_values.h -- reading the values that follow an option's name (numbers, the
 * seed, -o's file name, the mode, --irradiance-store's word), for the render command's
 * options (options.c) and the subcommands' alike, and the defaults that depend on the
 * mode.
 */
#ifndef PHOTON_OPTION_VALUES_H
#define PHOTON_OPTION_VALUES_H

#include <stddef.h>
#include <stdint.h>

#include "../base/error.h"
#include "render_options.h"

/* --mode's word for mode ("direct", ..., "2009"). */
const char *mode_name(enum mode mode);

/* Every mode, in the order the help lists them: N_EVERY_MODE of them (option_values.c
 * does not compile when that is not the list's count). */
#define N_EVERY_MODE 7
extern const enum mode every_mode[];

/* What a number must be: whole in [min, max], real in [min, max], real in (min, max], or
 * real in (min, max). */
enum number_kind { NUMBER_WHOLE, NUMBER_REAL, NUMBER_ABOVE, NUMBER_BETWEEN };

/* A number from text in base/number.h's syntax and within kind's range; -1 with *err
 * naming the option (name) and the range otherwise. Also for the subcommands' options. */
int read_number(const char *name, const char *text, double min, double max,
                enum number_kind kind, double *value, struct error *err);

/* The range of kind, min and max in words ("a whole number from 1 to 1048576"), as
 * read_number()'s message and --help say it, into text[size]. */
void number_range(enum number_kind kind, double min, double max, char *text, size_t size);

/* A --seed value: a whole number from 0 to 2^64 - 1; -1 with *err filled otherwise. */
int read_seed(const char *text, uint64_t *seed, struct error *err);

/* An -o value: a file name NAME.pfm, NAME.png or NAME.ppm (NAME not empty) shorter than
 * OUTPUT_PATH_MAX. Puts NAME.pfm, the image of record always written, in
 * output[OUTPUT_PATH_MAX], and the display image beside it in *display: PPM for NAME.ppm,
 * else PNG. -1 with *err filled otherwise. Also for photon merge. */
int read_output(const char *text, char *output, enum display_format *display,
                struct error *err);

/* --irradiance-store's word: *illumination 0 for photon, 1 for illumination; -1 with *err
 * filled for any other word. */
int read_store(const char *text, int *illumination, struct error *err);

/* The default output: the scene file's name without directory and extension, + ".pfm",
 * into output[OUTPUT_PATH_MAX]. */
void default_output(const char *scene_path, char *output);

/* Every option's default before the mode is known (mode_defaults() then fills the
 * options left unset for the mode). */
void option_defaults(struct options *o);

/* The defaults that depend on --mode, for the options the command line left unset (0, or
 * -1 for --cone): photons, gather, cone, passes, photons a pass and spp. */
void mode_defaults(struct options *o);

#endif
