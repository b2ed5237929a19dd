/*
 * photon/ordered_sink.h -- a photon sink (trace.h) that holds the photons it is given
 * and hands them on in the order of where they lie, not of when they were traced.
 *
 * Why: progressive photon mapping adds each photon to every hit point whose disc holds it
 * (hit_points.h), and the tracer stores photons in the order of their paths: one here, the
 * next across the scene. Each search then reads tree nodes and hit points that the last
 * one did not, from main memory (the first read of a hit point was 82% of 2009's
 * add_flux() on the Cornell box). Handed on place by place, consecutive photons read the
 * same hit points, still in the cache: the renders take 0.70 of the CPU seconds on the
 * Cornell box (2008 and 2009), 0.39 (2008) and 0.69 (2009) on the specular box
 * (src/modes/measured.md).
 *
 * The order: the cells of an ORDERED_GRID^3 grid over the box given, in Z-order (the
 * bits of the three cell coordinates interleaved, so that cells near in the order are
 * near in space), and within a cell the order the photons came in (a counting sort, which
 * keeps it). It depends on nothing but the photons, so a render stays deterministic; the
 * sums of each hit point add the same terms as before, in another order. At most
 * ORDERED_CHUNK photons are held (148 bytes each with their cell and place in the
 * order: 19 MB); the next one first hands those on.
 */
#ifndef PHOTON_ORDERED_SINK_H
#define PHOTON_ORDERED_SINK_H

#include <stddef.h>

#include "../geom/ray.h"
#include "trace.h"

#define ORDERED_GRID 32                /* cells along each axis of the box            */
#define ORDERED_CHUNK ((size_t)1 << 17) /* photons held at most                        */

struct ordered_sink {
    struct photon_sink to;      /* where the photons go                                */
    struct aabb box;            /* the grid's                                          */
    struct photon_event *held;  /* owned: the photons held, in the order given         */
    unsigned *cell;             /* owned: each held photon's cell, in Z-order           */
    size_t *order;              /* owned: the held photons, as they are handed on      */
    size_t *cell_start;         /* owned: per cell, where its photons start in order   */
    size_t n, capacity;         /* photons held, and room                              */
};

/* An empty sink that hands photons on to `to`, in the order of the cells of box (every
 * stored photon's position lies in it; one outside counts in the nearest cell). */
void ordered_sink_create(struct ordered_sink *os, struct aabb box, struct photon_sink to);

/* The sink a tracer stores into (trace_photons_into()): it holds each photon, handing
 * on all it holds first when it holds ORDERED_CHUNK. */
struct photon_sink ordered_sink_of(struct ordered_sink *os);

/* Hands on every photon held, in order, and holds none; -1 as soon as `to` returns -1
 * (the rest are dropped), else 0. */
int ordered_sink_flush(struct ordered_sink *os);

void ordered_sink_free(struct ordered_sink *os);

#endif
