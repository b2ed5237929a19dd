/*
 * base/file_kind.c -- whether a name is a directory (file_kind.h).
 */
#include "file_kind.h"

#include <stdio.h>
#include <string.h>

#include "alloc.h"

int file_is_directory(const char *name)
{
    if (name[0] == '\0')
        return 0;
    size_t n = strlen(name);
    char *dot = xmalloc(n + 3, 1, "file name");
    memcpy(dot, name, n);
    memcpy(dot + n, "/.", 3);
    FILE *f = fopen(dot, "rb");
    xfree(dot);
    if (f != NULL)
        fclose(f);
    return f != NULL;
}
