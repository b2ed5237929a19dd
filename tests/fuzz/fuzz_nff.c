/*
 * tests/fuzz/fuzz_nff.c -- libFuzzer target for the NFF reader (scene/nff.c), built by
 * `make fuzz` with clang -fsanitize=fuzzer,address,undefined; a development tool only.
 *
 * Each input is written to a temporary file and read with nff_load(); a scene that loads
 * is finished (camera set up, BVH built over its spheres, triangles and cones), so the
 * reader's every accepted output is also checked to build. A crash, a sanitizer report or
 * a leak is a bug; bad input must end in a struct error and nothing else.
 *   build/fuzz/fuzz_nff -max_len=8192 CORPUS_DIR ../shared/spd/balls-s2.nff ...
 */
#define _POSIX_C_SOURCE 200809L /* mkstemp(), close(): a development tool, not the product */

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../../src/scene/nff.h"

static char input_path[64]; /* this process's input file, made on the first call */

static void remove_input(void)
{
    remove(input_path);
}

/* Writes the bytes to this process's temporary file (the readers take file names), so
 * fuzzers running side by side never share one. */
static const char *input_file(const uint8_t *data, size_t size)
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

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct error err;
    struct scene *scene = nff_load(input_file(data, size), &err);
    if (scene != NULL)
        scene_finish(scene, 4, 4); /* a valid view is guaranteed; the size is irrelevant */
    scene_free(scene);
    return 0;
}
