/*
 * image/image_file.c -- the one entry for reading and for writing an image file: the
 * format is told by the file's first bytes when reading, by the name's ending when
 * writing (image.h).
 *
 * A PFM starts with "PF" (or "Pf", which pfm.c refuses by name); an OpenEXR file with its
 * magic number's bytes 0x76 0x2f 0x31 0x01. Anything else goes to pfm.c, whose message
 * says what a PFM must start with.
 */
#include "image.h"

#include <string.h>

#include "../base/input.h"
#include "exr.h"

/* Whether the file starts with OpenEXR's magic number; 0 when it cannot be read (the
 * PFM reader then says why). */
static int starts_as_exr(const char *name, struct error *err)
{
    static const unsigned char magic[4] = {0x76, 0x2f, 0x31, 0x01};
    unsigned char first[4];
    struct input in;
    if (input_open(&in, name, err) < 0)
        return -1;
    int exr = fread(first, 1, sizeof first, in.f) == sizeof first &&
              memcmp(first, magic, sizeof magic) == 0;
    input_close(&in);
    return exr;
}

static struct image *read_either(const char *name, int plus_infinity, struct error *err)
{
    int exr = starts_as_exr(name, err);
    if (exr < 0)
        return NULL;
    if (exr)
        return exr_read(name, plus_infinity, err);
    return plus_infinity ? pfm_read_bounds(name, err) : pfm_read(name, err);
}

struct image *image_read(const char *name, struct error *err)
{
    return read_either(name, 0, err);
}

struct image *image_read_bounds(const char *name, struct error *err)
{
    return read_either(name, 1, err);
}

int image_name_is_exr(const char *name)
{
    size_t n = strlen(name);
    return n >= 4 && strcmp(name + n - 4, ".exr") == 0;
}

int image_write(const char *name, const struct image *img, struct error *err)
{
    return image_name_is_exr(name) ? exr_write(name, img, err) : pfm_write(name, img, err);
}
