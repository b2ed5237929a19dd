/*
 * geom/bvh.h -- a bounding volume hierarchy over boxes: binned SAH build, one flat array of
 * 32-byte nodes, ordered closest-hit and any-hit traversal.
 *
 * The BVH knows items only as indices 0 .. n-1 into the array of boxes it was built from.
 * Invariants, verified by bvh_check():
 *   (1) the root is nodes[0]; an interior node's two children are the adjacent pair
 *       nodes[offset], nodes[offset + 1], so the two boxes tested together are read
 *       together, and every node but the root is some node's child;
 *   (2) every item appears in exactly one leaf, and each leaf holds the contiguous range
 *       items[offset .. offset + count) of the reordered item array;
 *   (3) a node's box contains its children's boxes and its items' boxes;
 *   (4) a leaf holds 1 .. BVH_MAX_LEAF items and no path from the root is longer than
 *       BVH_MAX_DEPTH nodes, which bounds the traversal stack.
 * Owns nodes[] and items[]; the item boxes stay the caller's. geometry.c uses the BVH and
 * does the per-item work in the leaf callbacks.
 */
#ifndef PHOTON_BVH_H
#define PHOTON_BVH_H

#include <stddef.h>
#include <stdint.h>

#include "ray.h"

/* Leaves hold at most 4 items: the SAH decides below that; above it a node always splits. */
#define BVH_MAX_LEAF 4
/* The longest path: SAH splits stop at depth 32, then halving the index range reaches a leaf
 * within 28 more levels for MAX_PRIMITIVES = 2^28 items, 61 in all; 64 leaves a margin and
 * is the size of the traversal stack. */
#define BVH_MAX_DEPTH 64

/* 32 bytes: bounds in float to halve the node, rounded outward (lo down, hi up, one ulp of
 * float at most) so a node's box contains the double box it stands for and no hit is lost. */
struct bvh_node {
    float box[6];     /* lo x, y, z, then hi x, y, z                                          */
    uint32_t offset;  /* leaf: first position in items[]; interior: index of first child    */
    uint32_t count;   /* leaf: number of items, 1 .. BVH_MAX_LEAF; interior: 0               */
};
extern char bvh_node_is_32_bytes[sizeof(struct bvh_node) == 32 ? 1 : -1];

struct bvh {
    struct bvh_node *nodes; /* owned; n_nodes of them, none when built over no items      */
    size_t n_nodes;
    uint32_t *items;        /* owned; item indices in leaf order, a permutation of 0..n-1 */
    size_t n_items;
};

/* Builds the BVH over bounds[0 .. n-1] (finite, lo <= hi): binned SAH on the box centres.
 * n <= 2^31. Never returns NULL (allocation failure is fatal). */
struct bvh *bvh_build(const struct aabb *bounds, size_t n);
void bvh_free(struct bvh *bvh); /* NULL is a no-op */
size_t bvh_bytes(const struct bvh *bvh);

/* 1 when invariants (1)-(4) hold for a BVH built over bounds[0 .. n-1], else 0. */
int bvh_check(const struct bvh *bvh, const struct aabb *bounds, size_t n);

/* Closest hit: visits, nearer child first (by the distance at which the ray enters each
 * child's box), every leaf whose box the ray enters before tmax, calling
 * leaf(ctx, first, count, &tmax) for items[first .. first + count). The callback tests its
 * items, lowers tmax to the nearest hit it finds and returns whether it found one. Returns
 * whether any callback did. ray.dir must not be zero. */
int bvh_intersect(const struct bvh *bvh, struct ray ray, double tmax,
                  int (*leaf)(void *ctx, size_t first, size_t count, double *tmax), void *ctx);

/* Any hit: as bvh_intersect() with a fixed tmax, stopping at the first leaf whose callback
 * returns 1. Returns that 1, or 0. */
int bvh_occluded(const struct bvh *bvh, struct ray ray, double tmax,
                 int (*leaf)(void *ctx, size_t first, size_t count, double tmax), void *ctx);

#endif
