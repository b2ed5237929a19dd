/*
 * base/deflate.h -- zlib compression (RFC 1950 around RFC 1951's deflate), for the OpenEXR
 * writer's ZIP chunks (image/exr_write.c); base/inflate.h undoes it.
 *
 * The stream goes into a buffer of the caller's of a stated capacity. A stream that would
 * not fit is abandoned: the OpenEXR writer gives the room of one byte less than the raw
 * chunk, and stores the chunk raw when it is not shortened (as the format allows). The
 * same input gives the same bytes on every compiler and run: integers only, and every
 * choice (which match, which code, which kind of block) made by a fixed rule.
 */
#ifndef PHOTON_DEFLATE_H
#define PHOTON_DEFLATE_H

#include <stddef.h>

/* Compresses in[0 .. in_size - 1] (in may be NULL when in_size is 0) into a zlib stream
 * at out[0 .. capacity - 1]. The stream's length; 0 when it would be longer than
 * capacity (what out holds then is unspecified; nothing past capacity is written). */
size_t zlib_deflate(const unsigned char *in, size_t in_size, unsigned char *out,
                    size_t capacity);

/* A capacity always enough for in_size bytes: what stored blocks need, the worst case. */
size_t zlib_deflate_bound(size_t in_size);

#endif
