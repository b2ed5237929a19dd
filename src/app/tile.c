/*
 * app/tile.c -- reading and writing the record beside a crop's PFM (tile.h).
 *
 * The reader is strict: the six lines in their order, each with exactly its words, every
 * number in range, nothing after them. A record that says less than it should must not
 * let merge place a tile where it does not belong.
 */
#include "tile.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../base/hash.h"
#include "../base/input.h"
#include "../base/number.h"
#include "../base/output.h"
#include "../image/image.h"

#define RECORD_LINE_MAX 128 /* the longest valid line, "window" with four 5-digit numbers,
                               is under 40 bytes                                          */
#define RECORD_WORDS_MAX 5  /* "window X0 Y0 X1 Y1" */

struct record_reader {
    struct input in;
    const char *file;             /* the record's name, for messages       */
    int line;                     /* 1-based number of the line in text    */
    char text[RECORD_LINE_MAX];   /* the current line, cut into words      */
    char *words[RECORD_WORDS_MAX];
    int n_words;
};

uint64_t tile_pixels_hash(const struct image *image)
{
    uint64_t h = FNV1A_OFFSET_BASIS;
    for (int y = 0; y < image->height; y++)
        for (int x = 0; x < image->width; x++) {
            struct vec3 v = image_get(image, x, y);
            float rgb[3] = {(float)v.x, (float)v.y, (float)v.z};
            unsigned char bytes[12];
            for (int c = 0; c < 3; c++) {
                uint32_t bits;
                memcpy(&bits, &rgb[c], sizeof bits);
                for (int i = 0; i < 4; i++)
                    bytes[4 * c + i] = (unsigned char)(bits >> (8 * i));
            }
            h = fnv1a(h, bytes, sizeof bytes);
        }
    return h;
}

/* pfm_name + TILE_RECORD_SUFFIX into name[FILENAME_MAX]. */
static int record_name(const char *pfm_name, char *name, struct error *err)
{
    if (strlen(pfm_name) + sizeof TILE_RECORD_SUFFIX > FILENAME_MAX)
        return error_set(err, pfm_name, 0, "the file name is too long");
    sprintf(name, "%s%s", pfm_name, TILE_RECORD_SUFFIX);
    return 0;
}

void tile_record_declare(const char *pfm_name)
{
    char name[FILENAME_MAX];
    if (record_name(pfm_name, name, NULL) == 0)
        output_declare(name, "the --crop record beside -o");
}

int tile_record_write(const char *pfm_name, const struct tile_record *r, struct error *err)
{
    char name[FILENAME_MAX];
    if (record_name(pfm_name, name, err) < 0)
        return -1;
    FILE *f = output_open(name, err);
    if (f == NULL)
        return -1;
    fprintf(f, "photon-window %d\nwindow %d %d %d %d\nimage %d %d\n", TILE_RECORD_VERSION,
            r->x0, r->y0, r->x1, r->y1, r->width, r->height);
    fprintf(f, "hash fnv1a64 %016llx\npixels fnv1a64 %016llx\ntime-limit %g\n",
            (unsigned long long)r->hash, (unsigned long long)r->pixels, r->time_limit);
    return output_commit(f, err); /* a failed write shows in ferror(), checked there */
}

int tile_record_remove(const char *pfm_name, struct error *err)
{
    char name[FILENAME_MAX];
    struct tile_record r;
    struct error not_a_record;
    if (record_name(pfm_name, name, err) < 0)
        return -1;
    if (tile_record_read(pfm_name, &r, &not_a_record) < 0)
        return 0; /* none, or the user's file of that name (tile.h): nothing of ours */
    if (remove(name) != 0)
        return error_set(err, name, 0, "cannot remove this record of an earlier crop (%s), "
                         "which would make photon merge take the whole image %s for that "
                         "crop", strerror(errno), pfm_name);
    return 0;
}

/* Cuts rd->text into words at white space; -1 when there are more than RECORD_WORDS_MAX. */
static int split_words(struct record_reader *rd)
{
    rd->n_words = 0;
    for (char *s = rd->text;;) {
        while (isspace((unsigned char)*s))
            *s++ = '\0';
        if (*s == '\0')
            return 0;
        if (rd->n_words == RECORD_WORDS_MAX)
            return -1;
        rd->words[rd->n_words++] = s;
        while (*s != '\0' && !isspace((unsigned char)*s))
            s++;
    }
}

/* Reads the next line, which must be form's keyword (its first word) and as many words
 * after it as form has; form spells the line for the message ("image WIDTH HEIGHT"). */
static int read_line(struct record_reader *rd, const char *form, struct error *err)
{
    int status = input_line(&rd->in, rd->text, sizeof rd->text, err);
    rd->line = rd->in.line + (status == 0);
    if (status < 0)
        return -1;
    if (status == 0)
        return error_set(err, rd->file, rd->line, "expected '%s', found the end of the file",
                         form);
    size_t keyword_length = strcspn(form, " ");
    int n_form_words = 1;
    for (const char *c = form; *c != '\0'; c++)
        n_form_words += *c == ' ';
    if (split_words(rd) < 0 || rd->n_words != n_form_words ||
        strlen(rd->words[0]) != keyword_length ||
        strncmp(rd->words[0], form, keyword_length) != 0)
        return error_set(err, rd->file, rd->line, "expected '%s'", form);
    return 0;
}

/* Word k of the line as a whole number in [min, max]. */
static int read_int(const struct record_reader *rd, int k, int min, int max, int *value,
                    struct error *err)
{
    double v;
    if (!number_parse(rd->words[k], 1, &v) || v < min || v > max)
        return error_set(err, rd->file, rd->line, "%s: '%s' is not a whole number from %d "
                         "to %d", rd->words[0], rd->words[k], min, max);
    *value = (int)v;
    return 0;
}

/* form, "hash fnv1a64 HHHHHHHHHHHHHHHH" or "pixels ...": the method named, and exactly 16
 * hex digits. */
static int read_hash(struct record_reader *rd, const char *form, uint64_t *hash,
                     struct error *err)
{
    if (read_line(rd, form, err) < 0)
        return -1;
    const char *digits = rd->words[2];
    int hex = strlen(digits) == 16;
    for (int i = 0; hex && i < 16; i++)
        hex = isxdigit((unsigned char)digits[i]);
    if (strcmp(rd->words[1], "fnv1a64") != 0 || !hex)
        return error_set(err, rd->file, rd->line, "%s: expected 'fnv1a64' and 16 hex "
                         "digits, got '%s %s'", rd->words[0], rd->words[1], digits);
    *hash = (uint64_t)strtoull(digits, NULL, 16);
    return 0;
}

static int read_time_limit(struct record_reader *rd, double *seconds, struct error *err)
{
    if (read_line(rd, "time-limit SECONDS", err) < 0)
        return -1;
    if (!number_parse(rd->words[1], 0, seconds) || *seconds < 0)
        return error_set(err, rd->file, rd->line, "time-limit: '%s' is not a number of "
                         "seconds (0 for none)", rd->words[1]);
    return 0;
}

/* The six lines, in order, and nothing after them. */
static int read_fields(struct record_reader *rd, struct tile_record *r, struct error *err)
{
    int version, w[4];
    if (read_line(rd, "photon-window 2", err) < 0 ||
        read_int(rd, 1, 0, INT_MAX, &version, err) < 0)
        return -1;
    if (version != TILE_RECORD_VERSION)
        return error_set(err, rd->file, rd->line, "version %d of the record; this photon "
                         "reads version %d (render the tile again)", version,
                         TILE_RECORD_VERSION);
    if (read_line(rd, "window X0 Y0 X1 Y1", err) < 0)
        return -1;
    int window_line = rd->line; /* checked against the image, read next */
    for (int k = 0; k < 4; k++)
        if (read_int(rd, k + 1, 0, MAX_IMAGE_SIDE, &w[k], err) < 0)
            return -1;
    if (read_line(rd, "image WIDTH HEIGHT", err) < 0 ||
        read_int(rd, 1, 1, MAX_IMAGE_SIDE, &r->width, err) < 0 ||
        read_int(rd, 2, 1, MAX_IMAGE_SIDE, &r->height, err) < 0 ||
        read_hash(rd, "hash fnv1a64 HHHHHHHHHHHHHHHH", &r->hash, err) < 0 ||
        read_hash(rd, "pixels fnv1a64 HHHHHHHHHHHHHHHH", &r->pixels, err) < 0 ||
        read_time_limit(rd, &r->time_limit, err) < 0)
        return -1;
    if (!(w[0] < w[2] && w[2] <= r->width && w[1] < w[3] && w[3] <= r->height))
        return error_set(err, rd->file, window_line, "window %d %d %d %d: not a window of the "
                         "%dx%d image (need X0 < X1 <= width, Y0 < Y1 <= height)", w[0], w[1],
                         w[2], w[3], r->width, r->height);
    r->x0 = w[0];
    r->y0 = w[1];
    r->x1 = w[2];
    r->y1 = w[3];
    int more = input_line(&rd->in, rd->text, sizeof rd->text, err);
    if (more > 0)
        return error_set(err, rd->file, rd->line + 1, "unexpected text after the record");
    return more;
}

int tile_record_read(const char *pfm_name, struct tile_record *r, struct error *err)
{
    char name[FILENAME_MAX];
    if (record_name(pfm_name, name, err) < 0)
        return -1;
    struct record_reader rd;
    if (input_open(&rd.in, name, err) < 0)
        return error_set(err, name, 0, "%s (is %s a --crop render?)", err->message, pfm_name);
    rd.file = name;
    rd.line = 0;
    int status = read_fields(&rd, r, err);
    input_close(&rd.in);
    return status;
}
