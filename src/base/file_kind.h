/*
 * base/file_kind.h -- whether a name is a directory, asked by behaviour: C99 has no
 * stat(), but "NAME/." opens only when NAME is a directory.
 *
 * A module of its own because both sides of the input/output pair ask it: input_open()
 * refuses a directory as an input (input.h), and the output registry refuses one as an
 * output (output.h), which input.h stands above.
 */
#ifndef PHOTON_FILE_KIND_H
#define PHOTON_FILE_KIND_H

/* Whether name is a directory (name + "/." opens); 0 for the empty name. */
int file_is_directory(const char *name);

#endif
