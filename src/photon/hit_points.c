/*
 * photon/hit_points.c -- the kd-tree over hit points (hit_points.h).
 *
 * Node [lo, hi) of the index array has its hit point at m = lo + (hi - lo) / 2; the points
 * of [lo, m) lie on one side of its split plane, those of [m + 1, hi) on the other, the
 * plane being across the axis along which the range's positions spread most. The build
 * picks each median by quickselect, O(n log n) in all. A range of at most HIT_POINT_LEAF
 * points is a leaf: one box for all of them, whose nodes a search reads one after the
 * other (they lie side by side), where descending would read as many boxes that mostly
 * overlap, the discs being about as wide as the spacing of the points. The build sorts an
 * array of positions with their indices, then moves the hit points into that order, cycle
 * by cycle, one hit point in hand at a time (no second copy of the array).
 */
#include "hit_points.h"

#include <stdlib.h>

#include "../base/alloc.h"
#include "trace.h"

#define HIT_POINT_LEAF 8 /* points in a leaf: leaves of 4, 8 or 16 search about as fast,
                            none at all much slower (src/modes/measured.md) */

/* The box of the sphere of the hit point's reach around it: its discs and then some. */
static struct aabb disc_box(const struct hit_point *hp)
{
    double reach = hit_point_reach(hp);
    struct vec3 r = vec3(reach, reach, reach);
    struct aabb box;
    box.lo = vec3_sub(hp->x, r);
    box.hi = vec3_add(hp->x, r);
    return box;
}

static int box_contains(struct aabb box, struct vec3 p)
{
    return p.x >= box.lo.x && p.x <= box.hi.x && p.y >= box.lo.y && p.y <= box.hi.y &&
           p.z >= box.lo.z && p.z <= box.hi.z;
}

/* What the build sorts: a hit point's position beside its index, so that the median
 * searches, which read every position of a range on every level, read a compact array in
 * order rather than 24 bytes of each of the far larger hit points, scattered through
 * memory by the index (2009 builds anew each pass). The same swaps as on the bare
 * indices: the same order. */
struct build_item {
    struct vec3 x; /* points[i].x */
    size_t i;
};

/* The axis along which the positions of items[lo .. hi-1] spread most. Plain comparisons,
 * not vec3_min()'s fmin(), a call into the maths library per coordinate: they differ only
 * for NaN, which no position is, and in the sign of a zero, which no extent sees. */
static int widest_axis(const struct build_item *items, size_t lo, size_t hi)
{
    double min[3], max[3];
    for (int a = 0; a < 3; a++)
        min[a] = max[a] = vec3_get(items[lo].x, a);
    for (size_t i = lo + 1; i < hi; i++)
        for (int a = 0; a < 3; a++) {
            double c = vec3_get(items[i].x, a);
            min[a] = c < min[a] ? c : min[a];
            max[a] = c > max[a] ? c : max[a];
        }
    struct vec3 extent = vec3(max[0] - min[0], max[1] - min[1], max[2] - min[2]);
    return extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
}

static void swap_items(struct build_item *items, size_t a, size_t b)
{
    struct build_item t = items[a];
    items[a] = items[b];
    items[b] = t;
}

/* Reorders items[lo .. hi-1] so that position m holds the element that sorting by the
 * axis coordinate would put there, smaller keys before it and larger after (Hoare's
 * quickselect with the middle element as pivot and a three-way partition, so equal keys
 * cost nothing extra). */
static void select_median(struct build_item *items, size_t lo, size_t hi, size_t m, int axis)
{
    while (hi - lo > 1) {
        double pivot = vec3_get(items[lo + (hi - lo) / 2].x, axis);
        size_t less = lo, i = lo, greater = hi;
        while (i < greater) {
            double k = vec3_get(items[i].x, axis);
            if (k < pivot)
                swap_items(items, less++, i++);
            else if (k > pivot)
                swap_items(items, i, --greater);
            else
                i++;
        }
        if (m < less)
            hi = less;
        else if (m >= greater)
            lo = greater;
        else
            return;
    }
}

/* Orders items[lo .. hi-1] as the tree below node [lo, hi) has them. */
static void build_range(struct build_item *items, size_t lo, size_t hi)
{
    if (hi - lo <= HIT_POINT_LEAF)
        return; /* a leaf: its order does not matter */
    size_t m = lo + (hi - lo) / 2;
    select_median(items, lo, hi, m, widest_axis(items, lo, hi));
    build_range(items, lo, m);
    build_range(items, m + 1, hi);
}

/* Moves points into the order of index (the point at index[k] goes to k), following each
 * cycle of the permutation with one point in hand; index ends as the identity. */
static void move_into_order(struct hit_point *points, size_t *index, size_t n)
{
    for (size_t start = 0; start < n; start++) {
        if (index[start] == start)
            continue;
        struct hit_point in_hand = points[start];
        size_t k = start;
        while (index[k] != start) {
            size_t from = index[k];
            points[k] = points[from];
            index[k] = k;
            k = from;
        }
        points[k] = in_hand;
        index[k] = k;
    }
}

/* Copies hit point index[m]'s position and R^2 into node m; returns its disc's box. */
static struct aabb refit_node(struct hit_point_tree *tree, size_t m)
{
    const struct hit_point *hp = &tree->points[m];
    tree->nodes[m].x = hp->x;
    tree->nodes[m].r2 = hit_point_reach(hp) * hit_point_reach(hp);
    return disc_box(hp);
}

/* Sets the nodes of [lo, hi) and below; returns the node's box, which node m keeps (a
 * leaf's other nodes keep none). hi > lo. */
static struct aabb refit_range(struct hit_point_tree *tree, size_t lo, size_t hi)
{
    size_t m = lo + (hi - lo) / 2;
    struct aabb box = refit_node(tree, m);
    if (hi - lo <= HIT_POINT_LEAF) {
        for (size_t k = lo; k < hi; k++)
            if (k != m)
                box = aabb_union(box, refit_node(tree, k));
    } else {
        box = aabb_union(box, refit_range(tree, lo, m));
        if (m + 1 < hi)
            box = aabb_union(box, refit_range(tree, m + 1, hi));
    }
    tree->boxes[m] = box;
    return box;
}

void hit_point_tree_build(struct hit_point_tree *tree, struct hit_point *points, size_t n)
{
    struct build_item *items = xmalloc(n > 0 ? n : 1, sizeof *items, "hit point tree");
    for (size_t i = 0; i < n; i++) {
        items[i].x = points[i].x;
        items[i].i = i;
    }
    build_range(items, 0, n);
    size_t *index = xmalloc(n > 0 ? n : 1, sizeof *index, "hit point tree");
    for (size_t k = 0; k < n; k++)
        index[k] = items[k].i;
    xfree(items);
    tree->points = points;
    tree->n = n;
    tree->place = xmalloc(n > 0 ? n : 1, sizeof *tree->place, "hit point tree");
    for (size_t k = 0; k < n; k++)
        tree->place[index[k]] = k;
    move_into_order(points, index, n);
    xfree(index);
    tree->nodes = xmalloc(n > 0 ? n : 1, sizeof *tree->nodes, "hit point tree");
    tree->boxes = xmalloc(n > 0 ? n : 1, sizeof *tree->boxes, "hit point tree");
    hit_point_tree_refit(tree);
}

void hit_point_tree_refit(struct hit_point_tree *tree)
{
    if (tree->n > 0)
        refit_range(tree, 0, tree->n);
}

static void visit_range(const struct hit_point_tree *tree, size_t lo, size_t hi, struct vec3 p,
                        void (*visit)(void *context, size_t i), void *context)
{
    while (hi > lo) {
        size_t m = lo + (hi - lo) / 2;
        if (!box_contains(tree->boxes[m], p))
            return;
        if (hi - lo <= HIT_POINT_LEAF) {
            for (size_t k = lo; k < hi; k++)
                if (vec3_length2(vec3_sub(p, tree->nodes[k].x)) <= tree->nodes[k].r2)
                    visit(context, k);
            return;
        }
        if (vec3_length2(vec3_sub(p, tree->nodes[m].x)) <= tree->nodes[m].r2)
            visit(context, m);
        visit_range(tree, lo, m, p, visit, context);
        lo = m + 1; /* the right half by iteration: recursion only as deep as the tree */
    }
}

void hit_point_tree_visit(const struct hit_point_tree *tree, struct vec3 p,
                          void (*visit)(void *context, size_t i), void *context)
{
    visit_range(tree, 0, tree->n, p, visit, context);
}

void hit_point_tree_free(struct hit_point_tree *tree)
{
    xfree(tree->boxes);
    xfree(tree->nodes);
    xfree(tree->place);
    tree->place = NULL;
    tree->nodes = NULL;
    tree->boxes = NULL;
    tree->n = 0;
}

/* The share of hp's members whose disc of radius r about their own hit holds p: those
 * within scale |p - member|^2 <= r^2 (scale 1 the disc, 2 the inner disc of radius
 * r / sqrt(2)). */
static double members_holding(const struct hit_point *hp, struct vec3 p, double r,
                              double scale)
{
    struct vec3 from_x = vec3_sub(p, hp->x);
    double share = 0.0;
    for (uint32_t j = 0; j < hp->n_members; j++) {
        const struct hit_member *m = &hp->members[j];
        if (scale * vec3_length2(vec3_sub(from_x, vec3(m->dx, m->dy, m->dz))) <= r * r)
            share += m->share;
    }
    return share;
}

/* w turned by the rotation about from x to that takes unit from onto unit to, which face
 * alike (from . to > 0): Rodrigues' formula with the axis from x to unnormalised,
 * w cos + (k x w) + k (k . w) / (1 + cos), with cos = from . to. */
static struct vec3 turned(struct vec3 w, struct vec3 from, struct vec3 to)
{
    struct vec3 k = vec3_cross(from, to);
    double c = vec3_dot(from, to);
    struct vec3 t = vec3_add(vec3_scale(w, c), vec3_cross(k, w));
    return vec3_madd(t, k, vec3_dot(k, w) / (1.0 + c));
}

struct vec3 hit_point_add_photon(struct hit_point *hp, const struct photon_event *photon,
                                 double photons_per_pass, int facing_test,
                                 int turn_directions, int caustic_apart, struct vec3 *inner)
{
    if (facing_test && vec3_dot(hp->n, photon->normal) <= 0)
        return vec3_zero();
    int caustic = photon->kind == PHOTON_CAUSTIC && caustic_apart;
    struct progressive_estimate *e = caustic ? &hp->caustic : &hp->global;
    int members = caustic && hp->n_members > 0;
    double r = e->radius, d2 = vec3_length2(vec3_sub(photon->position, hp->x));
    double share = members ? members_holding(hp, photon->position, r, 1.0) : d2 <= r * r;
    if (!(share > 0))
        return vec3_zero(); /* within the hit point's reach, not within this estimate's disc */
    double alike = vec3_dot(photon->normal, hp->n);
    struct vec3 wi = turn_directions && alike > 0 ? turned(photon->wi, photon->normal, hp->n)
                                                  : photon->wi;
    struct vec3 f = brdf_eval(hp->material, &hp->frame, hp->wo, wi);
    struct vec3 added = vec3_mul(f, vec3_scale(photon->power, photons_per_pass * share));
    e->tau = vec3_add(e->tau, added);
    e->m_photons += share;
    if (inner != NULL) { /* the inner disc's part, for an error image */
        double within = members ? members_holding(hp, photon->position, r, 2.0) : 2 * d2 <= r * r;
        struct vec3 part = within == share ? added
                                           : vec3_mul(f, vec3_scale(photon->power,
                                                                    photons_per_pass * within));
        if (within > 0)
            inner[caustic] = vec3_add(inner[caustic], part);
    }
    return added;
}
