/*
 * tests/files.h -- helpers the tests share for temporary files and captured output: unique
 * names under /tmp, writing a file from text or bytes, and reading one back to compare.
 *
 * Every helper opens and closes its own FILE; nothing stays open between calls. A file that
 * cannot be written is left absent, so the read that follows fails and the test says so.
 */
#ifndef PHOTON_TEST_FILES_H
#define PHOTON_TEST_FILES_H

#include <stddef.h>

struct image;

/* Puts "/tmp/photon_test_GROUP_RUN_WHAT" in out (size bytes), RUN unique to this process. */
void temp_name(char *out, size_t size, const char *group, const char *what);

/* Writes text (without its '\0') to name, replacing what was there. */
void write_text_file(const char *name, const char *text);
/* Writes the n bytes to name, replacing what was there; n may be 0. */
void write_bytes_file(const char *name, const unsigned char *bytes, size_t n);

/* Whether name can be opened for reading. */
int file_exists(const char *name);
/* The first MiB of name as a string (malloc'd, caller frees), or NULL when unreadable. */
char *read_text_file(const char *name);
/* Whether name can be read and its text contains text. */
int file_contains(const char *name, const char *text);
/* Whether name can be read and its whole text is exactly text. */
int file_equals_text(const char *name, const char *text);
/* --help's text, in place, with each row of option words (a preset's, --paper's) on one
 * line: help_row() goes on under the row's first word in a line of spaces and an option,
 * joined here to the line above by one space. */
void join_option_rows(char *help);
/* Whether both files can be read and hold the same bytes. */
int files_equal(const char *a, const char *b);
/* How many temporaries of the output name are on disk: files, links or directories
 * named NAME.XXXXXXXX.tmp (base/output.h) or NAME.tmp (the name photon once used).
 * name holds no quote. */
int count_temporaries(const char *name);
/* Whether count_temporaries(name) is 0. */
int no_temporaries(const char *name);

/* The number of the "key=value" line (as --stats prints) for key in file log; -1 when the
 * file has no such line. */
double file_stat(const char *log, const char *key);

/* Runs "PHOTON subcommand args" (subcommand may be "") with stdout and stderr captured in
 * log; the exit status, or -1 if the command is too long or did not exit. */
int photon_logged(const char *subcommand, const char *args, const char *log);

/* Renders scene with photon's options (a --mode and its settings) and --no-progress into
 * temporary files of group: the image it wrote (the caller frees it with image_free()),
 * or NULL when photon failed or wrote none. Its output, PNG and log are removed. */
struct image *photon_render(const char *group, const char *options, const char *scene);

#endif
