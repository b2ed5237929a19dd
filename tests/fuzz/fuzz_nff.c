/*
 * tests/fuzz/fuzz_nff.c -- libFuzzer target for the NFF reader (scene/nff.c), built by
 * `make fuzz` with clang -fsanitize=fuzzer,address,undefined; a development tool only.
 *
 * Each input is written to a temporary file and read with nff_load(); a scene that loads
 * is finished (camera set up, BVH built over its spheres, triangles and cones), so the
 * reader's every accepted output is also checked to build. A crash, a sanitizer report or
 * a leak is a bug; bad input must end in a struct error and nothing else.
 *   build/fuzz/fuzz_nff -max_len=8192 CORPUS_DIR tests/data/spd scenes
 */
#include <stdint.h>

#include "../../src/base/output.h"
#include "../../src/scene/nff.h"
#include "input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct error err;
    struct scene *scene = nff_load(input_file(data, size), &err);
    if (scene != NULL)
        scene_finish(scene, 4, 4); /* a valid view is guaranteed; the size is irrelevant */
    scene_free(scene);
    outputs_abandon(); /* forgets the inputs, so the registry does not grow */
    return 0;
}
