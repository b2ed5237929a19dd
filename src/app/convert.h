/*
 * app/convert.h -- `photon convert`: an image file as a picture to look at, by exposure
 * (as a render's display image) or in false colour with its scale (image/false_colour.h).
 */
#ifndef PHOTON_CONVERT_H
#define PHOTON_CONVERT_H

#include "../base/option_equals.h"

/* `photon convert IN.pfm -o OUT.png|.ppm [--exposure E | --false-colour [--min V]
 * [--max V] [--log]]`: argv[0] is "convert". Returns the exit status: 0, 2 for bad input
 * (messages on stderr), 1 when the output could not be written. */
int convert_command(int argc, char **argv);

/* Its options, for --NAME=VALUE (app/commands.h); a NULL name ends them. */
extern const struct option_arity convert_options[];

#endif
