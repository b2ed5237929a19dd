/*
 * app/first_screen.h -- what `photon --help` prints: one screen (at most 40 lines of at
 * most 100 columns) for a user who has not read the rest: the usage, the modes, the
 * options most renders want, the commands, and where the rest is (photon --help all, the
 * full list the manual page is written from; --help MODE; COMMAND --help).
 *
 * The modes and commands come from the tables the program runs (option_values.h's
 * every_mode, commands.h), the options' names and value words from the option table, so
 * none can be missing here or named differently from what the parser takes.
 */
#ifndef PHOTON_FIRST_SCREEN_H
#define PHOTON_FIRST_SCREEN_H

#define FIRST_SCREEN_LINES 40 /* the most lines it may take (tests/test_help.c) */

#include "help.h"

/* Prints the first screen on stdout. */
void print_first_screen(void);

/* The modes, a line each, as a section of the help in format: the first screen's, and the
 * full list's (photon --help all, the manual page). */
void help_modes(enum help_format format);

#endif
