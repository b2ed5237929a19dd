/*
 * photon/kdtree.c -- the balanced kd-tree photon map (Jensen 1996, Sec. 3).
 *
 * The photons sit in one array in heap order: node i (1-based) has children 2i and
 * 2i + 1, so the tree needs no pointers and a node is just a struct photon (20 bytes per
 * photon, the paper's figure). balance_kdtree() orders the array so that, with
 * a = node i's plane,
 *   (1) photons in i's left subtree have pos[a] <= i's pos[a]; in its right, >=;
 *   (2) every level is full except the last, which fills from the left.
 * (2) is what makes the pointer-free layout possible: a tree with n nodes fills array
 * slots 1..n exactly, so child 2i exists iff 2i <= n, and 2i + 1 iff 2i + 1 <= n. It also
 * bounds the depth by floor(log2 n) + 1, so locating k photons costs O(k log n) however
 * the photons are spread: balanced is what the paper buys, since photons crowd where
 * light is bright and an unbalanced tree would be deepest exactly where it is searched.
 * kdtree_check() verifies (1); (2) holds by construction of the layout.
 *
 * Balancing (as Jensen's photonmap.cc, which splits a cell's box where ours takes the
 * photons' own box): for the photons of a subtree, split on the axis of largest extent
 * of their bounding box, at the median that leaves exactly as many photons on the left
 * as a complete tree of that size holds in its left subtree; quickselect puts that
 * photon in place with the smaller ones before it. Each level costs O(n) expected, so
 * the build is O(n log n). The build needs no second array, which would double the
 * memory of a map of millions of photons: the selections leave the traced array holding
 * the tree laid out in order (left subtree, root, right subtree at every node), and
 * heap_from_inorder() then moves each record to its heap slot by following the
 * permutation's cycles, marking what it placed in the plane byte's spare bit. Both count
 * the photons they place for a watch (balance_kdtree_watched()).
 *
 * Owns photons[]: taken from the caller by balance_kdtree(), released by kdtree_free().
 * Elsewhere: photon.c packs the records; the radiance estimates read the search results.
 */
#include "kdtree.h"

#include <assert.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../base/alloc.h"

/* A tree of fewer than 2^63 nodes has at most 63 levels, so a search defers at most 63
 * nodes. balance_kdtree() asserts the bound (the array could not be allocated anyway). */
#define KDTREE_MAX_DEPTH 64

/* ---- balancing ---- */

/* The axis along which photons[0..m-1] spread most; ties go to the lower axis. */
static int widest_axis(const struct photon *photons, size_t m)
{
    float lo[3] = {photons[0].pos[0], photons[0].pos[1], photons[0].pos[2]};
    float hi[3] = {lo[0], lo[1], lo[2]};
    for (size_t i = 1; i < m; i++) {
        for (int a = 0; a < 3; a++) {
            float v = photons[i].pos[a];
            lo[a] = v < lo[a] ? v : lo[a];
            hi[a] = v > hi[a] ? v : hi[a];
        }
    }
    double extent[3];
    for (int a = 0; a < 3; a++)
        extent[a] = (double)hi[a] - lo[a];
    if (extent[1] > extent[0] && extent[1] >= extent[2])
        return 1;
    return extent[2] > extent[0] && extent[2] > extent[1] ? 2 : 0;
}

/* How many of m >= 1 nodes a complete tree puts in the root's left subtree: with
 * P = the largest power of two <= m + 1, the full levels hold P - 1 nodes, half of them
 * less the root on the left, and the last level's m + 1 - P nodes fill the left half
 * (P / 2 nodes) first. */
static size_t left_subtree_size(size_t m)
{
    size_t p = 1;
    while (p <= (m + 1) / 2)
        p *= 2;
    size_t last = m + 1 - p;
    return p / 2 - 1 + (last < p / 2 ? last : p / 2);
}

static float median_of_three(float a, float b, float c)
{
    if (a > b) {
        float t = a;
        a = b;
        b = t;
    }
    return c < a ? a : c > b ? b : c; /* a <= b: clamp c to [a, b] */
}

/* Quickselect (Hoare's FIND, in Wirth's form): reorders photons[0..m-1] so that
 * photons[nth] has the value it would have after sorting on pos[axis], those before it
 * are <=, those after >=. Both scans stop on keys equal to the pivot and swap them, so
 * runs of equal keys are split evenly and all-equal input takes O(m), not O(m^2). The
 * pivot is the median of three keys, which is deterministic; it is always the key of
 * a photon in the range, so each scan stops inside it. */
static void select_nth(struct photon *photons, size_t m, size_t nth, int axis)
{
    ptrdiff_t lo = 0, hi = (ptrdiff_t)m - 1, k = (ptrdiff_t)nth;
    while (lo < hi) {
        float pivot = median_of_three(photons[lo].pos[axis], photons[k].pos[axis],
                                      photons[hi].pos[axis]);
        ptrdiff_t i = lo, j = hi;
        do {
            while (photons[i].pos[axis] < pivot)
                i++;
            while (pivot < photons[j].pos[axis])
                j--;
            if (i <= j) {
                struct photon t = photons[i];
                photons[i++] = photons[j];
                photons[j--] = t;
            }
        } while (i <= j);
        /* now [lo, j] <= pivot <= [i, hi], and any photons between equal the pivot */
        if (j < k)
            lo = i;
        if (k < i)
            hi = j;
    }
}

/* A balancing's count of its steps, for its watch (balance_kdtree_watched()). */
struct balancing {
    const struct work_watch *watch; /* NULL: none */
    size_t steps;                   /* photons placed so far, each counted twice */
};

/* One photon placed: the watch is told every KDTREE_WATCH_EVERY steps. */
static void step(struct balancing *b)
{
    if (++b->steps % KDTREE_WATCH_EVERY == 0 && b->watch != NULL)
        b->watch->at(b->watch->context, b->steps);
}

/* Orders photons[0..m-1] (m >= 1) as the subtree they make laid out in order: the
 * left subtree first, then the root (its plane set), then the right subtree. Recursion
 * depth is the tree's depth, at most KDTREE_MAX_DEPTH. */
static void order_subtree(struct photon *photons, size_t m, struct balancing *b)
{
    int axis = widest_axis(photons, m);
    size_t n_left = left_subtree_size(m);
    select_nth(photons, m, n_left, axis);
    photons[n_left].plane = (unsigned char)axis;
    step(b);
    if (n_left > 0)
        order_subtree(photons, n_left, b);
    if (m - n_left > 1)
        order_subtree(photons + n_left + 1, m - n_left - 1, b);
}

static int floor_log2(size_t v) /* v >= 1 */
{
    int l = 0;
    while (v >>= 1)
        l++;
    return l;
}

/* The 1-based position, in order, of heap node h among the n nodes of a complete tree.
 * In the perfect tree of the same depth D = floor(log2 n), node h = 2^l + j of level l
 * is (2j + 1) 2^(D - l)-th; the last level holds only its first c = n + 1 - 2^D nodes,
 * and of the missing ones (perfect positions 2q + 1 for q >= c) those before h are the
 * q < R / 2: above the last level (R even) that is R / 2 - c of them when positive;
 * on it (R odd, j < c) none. */
static size_t inorder_rank(size_t h, size_t n, int depth)
{
    int l = floor_log2(h);
    size_t j = h - ((size_t)1 << l);
    size_t c = n + 1 - ((size_t)1 << depth);
    size_t r = (2 * j + 1) << (depth - l);
    return r / 2 > c ? r - (r / 2 - c) : r;
}

#define PLACED 0x80u /* a plane byte's mark while heap_from_inorder() runs: 0..2 need 2 bits */

/* Moves nodes a[1..n], laid out in order, to heap order in place: node h takes the
 * record at inorder_rank(h), following each cycle of that permutation once. */
static void heap_from_inorder(struct photon *a, size_t n, struct balancing *b)
{
    int depth = floor_log2(n);
    for (size_t h = 1; h <= n; h++) {
        if (a[h].plane & PLACED)
            continue;
        struct photon first = a[h];
        size_t to = h;
        for (size_t from = inorder_rank(to, n, depth); from != h;
             from = inorder_rank(to, n, depth)) {
            a[to] = a[from];
            a[to].plane |= PLACED;
            step(b);
            to = from;
        }
        a[to] = first;
        a[to].plane |= PLACED;
        step(b);
    }
    for (size_t h = 1; h <= n; h++)
        a[h].plane &= (unsigned char)~PLACED;
}

struct kdtree *balance_kdtree(struct photon *photons, size_t n)
{
    return balance_kdtree_watched(photons, n, NULL);
}

struct kdtree *balance_kdtree_watched(struct photon *photons, size_t n,
                                      const struct work_watch *watch)
{
    assert(n < SIZE_MAX / 2 && (n == 0 || photons != NULL));
    struct balancing b = {watch, 0};
    struct kdtree *map = xmalloc(1, sizeof *map, "photon map");
    /* in place: one record more for the unused heap[0], none beside the array */
    photons = xrealloc(photons, n + 1, sizeof *photons, "photon map");
    memmove(photons + 1, photons, n * sizeof *photons);
    memset(&photons[0], 0, sizeof photons[0]);
    if (n > 0) {
        order_subtree(photons + 1, n, &b);
        heap_from_inorder(photons, n, &b);
    }
    map->photons = photons;
    map->n_photons = n;
    return map;
}

struct kdtree *kdtree_from_heap(struct photon *heap, size_t n)
{
    assert(n < SIZE_MAX / 2 && heap != NULL);
    struct kdtree *map = xmalloc(1, sizeof *map, "photon map");
    memset(&heap[0], 0, sizeof heap[0]);
    map->photons = heap;
    map->n_photons = n;
    if (kdtree_check(map))
        return map;
    kdtree_free(map);
    return NULL;
}

void kdtree_free(struct kdtree *map)
{
    if (map == NULL)
        return;
    xfree(map->photons);
    xfree(map);
}

size_t kdtree_bytes(const struct kdtree *map)
{
    return sizeof *map + (map->n_photons + 1) * sizeof *map->photons;
}

/* Invariant (1) between node j and its ancestor i, whose subtree holds it on the side
 * of i's child c (left when c is even). */
static int on_correct_side(const struct photon *heap, size_t i, size_t c, size_t j)
{
    int a = heap[i].plane;
    if (c % 2 == 0)
        return heap[j].pos[a] <= heap[i].pos[a];
    return heap[j].pos[a] >= heap[i].pos[a];
}

int kdtree_check(const struct kdtree *map)
{
    if (map == NULL || map->photons == NULL)
        return 0;
    const struct photon *heap = map->photons;
    for (size_t j = 1; j <= map->n_photons; j++) {
        if (heap[j].plane > 2)
            return 0;
        for (size_t c = j; c > 1; c /= 2) {
            if (!on_correct_side(heap, c / 2, c, j))
                return 0;
        }
    }
    return 1;
}

/* ---- the k-nearest search ---- */

struct nearest *nearest_create(size_t k_max)
{
    assert(k_max >= 1);
    struct nearest *nn = xmalloc(1, sizeof *nn, "nearest photons");
    nn->k_max = k_max;
    nn->found = 0;
    nn->photon = xmalloc(k_max, sizeof *nn->photon, "nearest photons");
    nn->d2 = xmalloc(k_max, sizeof *nn->d2, "nearest photons");
    nn->r2 = 0;
    return nn;
}

void nearest_free(struct nearest *nn)
{
    if (nn == NULL)
        return;
    xfree(nn->photon);
    xfree(nn->d2);
    xfree(nn);
}

/* Restores the max-heap on d2[] (with photon[] alongside) below slot i, 0-based:
 * children of i are 2i + 1 and 2i + 2. */
static void sift_down(struct nearest *nn, size_t i, size_t count)
{
    const struct photon *p = nn->photon[i];
    double d2 = nn->d2[i];
    for (size_t c = 2 * i + 1; c < count; c = 2 * i + 1) {
        if (c + 1 < count && nn->d2[c + 1] > nn->d2[c])
            c++;
        if (!(nn->d2[c] > d2))
            break;
        nn->photon[i] = nn->photon[c];
        nn->d2[i] = nn->d2[c];
        i = c;
    }
    nn->photon[i] = p;
    nn->d2[i] = d2;
}

/* What a search looks for; the bound on d2 changes as it goes, so it is passed apart. */
struct search {
    double x[3];                /* the query point                            */
    unsigned kinds;             /* 0: no kind filter                          */
    size_t k;                   /* photons wanted                             */
    struct nearest *nn;         /* results so far                             */
};

static double squared_distance(const double x[3], const struct photon *p)
{
    double delta[3];
    for (int a = 0; a < 3; a++)
        delta[a] = (double)p->pos[a] - x[a];
    return delta[0] * delta[0] + delta[1] * delta[1] + delta[2] * delta[2];
}

/* Whether the kind filter keeps photon p. */
static int selected(const struct search *s, const struct photon *p)
{
    return s->kinds == 0 || (p->flags & s->kinds) != 0;
}

/* Offers photon p to the search. bound is exclusive: p is wanted iff d2 < bound. Until
 * k photons are found they are appended; at the k-th, d2[] becomes a max-heap and the
 * bound the heap's top, which a nearer photon then replaces. Returns the new bound. */
static double offer_photon(const struct search *s, const struct photon *p, double bound)
{
    double d2 = squared_distance(s->x, p);
    if (!(d2 < bound) || !selected(s, p))
        return bound;
    struct nearest *nn = s->nn;
    if (nn->found < s->k) {
        nn->photon[nn->found] = p;
        nn->d2[nn->found++] = d2;
        if (nn->found < s->k)
            return bound;
        for (size_t i = s->k / 2; i-- > 0;)
            sift_down(nn, i, s->k);
        return nn->d2[0];
    }
    nn->photon[0] = p;
    nn->d2[0] = d2;
    sift_down(nn, 0, s->k);
    return nn->d2[0];
}

/* A node whose near child is being searched; its own photon and its far child wait. */
struct deferred {
    size_t far;    /* the far child (may be n + 1, absent); the node is far / 2 */
    double delta2; /* squared distance from x to the node's splitting plane     */
};

/* Depth-first search, near child first, iterative with an explicit stack (a photon map
 * is searched millions of times per image). A node's photon and its far subtree lie at
 * least sqrt(delta2) from x along the plane's axis, so both are skipped once
 * delta2 >= bound; floating-point rounding is monotone, so the skip is exact. Returns
 * the final bound. */
static double search_tree(const struct kdtree *map, const struct search *s, double bound)
{
    const struct photon *heap = map->photons;
    size_t n = map->n_photons;
    struct deferred stack[KDTREE_MAX_DEPTH];
    size_t top = 0, node = n > 0 ? 1 : 0;
    while (node != 0) {
        while (2 * node <= n) { /* descend near children to a leaf, deferring the rest */
            int a = heap[node].plane;
            double delta = s->x[a] - heap[node].pos[a];
            size_t near = 2 * node + (delta > 0);
            stack[top].far = near ^ 1;
            stack[top++].delta2 = delta * delta;
            node = near;
        }
        if (node <= n) /* else the near child was a missing right child */
            bound = offer_photon(s, &heap[node], bound);
        node = 0;
        while (top > 0 && node == 0) { /* back up to a deferred node within reach */
            const struct deferred *d = &stack[--top];
            if (!(d->delta2 < bound))
                continue;
            bound = offer_photon(s, &heap[d->far / 2], bound);
            node = d->far <= n ? d->far : 0;
        }
    }
    return bound;
}

/* The largest of nn->d2[0..found-1], 0 when nothing was found. */
static double largest_d2(const struct nearest *nn)
{
    double r2 = 0;
    for (size_t i = 0; i < nn->found; i++)
        r2 = nn->d2[i] > r2 ? nn->d2[i] : r2;
    return r2;
}

void locate_photons_of_kinds(const struct kdtree *map, const struct photon_query *q,
                            struct nearest *nn)
{
    assert(q->k >= 1 && q->k <= nn->k_max);
    assert(q->max_r2 >= 0); /* also refuses NaN */
    struct search s;
    s.x[0] = q->x.x;
    s.x[1] = q->x.y;
    s.x[2] = q->x.z;
    s.kinds = q->kinds;
    s.k = q->k;
    s.nn = nn;
    nn->found = 0;
    /* d2 <= max_r2 is d2 < the next double above max_r2: one strict test throughout */
    search_tree(map, &s, nextafter(q->max_r2, HUGE_VAL));
    if (nn->found == q->k || q->max_r2 == HUGE_VAL)
        nn->r2 = largest_d2(nn); /* found == k: the heap's top, d2[0] */
    else
        nn->r2 = q->max_r2;
}

void locate_photons(const struct kdtree *map, struct vec3 x, double max_r2, size_t k,
                    struct nearest *nn)
{
    struct photon_query q;
    q.x = x;
    q.max_r2 = max_r2;
    q.k = k;
    q.kinds = 0;
    locate_photons_of_kinds(map, &q, nn);
}

void nearest_sort(struct nearest *nn)
{
    size_t count = nn->found;
    for (size_t i = count / 2; i-- > 0;)
        sift_down(nn, i, count); /* a max-heap on d2[] */
    while (count > 1) {
        /* the farthest left moves to the end of the unsorted part */
        count--;
        const struct photon *p = nn->photon[0];
        double d2 = nn->d2[0];
        nn->photon[0] = nn->photon[count];
        nn->d2[0] = nn->d2[count];
        nn->photon[count] = p;
        nn->d2[count] = d2;
        sift_down(nn, 0, count);
    }
}
