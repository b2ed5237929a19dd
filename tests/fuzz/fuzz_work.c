/*
 * tests/fuzz/fuzz_work.c -- libFuzzer target for the work file's reader (app/work_file.c,
 * --load-photons), built by `make fuzz`; a development tool only.
 *
 * The reader refuses a file saved for another render by its hash (bytes 12 to 19, lowest
 * first), which a fuzzer would not guess, so the hash expected is the one the input holds:
 * every input gets past the header to the maps, the cache's records and the illumination
 * maps. The checksum at the end refuses almost every input, but only after all of it has
 * been read: a crash, a sanitizer report or a leak on the way is a bug.
 *   build/fuzz/fuzz_work CORPUS_DIR tests/fuzz/seeds/work
 */
#include <stdint.h>
#include <string.h>

#include "../../src/app/work_file.h"
#include "../../src/base/output.h"
#include "input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    uint64_t hash = 0;
    for (int i = 7; i >= 0 && size >= 20; i--)
        hash = hash << 8 | data[12 + i];
    struct global_work work;
    memset(&work, 0, sizeof work);
    struct error err;
    work_file_read(input_file(data, size), hash, &work, &err);
    global_work_free(&work);
    outputs_abandon(); /* forgets the input, so the registry does not grow */
    return 0;
}
