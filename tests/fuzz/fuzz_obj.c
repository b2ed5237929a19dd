/*
 * tests/fuzz/fuzz_obj.c -- libFuzzer target for the OBJ reader (scene/obj.c), built by
 * `make fuzz` with clang -fsanitize=fuzzer,address,undefined; a development tool only.
 *
 * Each input is written to a temporary file and imported with obj_import() into a scene
 * that has one material and a camera; a mesh that loads is finished (BVH built). A crash,
 * a sanitizer report or a leak is a bug; bad input must end in a struct error.
 *   build/fuzz/fuzz_obj CORPUS_DIR scenes/mesh.obj
 */
#include <stdint.h>
#include <string.h>

#include "../../src/base/output.h"
#include "../../src/scene/obj.h"
#include "input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct scene *scene = scene_create();
    struct material m;
    memset(&m, 0, sizeof m);
    m.kind = MATERIAL_LAMBERT;
    m.rho = vec3(0.5, 0.5, 0.5);
    struct obj_placement place = obj_unmoved(scene_add_material(scene, &m));
    scene->camera.from = vec3(0, 0, 5);
    scene->camera.up = vec3(0, 1, 0);
    scene->camera.fov = 40;
    struct error err;
    if (obj_import(scene, input_file(data, size), &place, &err) == 0)
        scene_finish(scene, 4, 4);
    scene_free(scene);
    outputs_abandon(); /* forgets the inputs, so the registry does not grow */
    return 0;
}
