/*
 * tests/fuzz/fuzz_exr.c -- libFuzzer target for the OpenEXR reader (image/exr_read.c, with
 * base/inflate.c), built by `make fuzz` with clang -fsanitize=fuzzer,address,undefined; a
 * development tool only.
 *
 * Each input is written to a temporary file and read with image_read(), which sends a
 * file with OpenEXR's magic number to exr_read(). A crash, a sanitizer report or a leak is
 * a bug; bad input must end in a struct error. The sample files are a good seed corpus:
 *   build/fuzz/fuzz_exr CORPUS_DIR tests/data/exr/
 */
#include <stdint.h>

#include "../../src/base/output.h"
#include "../../src/image/image.h"
#include "input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct error err;
    image_free(image_read(input_file(data, size), &err));
    outputs_abandon(); /* forgets the inputs, so the registry does not grow */
    return 0;
}
