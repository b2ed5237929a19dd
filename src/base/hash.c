/*
 * base/hash.c -- FNV-1a (hash.h).
 */
#include "hash.h"

uint64_t fnv1a(uint64_t h, const void *bytes, size_t n)
{
    const unsigned char *b = bytes;
    for (size_t i = 0; i < n; i++)
        h = (h ^ b[i]) * FNV1A_PRIME; /* unsigned: wraps modulo 2^64 as FNV means */
    return h;
}
