/*
 * base/option_once.h -- refusing an option given twice on one command line, in one
 * wording for every command.
 *
 * An option that holds one value keeps only one: "--diff a.png --diff b.png" would write
 * b.png alone and say nothing of a.png, so the second is refused rather than silently
 * replacing the first, naming both with their values (--NAME=VALUE as --NAME VALUE):
 *
 *   compare: --diff b.png: given after --diff a.png; give the option once
 *
 * The subcommands (compare, convert, merge, export, plot, probe) record here the options
 * they have read; the render command, whose table knows its options, keeps its own record
 * (app/options.c) and words its refusal by option_given_again(), without "COMMAND: ".
 */
#ifndef PHOTON_OPTION_ONCE_H
#define PHOTON_OPTION_ONCE_H

#include "error.h"

#define OPTION_ONCE_MAX 16 /* more than any subcommand has options */

struct option_once {
    int at[OPTION_ONCE_MAX]; /* the argv index of each option read so far */
    int n;
};

/* Records the option at argv[i], which takes n_values words after it (argv with each
 * "--NAME=VALUE" already two words: option_equals.h). -1 with *err filled by
 * option_given_again() when an option of its name was recorded before. once starts as
 * {{0}, 0}. */
int option_once(struct option_once *once, const char *command, int argc, char **argv, int i,
                int n_values, struct error *err);

/* Fills *err with "COMMAND: NOW: given after BEFORE; give the option once" ("NOW: ..."
 * for command ""), NOW argv[i] and BEFORE argv[earlier], each followed by its n_values
 * words ("--spp 8", "--crop 0 0 4 4"; "--spp=8" is "--spp 8" by then); returns -1. */
int option_given_again(const char *command, int argc, char **argv, int earlier, int i,
                       int n_values, struct error *err);

#endif
