/*
 * base/inflate.h -- undoing zlib compression (RFC 1950 around RFC 1951's deflate), for the
 * OpenEXR reader's ZIP and ZIPS blocks (image/exr_read.c).
 *
 * The caller knows how many bytes the stream must give (an OpenEXR block states its
 * size), so the whole output buffer is given at once and a stream that would give more,
 * or fewer, is refused. Every length and distance is checked against the input and the
 * output, so no input, however damaged, reads or writes outside them or runs for longer
 * than its length allows.
 */
#ifndef PHOTON_INFLATE_H
#define PHOTON_INFLATE_H

#include <stddef.h>

/* Inflates the zlib stream in[0 .. in_size - 1] into out[0 .. out_size - 1], which it
 * must fill exactly; its Adler-32 checksum is checked. 0 on success; -1 with *message
 * set to a constant text saying what was wrong ("the stream ends early", ...). */
int zlib_inflate(const unsigned char *in, size_t in_size, unsigned char *out,
                 size_t out_size, const char **message);

/* The Adler-32 checksum of RFC 1950 over bytes[0 .. n - 1], which the writer also needs. */
unsigned long adler32(const unsigned char *bytes, size_t n);

#endif
