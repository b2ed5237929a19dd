/*
 * modes/trace_progress.h -- the progress line of a photon map's trace (--mode photons,
 * 1994, 1996): photons emitted of those to emit, and the time left at the rate so far.
 *
 * The tracer (photon/trace.h) knows nothing of lines or clocks: it tells a trace_watch how
 * far it has gone, and the watch here turns that into a progress line (base/progress.h).
 * 2008's and 2009's photon passes have none of their own: their passes' line says it.
 */
#ifndef MODES_TRACE_PROGRESS_H
#define MODES_TRACE_PROGRESS_H

#include "../base/progress.h"
#include "../photon/trace.h"

struct trace_progress {
    struct progress line;
    struct trace_watch watch; /* ts->watch points here while the trace runs */
    size_t n_emit;
    size_t emitted;           /* the count the watch was last told              */
};

/* Begins the line of phase (e.g. "global photon map"; on: whether progress is shown) for
 * ts->n_emit photons and hangs it on ts, which must not outlive tp. */
void trace_progress_begin(struct trace_progress *tp, int on, const char *phase,
                          struct trace_settings *ts);

/* Ends the line once the trace has returned: finished (every photon emitted), or stopped
 * (a full map), when the line shows the count the watch last saw, and the message that
 * follows starts a line of its own. */
void trace_progress_end(struct trace_progress *tp, int finished);

#endif
