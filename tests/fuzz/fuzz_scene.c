/*
 * tests/fuzz/fuzz_scene.c -- libFuzzer target for the scene-file parser (scene/parse.c),
 * built by `make fuzz` with clang -fsanitize=fuzzer,address,undefined; a development tool.
 *
 * Each input is written to a temporary file in /tmp and read with scene_load(); a scene
 * that loads is finished (camera set up, BVH built). `include`, `nff` and `obj` name
 * files relative to /tmp, so the input can at most read itself again (include depth is
 * limited) or files that happen to be there. Run it with standard input from /dev/null.
 *   build/fuzz/fuzz_scene CORPUS_DIR scenes/
 */
#define _POSIX_C_SOURCE 200809L /* mkstemp(), close(): a development tool, not the product */

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../../src/scene/scene.h"

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
    struct scene *scene = scene_load(input_file(data, size), &err);
    if (scene != NULL)
        scene_finish(scene, 4, 4); /* scene_load() guarantees a valid camera */
    scene_free(scene);
    return 0;
}
