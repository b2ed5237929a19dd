/*
 * base/option_once.h -- refusing an option given twice on one command line.
 *
 * An option that holds one value keeps only one: "--diff a.png --diff b.png" would write
 * b.png alone and say nothing of a.png, so the second is refused rather than silently
 * replacing the first. The subcommands (compare, merge, export, plot, probe) record here
 * the options they have read; the render command has its table (app/options.c).
 */
#ifndef PHOTON_OPTION_ONCE_H
#define PHOTON_OPTION_ONCE_H

#include "error.h"

#define OPTION_ONCE_MAX 16 /* more than any subcommand has options */

struct option_once {
    const char *seen[OPTION_ONCE_MAX]; /* the names read so far */
    int n;
};

/* Records the option name; -1 with *err "COMMAND: NAME is given twice ..." when it was
 * recorded before. once starts as {{0}, 0}. */
int option_once(struct option_once *once, const char *command, const char *name,
                struct error *err);

#endif
