/*
 * modes/trace_progress.h -- the progress lines of the phases that photon/ code works
 * through and tells a watch of: a photon map's trace (--mode photons, 1994, 1996), the
 * balancing of the maps a trace made (photon/kdtree.h), 1994's and 1996's precomputed
 * irradiance (photon/precomputed_irradiance.h). Each says how much of the phase's work is done, in
 * its units, and the time left at the rate so far.
 *
 * The photon/ code knows nothing of lines or clocks: it tells a watch (base/watch.h)
 * how far it has gone, and the watch here turns that
 * into a progress line (base/progress.h). 2008's and 2009's photon passes have none of
 * their own: their passes' line says it.
 */
#ifndef MODES_TRACE_PROGRESS_H
#define MODES_TRACE_PROGRESS_H

#include "../base/progress.h"
#include "../base/watch.h"
#include "../photon/kdtree.h"
#include "../photon/precomputed_irradiance.h"
#include "../photon/trace.h"

/* A phase's line, "DONE of TOTAL UNITS", fed by a watch. A phase may be made of parts
 * whose work the watch counts from 0 each (the maps of one trace, balanced one after
 * another): the line counts on from the parts before. */
struct watched_progress {
    struct progress line;
    struct work_watch watch; /* hand watched_progress_watch() to the work */
    const char *units;       /* e.g. "photons emitted"                    */
    size_t total;
    size_t before;           /* the work of the parts finished             */
    size_t done;             /* the work the line was last told of         */
};

/* Begins the line of phase (on: whether progress is shown) for total units of work. */
void watched_progress_begin(struct watched_progress *wp, int on, const char *phase,
                            size_t total, const char *units);

/* The watch to hand the work, or NULL when progress is off; wp must outlive its use. */
const struct work_watch *watched_progress_watch(const struct watched_progress *wp);

/* Ends the line once the work has returned: finished (all of total done), or stopped
 * (a full map), when the line shows the count the watch last saw, and the message that
 * follows starts a line of its own. */
void watched_progress_end(struct watched_progress *wp, int finished);

/* photons[0..n-1] balanced into a map (balance_kdtree_watched(), which takes them) as the
 * next part of wp's phase, whose units are balance_kdtree_watched()'s steps
 * (KDTREE_BALANCE_STEPS(n) of them). */
struct kdtree *balance_part(struct photon *photons, size_t n, struct watched_progress *wp);

/* precompute_irradiance() of records from map under its own line, "records estimated"
 * (on: whether progress is shown), the CPU seconds it took added to *seconds. 1994 and
 * 1996 precompute alike. */
struct precomputed_irradiance *precompute_watched(const struct kdtree *map,
                                                  const struct kdtree *records,
                                                  const struct irradiance_settings *is,
                                                  const struct scene *coverage, int on,
                                                  double *seconds);

/* A trace's line: photons emitted of those to emit. */
struct trace_progress {
    struct watched_progress phase; /* ts->watch points into it while the trace runs */
};

/* Begins the line of phase (e.g. "global photon map"; on: whether progress is shown) for
 * ts->n_emit photons and hangs it on ts, which must not outlive tp. */
void trace_progress_begin(struct trace_progress *tp, int on, const char *phase,
                          struct trace_settings *ts);

/* watched_progress_end() of the trace's line. */
void trace_progress_end(struct trace_progress *tp, int finished);

#endif
