/*
 * tests/fuzz/input.c -- the fuzz targets' input file (input.h).
 */
#include "input.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char input_path[L_tmpnam]; /* this process's input file, named on the first call */

static void remove_input(void)
{
    remove(input_path);
}

/* tmpnam() (standard C, unlike mkstemp) may race with another process taking the same name
 * before us; for a development tool writing its own scratch file that is acceptable. */
const char *input_file(const uint8_t *data, size_t size)
{
    if (input_path[0] == '\0') {
        if (tmpnam(input_path) == NULL)
            abort();
        atexit(remove_input);
    }
    FILE *f = fopen(input_path, "wb");
    if (f == NULL || fwrite(data, 1, size, f) != size || fclose(f) != 0)
        abort();
    return input_path;
}
