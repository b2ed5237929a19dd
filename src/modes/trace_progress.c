/*
 * modes/trace_progress.c -- the progress lines of watched phases (trace_progress.h).
 */
#include "trace_progress.h"

#include <time.h>

static void show(struct watched_progress *wp, size_t done)
{
    progress_print(&wp->line, "%zu of %zu %s", done, wp->total, wp->units);
}

/* The work's watch: a line when one is due. */
static void at(void *context, size_t done)
{
    struct watched_progress *wp = context;
    wp->done = wp->before + done;
    if (progress_update(&wp->line, (double)wp->done, time(NULL)))
        show(wp, wp->done);
}

void watched_progress_begin(struct watched_progress *wp, int on, const char *phase,
                            size_t total, const char *units)
{
    wp->units = units;
    wp->total = total;
    wp->before = 0;
    wp->done = 0;
    progress_begin(&wp->line, on ? stderr : NULL, phase, (double)total, time(NULL));
    wp->watch.at = at;
    wp->watch.context = wp;
}

const struct work_watch *watched_progress_watch(const struct watched_progress *wp)
{
    return wp->line.out != NULL ? &wp->watch : NULL;
}

void watched_progress_end(struct watched_progress *wp, int finished)
{
    size_t done = finished ? wp->total : wp->done;
    if (progress_end(&wp->line, (double)done, time(NULL)))
        show(wp, done);
}

struct kdtree *balance_part(struct photon *photons, size_t n, struct watched_progress *wp)
{
    struct kdtree *map = balance_kdtree_watched(photons, n, watched_progress_watch(wp));
    wp->before += KDTREE_BALANCE_STEPS(n);
    wp->done = wp->before;
    return map;
}

struct precomputed_irradiance *precompute_watched(const struct kdtree *map,
                                                  const struct kdtree *records,
                                                  const struct irradiance_settings *is,
                                                  const struct scene *coverage, int on,
                                                  double *seconds)
{
    clock_t start = clock();
    struct watched_progress line;
    watched_progress_begin(&line, on, "precomputed irradiance", records->n_photons,
                           "records estimated");
    struct precomputed_irradiance *pi =
        precompute_irradiance(map, records, is, coverage, watched_progress_watch(&line));
    watched_progress_end(&line, 1);
    *seconds += (double)(clock() - start) / CLOCKS_PER_SEC;
    return pi;
}

void trace_progress_begin(struct trace_progress *tp, int on, const char *phase,
                          struct trace_settings *ts)
{
    watched_progress_begin(&tp->phase, on, phase, ts->n_emit, "photons emitted");
    ts->watch = watched_progress_watch(&tp->phase);
}

void trace_progress_end(struct trace_progress *tp, int finished)
{
    watched_progress_end(&tp->phase, finished);
}
