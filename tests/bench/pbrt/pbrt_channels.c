/*
 * tests/bench/pbrt/pbrt_channels.c -- `make bench-pbrt`'s one step in C: three grey pbrt-v4
 * renders made into one colour image comparable with ours.
 *
 *   pbrt-channels OUT.pfm R.pfm G.pfm B.pfm
 *
 * pbrt-v4 renders spectrally, so the bench renders each of our channels as its own grey
 * scene (`photon export --format pbrt --channel R|G|B`, reference/README.md, "Colour in
 * pbrt-v4"): every albedo and radiance that channel's value, a constant spectrum, whose
 * render's luminance is exactly our channel. Pixel by pixel, channel c of OUT.pfm is the
 * luminance of the c-th input, Y = 0.2126 R + 0.7152 G + 0.0722 B (the film's colour
 * space, sRGB: its primaries' luminances). The three inputs must have one size.
 *
 * A development tool, built only by `make bench-pbrt`; photon never needs it.
 */
#include <stdio.h>

#include "../../../src/base/error.h"
#include "../../../src/image/image.h"

static double luminance(struct vec3 c)
{
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

int main(int argc, char **argv)
{
    if (argc != 5) {
        fprintf(stderr, "usage: pbrt-channels OUT.pfm R.pfm G.pfm B.pfm\n");
        return 2;
    }
    struct error err = {0};
    struct image *in[3] = {NULL, NULL, NULL};
    for (int c = 0; c < 3; c++) {
        in[c] = pfm_read(argv[2 + c], &err);
        if (in[c] == NULL) {
            error_print(&err);
            return error_exit_status(&err);
        }
        if (in[c]->width != in[0]->width || in[c]->height != in[0]->height) {
            fprintf(stderr, "pbrt-channels: %s is %d x %d, %s %d x %d\n", argv[2 + c],
                    in[c]->width, in[c]->height, argv[2], in[0]->width, in[0]->height);
            return 2;
        }
    }
    struct image *out = image_create(in[0]->width, in[0]->height);
    for (int y = 0; y < out->height; y++)
        for (int x = 0; x < out->width; x++)
            image_set(out, x, y,
                      vec3(luminance(image_get(in[0], x, y)), luminance(image_get(in[1], x, y)),
                           luminance(image_get(in[2], x, y))));
    int status = 0;
    if (pfm_write(argv[1], out, &err) != 0) {
        error_print(&err);
        status = error_exit_status(&err);
    }
    image_free(out);
    for (int c = 0; c < 3; c++)
        image_free(in[c]);
    return status;
}
