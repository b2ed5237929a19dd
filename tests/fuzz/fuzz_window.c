/*
 * tests/fuzz/fuzz_window.c -- libFuzzer target for the record beside a crop's PFM
 * (app/tile.c, FILE.pfm.window, read by photon merge), built by `make fuzz`; a
 * development tool only. The input becomes NAME.window for tile_record_read(NAME).
 *   build/fuzz/fuzz_window CORPUS_DIR tests/fuzz/seeds/window
 */
#include <stdint.h>
#include <stdio.h>

#include "../../src/app/tile.h"
#include "../../src/base/output.h"
#include "input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char name[FILENAME_MAX];
    const char *tile = input_file(data, size);
    snprintf(name, sizeof name, "%s%s", tile, TILE_RECORD_SUFFIX);
    if (rename(tile, name) != 0)
        return 0;
    struct tile_record r;
    struct error err;
    tile_record_read(tile, &r, &err);
    remove(name);
    outputs_abandon();
    return 0;
}
