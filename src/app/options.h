/*
 * app/options.h -- the render command's options: `photon [options] SCENE`, read into
 * struct options (render_options.h).
 *
 * One table (option_table.c) lists every option with its limits, default and help text;
 * --help all prints that table, so the help and the parser cannot disagree.
 */
#ifndef PHOTON_OPTIONS_H
#define PHOTON_OPTIONS_H

#include <stdint.h>

#include "../base/error.h"
#include "render_options.h"

#define PHOTON_VERSION "0.1.0"

/* Parses argv into *o: the defaults, then the words of the preset that --quality names for
 * --mode's mode (app/presets.h), then argv's words, so an option given in argv wins
 * wherever it stands. Returns 0 to render, 1 when --help or --version was printed
 * (exit 0), -1 with *err filled for bad options (exit 2), among them an option that
 * means nothing for the mode ("--passes: only for --mode 2008 ...") and one given that
 * does nothing with the others ("--footprints: does nothing with --radius, ...":
 * app/option_checks.h). */
int parse_options(int argc, char **argv, struct options *o, struct error *err);

/* h folded with this program's version and every option of o that changes pixels, each as
 * "name=value\n" in the order of the option table, after defaults are applied (so spelling
 * and order on the command line do not matter). Left out: the options that change no
 * pixel (-o, --crop, --stats, ...) and --time-limit (app/tile.h). An option that does not
 * apply to o->mode keeps its default (parse_options refuses it) and is hashed too. */
uint64_t options_hash(const struct options *o, uint64_t h);

#endif
