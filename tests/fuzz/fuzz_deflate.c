/*
 * tests/fuzz/fuzz_deflate.c -- libFuzzer target for the zlib compressor and decompressor
 * (base/deflate.c, base/inflate.c), built by `make fuzz`; a development tool only.
 *
 * Each input is compressed, and the stream must inflate back to the input, byte for byte:
 * anything else aborts, a bug. The input is also inflated as a stream of its own, which
 * must end in a message or in bytes, never in a crash or a sanitizer report. Long inputs
 * reach the block boundary and the window's edge:
 *   build/fuzz/fuzz_deflate -max_len=140000 CORPUS_DIR
 */
#include <stdlib.h>
#include <string.h>

#include "../../src/base/alloc.h"
#include "../../src/base/deflate.h"
#include "../../src/base/inflate.h"
#include "input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    size_t capacity = zlib_deflate_bound(size);
    unsigned char *stream = xmalloc(capacity, 1, "a fuzz input's stream");
    unsigned char *out = xmalloc(4 * size + 1, 1, "a fuzz input's inflated bytes");
    const char *message = NULL;
    size_t n = zlib_deflate(data, size, stream, capacity);
    if (n == 0 || zlib_inflate(stream, n, out, size, &message) != 0 ||
        (size > 0 && memcmp(out, data, size) != 0))
        abort();
    zlib_inflate(data, size, out, 4 * size, &message); /* as if it were a stream */
    xfree(out);
    xfree(stream);
    return 0;
}
