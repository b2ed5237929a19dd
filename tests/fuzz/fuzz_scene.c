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
#include <stdint.h>

#include "../../src/base/output.h"
#include "../../src/scene/scene.h"
#include "input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct error err;
    struct scene *scene = scene_load(input_file(data, size), &err);
    if (scene != NULL)
        scene_finish(scene, 4, 4); /* scene_load() guarantees a valid camera */
    scene_free(scene);
    outputs_abandon(); /* forgets the inputs, so the registry does not grow */
    return 0;
}
