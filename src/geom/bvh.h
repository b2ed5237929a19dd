/*
 * geom/bvh.h -- a bounding volume hierarchy over boxes: an 8-wide tree built by binned SAH,
 * one flat array of 256-byte nodes, ordered closest-hit and any-hit traversal.
 *
 * The BVH knows items only as indices 0 .. n-1 into the array of boxes it was built from.
 * A node has BVH_WIDTH slots, and a slot is an interior child, a leaf or empty. The node
 * holds its slots' boxes, so one node read gives the boxes the ray is tested against next
 * (the root's own box is stored nowhere: its slots are the first boxes tested).
 * Invariants, verified by bvh_check():
 *   (1) the root is nodes[0]; a node's interior children are its slots 0 .. n_nodes - 1,
 *       slot i's child being nodes[offset + i] with offset greater than the node's own
 *       index, so the children of a node lie side by side; every node but the root is the
 *       child of exactly one slot;
 *   (2) slots n_nodes .. n_slots - 1 are leaves, slot i holding the items
 *       items[first[i] .. first[i] + count[i]), 1 <= count[i] <= BVH_MAX_LEAF; the leaves'
 *       ranges cover items[0 .. n) once each, and items[] is a permutation of 0 .. n-1;
 *   (3) a slot's box contains its child's slot boxes, or its items' boxes; slots
 *       n_slots .. BVH_WIDTH - 1 are empty: count 0 and the box lo = +inf, hi = -inf, which
 *       no ray enters; a node uses at least 2 slots, except a root over a single leaf;
 *   (4) no path from the root has more than BVH_MAX_DEPTH nodes, which bounds the stack.
 * Owns nodes[] and items[]; the item boxes stay the caller's. geometry.c uses the BVH and
 * does the per-item work in the leaf callbacks. The build is bvh_build.c, the walk bvh.c.
 * Memory: 256 bytes a node and 4 an item; on a height field of 2 triangles a grid cell,
 * about one node per ten items (tests/bench/README.md has the workloads' bytes).
 */
#ifndef PHOTON_BVH_H
#define PHOTON_BVH_H

#include <stddef.h>
#include <stdint.h>

#include "ray.h"

#define BVH_WIDTH 8
/* Leaves hold at most 4 items: the SAH decides below that, and a range that a full node has
 * no slot left to split is a leaf at up to 4; above it a range always splits. */
#define BVH_MAX_LEAF 4
/* The longest path: SAH splits stop at binary depth 32, then halving the index range
 * reaches a leaf within 28 more levels for MAX_PRIMITIVES = 2^28 items, 61 in all; a
 * node spends at least one binary split (the root over groups perhaps none: 62 nodes), so
 * 64 bounds the nodes on a path too. */
#define BVH_MAX_DEPTH 64

/* 256 bytes, four cache lines. Bounds in float to keep the node small, rounded outward (lo
 * down, hi up, one ulp of float at most) so that a slot's box contains the double box it
 * stands for and no hit is lost. box[] is laid out bound by bound, so the eight slots' values
 * of one bound are adjacent and the box test is a loop over slots that compilers vectorise.
 * Interior node and leaf alike are slots of their parent: a leaf has no node of its own. The
 * walk reads slots below n_slots only, and packs a leaf's first and count into 32 bits
 * (positions below 2^28, counts up to BVH_MAX_LEAF). */
struct bvh_node {
    float box[6 * BVH_WIDTH]; /* box[BVH_WIDTH * k + i]: bound k of slot i, k = 0, 1, 2 the
                                 lo x, y, z and k = 3, 4, 5 the hi x, y, z             */
    uint32_t offset;          /* slot i < n_nodes: its child is nodes[offset + i]      */
    uint32_t first[BVH_WIDTH];/* leaf slot i: its first position in items[]; else 0    */
    uint8_t count[BVH_WIDTH]; /* leaf slot i: its number of items; interior, empty: 0  */
    uint8_t n_nodes;          /* slots 0 .. n_nodes - 1 are interior children          */
    uint8_t n_slots;          /* slots n_nodes .. n_slots - 1 are leaves; the rest empty */
    uint8_t unused[18];       /* zero: makes the node 256 bytes                         */
};
extern char bvh_node_is_256_bytes[sizeof(struct bvh_node) == 256 ? 1 : -1];

struct bvh {
    struct bvh_node *nodes; /* owned; n_nodes of them, none when built over no items      */
    size_t n_nodes;
    uint32_t *items;        /* owned; item indices in leaf order, a permutation of 0..n-1 */
    size_t n_items;
};

/* Builds the BVH over bounds[0 .. n-1] (finite, lo <= hi): binned SAH on the box centres.
 * n < 2^28 (MAX_PRIMITIVES). Never returns NULL (allocation failure is fatal). */
struct bvh *bvh_build(const struct aabb *bounds, size_t n);

/* The same over items in n_groups (1 .. BVH_WIDTH) groups of consecutive indices, group g
 * being [group_ends[g - 1], group_ends[g]) (group_ends[-1] taken as 0, the last end n;
 * groups may be empty), such that no leaf mixes groups and each group keeps its own
 * positions: items[k] lies in the same group as k. The root's slots start as one a group,
 * and the groups are split from there, so the separation costs no level of the tree.
 * geometry.c groups its primitives by kind: a leaf's position then says its kind and
 * index, with no table of references to read. */
struct bvh *bvh_build_groups(const struct aabb *bounds, size_t n, const size_t *group_ends,
                             int n_groups);
void bvh_free(struct bvh *bvh); /* NULL is a no-op */
size_t bvh_bytes(const struct bvh *bvh);

/* 1 when invariants (1)-(4) hold for a BVH built over bounds[0 .. n-1], else 0. */
int bvh_check(const struct bvh *bvh, const struct aabb *bounds, size_t n);

/* Closest hit: visits, nearer slot first (by the distance at which the ray enters each
 * slot's box), every leaf whose box the ray enters before tmax, calling
 * leaf(ctx, first, count, &tmax) for items[first .. first + count). The callback tests its
 * items, lowers tmax to the nearest hit it finds and returns whether it found one. Returns
 * whether any callback did. ray.dir must not be zero. */
int bvh_intersect(const struct bvh *bvh, struct ray ray, double tmax,
                  int (*leaf)(void *ctx, size_t first, size_t count, double *tmax), void *ctx);

/* Any hit: as bvh_intersect() with a fixed tmax and in no particular order, stopping at
 * the first leaf whose callback returns 1. Returns that 1, or 0. */
int bvh_occluded(const struct bvh *bvh, struct ray ray, double tmax,
                 int (*leaf)(void *ctx, size_t first, size_t count, double tmax), void *ctx);

#endif
