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

/* The Adler-32 checksum of RFC 1950 over bytes[0 .. n - 1], which the writers also need. */
unsigned long adler32(const unsigned char *bytes, size_t n);

/* adler32() carried on: the checksum of what `adler` was the checksum of (1 for nothing)
 * followed by bytes[0 .. n - 1], for a writer that sends its bytes in pieces (png.c). */
unsigned long adler32_update(unsigned long adler, const unsigned char *bytes, size_t n);

/* RFC 1951's numbers and tables, defined in inflate.c and coded with by deflate.c too. */
#define DEFLATE_MAX_BITS 15       /* the longest Huffman code deflate allows            */
#define DEFLATE_N_LITLEN 288      /* literal/length symbols in the fixed code (286 used) */
#define DEFLATE_N_DIST 30         /* distance symbols                                    */
#define DEFLATE_N_LENGTHS 29      /* length symbols, 257..285                            */
#define DEFLATE_N_CODE_LENGTHS 19 /* symbols of the code that codes the code lengths     */
#define DEFLATE_END_OF_BLOCK 256  /* the literal/length symbol that ends a block         */

/* Section 3.2.5: length symbol 257 + i copies deflate_length_base[i] bytes plus the value
 * of the deflate_length_extra[i] bits after it; distance symbol i, likewise. */
extern const short deflate_length_base[DEFLATE_N_LENGTHS];
extern const short deflate_length_extra[DEFLATE_N_LENGTHS];
extern const short deflate_dist_base[DEFLATE_N_DIST];
extern const short deflate_dist_extra[DEFLATE_N_DIST];
/* Section 3.2.7: the order of a dynamic block's code-length code lengths. */
extern const unsigned char deflate_code_length_order[DEFLATE_N_CODE_LENGTHS];
/* Section 3.2.6: the fixed literal/length and distance codes' lengths. */
void deflate_fixed_lengths(unsigned char litlen[DEFLATE_N_LITLEN],
                           unsigned char dist[DEFLATE_N_DIST]);

#endif
