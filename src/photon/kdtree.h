/*
 * photon/kdtree.h -- the photon map: a balanced, pointer-free kd-tree of photons
 * (Jensen 1996, Sec. 3), and the searches the radiance estimates make in it.
 *
 * Life of a map: the photon tracer fills an array of photons, balance_kdtree() takes it
 * and returns the map, estimates call locate_photons() (the k nearest) any number of
 * times with a struct nearest made once per render, and kdtree_free() releases the map.
 * A built map is only read.
 * The tree's layout and invariants are described at the top of kdtree.c.
 */
#ifndef PHOTON_KDTREE_H
#define PHOTON_KDTREE_H

#include <stddef.h>

#include "../base/watch.h"
#include "photon.h"

struct kdtree {
    struct photon *photons; /* owned; n_photons + 1 records, photons[1..n_photons] in
                               heap order (node i has children 2i, 2i + 1), [0] unused */
    size_t n_photons;       /* N, the number of photons in the map (may be 0) */
};

/* Builds the map from photons[0..n-1], taking ownership of the array (from xmalloc or
 * xrealloc, of any capacity >= n; NULL is allowed when n = 0): the map reorders it into
 * heap order in place, resized to n + 1 records, and holds no other copy. O(n log n)
 * time. Sets every photon's plane. Never fails (out of memory is fatal()). */
struct kdtree *balance_kdtree(struct photon *photons, size_t n);
void kdtree_free(struct kdtree *map); /* NULL is a no-op */

/* balance_kdtree(), telling watch (NULL: none) how far it has gone, in steps of 2n: a
 * step places one photon, first at its node among the others (the selections, most of
 * the time), then in its heap slot (a pass of its own, a fifth of the time or less).
 * watch->at(context, steps) whenever steps is a positive multiple of
 * KDTREE_WATCH_EVERY. The map is the same, watched or not. */
struct kdtree *balance_kdtree_watched(struct photon *photons, size_t n,
                                      const struct work_watch *watch);

#define KDTREE_WATCH_EVERY 4096 /* steps: about a millisecond of balancing */
#define KDTREE_BALANCE_STEPS(n) (2 * (size_t)(n)) /* the steps for n photons */

/* A map made from records already in heap order, as a map holds them: heap[1..n] (heap[0]
 * is unused and set to zeros here), n + 1 records, taken over as they are, so a map read
 * back from a file (app/work_file.h) is the map that was written, node for node, whatever
 * order balance_kdtree() would choose. NULL when they break the invariants (kdtree_check);
 * heap is freed then too. */
struct kdtree *kdtree_from_heap(struct photon *heap, size_t n);

/* 1 when the map satisfies the invariants stated in kdtree.c, else 0. O(n log n). */
int kdtree_check(const struct kdtree *map);

/* Bytes the map occupies (records and header), for the stats' bytes per photon. */
size_t kdtree_bytes(const struct kdtree *map);

/* The result of a k-nearest search, and the scratch for it: made once per render (or
 * per thread of work) with room for k_max photons, reused by every locate_photons(). */
struct nearest {
    size_t k_max;                 /* capacity of photon[] and d2[], >= 1            */
    size_t found;                 /* photons found by the last search, <= its k     */
    const struct photon **photon; /* owned array; [0..found-1] borrowed from the map,
                                     in no particular order                         */
    double *d2;                   /* owned array; d2[i] = |photon i - x|^2          */
    double r2;                    /* r^2, the squared radius of the found set:
                                     found == k: the largest d2[] (the k-th nearest);
                                     found < k, max_r2 finite: max_r2, the radius that
                                       was searched completely (Jensen's photonmap.cc);
                                     found < k, max_r2 = HUGE_VAL: the largest d2[]
                                       (the map holds fewer than k photons), 0 if none */
};

struct nearest *nearest_create(size_t k_max); /* k_max >= 1 */
void nearest_free(struct nearest *nn);        /* NULL is a no-op */

/* A k-nearest search of one class of light. The kind filter keeps only photons with one
 * of the given PHOTON_* flags (photon.h), so one map can answer for a class of light
 * (Jensen 1996: the indirect photons of the global map; a single map's caustic photons).
 * It selects photons; the search itself is unchanged. */
struct photon_query {
    struct vec3 x;             /* the query point                                    */
    double max_r2;             /* photons with |p - x|^2 <= max_r2 qualify; HUGE_VAL
                                  for no maximum radius; >= 0, not NaN               */
    size_t k;                  /* photons wanted, 1 <= k <= the scratch's k_max      */
    unsigned kinds;            /* keep photons with (flags & kinds) != 0; 0 keeps all */
};

/* Finds the k photons nearest to x with |p - x|^2 <= max_r2 (all of those if fewer),
 * and fills nn->found, nn->photon[], nn->d2[], nn->r2 as documented on struct nearest.
 * Distances are computed in double from the records' floats; among photons at the
 * same distance, which are kept depends (deterministically) on the tree. O(k log n)
 * for well-spread photons. Allocates nothing. */
void locate_photons(const struct kdtree *map, struct vec3 x, double max_r2, size_t k,
                    struct nearest *nn);

/* locate_photons() with the kind filter of q (off when q->kinds is 0). */
void locate_photons_of_kinds(const struct kdtree *map, const struct photon_query *q,
                            struct nearest *nn);

/* Puts the last search's photons in order of distance, nearest first (photon[] moved
 * with d2[]): for estimates that add photons one by one outwards, like the differential
 * checking of Jensen and Christensen 1994 (estimate.h). Heapsort: O(found log found),
 * in place, allocates nothing. Photons at equal distance keep a deterministic order. */
void nearest_sort(struct nearest *nn);

#endif
