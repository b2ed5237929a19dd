/*
 * base/alloc.h -- allocation that never returns NULL, and counts what it holds.
 *
 * Out of memory is a machine failure: these call fatal() naming what was being
 * allocated. count * size is checked for overflow before anything is asked of malloc.
 * Sizes that come from input must be checked against documented limits by the reader
 * first, so that absurd input is bad input (exit 2), not an allocation failure.
 *
 * Every block these return is released by xfree(), never by xfree(): a hidden header in
 * front of the block keeps its size, so that the program can say how much it holds.
 * What is counted: the payload bytes asked for (count * size; a zero-byte request counts
 * the one byte it gets). Not counted: the header, malloc's own overhead, and memory libc
 * takes for itself (stdio's buffers). xrealloc counts the new size in place of the old,
 * although realloc may hold both for a moment while it copies.
 */
#ifndef PHOTON_ALLOC_H
#define PHOTON_ALLOC_H

#include <stddef.h>

void *xmalloc(size_t count, size_t size, const char *what);
void *xcalloc(size_t count, size_t size, const char *what); /* zero-filled */
/* p is NULL (then as xmalloc) or a block from these; its contents up to the smaller
 * size are kept. */
void *xrealloc(void *p, size_t count, size_t size, const char *what);
char *xstrdup(const char *s);
/* Releases a block from the functions above; xfree(NULL) does nothing. */
void xfree(void *p);

/* Payload bytes held now, and the most ever held at once since the program started
 * (or since alloc_restart_peak()). */
size_t alloc_bytes_now(void);
size_t alloc_bytes_peak(void);
/* Starts the high-water mark again from the bytes held now, so that a test can measure
 * the peak of one sequence of calls. */
void alloc_restart_peak(void);

#endif
