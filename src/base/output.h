/*
 * base/output.h -- the files one command writes: declared first, checked together before
 * any work, written under temporary names, and put in place together: all or none.
 *
 * A command declares every file it will write (output_declare), with the role that
 * names it in messages ("-o", "--variance", "the PNG beside -o"), and calls
 * outputs_check() before it computes anything. That refuses, as bad input (exit 2):
 *   - an empty name, a name ending in '/', and a name that is a directory;
 *   - a FIFO or a terminal (file_kind.h): a FIFO would take the bytes of no whole file, and
 *     opening it to write waits for a reader; found without waiting, as every look at an
 *     output here is (an open for update, a rename onto itself: file_kind.h);
 *   - a name whose directory is missing or not writable (its temporary cannot be made);
 *   - an existing file that cannot be opened for update (mode 444, and 222 too). C99
 *     cannot read a file's mode, so this asks fopen(); for root, who may write any file,
 *     it opens;
 *   - an existing file that cannot be moved, so that it could not be replaced either (a
 *     file of another owner in a sticky directory such as /tmp): it is renamed aside and
 *     back (below);
 *   - two outputs that are one file, however spelt (see "Identity" below);
 *   - an output that is an input of the command: every reader opens its file through
 *     input_open() (input.h), which asks output_refuse_input(), and outputs_check()
 *     asks the same of the inputs opened before it.
 * Each output is then written to a temporary (output_open), completed (output_commit),
 * and, once every one is complete, outputs_publish() renames them all to their names.
 * The files they replace are first moved aside, so that if a rename fails, every output
 * already in place gives back the file it replaced (or is removed, where there was
 * none): a failed publish leaves what was there. An exit before that, by any path
 * (fatal(), an error, a return from main, a signal: undo.h), removes every temporary: a
 * command's outputs appear whole and together, or not at all. A file written while
 * nothing is declared (a test's lone pfm_write()) is renamed by its own commit.
 *
 * Files of ours. photon removes only files it made, and makes each one new: a temporary,
 * a probe of the check, the place a replaced file waits is NAME.XXXXXXXX.tmp, beside
 * NAME so that the final rename stays within its directory (atomic), XXXXXXXX 8 hex
 * digits: the run's mark, then the mark + 1, ... for the next name (16 in all) when one
 * is taken, or (but for a probe) is the name of a declared output, which may not be on
 * disk yet. A name is taken when renaming it onto itself succeeds (file_is_there(), which
 * opens nothing, so a FIFO there is passed over without waiting) or when fopen()'s
 * exclusive create, mode "wbx", refuses it. "x" is C11's, not C99's: glibc and musl
 * honour it (O_EXCL: any existing entry refuses it, a symbolic link too, even a dangling
 * one, and a FIFO without waiting); a C99 library that ignored it would be left with the
 * rename test alone. So a user's file at any of these
 * names, a scene named NAME.tmp, a link, stay untouched; and two runs writing the same
 * NAME at once each write their own temporary (the one renamed last is NAME, whole).
 * temporary_name.h makes the names: the run's mark, and a long NAME's names of ours cut
 * to the 255 bytes a file system takes.
 *
 * Identity, with C99's files only (no stat(), no inode numbers):
 *   - Two outputs. outputs_check() makes each output's probe in turn, holding a marker
 *     of this run and of the output; an output whose names of ours hold an earlier
 *     output's marker is that output: the same directory entry, whatever the spelling
 *     ("a.pfm", "./a.pfm", an absolute path, a symbolic link to the directory, a file
 *     system that ignores case).
 *   - An output and an input. Outputs are renamed into place, so what an output
 *     destroys is the file its name's directory entry held; an input is lost only when
 *     opening it goes through that entry (the same name, or a symbolic link to it).
 *     outputs_check() renames each existing output aside for a moment, onto its probe,
 *     and opens every input read so far again; one that opens only with the output in
 *     place is that output. An input read later is tested so when it has the same size
 *     and bytes as an output. A hard link to an output keeps its bytes when the output
 *     is replaced, and passes. While a file is aside, a signal renames it back (undo.h);
 *     only SIGKILL or a crash in that moment leaves it under its NAME.XXXXXXXX.tmp.
 */
#ifndef PHOTON_OUTPUT_H
#define PHOTON_OUTPUT_H

#include <stdio.h>

#include "error.h"

#include "undo.h"

/* The longest output name, its temporary's ".XXXXXXXX.tmp" and '\0' included: the
 * longest path the signal handler copies (undo.h). */
#define OUTPUT_NAME_MAX UNDO_PATH_MAX

/* Declares name (copied) as a file this command writes; role (a string literal) names
 * it in messages. Two declarations of one file, even spelt alike, are refused by
 * outputs_check(). */
void output_declare(const char *name, const char *role);

/* Checks every declared output as above, before any output is opened. -1 with *err
 * filled (bad input) when one is refused; nothing is left on disk by the check. */
int outputs_check(struct error *err);

/* output_declare() and outputs_check() for a command with one output. */
int output_check_one(const char *name, const char *role, struct error *err);

/* Opens a new temporary for name (above) for binary writing. name must have been
 * declared and checked, unless nothing is declared (a lone file). NULL with *err filled
 * (a failed write). */
FILE *output_open(const char *name, struct error *err);

/* Closes the stream of output_open(); its bytes wait in the temporary for
 * outputs_publish() (a lone file is renamed now). A failed write or close removes the
 * temporary and returns -1 with *err filled (a failed write): "NAME: cannot write output
 * file: REASON", NAME the output's own name, REASON strerror()'s ("No space left on
 * device"), learnt by asking the file again, as stdio keeps no errno (output.c). */
int output_commit(FILE *f, struct error *err);

/* Closes and removes a temporary that will not be completed. */
void output_abandon(FILE *f);

/* Renames every committed output to its name, in the order declared. -1 with *err filled
 * (a failed write) when a rename fails: the outputs it renamed give back the files they
 * replaced (or are removed), and the committed temporaries are removed; open ones stay
 * open. Where giving back fails too, *err names the first output left so, the system's
 * reason and where the file it replaced is kept, then the write that failed. A signal
 * meanwhile waits until the publish is over, either way. Outputs stay declared, so a
 * command may write and publish again (2008's checkpoints publish -o's pair as they go). */
int outputs_publish(struct error *err);

/* Removes every temporary and forgets every output and input; at exit, by atexit(). */
void outputs_abandon(void);

/* Called by input_open() with the input's name and size: -1 with *err filled when a
 * declared output is that file (above). Remembers the input for outputs_check(). */
int output_refuse_input(const char *name, long size, struct error *err);

#endif
