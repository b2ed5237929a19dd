/*
 * app/commands.h -- the commands beside rendering (photon compare, plot, ...): one table
 * of their names, what runs each and what each is for, read by main.c to run a command,
 * by the first screen of --help (first_screen.h) to list them and by the tests to ask
 * each for its --help, so that a command added once is run, listed and tested. Each row
 * also names the command's options, by which main.c splits each --NAME=VALUE into
 * --NAME VALUE before the command reads its words (base/option_equals.h).
 */
#ifndef PHOTON_COMMANDS_H
#define PHOTON_COMMANDS_H

#include <stddef.h>

#include "../base/option_equals.h"

struct command {
    const char *name;                  /* the first word: photon NAME ARGS...        */
    int (*run)(int argc, char **argv); /* argv[0] is NAME; returns the exit status    */
    const char *summary;               /* one line of the first screen: what it does */
    const struct option_arity *options; /* its options, ended by a NULL name        */
};

/* The rows of commands.c, N_COMMANDS of them (commands.c does not compile when that is
 * not the rows' count). */
#define N_COMMANDS 6
extern const struct command commands[];

#endif
