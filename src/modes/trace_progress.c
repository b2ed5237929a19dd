/*
 * modes/trace_progress.c -- the progress line of a photon map's trace (trace_progress.h).
 */
#include "trace_progress.h"

#include <time.h>

static void show(struct trace_progress *tp, size_t emitted)
{
    progress_print(&tp->line, "%zu of %zu photons emitted", emitted, tp->n_emit);
}

/* The tracer's watch: a line when one is due. */
static void at(void *context, size_t emitted)
{
    struct trace_progress *tp = context;
    tp->emitted = emitted;
    if (progress_update(&tp->line, (double)emitted, time(NULL)))
        show(tp, emitted);
}

void trace_progress_begin(struct trace_progress *tp, int on, const char *phase,
                          struct trace_settings *ts)
{
    tp->n_emit = ts->n_emit;
    tp->emitted = 0;
    progress_begin(&tp->line, on ? stderr : NULL, phase, (double)ts->n_emit, time(NULL));
    tp->watch.at = at;
    tp->watch.context = tp;
    ts->watch = on ? &tp->watch : NULL;
}

void trace_progress_end(struct trace_progress *tp, int finished)
{
    size_t emitted = finished ? tp->n_emit : tp->emitted;
    if (progress_end(&tp->line, (double)emitted, time(NULL)))
        show(tp, emitted);
}
