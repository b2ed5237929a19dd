/*
 * geom/bvh_build.c -- the binned SAH build of the 4-wide BVH and its checker (see bvh.h).
 *
 * Binary splits (Wald, "On fast construction of SAH-based bounding volume hierarchies",
 * 2007): for a range of items, the centres of their boxes are dropped into BVH_BINS equal
 * bins along each axis; between each pair of neighbouring bins the surface area heuristic
 *   cost = C_trav + C_isect (A_left N_left + A_right N_right) / A_node
 * is evaluated, the cheapest plane wins, and the range is partitioned in place. Ranges of
 * at most BVH_MAX_LEAF items become a leaf when that is no dearer (C_isect N). When every
 * centre coincides (identical or degenerate boxes) or the splits are BVH_SAH_DEPTH deep,
 * the range is split at its middle index instead, which always terminates and bounds the
 * depth.
 *
 * A node of BVH_WIDTH slots is made from one range by binary splits, each time splitting
 * the slot with the largest box among those that are not leaves, until the node is full or
 * only leaves remain (the collapse of a binary SAH tree that Embree's builders and Wald et
 * al.'s "Getting rid of packets" (2008) use). The slots that are still ranges become the
 * node's interior children, laid side by side and built the same way, depth first; but a
 * range of at most BVH_MAX_LEAF items becomes a leaf even where the SAH would split it, as a
 * node of two or three tiny leaves costs a visit and 256 bytes for little: fewer nodes, and
 * faster rays, most of all secondary ones. C_trav = C_isect = 1 and 16 bins: other ratios
 * and more bins gain nothing the rays workload can tell from noise (src/modes/measured.md
 * has the figures of both).
 */
#include "bvh.h"

#include <assert.h>
#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "../base/alloc.h"

#define BVH_BINS 16         /* centroid bins per axis: more cost more, gain little (Wald 2007) */
#define BVH_SAH_DEPTH 32    /* below this depth, ranges split at the middle index             */
/* C_trav and C_isect, relative costs of a binary split's box test and a primitive's test. */
#define SAH_COST_TRAVERSE 1.0
#define SAH_COST_INTERSECT 1.0

char bvh_node_is_256_bytes[sizeof(struct bvh_node) == 256 ? 1 : -1];

/* ---- node boxes in float, rounded outward ---- */

static float round_down(double x)
{
    if (x > FLT_MAX)
        return FLT_MAX;
    if (x < -FLT_MAX)
        return -INFINITY;
    float f = (float)x;
    return (double)f > x ? nextafterf(f, -INFINITY) : f;
}

static float round_up(double x)
{
    if (x > FLT_MAX)
        return INFINITY;
    if (x < -FLT_MAX)
        return -FLT_MAX;
    float f = (float)x;
    return (double)f < x ? nextafterf(f, INFINITY) : f;
}

/* Slot's box from box; the empty box (lo = +inf, hi = -inf) stays exactly that. */
static void set_slot_box(struct bvh_node *node, int slot, struct aabb box)
{
    if (!(box.lo.x <= box.hi.x)) {
        for (int k = 0; k < 3; k++) {
            node->box[k * BVH_WIDTH + slot] = INFINITY;
            node->box[(3 + k) * BVH_WIDTH + slot] = -INFINITY;
        }
        return;
    }
    node->box[0 * BVH_WIDTH + slot] = round_down(box.lo.x);
    node->box[1 * BVH_WIDTH + slot] = round_down(box.lo.y);
    node->box[2 * BVH_WIDTH + slot] = round_down(box.lo.z);
    node->box[3 * BVH_WIDTH + slot] = round_up(box.hi.x);
    node->box[4 * BVH_WIDTH + slot] = round_up(box.hi.y);
    node->box[5 * BVH_WIDTH + slot] = round_up(box.hi.z);
}

/* ---- boxes in double ---- */

static struct aabb box_empty(void)
{
    struct aabb box;
    box.lo = vec3(INFINITY, INFINITY, INFINITY);
    box.hi = vec3(-INFINITY, -INFINITY, -INFINITY);
    return box;
}

/* Minimum and maximum of numbers (never NaN here): plain comparisons, which compile to
 * single instructions where libm's fmin and fmax, bound by NaN rules, are calls. */
static double min_of(double a, double b)
{
    return a < b ? a : b;
}

static double max_of(double a, double b)
{
    return a > b ? a : b;
}

static struct aabb box_union(struct aabb a, struct aabb b)
{
    a.lo = vec3(min_of(a.lo.x, b.lo.x), min_of(a.lo.y, b.lo.y), min_of(a.lo.z, b.lo.z));
    a.hi = vec3(max_of(a.hi.x, b.hi.x), max_of(a.hi.y, b.hi.y), max_of(a.hi.z, b.hi.z));
    return a;
}

static struct aabb box_add_point(struct aabb a, struct vec3 p)
{
    a.lo = vec3(min_of(a.lo.x, p.x), min_of(a.lo.y, p.y), min_of(a.lo.z, p.z));
    a.hi = vec3(max_of(a.hi.x, p.x), max_of(a.hi.y, p.y), max_of(a.hi.z, p.z));
    return a;
}

/* Half the surface area, which is all the SAH's ratios need; 0 for an empty box. */
static double box_half_area(struct aabb box)
{
    if (!(box.lo.x <= box.hi.x))
        return 0.0;
    struct vec3 e = vec3_sub(box.hi, box.lo);
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

/* ---- binary SAH splits ---- */

struct builder {
    const struct aabb *bounds;  /* borrowed from bvh_build()'s caller: the items' boxes   */
    struct vec3 *centroids;     /* owned by bvh_build(): the boxes' centres               */
    uint32_t *items;            /* the bvh's item array, partitioned in place              */
    struct bvh_node *nodes;     /* the bvh's node array: n_nodes made or reserved, room for
                                   cap_nodes                                               */
    size_t n_nodes, cap_nodes;
};

/* The items items[first .. first + count), the union of their boxes and the box of their
 * centres; a split hands both boxes to the two halves, so each level reads the items
 * twice (binning, partitioning) and no more. depth counts the binary splits above it. */
struct range {
    size_t first, count;
    struct aabb box, centres;
    int depth;
};

struct bin {
    struct aabb box;  /* union of the boxes whose centres fall in the bin */
    size_t count;
};

/* The binning of a range: scale[axis] = BVH_BINS / centre extent, 0 for an axis without
 * spread (or with one too small to bin). */
struct binning {
    double cmin[3], scale[3];
    struct bin bins[3][BVH_BINS];
};

/* The plane chosen for a range: after bin `bin` along `axis`; axis -1 when none exists. */
struct split {
    int axis;
    int bin;
    double cost;      /* A_left N_left + A_right N_right */
};

static int bin_of(double c, double cmin, double scale)
{
    int i = (int)((c - cmin) * scale);   /* c >= cmin, so i >= 0 */
    return i < BVH_BINS ? i : BVH_BINS - 1;
}

/* Drops the range's centres into the bins of every axis with spread, in one pass. */
static void fill_bins(const struct builder *b, const struct range *r, struct binning *bn)
{
    double lo[3] = {r->centres.lo.x, r->centres.lo.y, r->centres.lo.z};
    double hi[3] = {r->centres.hi.x, r->centres.hi.y, r->centres.hi.z};
    for (int axis = 0; axis < 3; axis++) {
        double extent = hi[axis] - lo[axis];
        bn->cmin[axis] = lo[axis];
        bn->scale[axis] = extent > 0 && BVH_BINS / extent < INFINITY ? BVH_BINS / extent : 0.0;
        for (int i = 0; i < BVH_BINS; i++) {
            bn->bins[axis][i].box = box_empty();
            bn->bins[axis][i].count = 0;
        }
    }
    for (size_t k = r->first; k < r->first + r->count; k++) {
        uint32_t item = b->items[k];
        struct vec3 cv = b->centroids[item];
        double c[3] = {cv.x, cv.y, cv.z};
        for (int axis = 0; axis < 3; axis++) {
            if (bn->scale[axis] == 0)
                continue;
            struct bin *bin = &bn->bins[axis][bin_of(c[axis], bn->cmin[axis], bn->scale[axis])];
            bin->box = box_union(bin->box, b->bounds[item]);
            bin->count++;
        }
    }
}

/* Sweeps one axis's bins from both ends and keeps the cheapest plane in *best. */
static void sweep_axis(const struct bin bins[BVH_BINS], size_t count, int axis,
                       struct split *best)
{
    double right_area[BVH_BINS];   /* right_area[i]: A N of bins i .. BVH_BINS-1 */
    struct aabb right = box_empty();
    size_t n_right = 0;
    for (int i = BVH_BINS - 1; i > 0; i--) {
        right = box_union(right, bins[i].box);
        n_right += bins[i].count;
        right_area[i] = box_half_area(right) * (double)n_right;
    }
    struct aabb left = box_empty();
    size_t n_left = 0;
    for (int i = 0; i < BVH_BINS - 1; i++) {
        left = box_union(left, bins[i].box);
        n_left += bins[i].count;
        double cost = box_half_area(left) * (double)n_left + right_area[i + 1];
        if (n_left > 0 && n_left < count && cost < best->cost) {
            best->cost = cost;
            best->axis = axis;
            best->bin = i;
        }
    }
}

/* Moves the range's items left of the plane to its front and makes the two halves. */
static void partition(struct builder *b, const struct range *r, const struct binning *bn,
                      struct split s, struct range *left, struct range *right)
{
    size_t i = r->first, j = r->first + r->count;
    left->box = left->centres = right->box = right->centres = box_empty();
    while (i < j) {
        uint32_t item = b->items[i];
        struct vec3 cv = b->centroids[item];
        double c[3] = {cv.x, cv.y, cv.z};
        struct range *side = right;
        if (bin_of(c[s.axis], bn->cmin[s.axis], bn->scale[s.axis]) <= s.bin) {
            side = left;
            i++;
        } else {
            b->items[i] = b->items[--j];
            b->items[j] = item;
        }
        side->box = box_union(side->box, b->bounds[item]);
        side->centres = box_add_point(side->centres, cv);
    }
    left->first = r->first;
    left->count = i - r->first;
    right->first = i;
    right->count = r->first + r->count - i;
}

/* The boxes of items[first .. first + count), for a range made without binning. */
static struct range make_range(const struct builder *b, size_t first, size_t count, int depth)
{
    struct range r;
    r.first = first;
    r.count = count;
    r.box = r.centres = box_empty();
    r.depth = depth;
    for (size_t k = first; k < first + count; k++) {
        r.box = box_union(r.box, b->bounds[b->items[k]]);
        r.centres = box_add_point(r.centres, b->centroids[b->items[k]]);
    }
    return r;
}

/* Whether the range splits, and if so into *left and *right (the range's items
 * partitioned in place). A range that does not split is left as it was: a leaf. */
static int split_range(struct builder *b, const struct range *r, struct range *left,
                       struct range *right)
{
    if (r->count == 1)
        return 0;
    if (r->depth < BVH_SAH_DEPTH) {
        struct binning bn;
        struct split s = {-1, 0, INFINITY};
        fill_bins(b, r, &bn);
        for (int axis = 0; axis < 3; axis++)
            if (bn.scale[axis] > 0)
                sweep_axis(bn.bins[axis], r->count, axis, &s);
        double area = box_half_area(r->box);
        /* SAH costs multiplied by A_node, so a flat node (area 0) needs no division. */
        double leaf_cost = SAH_COST_INTERSECT * (double)r->count * area;
        double split_cost = SAH_COST_TRAVERSE * area + SAH_COST_INTERSECT * s.cost;
        if (s.axis >= 0 && (r->count > BVH_MAX_LEAF || split_cost < leaf_cost)) {
            partition(b, r, &bn, s, left, right);
            left->depth = right->depth = r->depth + 1;
            return 1;
        }
    }
    if (r->count <= BVH_MAX_LEAF)
        return 0;
    /* Coincident centres, or the depth limit: split at the middle index. */
    *left = make_range(b, r->first, r->count / 2, r->depth + 1);
    *right = make_range(b, r->first + r->count / 2, r->count - r->count / 2, r->depth + 1);
    return 1;
}

/* ---- wide nodes ---- */

/* The slots of one node while it is being made. */
struct slots {
    struct range range[BVH_WIDTH];
    int is_leaf[BVH_WIDTH];   /* split_range() declined it */
    int n;
};

/* Splits slots until BVH_WIDTH are used or all are leaves; the largest box goes first. */
static void fill_slots(struct builder *b, struct slots *s)
{
    while (s->n < BVH_WIDTH) {
        int widest = -1;
        double widest_area = -1.0;
        for (int i = 0; i < s->n; i++) {
            double area = box_half_area(s->range[i].box);
            if (!s->is_leaf[i] && area > widest_area) {
                widest = i;
                widest_area = area;
            }
        }
        if (widest < 0)
            return;
        struct range left, right;
        if (!split_range(b, &s->range[widest], &left, &right)) {
            s->is_leaf[widest] = 1;
            continue;
        }
        s->range[widest] = left;
        s->range[s->n] = right;
        s->is_leaf[s->n] = 0;
        s->n++;
    }
    /* Ranges the node had no room to split become leaves when they may: a child node
     * over a few items would hold two or three small leaves in its eight slots, for the
     * price of a node visit (and 256 bytes) saved on the items' tests. */
    for (int i = 0; i < s->n; i++)
        if (s->range[i].count <= BVH_MAX_LEAF)
            s->is_leaf[i] = 1;
}

static void build_node(struct builder *b, size_t index, struct slots *first_slots);

/* Makes nodes[index] the node over the range. */
static void build_range(struct builder *b, size_t index, const struct range *r)
{
    struct slots s;
    s.range[0] = *r;
    s.is_leaf[0] = 0;
    s.n = 1;
    build_node(b, index, &s);
}

/* Makes nodes[index] the node whose slots start as the ranges of first_slots and are split
 * further; its interior children go to the next free slots of nodes[], side by side, and
 * are made in turn. */
static void build_node(struct builder *b, size_t index, struct slots *first_slots)
{
    struct slots s = *first_slots;
    fill_slots(b, &s);
    int order[BVH_WIDTH], n_nodes = 0;          /* interior slots first, then leaves */
    for (int i = 0; i < s.n; i++)
        if (!s.is_leaf[i])
            order[n_nodes++] = i;
    int n_slots = n_nodes;
    for (int i = 0; i < s.n; i++)
        if (s.is_leaf[i])
            order[n_slots++] = i;
    if (b->n_nodes + (size_t)n_nodes > b->cap_nodes) {   /* before node points into nodes[] */
        b->cap_nodes = 2 * b->cap_nodes + (size_t)n_nodes;
        b->nodes = xrealloc(b->nodes, b->cap_nodes, sizeof *b->nodes, "BVH nodes");
    }
    struct bvh_node *node = &b->nodes[index];
    memset(node, 0, sizeof *node);
    for (int i = 0; i < BVH_WIDTH; i++)
        set_slot_box(node, i, i < n_slots ? s.range[order[i]].box : box_empty());
    node->n_nodes = (uint8_t)n_nodes;
    node->n_slots = (uint8_t)n_slots;
    node->offset = (uint32_t)b->n_nodes;
    b->n_nodes += (size_t)n_nodes;
    for (int i = n_nodes; i < n_slots; i++) {
        node->first[i] = (uint32_t)s.range[order[i]].first;
        node->count[i] = (uint8_t)s.range[order[i]].count;
    }
    size_t offset = node->offset;
    for (int i = 0; i < n_nodes; i++)
        build_range(b, offset + (size_t)i, &s.range[order[i]]);
}

struct bvh *bvh_build(const struct aabb *bounds, size_t n)
{
    return bvh_build_groups(bounds, n, &n, 1);
}

struct bvh *bvh_build_groups(const struct aabb *bounds, size_t n, const size_t *group_ends,
                             int n_groups)
{
    assert(n < ((size_t)1 << 28));   /* bvh.c packs positions in items[] in 28 bits */
    assert(n_groups >= 1 && n_groups <= BVH_WIDTH && group_ends[n_groups - 1] == n);
    struct bvh *bvh = xmalloc(1, sizeof *bvh, "BVH");
    struct builder b;
    b.bounds = bounds;
    b.centroids = xmalloc(n, sizeof *b.centroids, "BVH centroids");
    b.items = xmalloc(n, sizeof *b.items, "BVH items");
    b.cap_nodes = n > 0 ? 1 : 0;
    b.nodes = xmalloc(b.cap_nodes, sizeof *b.nodes, "BVH nodes");
    b.n_nodes = b.cap_nodes;   /* the root */
    for (size_t i = 0; i < n; i++) {
        b.centroids[i] = vec3_add(vec3_scale(bounds[i].lo, 0.5), vec3_scale(bounds[i].hi, 0.5));
        b.items[i] = (uint32_t)i;
    }
    if (n > 0) {   /* the root's first slots: one range a group that has items */
        struct slots s;
        s.n = 0;
        for (int g = 0; g < n_groups; g++) {
            size_t first = g > 0 ? group_ends[g - 1] : 0;
            assert(first <= group_ends[g]);
            if (group_ends[g] == first)
                continue;
            s.range[s.n] = make_range(&b, first, group_ends[g] - first, 0);
            s.is_leaf[s.n++] = 0;
        }
        build_node(&b, 0, &s);
    }
    xfree(b.centroids);
    bvh->nodes = xrealloc(b.nodes, b.n_nodes, sizeof *b.nodes, "BVH nodes");
    bvh->n_nodes = b.n_nodes;
    bvh->items = b.items;
    bvh->n_items = n;
    return bvh;
}

void bvh_free(struct bvh *bvh)
{
    if (bvh == NULL)
        return;
    xfree(bvh->nodes);
    xfree(bvh->items);
    xfree(bvh);
}

size_t bvh_bytes(const struct bvh *bvh)
{
    return sizeof *bvh + bvh->n_nodes * sizeof *bvh->nodes + bvh->n_items * sizeof *bvh->items;
}

/* ---- the structural checker ---- */

struct checker {
    const struct bvh *bvh;
    const struct aabb *bounds;
    size_t n;
    unsigned char *seen;    /* seen[k]: position k of items[] is in a leaf; seen[n + item]:
                               the item was found in a leaf                              */
    size_t n_nodes_seen;
};

/* Slot i of node (0 .. BVH_WIDTH - 1) as an aabb in float's values. */
static void slot_box(const struct bvh_node *node, int i, float lo[3], float hi[3])
{
    for (int a = 0; a < 3; a++) {
        lo[a] = node->box[a * BVH_WIDTH + i];
        hi[a] = node->box[(3 + a) * BVH_WIDTH + i];
    }
}

static int slot_holds_box(const struct bvh_node *node, int i, struct aabb box)
{
    float lo[3], hi[3];
    slot_box(node, i, lo, hi);
    return box.lo.x >= lo[0] && box.lo.y >= lo[1] && box.lo.z >= lo[2]
           && box.hi.x <= hi[0] && box.hi.y <= hi[1] && box.hi.z <= hi[2];
}

/* Whether every used slot of child lies in slot i of its parent. */
static int slot_holds_node(const struct bvh_node *parent, int i, const struct bvh_node *child)
{
    float lo[3], hi[3];
    slot_box(parent, i, lo, hi);
    for (int j = 0; j < child->n_slots; j++) {
        float clo[3], chi[3];
        slot_box(child, j, clo, chi);
        for (int a = 0; a < 3; a++)
            if (!(clo[a] >= lo[a] && chi[a] <= hi[a]))
                return 0;
    }
    return 1;
}

static int check_leaf(struct checker *c, const struct bvh_node *node, int i)
{
    size_t first = node->first[i], count = node->count[i];
    if (count < 1 || count > BVH_MAX_LEAF || first > c->n || count > c->n - first)
        return 0;
    for (size_t k = first; k < first + count; k++) {
        uint32_t item = c->bvh->items[k];
        if (c->seen[k] || item >= c->n || c->seen[c->n + item]
            || !slot_holds_box(node, i, c->bounds[item]))
            return 0;
        c->seen[k] = 1;
        c->seen[c->n + item] = 1;
    }
    return 1;
}

static int is_empty_slot(const struct bvh_node *node, int i)
{
    float lo[3], hi[3];
    slot_box(node, i, lo, hi);
    for (int a = 0; a < 3; a++)
        if (!(lo[a] == INFINITY && hi[a] == -INFINITY))
            return 0;
    return node->count[i] == 0 && node->first[i] == 0;
}

static int check_node(struct checker *c, size_t index, int depth, int is_root)
{
    if (index >= c->bvh->n_nodes || depth >= BVH_MAX_DEPTH)
        return 0;
    const struct bvh_node *node = &c->bvh->nodes[index];
    c->n_nodes_seen++;
    int n_nodes = node->n_nodes, n_slots = node->n_slots;
    if (n_nodes > n_slots || n_slots > BVH_WIDTH || (n_slots < 2 && !(is_root && n_slots == 1)))
        return 0;
    if (n_nodes > 0 && (node->offset <= index || node->offset + (size_t)n_nodes > c->bvh->n_nodes))
        return 0;
    for (int i = 0; i < BVH_WIDTH; i++) {
        if (i < n_nodes) {
            const struct bvh_node *child = &c->bvh->nodes[node->offset + i];
            if (node->count[i] != 0 || !slot_holds_node(node, i, child)
                || !check_node(c, node->offset + (size_t)i, depth + 1, 0))
                return 0;
        } else if (i < n_slots) {
            if (!check_leaf(c, node, i))
                return 0;
        } else if (!is_empty_slot(node, i)) {
            return 0;
        }
    }
    return 1;
}

int bvh_check(const struct bvh *bvh, const struct aabb *bounds, size_t n)
{
    if (bvh->n_items != n)
        return 0;
    if (n == 0)
        return bvh->n_nodes == 0;
    struct checker c;
    c.bvh = bvh;
    c.bounds = bounds;
    c.n = n;
    c.seen = xcalloc(2 * n, 1, "BVH check");
    c.n_nodes_seen = 0;
    int ok = check_node(&c, 0, 0, 1) && c.n_nodes_seen == bvh->n_nodes;
    for (size_t k = 0; ok && k < 2 * n; k++)
        ok = c.seen[k];
    xfree(c.seen);
    return ok;
}
