/*
 * base/watch.h -- how work that keeps no clock and prints nothing tells its caller how far
 * it has gone, so that the caller's progress line (progress.h) can hang on it: the
 * trace of photons (photon/trace.h), the balancing of a photon map (photon/kdtree.h) and
 * 1996's precomputed irradiance (photon/precomputed_irradiance.h). What a watch does
 * cannot change the work's result.
 */
#ifndef PHOTON_WATCH_H
#define PHOTON_WATCH_H

#include <stddef.h>

struct work_watch {
    void (*at)(void *context, size_t done); /* done: units of work finished so far */
    void *context;
};

#endif
