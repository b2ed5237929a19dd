/*
 * app/report.h -- error against time as a render progresses (--reference, --report).
 *
 * At each checkpoint the current image is compared with the reference (the same window of
 * it, for a crop) and one CSV row "seconds,work,rmse,relmse" is written: CPU seconds of
 * rendering (the comparisons themselves excluded), the work done so far (samples per
 * pixel, or photons emitted), and the metrics of image/compare.h.
 */
#ifndef PHOTON_REPORT_H
#define PHOTON_REPORT_H

#include <stdio.h>

#include "../modes/render.h"

struct report {
    FILE *csv;                     /* owned: a temporary until report_close()        */
    const struct image *reference; /* borrowed: the whole image's reference          */
    int x0, y0;                    /* the window's corner in the whole image          */
    struct image *window;          /* owned: the reference's pixels under the window  */
};

/* Opens the CSV and cuts the window out of reference, which must be the whole image's
 * size (width x height). Returns -1 with *err filled otherwise. */
int report_open(struct report *r, const char *csv_path, const struct image *reference,
                int width, int height, const struct render_settings *rs, struct error *err);

/* The checkpoint callback (struct checkpoint); context is a struct report. */
double report_checkpoint(void *context, const struct image *mean, long long work,
                         double seconds);

/* Completes the CSV (renamed into place) and frees the window; -1 on a failed write. */
int report_close(struct report *r, struct error *err);

/* Closes and removes an unfinished report. */
void report_abandon(struct report *r);

#endif
