/*
 * app/merge.c -- `photon merge` (merge.h): tiles checked against each other, then pasted.
 *
 * Every check runs before anything is written: first each record alone and against the
 * first tile's (same image, same hash, no time limit), then the windows against each other
 * (no overlap) and the image (no gap), then each PFM against its record (its window's size,
 * its pixels' hash). Once FULL.pfm is in place, a crop's record of that name left by an
 * earlier render is removed, as a whole render removes it (tile.h). Pixels are copied, never computed, so the
 * whole image's floats come back exactly: the PFM reader widens each float to a double and
 * the writer rounds it back to the same float.
 */
#include "merge.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../base/alloc.h"
#include "../base/option_once.h"
#include "../base/output.h"
#include "../image/image.h"
#include "option_values.h"
#include "tile.h"

#define MERGE_USAGE "usage: photon merge -o FULL.pfm|.exr TILE.pfm|.exr [TILE ...] " \
                    "[--exposure E]"
#define MERGE_MAX_GAPS 4 /* missing windows named in one message; the rest are counted */

struct merge_args {
    char output[OUTPUT_PATH_MAX]; /* FULL.pfm; "" until -o                         */
    enum display_format display;  /* FULL.png or FULL.ppm beside it, as -o's ending */
    double exposure;              /* for the display image, as a render's --exposure */
    char **tiles;                 /* borrowed from argv: the tiles' PFMs            */
    int n_tiles;
};

const struct option_arity merge_options[] = {
    {"-o", 1}, {"--exposure", 1}, {"--help", 0}, {NULL, 0},
};

/* The arguments after "merge"; 1 when --help was printed. */
static int parse_merge_args(int argc, char **argv, struct merge_args *args, struct error *err)
{
    args->output[0] = '\0';
    args->display = DISPLAY_PNG;
    args->exposure = 1.0;
    args->tiles = xmalloc((size_t)argc, sizeof *args->tiles, "tile names");
    args->n_tiles = 0;
    struct option_once once = {{0}, 0};
    for (int i = 1; i < argc; i++) {
        const char *value = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            printf("%s\n\nPuts crops (renders with --crop, each with its FILE.pfm.window) "
                   "back into the\nwhole image: FULL.pfm and FULL.png beside it (-o FULL.png "
                   "means the same; -o\nFULL.ppm writes FULL.pfm and FULL.ppm; -o FULL.exr, "
                   "OpenEXR in place of the PFM;\ntiles are PFM or OpenEXR files). Refused, "
                   "with "
                   "exit status 2 and nothing\nwritten: tiles of different images, scenes, "
                   "modes, seeds or options; tiles\nrendered with --time-limit; overlaps, and "
                   "a tile given twice; gaps (named as\n--crop windows to render); a PFM "
                   "that is not the one its record was written\nwith (a --checkpoint).\n",
                   MERGE_USAGE);
            return 1;
        }
        if ((strcmp(argv[i], "-o") == 0 || strcmp(argv[i], "--exposure") == 0) &&
            option_once(&once, "merge", argc, argv, i, 1, err) < 0)
            return -1;
        if (strcmp(argv[i], "-o") == 0 &&
            read_output(value, args->output, &args->display, err) < 0)
            return -1;
        if (strcmp(argv[i], "--exposure") == 0 &&
            read_number("--exposure", value, 0, 1e30, NUMBER_REAL, &args->exposure, err) < 0)
            return -1;
        if (strcmp(argv[i], "-o") == 0 || strcmp(argv[i], "--exposure") == 0)
            i++;
        else if (argv[i][0] == '-' && argv[i][1] != '\0')
            return error_set(err, "", 0, "merge: unknown option '%s'; " MERGE_USAGE, argv[i]);
        else
            args->tiles[args->n_tiles++] = argv[i];
    }
    if (args->output[0] == '\0' || args->n_tiles == 0)
        return error_set(err, "", 0, "merge: -o and at least one tile are needed; " MERGE_USAGE);
    return 0;
}

/* Tile i's record, refused when it cannot be merged with tile 0's (already read). */
static int read_record(const struct merge_args *args, int i, struct tile_record *records,
                       struct error *err)
{
    const char *name = args->tiles[i];
    struct tile_record *r = &records[i];
    if (tile_record_read(name, r, err) < 0)
        return -1;
    if (r->time_limit > 0)
        return error_set(err, name, 0, "rendered with --time-limit %g, so its pixels depend "
                         "on the speed of the machine that made it; render tiles without "
                         "--time-limit (their work fixed by --spp, or --passes in 2008 and "
                         "2009)", r->time_limit);
    if (r->width != records[0].width || r->height != records[0].height)
        return error_set(err, name, 0, "a window of a %dx%d image, but %s is of a %dx%d one",
                         r->width, r->height, args->tiles[0], records[0].width,
                         records[0].height);
    if (r->hash != records[0].hash)
        return error_set(err, name, 0, "made from other scene files, mode, seed or options "
                         "than %s (hash %016llx, not %016llx)", args->tiles[0],
                         (unsigned long long)r->hash, (unsigned long long)records[0].hash);
    return 0;
}

static long long window_area(const struct tile_record *r)
{
    return (long long)(r->x1 - r->x0) * (r->y1 - r->y0);
}

static int same_window(const struct tile_record *a, const struct tile_record *b)
{
    return a->x0 == b->x0 && a->y0 == b->y0 && a->x1 == b->x1 && a->y1 == b->y1;
}

/* No pixel in two tiles: each pair's windows must not intersect (n^2 pairs, for the few
 * tiles an image is cut into). Two tiles of one window are one tile given twice, under
 * one name or two: their hashes agree (read_record), so by the determinism README states their
 * pixels do too; the message says so and names both arguments, not an overlap. */
static int check_overlaps(const struct merge_args *args, const struct tile_record *records,
                          struct error *err)
{
    for (int i = 0; i < args->n_tiles; i++)
        for (int j = 0; j < i; j++) {
            const struct tile_record *a = &records[j], *b = &records[i];
            if (same_window(a, b))
                return error_set(err, "", 0, "merge: one tile given twice: tile %d (%s) and "
                                 "tile %d (%s) are both the window %d %d %d %d", j + 1,
                                 args->tiles[j], i + 1, args->tiles[i], a->x0, a->y0, a->x1,
                                 a->y1);
            int x0 = a->x0 > b->x0 ? a->x0 : b->x0, x1 = a->x1 < b->x1 ? a->x1 : b->x1;
            int y0 = a->y0 > b->y0 ? a->y0 : b->y0, y1 = a->y1 < b->y1 ? a->y1 : b->y1;
            if (x0 < x1 && y0 < y1)
                return error_set(err, args->tiles[i], 0, "overlaps %s in the window %d %d "
                                 "%d %d (X0 Y0 X1 Y1)", args->tiles[j], x0, y0, x1, y1);
        }
    return 0;
}

/* Whether pixels x0..x1-1 of row y are all uncovered. */
static int row_uncovered(const unsigned char *covered, int width, int y, int x0, int x1)
{
    for (int x = x0; x < x1; x++)
        if (covered[(size_t)y * width + x])
            return 0;
    return 1;
}

/* From the first pixel of covered[] not yet covered, in reading order: the rectangle that
 * runs right while pixels are uncovered, then down while its whole row is; marked covered.
 * A missing tile of a grid comes out as its own window. w: x0 y0 x1 y1. */
static void next_gap(unsigned char *covered, int width, int height, int *w)
{
    size_t i = 0;
    while (covered[i])
        i++; /* the caller knows some pixel is uncovered */
    int x0 = (int)(i % (size_t)width), y0 = (int)(i / (size_t)width);
    int x1 = x0 + 1, y1 = y0 + 1;
    while (x1 < width && !covered[(size_t)y0 * width + x1])
        x1++;
    while (y1 < height && row_uncovered(covered, width, y1, x0, x1))
        y1++;
    for (int y = y0; y < y1; y++)
        memset(covered + (size_t)y * width + x0, 1, (size_t)(x1 - x0));
    w[0] = x0;
    w[1] = y0;
    w[2] = x1;
    w[3] = y1;
}

/* Every pixel in some tile. With no overlap (checked first), the windows cover the image
 * exactly when their areas add up to its area; otherwise the missing windows are named, as
 * --crop arguments that would fill them. */
static int check_coverage(const struct merge_args *args, const struct tile_record *records,
                          struct error *err)
{
    int width = records[0].width, height = records[0].height;
    long long missing = (long long)width * height;
    for (int i = 0; i < args->n_tiles; i++)
        missing -= window_area(&records[i]);
    if (missing == 0)
        return 0;
    unsigned char *covered = xcalloc((size_t)width * height, 1, "merge coverage");
    for (int i = 0; i < args->n_tiles; i++)
        for (int y = records[i].y0; y < records[i].y1; y++)
            memset(covered + (size_t)y * width + records[i].x0, 1,
                   (size_t)(records[i].x1 - records[i].x0));
    char list[MERGE_MAX_GAPS * 32] = "";
    long long left = missing;
    for (int k = 0; k < MERGE_MAX_GAPS && left > 0; k++) {
        int w[4];
        next_gap(covered, width, height, w);
        left -= (long long)(w[2] - w[0]) * (w[3] - w[1]);
        sprintf(list + strlen(list), "%s--crop %d %d %d %d", k > 0 ? ", " : "", w[0], w[1],
                w[2], w[3]);
    }
    xfree(covered);
    return error_set(err, "", 0, "merge: the tiles leave %lld of the %dx%d image's pixels "
                     "uncovered: %s%s", missing, width, height, list,
                     left > 0 ? ", and more" : "");
}

/* Reads each tile's PFM, checks it is its window's size and the very pixels its record
 * was written with (tile.h), and copies it into full. */
static int paste_tiles(const struct merge_args *args, const struct tile_record *records,
                       struct image *full, struct error *err)
{
    for (int i = 0; i < args->n_tiles; i++) {
        const struct tile_record *r = &records[i];
        struct image *tile = image_read(args->tiles[i], err);
        if (tile == NULL)
            return error_set(err, err->file, err->line, "%s (tile %d)", err->message, i + 1);
        if (tile->width != r->x1 - r->x0 || tile->height != r->y1 - r->y0) {
            error_set(err, args->tiles[i], 0, "%dx%d pixels, but its record's window %d %d "
                      "%d %d is %dx%d", tile->width, tile->height, r->x0, r->y0, r->x1, r->y1,
                      r->x1 - r->x0, r->y1 - r->y0);
            image_free(tile);
            return -1;
        }
        uint64_t pixels = tile_pixels_hash(tile);
        if (pixels != r->pixels) {
            error_set(err, args->tiles[i], 0, "not the pixels its record %s%s describes "
                      "(pixels %016llx, not %016llx): the PFM was written again without it "
                      "(a --checkpoint, or a render that did not finish); render the tile "
                      "again", args->tiles[i], TILE_RECORD_SUFFIX,
                      (unsigned long long)pixels, (unsigned long long)r->pixels);
            image_free(tile);
            return -1;
        }
        for (int y = 0; y < tile->height; y++)
            for (int x = 0; x < tile->width; x++)
                image_set(full, r->x0 + x, r->y0 + y, image_get(tile, x, y));
        image_free(tile);
    }
    return 0;
}

static int merge_tiles(const struct merge_args *args, struct tile_record *records,
                       struct error *err)
{
    for (int i = 0; i < args->n_tiles; i++)
        if (read_record(args, i, records, err) < 0)
            return -1;
    if (check_overlaps(args, records, err) < 0 || check_coverage(args, records, err) < 0)
        return -1;
    struct image *full = image_create(records[0].width, records[0].height);
    int status = paste_tiles(args, records, full, err);
    if (status == 0)
        status = image_write_pair(args->output, args->display, full, args->exposure, err);
    image_free(full);
    return status;
}

int merge_command(int argc, char **argv)
{
    struct merge_args args;
    struct error err;
    int parsed = parse_merge_args(argc, argv, &args, &err);
    if (parsed == 0)
        image_declare_pair(args.output, args.display, "-o", args.display == DISPLAY_PPM
                                                                ? "the PPM beside -o"
                                                                : "the PNG beside -o");
    int status = parsed == 0 ? outputs_check(&err) : parsed;
    if (status == 0) {
        struct tile_record *records = xmalloc((size_t)args.n_tiles, sizeof *records,
                                              "tile records");
        status = merge_tiles(&args, records, &err);
        if (status == 0)
            status = outputs_publish(&err);
        if (status == 0) /* FULL.pfm is whole: a crop's record of that name would lie */
            status = tile_record_remove(args.output, &err);
        xfree(records);
    }
    if (status < 0)
        error_print(&err);
    xfree(args.tiles);
    return status < 0 ? error_exit_status(&err) : 0; /* 1: --help was printed */
}
