/*
 * base/output.h -- the files one command writes: declared first, checked together before
 * any work, written under temporary names, and put in place together: all or none.
 *
 * A command declares every file it will write (output_declare), with the role that
 * names it in messages ("-o", "--variance", "the PNG beside -o"), and calls
 * outputs_check() before it computes anything. That refuses, as bad input (exit 2):
 *   - an empty name, a name ending in '/', and a name that is a directory;
 *   - a name whose directory is missing or not writable (its temporary cannot be made);
 *   - an existing file that cannot be opened for writing (mode 444). C99 cannot read a
 *     file's mode, so this asks fopen(); for root, who may write any file, it opens;
 *   - two outputs that are one file, however spelt (see "Identity" below);
 *   - an output that is an input of the command: every reader opens its file through
 *     input_open() (input.h), which asks output_refuse_input(), and outputs_check()
 *     asks the same of the inputs opened before it.
 * Each output is then written to NAME.tmp (output_open), completed (output_commit),
 * and, once every one is complete, outputs_publish() renames them all to their names;
 * if a rename fails, the ones it already renamed are removed. An exit before that, by
 * any path (fatal(), an error, a return from main), removes every temporary: a
 * command's outputs appear whole and together, or not at all. A file written while
 * nothing is declared (a test's lone pfm_write()) is renamed by its own commit.
 *
 * Identity, with C99's files only (no stat(), no inode numbers):
 *   - Two outputs. outputs_check() makes each output's temporary in turn, holding a
 *     marker of this run and of the output; an output whose temporary is already there
 *     with an earlier output's marker is that output: the same directory entry, whatever
 *     the spelling ("a.pfm", "./a.pfm", an absolute path, a symbolic link to the
 *     directory, a file system that ignores case).
 *   - An output and an input. Outputs are renamed into place, so what an output
 *     destroys is the file its name's directory entry held; an input is lost only when
 *     opening it goes through that entry (the same name, or a symbolic link to it). An
 *     input with the same size and bytes as an existing output is tested by renaming
 *     the output aside for a moment, to its temporary's name, and opening the input
 *     again: if that fails the two are one file, and the rename is undone either way.
 *     A hard link to an output keeps its bytes when the output is replaced, and passes.
 */
#ifndef PHOTON_OUTPUT_H
#define PHOTON_OUTPUT_H

#include <stdio.h>

#include "error.h"

#define OUTPUT_NAME_MAX 1024 /* longest output name, ".tmp" included */

/* Declares name (copied) as a file this command writes; role (a string literal) names
 * it in messages. Two declarations of one file, even spelt alike, are refused by
 * outputs_check(). */
void output_declare(const char *name, const char *role);

/* Checks every declared output as above, before any output is opened. -1 with *err
 * filled (bad input) when one is refused; nothing is left on disk by the check. */
int outputs_check(struct error *err);

/* output_declare() and outputs_check() for a command with one output. */
int output_check_one(const char *name, const char *role, struct error *err);

/* Opens NAME.tmp for binary writing. name must have been declared and checked, unless
 * nothing is declared (a lone file). NULL with *err filled (a failed write). */
FILE *output_open(const char *name, struct error *err);

/* Closes the stream of output_open(); its bytes wait under NAME.tmp for
 * outputs_publish() (a lone file is renamed now). A failed write or close removes the
 * temporary and returns -1 with *err filled (a failed write). */
int output_commit(FILE *f, struct error *err);

/* Closes and removes a temporary that will not be completed. */
void output_abandon(FILE *f);

/* Renames every committed output to its name, in the order declared. -1 with *err filled
 * (a failed write) when a rename fails: the outputs it renamed are removed, and the
 * committed temporaries; open ones stay open. Outputs stay declared, so a command may
 * write and publish again (2008's checkpoints publish -o's pair as they go). */
int outputs_publish(struct error *err);

/* Removes every temporary and forgets every output and input; at exit, by atexit(). */
void outputs_abandon(void);

/* Called by input_open() with the input's name and size: -1 with *err filled when a
 * declared output is that file (above). Remembers the input for outputs_check(). */
int output_refuse_input(const char *name, long size, struct error *err);

#endif
