/*
 * image/false_colour.c -- an image in false colour with its scale beside it
 * (false_colour.h).
 *
 * The number of a pixel is the largest of its three channels. For an error image (|a - b|,
 * a relative error, photon --error's bounds) that is the worst channel's error: a mean
 * would show an error in one channel at a third of its size, and luminance would all but
 * hide one in blue (weight 0.07). For a radiance image it is the brightest channel, which
 * is what clips first on a display.
 *
 * The default range. Bottom: 0 (with --log, the top / 1000: three decades). Top: the 99th
 * percentile of the numbers, by nearest rank (the ceil(0.99 n)-th smallest of the n
 * pixels' numbers, +Inf left out), so that a few outliers (fireflies) do not squash the
 * rest of the picture into the map's first colours; rounded to two significant digits, so
 * that the label states it exactly. When that is not above the bottom (an image of 99%
 * zeros), the top is the largest number instead, and when no number is above the bottom,
 * bottom + 1 (with --log, bottom x 10). The top label then says " p99" only when the top
 * is the percentile. Numbers beyond the range take the colour of its nearer end.
 *
 * The layout, every length in units of s = image height / 256 rounded down, from 1 to 4
 * (so the labels stay about as large beside the image at any size): to the right of the
 * image a strip of 6 (gap) + 12 (bar) + 2 (tick) + 4 (gap) + the longest label's width
 * (6 per character less 1) + 4 (margin), that is s (27 + 6 n) pixels for a longest label of
 * n characters; the picture is as tall as the image but at least 60 s, the image at the
 * top left, the rest black. The bar runs from 6 s below the top to 6 s above the bottom
 * (an odd number of rows, so that its middle row is the middle of the range): max's colour
 * at the top, min's at the bottom, with ticks and labels at both ends and the middle
 * (linear: the mean of the ends; log: their geometric mean). Labels and ticks are white,
 * 5 x 7 glyphs (font.h), each centred on its row.
 */
#include "false_colour.h"

#include <assert.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../base/alloc.h"
#include "colour_map.h"
#include "font.h"
#include "png.h"

#define SIDE_PER_SCALE 256 /* image rows per unit of the layout's scale s              */
#define SCALE_MAX 4        /* the largest s                                             */
#define GAP 6              /* between the image and the bar; the bar's ends from the
                              picture's top and bottom                                  */
#define BAR 12             /* the bar's width                                           */
#define TICK 2             /* a tick's length, to the right of the bar                  */
#define LABEL_GAP 4        /* between a tick and its label: wider than between glyphs,
                              so that a tick does not read as a minus sign              */
#define MARGIN 4           /* right of the longest label                                */
#define MIN_HEIGHT 60      /* the picture's least height: room for three labels         */
#define LABEL_MAX 32       /* a label's characters, with its '\0'                       */

static const unsigned char white[3] = {255, 255, 255};

double false_colour_number(struct vec3 pixel)
{
    return fmax(pixel.x, fmax(pixel.y, pixel.z));
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* x to two significant digits, to the nearest; 0 stays 0. */
static double two_digits(double x)
{
    if (x == 0 || !isfinite(x))
        return x;
    double unit = pow(10.0, floor(log10(fabs(x))) - 1.0);
    return floor(x / unit + 0.5) * unit;
}

/* The top of the default range for numbers sorted ascending, n_finite of them finite
 * (+Inf after them), above bottom; *percentile 1 when it is the percentile. */
static double default_top(const double *sorted, size_t n_finite, double bottom,
                          int *percentile)
{
    *percentile = 0;
    if (n_finite == 0)
        return bottom;
    /* ceil(99 n / 100) in whole numbers: 0.99 is no double, and 0.99 x 100 may round up */
    unsigned long long n = n_finite;
    size_t rank = (size_t)((FALSE_COLOUR_PERCENTILE * n + 99) / 100);
    double top = two_digits(sorted[rank - 1]); /* rank >= 1, since n >= 1 */
    if (top > bottom) {
        *percentile = 1;
        return top;
    }
    return two_digits(sorted[n_finite - 1]) > bottom ? two_digits(sorted[n_finite - 1])
                                                     : sorted[n_finite - 1];
}

void false_colour_range(const struct image *img, int has_min, int has_max,
                        struct false_colour *fc)
{
    size_t n = (size_t)img->width * (size_t)img->height, n_finite = 0;
    double *numbers = xmalloc(n, sizeof *numbers, "false-colour numbers");
    for (size_t i = 0; i < n; i++) {
        double v = false_colour_number(img->pixels[i]);
        if (isfinite(v))
            numbers[n_finite++] = v;
    }
    qsort(numbers, n_finite, sizeof *numbers, compare_doubles);
    fc->percentile = 0;
    if (!has_max) {
        double bottom = has_min ? fc->min : 0.0; /* without --min, any top above 0 will do */
        fc->max = default_top(numbers, n_finite, bottom, &fc->percentile);
        if (!(fc->max > bottom)) /* no number above the bottom */
            fc->max = fc->log && has_min ? bottom * 10.0 : bottom + 1.0;
    }
    if (!has_min)
        fc->min = fc->log ? fc->max / FALSE_COLOUR_LOG_DECADES
                  : fc->max > 0 ? 0.0 : fc->max - 1.0; /* a given top at or below 0 */
    xfree(numbers);
}

void false_colour_label(double value, const struct false_colour *fc, char *text,
                        size_t size)
{
    char number[LABEL_MAX];
    double shown = fc->percent ? 100.0 * value : value;
    snprintf(number, sizeof number, "%.3g", shown == 0 ? 0.0 : shown); /* no "-0" */
    char *e = strchr(number, 'e');
    if (e != NULL) { /* "1e-05" -> "1e-5", "2.5e+06" -> "2.5e6" */
        char *digits = e + 1 + (e[1] == '+' || e[1] == '-');
        char *first = digits;
        while (first[0] == '0' && first[1] != '\0')
            first++;
        memmove(digits, first, strlen(first) + 1);
        if (e[1] == '+')
            memmove(e + 1, e + 2, strlen(e + 2) + 1);
    }
    snprintf(text, size, "%s%s", number, fc->percent ? "%" : "");
}

struct false_colour_layout false_colour_layout(int width, int height, int label_chars)
{
    struct false_colour_layout l;
    int s = height / SIDE_PER_SCALE;
    l.scale = s = s < 1 ? 1 : s > SCALE_MAX ? SCALE_MAX : s;
    l.bar_x0 = width + GAP * s;
    l.bar_x1 = l.bar_x0 + BAR * s;
    l.label_x = l.bar_x1 + (TICK + LABEL_GAP) * s;
    l.width = l.label_x + (FONT_ADVANCE * label_chars - (FONT_ADVANCE - FONT_WIDTH)) * s +
              MARGIN * s;
    l.height = height > MIN_HEIGHT * s ? height : MIN_HEIGHT * s;
    l.bar_y0 = GAP * s;
    l.bar_y1 = l.height - GAP * s;
    if ((l.bar_y1 - 1 - l.bar_y0) % 2 != 0) /* an odd number of rows: a middle row */
        l.bar_y1--;
    return l;
}

/* Where number v falls in fc's range: 0 at min, 1 at max (beyond: below 0, above 1). */
static double position(double v, const struct false_colour *fc)
{
    if (!fc->log)
        return (v - fc->min) / (fc->max - fc->min);
    return v > 0 ? (log10(v) - log10(fc->min)) / (log10(fc->max) - log10(fc->min)) : 0.0;
}

/* One label with its tick, centred on row y. */
static void draw_label(struct picture *p, const struct false_colour_layout *l, int y,
                       const char *text)
{
    int s = l->scale;
    for (int row = y; row < y + s; row++)
        for (int x = l->bar_x1; x < l->bar_x1 + TICK * s; x++)
            memcpy(p->rgb + 3 * ((size_t)row * (size_t)p->width + (size_t)x), white, 3);
    font_draw(p->rgb, p->width, p->height, l->label_x, y - (FONT_HEIGHT / 2) * s, s, text,
              white);
}

struct picture false_colour_picture(const struct image *img, const struct false_colour *fc)
{
    assert(fc->min < fc->max && (!fc->log || fc->min > 0));
    char top[LABEL_MAX], middle[LABEL_MAX], bottom[LABEL_MAX];
    double mid = fc->log ? sqrt(fc->min) * sqrt(fc->max) : 0.5 * (fc->min + fc->max);
    false_colour_label(fc->max, fc, top, sizeof top - 4);
    if (fc->percentile)
        strcat(top, " p99");
    false_colour_label(mid, fc, middle, sizeof middle);
    false_colour_label(fc->min, fc, bottom, sizeof bottom);
    size_t longest = strlen(top);
    if (strlen(middle) > longest)
        longest = strlen(middle);
    if (strlen(bottom) > longest)
        longest = strlen(bottom);
    struct false_colour_layout l = false_colour_layout(img->width, img->height, (int)longest);
    struct picture p = {l.width, l.height, NULL};
    p.rgb = xmalloc((size_t)p.width * (size_t)p.height, 3, "false-colour picture");
    memset(p.rgb, 0, (size_t)p.width * (size_t)p.height * 3);
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++)
            colour_map(position(false_colour_number(image_get(img, x, y)), fc),
                       p.rgb + 3 * ((size_t)y * (size_t)p.width + (size_t)x));
    int last = l.bar_y1 - 1;
    for (int y = l.bar_y0; y <= last; y++) {
        unsigned char rgb[3];
        colour_map((double)(last - y) / (double)(last - l.bar_y0), rgb);
        for (int x = l.bar_x0; x < l.bar_x1; x++)
            memcpy(p.rgb + 3 * ((size_t)y * (size_t)p.width + (size_t)x), rgb, 3);
    }
    draw_label(&p, &l, l.bar_y0, top);
    draw_label(&p, &l, (l.bar_y0 + last) / 2, middle);
    draw_label(&p, &l, last, bottom);
    return p;
}

void picture_free(struct picture *p)
{
    xfree(p->rgb);
    p->rgb = NULL;
}

int picture_write(const char *name, const struct picture *p, struct error *err)
{
    size_t n = strlen(name);
    if (n >= 4 && strcmp(name + n - 4, display_suffix(DISPLAY_PPM)) == 0)
        return ppm_write_bytes(name, p->width, p->height, p->rgb, err);
    return png_write_bytes(name, p->width, p->height, p->rgb, err);
}
