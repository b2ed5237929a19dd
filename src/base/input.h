/*
 * base/input.h -- opening a file photon reads, and reading its text a line at a time.
 *
 * Every reader (scene files and their includes, NFF, OBJ, PFM, CSV, a tile's record, the
 * work file) opens its file through input_open(), which refuses what is not a regular
 * file before a byte is used, and before anything waits: a directory ("is a directory"), a
 * FIFO ("is a FIFO", told without waiting for its writer: file_kind.h), a device that
 * cannot tell its size, and a device that yields bytes past the size it tells (/dev/zero,
 * /dev/urandom). The size it measures bounds the reading: input_line() refuses a file
 * that goes on past it (one that grows while it is read), so no reader can read for
 * ever. input_open() also hands the name to the output registry (output.h), which
 * refuses the input when an output of the command is that file.
 *
 * Text lines are read whole, up to a caller's limit; a NUL byte in a line is refused
 * (C's strings would silently end there), and so is a line longer than the limit.
 * Errors fill a struct error with the file and, for a line, its number; the caller
 * closes what input_open() opened, whatever followed.
 */
#ifndef PHOTON_INPUT_H
#define PHOTON_INPUT_H

#include <stddef.h>
#include <stdio.h>

#include "error.h"

struct input {
    FILE *f;          /* owned: open for reading (binary: CR LF reaches the reader)    */
    const char *name; /* borrowed: the file's name, for messages                        */
    long size;        /* bytes the file held when opened: nothing past them is read     */
    long offset;      /* bytes input_line() has read                                    */
    int line;         /* 1-based number of the last line input_line() read; 0 before    */
};

/* Opens name for reading into *in and measures it. -1 with *err filled ("NAME: is a
 * directory", "NAME: is a FIFO ...", "NAME: not a regular file ...", "NAME: cannot open:
 * reason", or the output registry's refusal); nothing is left open then. */
int input_open(struct input *in, const char *name, struct error *err);

/* The next line, its '\n' kept when it has one, into text[size] (size >= 3) as a string.
 * Returns 1 for a line, 0 at the end of the file, -1 with *err filled ("NAME:LINE: ...")
 * for a line that holds a NUL byte or would not fit (more than size bytes with its
 * newline: a line of exactly size bytes is read without its newline), a read that
 * fails, or bytes past the measured size. */
int input_line(struct input *in, char *text, size_t size, struct error *err);

/* Why the open or read that just failed failed, for a message: strerror(errno), or
 * "unknown reason" where the library set none (errno set to 0 before it). */
const char *input_failure(void);

/* Closes what input_open() opened; a closed or never opened input is left alone. */
void input_close(struct input *in);

#endif
