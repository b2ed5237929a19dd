/*
 * app/report.c -- the --report CSV (report.h).
 */
#include "report.h"

#include <time.h>

#include "../base/output.h"
#include "../image/compare.h"

int report_open(struct report *r, const char *csv_path, const struct image *reference,
                int width, int height, const struct render_settings *rs, struct error *err)
{
    r->csv = NULL;
    r->window = NULL;
    if (reference->width != width || reference->height != height)
        return error_set(err, "", 0, "--reference is %dx%d but the image is %dx%d",
                         reference->width, reference->height, width, height);
    r->csv = output_open(csv_path, err);
    if (r->csv == NULL)
        return -1;
    fprintf(r->csv, "seconds,work,rmse,relmse\n");
    r->reference = reference;
    r->x0 = rs->x0;
    r->y0 = rs->y0;
    r->window = image_create(rs->x1 - rs->x0, rs->y1 - rs->y0);
    for (int y = 0; y < r->window->height; y++)
        for (int x = 0; x < r->window->width; x++)
            image_set(r->window, x, y, image_get(reference, x + r->x0, y + r->y0));
    return 0;
}

double report_checkpoint(void *context, const struct image *mean, long long work,
                         double seconds)
{
    clock_t start = clock();
    struct report *r = context;
    struct image_error e = image_compare(mean, r->window);
    fprintf(r->csv, "%.6f,%lld,%.9g,%.9g\n", seconds, work, e.rmse, e.relmse);
    fflush(r->csv);
    return (double)(clock() - start) / CLOCKS_PER_SEC;
}

int report_close(struct report *r, struct error *err)
{
    image_free(r->window);
    r->window = NULL;
    FILE *csv = r->csv;
    r->csv = NULL;
    return csv != NULL ? output_commit(csv, err) : 0;
}

void report_abandon(struct report *r)
{
    image_free(r->window);
    r->window = NULL;
    if (r->csv != NULL)
        output_abandon(r->csv);
    r->csv = NULL;
}
