/*
 * base/file_kind.c -- what kind of file a name is (file_kind.h).
 */
#include "file_kind.h"

#include <errno.h>
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

FILE *file_open_no_wait(const char *name, int *pipe)
{
    *pipe = 0;
    FILE *f = fopen(name, "r+b");
    if (f == NULL)
        return NULL;
    if (fseek(f, 0, SEEK_END) != 0 || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        *pipe = 1;
        return NULL;
    }
    return f;
}

FILE *file_open_read(const char *name, int *pipe)
{
    FILE *f = file_open_no_wait(name, pipe);
    if (f != NULL || *pipe)
        return f;
    errno = 0;
    return fopen(name, "rb"); /* not ours to write: the one open that may wait (.h) */
}

int file_is_pipe(const char *name)
{
    int pipe;
    FILE *f = file_open_no_wait(name, &pipe);
    if (f != NULL)
        fclose(f);
    return pipe;
}

int file_is_there(const char *name)
{
    return name[0] != '\0' && rename(name, name) == 0;
}
