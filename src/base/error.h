/*
 * base/error.h -- the two kinds of failure and the outputs that must be whole or absent.
 *
 * Bad input (scene files, imports, options, image files) is reported, not fatal: the
 * reader fills a struct error with file, line and message and returns -1 (or NULL), and
 * main() prints "file:line: message" and exits with status 2.
 *
 * Machine failures (out of memory, a failed write) exit with status 1: out of memory
 * through fatal(), which prints "photon: message" and exits, and at exit every temporary
 * output still open is removed (output.h); a failed write is reported like bad input,
 * with failed_write set, so that the command finishes cleanly and exits 1
 * (error_exit_status). An output that cannot be written where it is to go is bad input,
 * found by outputs_check() before any work (output.h, where outputs are written whole or
 * not at all).
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

/* Prints the printf-style message and a newline on stderr, its bytes outside printable
 * ASCII quoted as error_set() quotes them: a warning or a note that echoes a name from a
 * file ("photon: warning: ... material '\x1b[31m'"), which must not reach the terminal raw.
 * At most ERROR_MESSAGE_MAX - 1 bytes of the message are printed. */
void message_print(const char *format, ...);

/* Prints err as "file:line: message" (or "photon: message" without a file) on stderr. */
void error_print(const struct error *err);

/* The exit status for err: 1 when a write failed, 2 for bad input. */
int error_exit_status(const struct error *err);

/* The exit status once the standard output is flushed: status, unless what was printed
 * there could not all be written (photon --manual > /dev/full: a full disk); then
 * "photon: cannot write the standard output: reason" is printed, and a status of 0
 * becomes 1 (a failed write). main() returns through it. */
int standard_output_status(int status);

/* Prints "photon: message" and exits with status 1; exit() runs the output registry's
 * cleanup, which removes every temporary output (output.h registers it by atexit()). */
void fatal(const char *format, ...);

#endif
