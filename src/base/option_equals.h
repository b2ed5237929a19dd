/*
 * base/option_equals.h -- the spelling --NAME=VALUE, getopt_long()'s, which users bring
 * from other tools: the same as the two words --NAME VALUE, for the render command
 * (app/options.c) and every subcommand (app/commands.h) alike.
 *
 * Each command states its options' names and how many words of values follow each; the
 * words are split before the command reads them, so that no command spells '=' itself.
 * An option of one value is split at the first '=' (a file name may hold more). One of
 * no value, or of several, is refused with '=': --stats=0 is not --stats, and
 * --crop=0 0 4 4 would leave three words apart. A word that names no option of the
 * command is left whole, for the command to read or refuse as it will.
 */
#ifndef PHOTON_OPTION_EQUALS_H
#define PHOTON_OPTION_EQUALS_H

#include "error.h"

/* One option of a command, as split_equals() needs it. */
struct option_arity {
    const char *name; /* as typed: "--spp", "-o"; NULL ends a table */
    int values;       /* the words that follow it: 0 for a switch */
};

/* argv with each word "--NAME=VALUE" after argv[0], NAME an option of table (its rows,
 * ended by one whose name is NULL) that takes one value, as the two words NAME (the
 * table's string) and VALUE: a new array *split of *split_argc words and a NULL, which
 * the caller frees with xfree() whatever is returned; its words are argv's and table's,
 * only read. -1 with *err
 * "COMMAND: WORD: NAME takes no value, not '=' and a value" (or "four values", ...;
 * "WORD: ..." for command "") for an option that takes none or several; else 0. */
int split_equals(const char *command, int argc, char **argv,
                 const struct option_arity *table, char ***split, int *split_argc,
                 struct error *err);

#endif
