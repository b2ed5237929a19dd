/*
 * base/file_kind.h -- what kind of file a name is, asked by behaviour: C99 has no stat().
 *
 * A directory: "NAME/." opens only when NAME is one. A FIFO (named pipe), or a terminal:
 * fopen(NAME, "rb") of a FIFO waits until something opens its other end, for ever if
 * nothing does; so it is never asked first. fopen(NAME, "r+b") does not wait on Linux
 * (a FIFO opened for reading and writing is its own writer), and a FIFO cannot seek, while
 * a regular file can: file_open_read() opens for update, to read only, and refuses what
 * cannot seek. Opening for update changes no byte and no time of the file (the only trace
 * is inotify's "closed after writing" event). A file the user may read but not write
 * cannot be opened so; it is then opened for reading, and if it is a FIFO that open waits:
 * no C99 means tells such a FIFO from a read-only file without opening it (README).
 *
 * A module of its own because both sides of the input/output pair ask it: input_open()
 * refuses a directory or a FIFO as an input (input.h), and the output registry refuses
 * one as an output (output.h), which input.h stands above.
 */
#ifndef PHOTON_FILE_KIND_H
#define PHOTON_FILE_KIND_H

#include <stdio.h>

/* Whether name is a directory (name + "/." opens); 0 for the empty name. */
int file_is_directory(const char *name);

/* Opens name for binary reading at its start without waiting for a FIFO's writer (above).
 * NULL when it does not open (errno says why; *pipe is 0) or when it opened but cannot
 * seek (*pipe is 1: a FIFO, or a terminal). The stream may be open for update: the caller
 * only reads it. */
FILE *file_open_read(const char *name, int *pipe);

/* file_open_read() that never waits: NULL (and *pipe 0) also when name does not open for
 * update (the user may not write it), where file_open_read() would open it for reading. */
FILE *file_open_no_wait(const char *name, int *pipe);

/* Whether name is a FIFO or a terminal, as file_open_no_wait() tells: 0 when it is not,
 * and when it cannot be opened for update, and so cannot be told. */
int file_is_pipe(const char *name);

/* Whether anything is at name, a FIFO and a dangling symbolic link too, found without
 * opening it: rename(name, name), which POSIX makes a no-op that succeeds when name
 * exists (C99 leaves renaming onto an existing name to the implementation). */
int file_is_there(const char *name);

#endif
