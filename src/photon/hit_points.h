/*
 * photon/hit_points.h -- the hit points of progressive photon mapping (Hachisuka, Ogaki and
 * Jensen 2008, Sec. 3.1) and the tree that finds, for a photon, every hit point whose disc
 * holds it.
 *
 * The paper's struct hitpoint, field for field: position x, normal n, ray direction w, the
 * BRDF, the pixel, the pixel weight, and the three values of the progressive estimate:
 * radius R, accumulated photon count N, accumulated flux tau. Our N is a double, since
 * Eq. 7 adds alpha M, a fraction of a photon. A hit point may hold two such estimates,
 * as Jensen's global and caustic photon maps: caustic photons, sparse and sharp, at a
 * smaller radius of their own (ppm2008.c).
 *
 * The tree is a kd-tree over the hit points' positions, balanced by median splits and
 * stored without pointers (node = the middle of an index range), each node with the box
 * that bounds the discs (as spheres of the reach) of every hit point below it, and a copy
 * of its own hit point's position and reach squared (the two in arrays of their own: a
 * leaf's copies, read one after the other, lie side by side). The build moves the hit
 * points into the tree's order, so that a search, which reads the nodes in tree order,
 * finds the hit points it adds a photon to beside each other in memory too, not
 * scattered over the whole array; place[] remembers where each went, so the image can
 * still sum a pixel's hit points in the order they were made, and a pixel's value does
 * not depend on the rest of the window. The copies and boxes are made by the build and
 * by each refit, which must follow every change of a radius (after each pass).
 *
 * The one index of both progressive modes: 2008 builds it once over its fixed hit points
 * and refits it after each pass; 2009 builds it anew over each pass's. A hash grid, cells
 * as wide as the largest disc, rebuilt each pass, gives the same images to the bit, a
 * little faster for 2009 and much slower for 2008, whose discs differ in size many times
 * over (src/modes/measured.md; measured before the photons came in the order of where
 * they lie, ordered_sink.h).
 */
#ifndef PHOTON_HIT_POINTS_H
#define PHOTON_HIT_POINTS_H

#include <stddef.h>
#include <stdint.h>

#include "../geom/ray.h"
#include "../scene/brdf.h"

/* One progressive estimate (Sec. 4) of a hit point. */
struct progressive_estimate {
    double radius;     /* R(x)                                                           */
    double n_photons;  /* N(x), photons accumulated                                      */
    struct vec3 tau;   /* tau(x, w): flux times BRDF, unnormalised; during a pass it also
                          gathers the pass's tau_M                                       */
    double m_photons;  /* M(x): photons found in the current pass (a caustic estimate of
                          a merged hit point counts a photon by the share of its members
                          whose discs hold it, so it may be a fraction)                  */
};

/* One of the eye rays a merged hit point stands for (ppm2008.c's --merge-hit-points): its
 * hit position, for the caustic estimate, which is the mean over the members' discs. */
struct hit_member {
    float dx, dy, dz; /* its hit position less the hit point's x (within the hit point's
                         disc, so a float keeps it to a ten-millionth of the radius)     */
    float share;      /* its part of the hit point's weight (by luminance); the members'
                         shares sum to 1                                                 */
};

/* The fields in the order a photon reads them: the disc tests' first (x, n, R), then the
 * BRDF's, the rest last: so a photon's reads, each hit point's far from the last, fall in
 * as few cache lines as they can. */
struct hit_point {
    struct vec3 x;                   /* hit location                                     */
    struct vec3 n;                   /* unit geometric normal, on the viewer's side      */
    struct progressive_estimate global;  /* from every photon the caustic one leaves    */
    struct vec3 wo;                  /* unit, back along the ray: the paper's w reversed */
    const struct material *material; /* borrowed from the scene: the paper's BRDF index  */
    struct shading_frame frame;      /* for the BRDF (TRANSPORT_RADIANCE)                */
    size_t pixel;                    /* row-major index in the rendered window           */
    struct vec3 weight;              /* pixel weight: the eye path's throughput / spp    */
    struct progressive_estimate caustic; /* from caustic photons (L S+ D) alone, at a
                                            radius of their own; radius 0 when unused   */
    const struct hit_member *members;    /* borrowed: n_members eye rays merged into it,
                                            whose caustic discs are centred on their own
                                            hits; NULL (0): its caustic disc is x's     */
    uint32_t n_members;
    double spread;                       /* the farthest member from x (0 without)      */
};

/* How far from x a photon can count for hp: the larger of its estimates' radii, the
 * caustic one about the farthest member. */
static inline double hit_point_reach(const struct hit_point *hp)
{
    double caustic = hp->caustic.radius + hp->spread;
    return hp->global.radius > caustic ? hp->global.radius : caustic;
}

struct photon_event;

/* A photon within hp's reach: tau_M += f_r(x, w, w_p) Phi'_p and M += 1 (2008, Eq. 11),
 * or for the caustic estimate of a hit point with members, both times the share of its
 * members whose caustic discs hold the photon,
 * Phi' being the photon's power times photons_per_pass (the tracer's Phi / N turned back
 * into the paper's unnormalised flux), for the estimate it belongs to: hp's caustic one for a
 * caustic photon when caustic_apart, else the global one. Nothing when it lies outside
 * that estimate's disc, or, with facing_test, when the two surfaces face apart (a photon
 * on the far side of a thin wall, or on the back of hp's own surface); a photon on a wall
 * at right angles is not counted either, which is why R0 stops at walls. No cosine: it
 * is in the photon's flux already. With turn_directions, w_p is first turned by the
 * rotation that takes the photon's normal onto hp's (where the two face alike): so on a
 * curved surface f_r sees the photon arrive at the angle it met its own surface, and no
 * photon within R falls below hp's horizon to be lost (the papers' f_r(x, w, w_p) takes
 * w_p as it arrived). Returns what it added to tau (zero for nothing).
 * inner: NULL, or the sums of what the estimates' inner discs, of radius R / sqrt(2)
 * about x, took of it ([0] the global estimate's, [1] the caustic one's, touched only
 * with caustic_apart): for a caustic estimate with members by the share of them whose
 * inner discs hold the photon. From them an error image estimates the bias of the
 * estimates' discs (modes/sppm_error.h). */
struct vec3 hit_point_add_photon(struct hit_point *hp, const struct photon_event *photon,
                                 double photons_per_pass, int facing_test,
                                 int turn_directions, int caustic_apart, struct vec3 *inner);

/* The node whose middle is m: what a search reads of it besides its box. Kept apart from
 * the boxes, which only the middle of a leaf has among the leaf's nodes: so a leaf's
 * nodes, which a search reads one after the other, take 32 bytes each, two to a cache
 * line, not 80 (a box read between them), and the searches fetch fewer lines. */
struct hit_point_node {
    struct vec3 x;   /* position of hit point m                                          */
    double r2;       /* its reach squared at the last build or refit                     */
};

struct hit_point_tree {
    struct hit_point *points;       /* borrowed; n of them, in tree order since the build */
    size_t n;
    size_t *place;                  /* owned: the hit point that was points[i] before the
                                       build is points[place[i]]                         */
    struct hit_point_node *nodes;   /* owned: nodes[m] for the node whose middle is m    */
    struct aabb *boxes;             /* owned: boxes[m] bounds the discs of every hit point
                                       in the range of the node whose middle is m (only
                                       the middle of a leaf has one; the rest are unset) */
};

/* Builds the tree over points[0 .. n-1] (n >= 0) with their current radii, moving the
 * hit points into the tree's order (tree->place says where each went). */
void hit_point_tree_build(struct hit_point_tree *tree, struct hit_point *points, size_t n);

/* Takes the hit points' current radii into the nodes and tightens every box to them. */
void hit_point_tree_refit(struct hit_point_tree *tree);

/* Calls visit(context, i) for every hit point points[i] whose reach holds p:
 * |x_i - p| <= hit_point_reach() as at the last build or refit, in tree order. */
void hit_point_tree_visit(const struct hit_point_tree *tree, struct vec3 p,
                          void (*visit)(void *context, size_t i), void *context);

/* Bytes the tree owns per hit point: its place, a node and a box. */
#define HIT_POINT_TREE_BYTES_PER_POINT                                                     \
    (sizeof(size_t) + sizeof(struct hit_point_node) + sizeof(struct aabb))

void hit_point_tree_free(struct hit_point_tree *tree);

#endif
