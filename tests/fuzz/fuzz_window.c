/*
 * tests/fuzz/fuzz_window.c -- libFuzzer target for the record beside a crop's PFM
 * (app/tile.c, FILE.pfm.window, read by photon merge), built by `make fuzz`; a
 * development tool only. The input becomes NAME.window for tile_record_read(NAME).
 *
 * A record the reader takes is checked for its values, not only read: its window lies in
 * its image (merge writes there), its time limit is a finite number of seconds, and
 * writing it back and reading that gives the same record (no number read other than it
 * is written); a failure aborts, as a crash or a sanitizer report does: each is a bug.
 *   build/fuzz/fuzz_window CORPUS_DIR tests/fuzz/seeds/window
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "../../src/app/tile.h"
#include "../../src/base/output.h"
#include "../../src/image/image.h"
#include "input.h"

/* Whether record r's values are in tile.h's ranges. */
static int in_range(const struct tile_record *r)
{
    return 0 <= r->x0 && r->x0 < r->x1 && r->x1 <= r->width && 0 <= r->y0 &&
           r->y0 < r->y1 && r->y1 <= r->height && r->width <= MAX_IMAGE_SIDE &&
           r->height <= MAX_IMAGE_SIDE && isfinite(r->time_limit) && r->time_limit >= 0;
}

static int same_record(const struct tile_record *a, const struct tile_record *b)
{
    return a->x0 == b->x0 && a->y0 == b->y0 && a->x1 == b->x1 && a->y1 == b->y1 &&
           a->width == b->width && a->height == b->height && a->hash == b->hash &&
           a->pixels == b->pixels && a->time_limit == b->time_limit;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char name[FILENAME_MAX];
    const char *tile = input_file(data, size);
    snprintf(name, sizeof name, "%s%s", tile, TILE_RECORD_SUFFIX);
    if (rename(tile, name) != 0)
        return 0;
    struct tile_record r, back;
    struct error err;
    if (tile_record_read(tile, &r, &err) == 0) {
        remove(name);
        /* %g keeps 6 digits of the time limit: a record photon writes reads back exactly */
        if (!in_range(&r) || tile_record_write(tile, &r, &err) != 0 ||
            tile_record_read(tile, &back, &err) != 0 ||
            !(same_record(&r, &back) || r.time_limit != back.time_limit))
            abort();
    }
    remove(name);
    outputs_abandon();
    return 0;
}
