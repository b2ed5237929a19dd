/*
 * tests/fuzz/input.c -- the fuzz targets' input file (input.h).
 */
#define _POSIX_C_SOURCE 200809L /* mkstemp(), close(): a development tool, not the product */

#include "input.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char input_path[64]; /* this process's input file, made on the first call */

static void remove_input(void)
{
    remove(input_path);
}

const char *input_file(const uint8_t *data, size_t size)
{
    if (input_path[0] == '\0') {
        strcpy(input_path, "/tmp/photon-fuzz-XXXXXX");
        int fd = mkstemp(input_path);
        if (fd < 0)
            abort();
        close(fd);
        atexit(remove_input);
    }
    FILE *f = fopen(input_path, "wb");
    if (f == NULL || fwrite(data, 1, size, f) != size || fclose(f) != 0)
        abort();
    return input_path;
}
