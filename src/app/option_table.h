/*
 * app/option_table.h -- the render command's options, one row each: name, kind, field,
 * limits, help text and the modes it means something for. options.c parses and prints
 * --help from this one table, so the help and the parser cannot disagree.
 */
#ifndef PHOTON_OPTION_TABLE_H
#define PHOTON_OPTION_TABLE_H

#include <stddef.h>

#include "render_options.h"

/* A departure from a mode's paper is switched by a pair of options: --NAME, its default
 * side, and --no-NAME, the paper's (--paper's words are such --no-NAMEs, or an option
 * with the paper's value). OPT_FLAG sets its int field to 0 when its name starts with
 * --no-, else to 1. A departure with a value is --NAME VALUE, whose range leaves out 0,
 * and --no-NAME, an OPT_OFF: it sets the field of --NAME to 0, which the modes read as
 * the departure off. */
enum option_kind {
    OPT_FLAG, OPT_OFF, OPT_INT, OPT_SEED, OPT_REAL, OPT_REAL_ABOVE, OPT_REAL_BETWEEN, OPT_MODE,
    OPT_QUALITY, OPT_OUTPUT, OPT_FILE, OPT_CROP, OPT_STORE
};

struct option_spec {
    const char *name;
    enum option_kind kind;
    size_t offset;    /* of the field in struct options */
    double min, max;  /* limits for numbers: [min, max]; OPT_REAL_ABOVE (min, max],
                         OPT_REAL_BETWEEN (min, max); --help prints them        */
    const char *args; /* what follows the name in --help */
    const char *help;
    unsigned modes;   /* the modes it means something for: bit 1 << m for enum mode m;
                         given for another, it is refused (check_modes), and --help
                         prints the modes before its text                            */
};

/* Sets of modes for option_spec.modes. */
#define FOR_DIRECT (1u << MODE_DIRECT)
#define FOR_PT (1u << MODE_PT)
#define FOR_PHOTONS (1u << MODE_PHOTONS)
#define FOR_1994 (1u << MODE_JENSEN1994)
#define FOR_1996 (1u << MODE_JENSEN1996)
#define FOR_2008 (1u << MODE_PPM2008)
#define FOR_2009 (1u << MODE_SPPM2009)
#define FOR_ALL (FOR_DIRECT | FOR_PT | FOR_PHOTONS | FOR_1994 | FOR_1996 | FOR_2008 | FOR_2009)
#define FOR_PHOTON_MAPS (FOR_PHOTONS | FOR_1994 | FOR_1996) /* the modes that keep maps */
#define FOR_PROGRESSIVE (FOR_2008 | FOR_2009)
#define FOR_SAMPLES (FOR_ALL & ~FOR_PROGRESSIVE) /* pixels: means of independent samples */

/* The rows of option_table.c, N_OPTION_SPECS of them (a constant, for arrays of one entry
 * an option; option_table.c does not compile when it is not the rows' count). */
#define N_OPTION_SPECS 88
extern const struct option_spec option_specs[];

#endif
