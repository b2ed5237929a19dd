/*
 * base/alloc.h -- allocation that never returns NULL.
 *
 * Out of memory is a machine failure: these call fatal() naming what was being
 * allocated. count * size is checked for overflow before anything is asked of malloc.
 * Sizes that come from input must be checked against documented limits by the reader
 * first, so that absurd input is bad input (exit 2), not an allocation failure.
 */
#ifndef PHOTON_ALLOC_H
#define PHOTON_ALLOC_H

#include <stddef.h>

void *xmalloc(size_t count, size_t size, const char *what);
void *xcalloc(size_t count, size_t size, const char *what);
void *xrealloc(void *p, size_t count, size_t size, const char *what);
char *xstrdup(const char *s);

#endif
