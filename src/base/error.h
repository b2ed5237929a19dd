/*
 * base/error.h -- the two kinds of failure and the outputs that must be whole or absent.
 *
 * Bad input (scene files, imports, options, image files) is reported, not fatal: the
 * reader fills a struct error with file, line and message and returns -1 (or NULL), and
 * main() prints "file:line: message" and exits with status 2.
 *
 * Machine failures (out of memory, a failed write) exit with status 1: out of memory
 * through fatal(), which removes every temporary output still open and prints
 * "photon: message"; a failed write is reported like bad input, with failed_write set,
 * so that the command finishes cleanly and exits 1 (error_exit_status). An output
 * whose directory is missing or not writable is bad input, found by output_check()
 * before any work.
 *
 * Outputs are written to NAME.tmp (output_open) and renamed to NAME once complete
 * (output_commit), so an interrupted or failed run never leaves a partial file.
 */
#ifndef PHOTON_ERROR_H
#define PHOTON_ERROR_H

#include <stdio.h>

#define ERROR_FILE_MAX 512
#define ERROR_MESSAGE_MAX 512

struct error {
    char file[ERROR_FILE_MAX];       /* input file the problem is in ("" for options) */
    int line;                        /* 1-based line number, 0 when it has none       */
    char message[ERROR_MESSAGE_MAX]; /* what was expected and what was found          */
    int failed_write;                /* 1: a write failed (exit 1); 0: bad input (2)  */
};

/* Fills *err (if err is not NULL) with a printf-style message; returns -1 so that
 * callers can write "return error_set(err, ...)". Bytes of the message and the file name
 * outside printable ASCII are written as \xNN (input echoed in a message stays text). */
int error_set(struct error *err, const char *file, int line, const char *format, ...);

/* Prints err as "file:line: message" (or "photon: message" without a file) on stderr. */
void error_print(const struct error *err);

/* The exit status for err: 1 when a write failed, 2 for bad input. */
int error_exit_status(const struct error *err);

/* Removes temporary outputs, prints "photon: message" and exits with status 1. */
void fatal(const char *format, ...);

/* Opens NAME.tmp for binary writing and remembers it for fatal(). Returns NULL with *err
 * filled (a failed write) when the file cannot be created. */
FILE *output_open(const char *name, struct error *err);

/* Whether NAME can be written, asked before any work: creates NAME.tmp, the temporary
 * output_open() will use, and removes it. -1 with *err filled (bad input: the directory
 * is missing or not writable, or the name too long) when it cannot be created. */
int output_check(const char *name, struct error *err);

/* Closes the stream returned by output_open() and renames NAME.tmp to NAME; a failed
 * write or close removes the temporary and returns -1 with *err filled (a failed
 * write). */
int output_commit(FILE *f, struct error *err);

/* Closes and removes a temporary output that will not be completed. */
void output_abandon(FILE *f);

#endif
