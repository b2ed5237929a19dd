/*
 * tests/fuzz/fuzz_pfm.c -- libFuzzer target for the PFM reader (image/pfm.c), built by
 * `make fuzz` with clang -fsanitize=fuzzer,address,undefined; a development tool only.
 *
 * Each input is written to a temporary file and read with pfm_read(). A crash, a
 * sanitizer report or a leak is a bug; bad input must end in a struct error.
 *   build/fuzz/fuzz_pfm CORPUS_DIR reference/
 */
#include <stdint.h>

#include "../../src/base/output.h"
#include "../../src/image/image.h"
#include "input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct error err;
    image_free(pfm_read(input_file(data, size), &err));
    outputs_abandon(); /* forgets the inputs, so the registry does not grow */
    return 0;
}
