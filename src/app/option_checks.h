/*
 * app/option_checks.h -- the refusals of render options that are good one by one but not
 * together: not in the render's mode for a reason the option table's modes cannot say, or
 * doing nothing given the others (option_checks.c says which and why).
 *
 * Apart from options.c, which reads the command line into its table, since these follow
 * what the modes make of the options, and grow with the modes.
 */
#ifndef PHOTON_OPTION_CHECKS_H
#define PHOTON_OPTION_CHECKS_H

#include "render_options.h"

/* Which options the command line itself gave: given(table, name) is the index in argv of
 * the word that named the option called name, 0 when none did (a preset or --paper may
 * still have set it). options.c answers from its table (option_table.c). */
struct command_words {
    int (*given)(const void *table, const char *name);
    const void *table;
};

/* o with every default filled in: 0 when its options go together, else -1 with *err
 * naming the option at fault and why ("--footprints: does nothing with --radius, which
 * sets R0 in scene units"). An option that does nothing is refused only when the command
 * line gave it: a preset or --paper sets a whole list, some of which another option given
 * may leave idle. */
int check_combinations(const struct options *o, const struct command_words *words,
                       struct error *err);

#endif
