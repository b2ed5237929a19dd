/*
 * base/error.h -- the two kinds of failure and the outputs that must be whole or absent.
 *
 * Bad input (scene files, imports, options, image files) is reported, not fatal: the
 * reader fills a struct error with file, line and message and returns -1 (or NULL), and
 * main() prints "file:line: message" and exits with status 2.
 *
 * Machine failures (out of memory, a failed write) go through fatal(), which removes
 * every temporary output still open, prints "photon: message" and exits with status 1.
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
};

/* Fills *err (if err is not NULL) with a printf-style message; returns -1 so that
 * callers can write "return error_set(err, ...)". */
int error_set(struct error *err, const char *file, int line, const char *format, ...);

/* Prints err as "file:line: message" (or "photon: message" without a file) on stderr. */
void error_print(const struct error *err);

/* Removes temporary outputs, prints "photon: message" and exits with status 1. */
void fatal(const char *format, ...);

/* Opens NAME.tmp for binary writing and remembers it for fatal(). Returns NULL with *err
 * filled when the file cannot be created. */
FILE *output_open(const char *name, struct error *err);

/* Closes the stream returned by output_open() and renames NAME.tmp to NAME; a failed
 * write or close removes the temporary and returns -1 with *err filled. */
int output_commit(FILE *f, struct error *err);

/* Closes and removes a temporary output that will not be completed. */
void output_abandon(FILE *f);

#endif
