/*
 * base/hash.h -- FNV-1a, the 64-bit hash a tile's record keeps of what made its pixels.
 *
 * FNV-1a (Fowler, Noll, Vo; http://www.isthe.com/chongo/tech/comp/fnv/): start from the
 * offset basis, then for each byte b: h = (h XOR b) * FNV1A_PRIME, modulo 2^64. A fold can
 * go on from any earlier h, so inputs read at different places (the scene's lines, the
 * options) hash as one stream. It tells inputs apart that differ by accident (another
 * seed, an edited scene), not ones made to collide: it is not a cryptographic hash.
 */
#ifndef PHOTON_HASH_H
#define PHOTON_HASH_H

#include <stddef.h>
#include <stdint.h>

#define FNV1A_OFFSET_BASIS UINT64_C(14695981039346656037) /* the FNV-1a 64 h of no bytes */
#define FNV1A_PRIME UINT64_C(1099511628211)               /* 2^40 + 2^8 + 0xb3           */

/* h folded with the n bytes at bytes, in order. */
uint64_t fnv1a(uint64_t h, const void *bytes, size_t n);

#endif
