/*
 * base/alloc.c -- checked, counted allocation (see alloc.h).
 *
 * Each block is [header | payload]: the header holds the payload's size and is as large
 * as the most strictly aligned of C99's basic types, so the payload behind it is aligned
 * for any object, as malloc's own result is. Callers only ever see the payload.
 * Invariant: bytes_now is the sum of the sizes in the headers of the blocks not yet
 * freed, and bytes_peak >= bytes_now. A zero-byte request gets a one-byte payload so
 * that every block is writable up to what it says it holds.
 */
#include "alloc.h"

#include <assert.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"

/* The strictest alignment C99 promises malloc to meet is one of these. */
union max_align {
    long double ld;
    long long ll;
    double d;
    void *p;
    void (*f)(void);
};

/* sizeof is a multiple of every member's alignment, so payload = header + 1 is aligned. */
union block_header {
    size_t size;           /* payload bytes, as counted in bytes_now */
    union max_align align; /* never read: makes the header's size */
};

static size_t bytes_now;  /* payload bytes in blocks not yet freed */
static size_t bytes_peak; /* the most bytes_now has been           */

/* count * size (at least 1), fatal when it or the block around it overflows size_t. */
static size_t checked_bytes(size_t count, size_t size, const char *what)
{
    if (size != 0 && count > SIZE_MAX / size)
        fatal("out of memory: %s (%zu x %zu bytes overflows)", what, count, size);
    size_t bytes = count * size;
    if (bytes > SIZE_MAX - sizeof(union block_header))
        fatal("out of memory: %s (%zu x %zu bytes overflows)", what, count, size);
    return bytes > 0 ? bytes : 1;
}

/* Fills in a new block's header, counts its payload and returns the payload. */
static void *counted(union block_header *block, size_t bytes, size_t count, size_t size,
                     const char *what)
{
    if (block == NULL)
        fatal("out of memory: %s (%zu x %zu bytes)", what, count, size);
    block->size = bytes;
    bytes_now += bytes;
    if (bytes_now > bytes_peak)
        bytes_peak = bytes_now;
    return block + 1;
}

static union block_header *header_of(void *p)
{
    return (union block_header *)p - 1;
}

void *xmalloc(size_t count, size_t size, const char *what)
{
    size_t bytes = checked_bytes(count, size, what);
    return counted(malloc(sizeof(union block_header) + bytes), bytes, count, size, what);
}

void *xcalloc(size_t count, size_t size, const char *what)
{
    size_t bytes = checked_bytes(count, size, what);
    return counted(calloc(1, sizeof(union block_header) + bytes), bytes, count, size, what);
}

void *xrealloc(void *p, size_t count, size_t size, const char *what)
{
    if (p == NULL)
        return xmalloc(count, size, what);
    size_t bytes = checked_bytes(count, size, what);
    union block_header *old = header_of(p);
    size_t old_bytes = old->size;
    union block_header *block = realloc(old, sizeof(union block_header) + bytes);
    if (block != NULL)
        bytes_now -= old_bytes; /* the new size replaces the old (see alloc.h) */
    return counted(block, bytes, count, size, what);
}

char *xstrdup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *copy = xmalloc(n, 1, "string");
    memcpy(copy, s, n);
    return copy;
}

void xfree(void *p)
{
    if (p == NULL)
        return;
    union block_header *block = header_of(p);
    assert(block->size <= bytes_now);
    bytes_now -= block->size;
    free(block);
}

size_t alloc_bytes_now(void)
{
    return bytes_now;
}

size_t alloc_bytes_peak(void)
{
    return bytes_peak;
}

void alloc_restart_peak(void)
{
    bytes_peak = bytes_now;
}
