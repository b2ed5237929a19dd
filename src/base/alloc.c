/*
 * base/alloc.c -- checked allocation (see alloc.h). A zero-byte request allocates one
 * byte so that a NULL return always means failure.
 */
#include "alloc.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"

static size_t checked_bytes(size_t count, size_t size, const char *what)
{
    if (size != 0 && count > SIZE_MAX / size)
        fatal("out of memory: %s (%zu x %zu bytes overflows)", what, count, size);
    size_t bytes = count * size;
    return bytes > 0 ? bytes : 1;
}

void *xmalloc(size_t count, size_t size, const char *what)
{
    void *p = malloc(checked_bytes(count, size, what));
    if (p == NULL)
        fatal("out of memory: %s (%zu x %zu bytes)", what, count, size);
    return p;
}

void *xcalloc(size_t count, size_t size, const char *what)
{
    checked_bytes(count, size, what);
    void *p = calloc(count > 0 ? count : 1, size > 0 ? size : 1);
    if (p == NULL)
        fatal("out of memory: %s (%zu x %zu bytes)", what, count, size);
    return p;
}

void *xrealloc(void *p, size_t count, size_t size, const char *what)
{
    void *q = realloc(p, checked_bytes(count, size, what));
    if (q == NULL)
        fatal("out of memory: %s (%zu x %zu bytes)", what, count, size);
    return q;
}

char *xstrdup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *copy = xmalloc(n, 1, "string");
    memcpy(copy, s, n);
    return copy;
}
