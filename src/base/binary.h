/*
 * base/binary.h -- numbers in a binary file, the same bytes on every machine: the file of
 * a render's global work (app/work_file.h) and the structures it holds that keep their
 * layout to themselves (photon/illumination_map.h) write and read through it.
 *
 * A whole number goes out in a stated number of bytes, lowest first; a double as the 64
 * bits of its IEEE 754 form, the same way. So a file does not depend on the machine's byte
 * order or on how a compiler lays out a struct (C99 does not promise IEEE 754, but every
 * machine photon runs on has it; binary.c checks the sizes). Both sides fold every byte
 * into an FNV-1a checksum (base/hash.h) as it passes, which the file keeps at its end.
 *
 * The reader knows the file's size, so a count read from the file is checked against the
 * bytes left (binary_fits) before anything is allocated for it: a damaged count is
 * reported as truncation, not tried. Every read names what it is reading, and a failure
 * fills a struct error as "FILE: message" and returns -1.
 */
#ifndef PHOTON_BINARY_H
#define PHOTON_BINARY_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "error.h"

#define BINARY_DOUBLE_BYTES 8 /* a double in the file: its IEEE 754 binary64 bits */

struct binary_writer {
    FILE *f;           /* borrowed: open for writing (a failed write shows in ferror()) */
    uint64_t checksum; /* FNV-1a of every byte written so far; FNV1A_OFFSET_BASIS first */
};

struct binary_reader {
    FILE *f;           /* borrowed: open for reading at the start of the file            */
    const char *name;  /* borrowed: the file's name, for messages                        */
    long size;         /* of the whole file, in bytes                                    */
    uint64_t checksum; /* FNV-1a of every byte read so far; FNV1A_OFFSET_BASIS first     */
};

void binary_put_bytes(struct binary_writer *w, const unsigned char *bytes, size_t n);

/* The n_bytes (1..8) lowest bytes of v, lowest first. */
void binary_put_uint(struct binary_writer *w, uint64_t v, int n_bytes);

void binary_put_double(struct binary_writer *w, double x);

/* The checksum of every byte before it, in 8 bytes; the last thing in a file. */
void binary_put_checksum(struct binary_writer *w);

/* Opens name for reading into *r and learns its size. -1 with *err when it cannot be
 * opened or is not a regular file; otherwise the caller closes r->f. */
int binary_open(const char *name, struct binary_reader *r, struct error *err);

/* n bytes of the part of the file that what names ("the header"), for the message that
 * the file ends inside it. */
int binary_get_bytes(struct binary_reader *r, unsigned char *bytes, size_t n, const char *what,
                     struct error *err);

/* A whole number of n_bytes (1..8) bytes, lowest first. */
int binary_get_uint(struct binary_reader *r, int n_bytes, const char *what, uint64_t *v,
                    struct error *err);

/* A byte that says whether something follows: 0 or 1, anything else refused. */
int binary_get_flag(struct binary_reader *r, const char *what, int *flag, struct error *err);

/* A double, refused unless finite. */
int binary_get_double(struct binary_reader *r, const char *what, double *x,
                      struct error *err);

/* Whether count items of item_bytes (>= 1) each fit in what is left of the file; the
 * message says truncation otherwise. Call it before allocating for them. */
int binary_fits(const struct binary_reader *r, uint64_t count, size_t item_bytes,
                const char *what, struct error *err);

/* The checksum at the end of the file, compared with the bytes read before it; then
 * nothing may follow. */
int binary_get_checksum(struct binary_reader *r, struct error *err);

#endif
