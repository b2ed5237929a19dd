/*
 * geom/bvh.c -- stack traversal of the 8-wide BVH (see bvh.h; the build is bvh_build.c).
 *
 * At a node the ray is tested against all eight slot boxes at once (enter_slots(): one
 * loop over the slots, which compilers turn into vector instructions); the slots it enters
 * are put on the stack farthest first with the distance at which the ray enters them, and
 * the nearest is taken next. A popped entry that starts beyond the nearest hit found
 * meanwhile is skipped. The any-hit walk does the same without sorting.
 *
 * The box test is the slab test in float (Williams et al., "An efficient and robust
 * ray-box intersection algorithm", 2005), made conservative so that no box the ray enters
 * in exact arithmetic is ever rejected:
 *   - the boxes are rounded outward when they are stored (bvh_build.c);
 *   - per axis, the origin is rounded to float upwards for the near plane and downwards for
 *     the far one when d > 0 (the other way round when d < 0), and 1/d towards zero for the
 *     near plane, away from zero for the far one, each by a relative margin of 3u or more
 *     (float_bracket(): 2^-22 less a float's rounding), which also covers the rounding of
 *     the subtraction and of the product that follow (u = 2^-24 relative each): the
 *     computed entry t0 and exit t1 of a slot satisfy t0 <= T0 + 2^-150 and
 *     t1 >= T1 - 2^-150 for the true T0 and T1, 2^-150 being what an underflowing product
 *     may lose;
 *   - so a slot is entered when t0 <= t1 + 2^-126 (REACH_FLOOR), computed, which holds
 *     whenever T0 <= T1, and a waiting slot is skipped when its t0 exceeds tmax + 2^-126;
 *   - a zero component of d gives 1/d = +-inf; where the origin lies on a slab's plane
 *     (0 * inf = NaN) the comparisons are false for NaN, so that slab constrains nothing,
 *     which is right for a ray running inside it;
 *   - tmax is rounded up to float.
 */
#include "bvh.h"

#include <assert.h>
#include <float.h>

/* The slack of the exit distances (see the top): two underflowing products' loss and more. */
#define REACH_FLOOR 0x1p-126f

/* Each visited node pushes at most BVH_WIDTH entries and pops one. */
#define STACK_SIZE (BVH_MAX_DEPTH * (BVH_WIDTH - 1) + 1)

/* A float no smaller than x (x not NaN): x moved up by more than the rounding to float
 * can take back, |x| 2^-22 (four times a float's relative spacing) plus 2^-149 (float's
 * smallest spacing, for x near 0). Coarser than the next float up by a float ulp or two,
 * which only makes a test a little more generous, and without libm's calls. */
static float float_at_least(double x)
{
    if (x > FLT_MAX)
        return INFINITY;
    if (x < -FLT_MAX)
        return -FLT_MAX;
    double y = x + fabs(x) * 0x1p-22 + 0x1p-149;
    return y >= FLT_MAX ? FLT_MAX : (float)y;   /* x <= FLT_MAX */
}

static float float_at_most(double x)
{
    return -float_at_least(-x);
}

/* The ray as the box test uses it, per axis a, each value repeated for the BVH_WIDTH
 * slots (so the slot loop reads it as it reads the boxes). */
struct box_ray {
    float origin_near[3][BVH_WIDTH]; /* the origin rounded for near planes, and far ones */
    float origin_far[3][BVH_WIDTH];
    float inv_near[3][BVH_WIDTH];    /* 1/d rounded towards zero, and away from zero     */
    float inv_far[3][BVH_WIDTH];
    int near[3], far[3];             /* BVH_WIDTH * the bound of the plane the ray meets
                                        first / last along the axis                    */
};

/* Floats *below <= x <= *above, as float_at_most() and float_at_least() give them, with
 * one margin for both and without their range tests where x is far inside float's range. */
static inline void float_bracket(double x, float *below, float *above)
{
    double margin = fabs(x) * 0x1p-22 + 0x1p-149;
    if (fabs(x) <= 0x1p126) {   /* x -+ margin round to finite floats */
        *below = (float)(x - margin);
        *above = (float)(x + margin);
        return;
    }
    *below = float_at_most(x);
    *above = float_at_least(x);
}

/* The double 1/d is within half an ulp of double of the exact 1/d, far inside the margin
 * of float_bracket(), so it brackets the exact value too. For d = +-0, 1/d = +-inf, and the
 * near factor becomes +-FLT_MAX, which keeps every sign the slab test reads. Both
 * roundings are made and one kept, so the ray's signs cost no branches. */
static void box_ray(struct ray ray, struct box_ray *r)
{
    double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    double d[3] = {ray.dir.x, ray.dir.y, ray.dir.z};
    for (int a = 0; a < 3; a++) {
        double inv = 1.0 / d[a];   /* d = +-0 gives +-inf */
        int positive = inv > 0;
        float o_down, o_up, inv_down, inv_up;
        float_bracket(o[a], &o_down, &o_up);
        float_bracket(inv, &inv_down, &inv_up);
        float on = positive ? o_up : o_down, of = positive ? o_down : o_up;
        float in = positive ? inv_down : inv_up, inf_ = positive ? inv_up : inv_down;
        for (int i = 0; i < BVH_WIDTH; i++) {
            r->origin_near[a][i] = on;
            r->origin_far[a][i] = of;
            r->inv_near[a][i] = in;
            r->inv_far[a][i] = inf_;
        }
        r->near[a] = BVH_WIDTH * (positive ? a : 3 + a);
        r->far[a] = BVH_WIDTH * (positive ? 3 + a : a);
    }
}

/* tmax grown by the exit distances' slack: the largest computed entry distance that may
 * still belong to a box entered before tmax. */
static float reach(float tmax)
{
    return tmax + REACH_FLOOR;
}

/* The slots of node the ray enters before tmax (tmax_reach = reach() of a float above it),
 * one bit each, and
 * each slot's entry distance in t_enter[]; the box test of all slots is one loop, which
 * compilers vectorise. Each "a > b ? a : b" keeps b when a is NaN, so a NaN slab
 * constrains nothing. Only used slots count: an origin beyond float's range passes every
 * box test, empty slots' too. */
static unsigned enter_slots(const struct bvh_node *node, const struct box_ray *r, float tmax_reach,
                            float t_enter[BVH_WIDTH])
{
    static const unsigned bit[BVH_WIDTH] = {1, 2, 4, 8, 16, 32, 64, 128};
    const float *near_x = node->box + r->near[0], *far_x = node->box + r->far[0];
    const float *near_y = node->box + r->near[1], *far_y = node->box + r->far[1];
    const float *near_z = node->box + r->near[2], *far_z = node->box + r->far[2];
    unsigned entered = 0;
    for (int i = 0; i < BVH_WIDTH; i++) {
        float nx = (near_x[i] - r->origin_near[0][i]) * r->inv_near[0][i];
        float ny = (near_y[i] - r->origin_near[1][i]) * r->inv_near[1][i];
        float nz = (near_z[i] - r->origin_near[2][i]) * r->inv_near[2][i];
        float fx = (far_x[i] - r->origin_far[0][i]) * r->inv_far[0][i];
        float fy = (far_y[i] - r->origin_far[1][i]) * r->inv_far[1][i];
        float fz = (far_z[i] - r->origin_far[2][i]) * r->inv_far[2][i];
        float enter = nx > 0.0f ? nx : 0.0f;
        enter = ny > enter ? ny : enter;
        enter = nz > enter ? nz : enter;
        float leave = fx < tmax_reach ? fx : tmax_reach;
        leave = fy < leave ? fy : leave;
        leave = fz < leave ? fz : leave;
        t_enter[i] = enter;
        entered |= enter <= leave + REACH_FLOOR ? bit[i] : 0u;
    }
    return entered & ((1u << node->n_slots) - 1u);
}

/* A slot waiting on the traversal stack, or the one visited next. */
struct pending {
    uint32_t ref;     /* a node: its index; a leaf: its first position in items[] plus
                         (its count << LEAF_SHIFT)                                        */
    float t_enter;    /* where the ray enters the slot's box                            */
};

/* Positions in items[] are below 2^28 (bvh_build() asserts it), leaving room for the count. */
#define LEAF_SHIFT 28

static uint32_t slot_ref(const struct bvh_node *node, int i)
{
    uint32_t child = node->offset + (uint32_t)i;
    uint32_t items = node->first[i] | (uint32_t)node->count[i] << LEAF_SHIFT;
    return i < node->n_nodes ? child : items;   /* both made: a select, not a branch */
}

/* The index of the lowest set bit of mask (mask > 0). A loop, whose branches the
 * processor predicts, beat a de Bruijn multiply and table, whose result every following
 * load waits for. */
static int lowest_slot(unsigned mask)
{
    int i = 0;
    while (!(mask >> i & 1u))
        i++;
    return i;
}

/* Of the entered slots (entered > 0), returns the nearest and pushes the others onto
 * stack[*top ...], farthest deepest, when sorted (ties keep the slots' order); else in
 * slot order. Most nodes have one entered slot, which needs neither. */
static struct pending next_slot(const struct bvh_node *node, unsigned entered,
                                const float t_enter[BVH_WIDTH], int sorted,
                                struct pending *stack, int *top)
{
    struct pending e[BVH_WIDTH];
    int i = lowest_slot(entered);
    e[0].ref = slot_ref(node, i);
    e[0].t_enter = t_enter[i];
    entered &= entered - 1;
    if (entered == 0)
        return e[0];
    int n = 1;
    for (; entered != 0; entered &= entered - 1) {
        i = lowest_slot(entered);
        struct pending p;
        p.ref = slot_ref(node, i);
        p.t_enter = t_enter[i];
        int k = n++;
        if (sorted)   /* insertion: e[] ascending by distance */
            for (; k > 0 && e[k - 1].t_enter > p.t_enter; k--)
                e[k] = e[k - 1];
        e[k] = p;
    }
    assert(*top + n - 1 <= STACK_SIZE);   /* invariant (4) bounds the depth */
    for (int k = n - 1; k > 0; k--)
        stack[(*top)++] = e[k];
    return e[0];
}

/* The walk shared by both queries: closest (1) visits in order and lowers tmax at each hit;
 * otherwise the walk stops at the first leaf that reports a hit. */
static int traverse(const struct bvh *bvh, struct ray ray, double tmax, int closest,
                    int (*leaf)(void *ctx, size_t first, size_t count, double *tmax), void *ctx)
{
    if (bvh->n_nodes == 0)
        return 0;
    struct box_ray r;
    box_ray(ray, &r);
    float tmax_reach = reach(float_at_least(tmax));
    struct pending stack[STACK_SIZE];
    struct pending p = {0, 0.0f};   /* the root, whose box is no slot's */
    int top = 0, found = 0;
    for (;;) {
        uint32_t count = p.ref >> LEAF_SHIFT;
        if (count == 0) {
            float t_enter[BVH_WIDTH];
            const struct bvh_node *node = &bvh->nodes[p.ref];
            unsigned entered = enter_slots(node, &r, tmax_reach, t_enter);
            if (entered != 0) {
                p = next_slot(node, entered, t_enter, closest, stack, &top);
                continue;   /* the nearest, entered before tmax just now */
            }
        } else if (leaf(ctx, p.ref & ((UINT32_C(1) << LEAF_SHIFT) - 1), count, &tmax)) {
            if (!closest)
                return 1;
            found = 1;
            tmax_reach = reach(float_at_least(tmax));
        }
        do {   /* the most recent waiting slot the ray enters before the current tmax */
            if (top == 0)
                return found;
            p = stack[--top];
        } while (p.t_enter > tmax_reach);
    }
}

int bvh_intersect(const struct bvh *bvh, struct ray ray, double tmax,
                  int (*leaf)(void *ctx, size_t first, size_t count, double *tmax), void *ctx)
{
    return traverse(bvh, ray, tmax, 1, leaf, ctx);
}

/* The any-hit callback behind the shared walk's signature. */
struct any_hit {
    int (*leaf)(void *ctx, size_t first, size_t count, double tmax);
    void *ctx;
};

static int any_hit_leaf(void *ctx, size_t first, size_t count, double *tmax)
{
    const struct any_hit *a = ctx;
    return a->leaf(a->ctx, first, count, *tmax);
}

int bvh_occluded(const struct bvh *bvh, struct ray ray, double tmax,
                 int (*leaf)(void *ctx, size_t first, size_t count, double tmax), void *ctx)
{
    struct any_hit a;
    a.leaf = leaf;
    a.ctx = ctx;
    return traverse(bvh, ray, tmax, 0, any_hit_leaf, &a);
}
