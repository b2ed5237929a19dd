/*
 * geom/bvh.c -- binned SAH build and stack traversal of the BVH (see bvh.h).
 *
 * Build (Wald, "On fast construction of SAH-based bounding volume hierarchies", 2007):
 * for a range of items, the centres of their boxes are dropped into BVH_BINS equal bins
 * along each axis; between each pair of neighbouring bins the surface area heuristic
 *   cost = C_trav + C_isect (A_left N_left + A_right N_right) / A_node
 * is evaluated, the cheapest plane wins, and the range is partitioned in place. Ranges of
 * at most BVH_MAX_LEAF items become a leaf when that is no dearer (C_isect N). When every
 * centre coincides (identical or degenerate boxes) or the tree is BVH_SAH_DEPTH deep, the
 * range is split at its middle index instead, which always terminates and bounds the depth.
 *
 * Traversal: at an interior node both children's boxes are tested (they share a cache
 * line or two); the nearer child by entry distance is visited next and the farther waits on
 * a stack with its entry distance, to be skipped when popped if a closer hit has been found
 * meanwhile. Box test (Williams et al., "An efficient and robust ray-box intersection
 * algorithm", 2005, with the error bound of pbrt-v4's Bounds3::IntersectP): each slab gives
 * an entry and an exit distance from 1/d; a zero component gives 1/d = +-inf, and where the
 * origin lies exactly on the slab's plane (0 * inf = NaN) the comparisons are false for NaN,
 * so that slab constrains nothing, which is right for a ray running inside it. The exit
 * distance is enlarged by BOX_EXIT_GROWTH to cover the rounding of the distances.
 */
#include "bvh.h"

#include <assert.h>
#include <float.h>
#include <stdlib.h>

#include "../base/alloc.h"

#define BVH_BINS 16         /* centroid bins per axis: more cost more, gain little (Wald 2007) */
#define BVH_SAH_DEPTH 32    /* below this depth, ranges split at the middle index             */
/* C_trav and C_isect, relative costs of a node's box test and a primitive's test. Halving or
 * doubling their ratio, or 32 bins, moved no terrain1m figure beyond the noise (bench_rays). */
#define SAH_COST_TRAVERSE 1.0
#define SAH_COST_INTERSECT 1.0
/* 1 + 2 gamma(3), gamma(n) = n eps / (1 - n eps) (pbrt-v4, Sec. 6.8): the entry and exit
 * distances each carry at most gamma(3) of relative error. */
#define BOX_EXIT_GROWTH (1.0 + 2.0 * (3.0 * DBL_EPSILON) / (1.0 - 3.0 * DBL_EPSILON))

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

static void set_node_box(struct bvh_node *node, struct aabb box)
{
    node->box[0] = round_down(box.lo.x);
    node->box[1] = round_down(box.lo.y);
    node->box[2] = round_down(box.lo.z);
    node->box[3] = round_up(box.hi.x);
    node->box[4] = round_up(box.hi.y);
    node->box[5] = round_up(box.hi.z);
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

/* ---- the binned SAH builder ---- */

struct builder {
    const struct aabb *bounds;  /* borrowed from bvh_build()'s caller: the items' boxes   */
    struct vec3 *centroids;     /* owned by bvh_build(): the boxes' centres               */
    uint32_t *items;            /* the bvh's item array, partitioned in place              */
    struct bvh_node *nodes;     /* the bvh's node array, with room for 2n - 1 nodes       */
    size_t n_nodes;
};

/* The items items[first .. first + count), the union of their boxes and the box of their
 * centres; a split hands both boxes to the two halves, so each level reads the items
 * twice (binning, partitioning) and no more. */
struct range {
    size_t first, count;
    struct aabb box, centres;
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
static struct range make_range(const struct builder *b, size_t first, size_t count)
{
    struct range r;
    r.first = first;
    r.count = count;
    r.box = r.centres = box_empty();
    for (size_t k = first; k < first + count; k++) {
        r.box = box_union(r.box, b->bounds[b->items[k]]);
        r.centres = box_add_point(r.centres, b->centroids[b->items[k]]);
    }
    return r;
}

/* Whether the range splits, and if so into *left and *right. */
static int split_range(struct builder *b, const struct range *r, int depth, struct range *left,
                       struct range *right)
{
    if (r->count == 1)
        return 0;
    if (depth < BVH_SAH_DEPTH) {
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
            return 1;
        }
    }
    if (r->count <= BVH_MAX_LEAF)
        return 0;
    /* Coincident centres, or the depth limit: split at the middle index. */
    *left = make_range(b, r->first, r->count / 2);
    *right = make_range(b, r->first + r->count / 2, r->count - r->count / 2);
    return 1;
}

/* Makes nodes[index] the node over the range; its children, if any, go to the next free
 * pair of slots. */
static void build_node(struct builder *b, size_t index, const struct range *r, int depth)
{
    struct bvh_node *node = &b->nodes[index];   /* nodes[] never moves: sized up front */
    set_node_box(node, r->box);
    struct range left, right;
    if (!split_range(b, r, depth, &left, &right)) {
        node->offset = (uint32_t)r->first;
        node->count = (uint32_t)r->count;
        return;
    }
    size_t children = b->n_nodes;
    b->n_nodes += 2;
    node->offset = (uint32_t)children;
    node->count = 0;
    build_node(b, children, &left, depth + 1);
    build_node(b, children + 1, &right, depth + 1);
}

struct bvh *bvh_build(const struct aabb *bounds, size_t n)
{
    assert(n <= ((size_t)1 << 31));
    struct bvh *bvh = xmalloc(1, sizeof *bvh, "BVH");
    struct builder b;
    b.bounds = bounds;
    b.centroids = xmalloc(n, sizeof *b.centroids, "BVH centroids");
    b.items = xmalloc(n, sizeof *b.items, "BVH items");
    b.nodes = xmalloc(n > 0 ? 2 * n - 1 : 0, sizeof *b.nodes, "BVH nodes");
    b.n_nodes = n > 0 ? 1 : 0;   /* the root */
    for (size_t i = 0; i < n; i++) {
        b.centroids[i] = vec3_add(vec3_scale(bounds[i].lo, 0.5), vec3_scale(bounds[i].hi, 0.5));
        b.items[i] = (uint32_t)i;
    }
    if (n > 0) {
        struct range all = make_range(&b, 0, n);
        build_node(&b, 0, &all, 0);
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
    unsigned char *seen;    /* seen[item]: the item was found in a leaf     */
    size_t next_item;       /* leaves must cover items[] in order, no gaps  */
    size_t n_nodes_seen;
};

static int box_inside(const struct bvh_node *inner, const struct bvh_node *outer)
{
    for (int a = 0; a < 3; a++)
        if (!(inner->box[a] >= outer->box[a] && inner->box[3 + a] <= outer->box[3 + a]))
            return 0;
    return 1;
}

static int item_inside(struct aabb box, const struct bvh_node *node)
{
    const float *b = node->box;
    return box.lo.x >= b[0] && box.lo.y >= b[1] && box.lo.z >= b[2]
           && box.hi.x <= b[3] && box.hi.y <= b[4] && box.hi.z <= b[5];
}

static int check_leaf(struct checker *c, const struct bvh_node *node)
{
    if (node->count > BVH_MAX_LEAF || node->offset != c->next_item
        || node->count > c->n - c->next_item)
        return 0;
    for (size_t k = node->offset; k < (size_t)node->offset + node->count; k++) {
        uint32_t item = c->bvh->items[k];
        if (item >= c->n || c->seen[item] || !item_inside(c->bounds[item], node))
            return 0;
        c->seen[item] = 1;
    }
    c->next_item += node->count;
    return 1;
}

static int check_node(struct checker *c, size_t index, int depth)
{
    if (index >= c->bvh->n_nodes || depth >= BVH_MAX_DEPTH)
        return 0;
    const struct bvh_node *node = &c->bvh->nodes[index];
    c->n_nodes_seen++;
    if (node->count > 0)
        return check_leaf(c, node);
    size_t first = node->offset;   /* children: first and first + 1 */
    if (first <= index || first + 1 >= c->bvh->n_nodes)
        return 0;
    if (!box_inside(&c->bvh->nodes[first], node) || !box_inside(&c->bvh->nodes[first + 1], node))
        return 0;
    return check_node(c, first, depth + 1) && check_node(c, first + 1, depth + 1);
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
    c.seen = xcalloc(n, 1, "BVH check");
    c.next_item = 0;
    c.n_nodes_seen = 0;
    int ok = check_node(&c, 0, 0) && c.next_item == n && c.n_nodes_seen == bvh->n_nodes;
    xfree(c.seen);
    return ok;
}

/* ---- traversal ---- */

/* The ray as the slab test uses it. */
struct slab_ray {
    double origin[3];
    double inv_dir[3];  /* 1 / d, +-inf for a zero component (IEEE division)            */
    int near[3];        /* near[a]: index in node.box of the side the ray meets first
                           along axis a (a for lo, 3 + a for hi when d[a] < 0)           */
    int far[3];         /* the other side's index                                        */
};

static struct slab_ray slab_ray(struct ray ray)
{
    struct slab_ray s;
    double d[3] = {ray.dir.x, ray.dir.y, ray.dir.z};
    s.origin[0] = ray.origin.x;
    s.origin[1] = ray.origin.y;
    s.origin[2] = ray.origin.z;
    for (int a = 0; a < 3; a++) {
        s.inv_dir[a] = 1.0 / d[a];   /* d = +-0 gives +-inf, which the slab test expects */
        s.near[a] = s.inv_dir[a] < 0 ? 3 + a : a;
        s.far[a] = s.inv_dir[a] < 0 ? a : 3 + a;
    }
    return s;
}

/* Whether the ray meets the node's box at some t in [0, tmax]; *t_enter is where. Each
 * "a > b ? a : b" keeps b when a is NaN (the ray runs in that slab's plane), so such a slab
 * constrains nothing; tmax may grow by BOX_EXIT_GROWTH too, which only visits more. */
static inline int enters_box(const struct bvh_node *node, const struct slab_ray *r, double tmax,
                             double *t_enter)
{
    const float *box = node->box;
    double near_x = (box[r->near[0]] - r->origin[0]) * r->inv_dir[0];
    double near_y = (box[r->near[1]] - r->origin[1]) * r->inv_dir[1];
    double near_z = (box[r->near[2]] - r->origin[2]) * r->inv_dir[2];
    double far_x = (box[r->far[0]] - r->origin[0]) * r->inv_dir[0];
    double far_y = (box[r->far[1]] - r->origin[1]) * r->inv_dir[1];
    double far_z = (box[r->far[2]] - r->origin[2]) * r->inv_dir[2];
    double t0 = near_x > 0.0 ? near_x : 0.0;
    t0 = near_y > t0 ? near_y : t0;
    t0 = near_z > t0 ? near_z : t0;
    double t1 = far_x < tmax ? far_x : tmax;
    t1 = far_y < t1 ? far_y : t1;
    t1 = far_z < t1 ? far_z : t1;
    *t_enter = t0;
    return t0 <= t1 * BOX_EXIT_GROWTH;
}

/* A node waiting on the traversal stack, with the distance at which the ray enters it. */
struct pending {
    uint32_t index;
    double t_enter;
};

/* The children of an interior node that the ray enters before tmax: returns how many (0, 1
 * or 2), the nearer in *next and, with 2, the farther in *later. */
static int children_entered(const struct bvh *bvh, const struct bvh_node *node,
                            const struct slab_ray *r, double tmax, struct pending *next,
                            struct pending *later)
{
    struct pending a = {node->offset, 0.0}, b = {node->offset + 1, 0.0};
    int in_a = enters_box(&bvh->nodes[a.index], r, tmax, &a.t_enter);
    int in_b = enters_box(&bvh->nodes[b.index], r, tmax, &b.t_enter);
    if (in_a && in_b) {
        *next = a.t_enter <= b.t_enter ? a : b;
        *later = a.t_enter <= b.t_enter ? b : a;
        return 2;
    }
    *next = in_a ? a : b;
    return in_a + in_b;
}

int bvh_intersect(const struct bvh *bvh, struct ray ray, double tmax,
                  int (*leaf)(void *ctx, size_t first, size_t count, double *tmax), void *ctx)
{
    struct slab_ray r = slab_ray(ray);
    struct pending next = {0, 0.0}, stack[BVH_MAX_DEPTH];
    int top = 0, found = 0;
    if (bvh->n_nodes == 0 || !enters_box(&bvh->nodes[0], &r, tmax, &next.t_enter))
        return 0;
    for (;;) {
        const struct bvh_node *node = &bvh->nodes[next.index];
        if (node->count > 0) {
            found |= leaf(ctx, node->offset, node->count, &tmax);
        } else {
            assert(top < BVH_MAX_DEPTH);   /* one entry per level: invariant (4) */
            int n = children_entered(bvh, node, &r, tmax, &next, &stack[top]);
            top += n == 2;   /* the farther child waits */
            if (n > 0)
                continue;
        }
        do {   /* the most recent waiting node the ray reaches before the current tmax */
            if (top == 0)
                return found;
            next = stack[--top];
        } while (next.t_enter > tmax);
    }
}

int bvh_occluded(const struct bvh *bvh, struct ray ray, double tmax,
                 int (*leaf)(void *ctx, size_t first, size_t count, double tmax), void *ctx)
{
    struct slab_ray r = slab_ray(ray);
    struct pending next = {0, 0.0}, stack[BVH_MAX_DEPTH];
    int top = 0;
    if (bvh->n_nodes == 0 || !enters_box(&bvh->nodes[0], &r, tmax, &next.t_enter))
        return 0;
    for (;;) {
        const struct bvh_node *node = &bvh->nodes[next.index];
        if (node->count > 0) {
            if (leaf(ctx, node->offset, node->count, tmax))
                return 1;
        } else {
            assert(top < BVH_MAX_DEPTH);
            int n = children_entered(bvh, node, &r, tmax, &next, &stack[top]);
            top += n == 2;
            if (n > 0)
                continue;
        }
        if (top == 0)
            return 0;
        next = stack[--top];
    }
}
