/*
 * app/option_values.h -- the value readers options.c uses beyond those options.h offers
 * to the subcommands (read_number(), read_seed(), read_output(), in option_values.c), and
 * the defaults that depend on the mode.
 */
#ifndef PHOTON_OPTION_VALUES_H
#define PHOTON_OPTION_VALUES_H

#include "options.h"

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
