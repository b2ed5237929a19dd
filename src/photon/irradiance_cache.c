/*
 * photon/irradiance_cache.c -- Ward's irradiance cache with Ward and Heckbert's gradients
 * (irradiance_cache.h).
 *
 * Records: irradiance_record_make() turns a final gather's strata into E, R and the two
 * gradients. The formulas are Ward and Heckbert 1992's, in the form of Ward's own
 * implementation (Radiance, src/rt/ambcomp.c: dirgradient() and posgradient()); the
 * stratum geometry they use: ring j spans sin^2 theta in [j/m, (j+1)/m], so
 *   sin theta_j- = sqrt(j / m), cos^2 theta_j- = (m - j) / m      (its inner edge)
 * and sector k spans phi in [2 pi k / n, 2 pi (k + 1) / n].
 *
 * The index: a loose octree over a cube (side = the largest extent of the bounds given
 * to irradiance_cache_create()). A node at depth d has side s = side / 2^d. A record is
 * usable only within a R_i of p_i, and goes into the deepest node that contains p_i and
 * is at least 2 a R_i wide, at most MAX_DEPTH levels down; so it reaches at most half
 * its node's side beyond the node's box, and a lookup at p visits exactly the nodes
 * whose box, grown by half the node's side on every face, contains p (Ward 1988 kept
 * records in an octree the same way; Radiance's ambient.c grows each box by its whole
 * side). Records outside the cube stay in the root, whose list every lookup reads
 * whole: correct wherever records lie, slow only if a renderer puts many records
 * outside the bounds it gave. Invariants (irradiance_cache_check()):
 *   (1) a record of a node other than the root lies in the node's box, and
 *       2 a R_i <= the node's side;
 *   (2) a record inside the cube could not go one level deeper: its node is at depth
 *       MAX_DEPTH, or the node's children are narrower than 2 a R_i;
 *   (3) children come after their parents in nodes[], and no node is deeper than
 *       MAX_DEPTH; every record is counted in n_records.
 * Ownership: the cache owns nodes[] and every node's records[]; nodes refer to their
 * children by index, so growing nodes[] by realloc moves nothing that is pointed at.
 */
#include "irradiance_cache.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>

#include "../base/alloc.h"

/* MAX_DEPTH: 20 levels take the side down by 2^20 ~ 1e6, finer than the records of any
 * sensible r_min; records of smaller reach still go no deeper than 20, which is correct
 * (they reach less than half the node's side), only less selective. */
#define MAX_DEPTH 20

#define RECORDS_INITIAL 4 /* first capacity of a node's record array */
#define NODES_INITIAL 64  /* first capacity of the node array        */

struct cache_node {
    size_t child[8];                  /* index in nodes[] of octant i (bit 0: upper half
                                         in x, bit 1: in y, bit 2: in z); 0 = none (node 0
                                         is the root, nobody's child)                      */
    struct irradiance_record *records; /* owned; n_records of them, in insertion order    */
    size_t n_records, capacity;
};

struct irradiance_cache {
    struct vec3 origin;       /* the root cube's lower corner (the bounds' lo)           */
    double side;              /* the root cube's side, > 0                               */
    double accuracy;          /* Ward's a, > 0                                           */
    struct cache_node *nodes; /* owned; n_nodes used of capacity; nodes[0] is the root   */
    size_t n_nodes, capacity;
    size_t n_records;         /* records in all nodes                                    */
};

/* ---- Strata ------------------------------------------------------------------------ */

struct vec3 stratum_direction(int m, int n, int j, int k, double u1, double u2)
{
    assert(m >= 1 && n >= 1 && j >= 0 && j < m && k >= 0 && k < n);
    assert(u1 >= 0 && u1 < 1 && u2 >= 0 && u2 < 1);
    /* cos^2 = (m - j - u1) / m without cancellation: m - j >= 1 > u1, and 1 - u1 is
     * exact, so cos theta > 0 even for u1 just below 1. */
    double sin_theta = sqrt((j + u1) / m);
    double cos_theta = sqrt(((m - j) - u1) / m);
    double phi = 2 * PI * (k + u2) / n;
    return vec3(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
}

static int clamp_index(double x, int count)
{
    if (!(x >= 0))
        return 0;
    return x >= count ? count - 1 : (int)x;
}

void stratum_of(int m, int n, struct vec3 local, int *j, int *k)
{
    assert(m >= 1 && n >= 1 && vec3_length2(local) > 0);
    double rho2 = local.x * local.x + local.y * local.y;
    double sin2_theta = rho2 / (rho2 + local.z * local.z);
    double phi = atan2(local.y, local.x); /* in [-pi, pi] */
    if (phi < 0)
        phi += 2 * PI;
    *j = clamp_index(floor(sin2_theta * m), m);
    *k = clamp_index(floor(phi * n / (2 * PI)), n);
}

/* ---- Records ----------------------------------------------------------------------- */

/* Ward 1988: R_i = m n / sum 1 / r_jk, the harmonic mean, which the nearest surfaces
 * dominate; escaped strata add nothing. All escaped: r_max. Clamped to [r_min, r_max]. */
static double harmonic_mean_distance(int count, const struct stratum_sample *samples,
                                     double r_min, double r_max)
{
    double sum_inv_r = 0;
    for (int i = 0; i < count; i++) {
        assert(samples[i].distance >= 0); /* and not NaN */
        sum_inv_r += 1 / samples[i].distance; /* 1 / INFINITY = 0; 1 / 0 = INFINITY */
    }
    double r = sum_inv_r > 0 ? count / sum_inv_r : r_max;
    return fmin(fmax(r, r_min), r_max);
}

/* The local gradient (gx, gy per channel: x along t, y along b) in world space. */
static void gradient_to_world(struct vec3 gx, struct vec3 gy, struct vec3 t, struct vec3 b,
                              struct vec3 grad[3])
{
    for (int c = 0; c < 3; c++)
        grad[c] = vec3_add(vec3_scale(t, vec3_get(gx, c)), vec3_scale(b, vec3_get(gy, c)));
}

/* Ward and Heckbert's rotational gradient. Turning the normal by a small angle delta
 * about an axis a (so that n_i x n = delta a) moves it by delta (a x n), and
 * E = int L (w . n) dw changes by delta int L w . (a x n) dw = delta a . int L (n x w) dw;
 * so grad_r = int L (n x w) dw, and n x w = sin theta v(phi), v(phi) = (-sin phi,
 * cos phi, 0) locally. With L_jk constant over its stratum,
 *   grad_r E = sum_k sum_j L_jk int_jk sin theta v(phi) dw
 *            = sum_k v_k sin(pi / n) sum_j [(theta_j+ - theta_j-)
 *                                           - (sin theta cos theta)_j- ^j+] L_jk,
 * v_k = v at the middle of sector k. Departs from Ward and Heckbert (and Radiance's
 * dirgradient()), who take pi / (m n) tan theta at each ring's middle: the last ring's
 * tan theta runs to infinity and its middle value falls short of its mean, so theirs is
 * about 0.44 / sqrt(m) short (19% with the 6 rings of a 256-ray gather), which darkens
 * the underside of the Cornell box's balls; the exact integral of each stratum
 * costs nothing more (test_cache.c measures both). The sign is the one our convention
 * dE = (n_i x n) . grad_r asks for. */
static void rotational_gradient(int m, int n_phi, const struct stratum_sample *samples,
                                struct vec3 t, struct vec3 b, struct vec3 grad_r[3])
{
    struct vec3 gx = vec3_zero(), gy = vec3_zero();
    for (int k = 0; k < n_phi; k++) {
        struct vec3 sum = vec3_zero(); /* sum_j (stratum integral of sin^2) L_jk */
        for (int j = 0; j < m; j++) {
            double inner = asin(sqrt((double)j / m)), outer = asin(sqrt((double)(j + 1) / m));
            double weight = (outer - inner) - (sin(outer) * cos(outer) - sin(inner) * cos(inner));
            sum = vec3_madd(sum, samples[j * n_phi + k].radiance, weight);
        }
        double phi = 2 * PI * (k + 0.5) / n_phi;
        gx = vec3_madd(gx, sum, -sin(phi)); /* v_k = (-sin phi_k, cos phi_k) */
        gy = vec3_madd(gy, sum, cos(phi));
    }
    double scale = sin(PI / n_phi);
    gradient_to_world(vec3_scale(gx, scale), vec3_scale(gy, scale), t, b, grad_r);
}

/* 1 / min(r_a, r_b), the distance that decides how fast a boundary between two strata
 * sweeps across the scene as the point moves; 0 when both escaped. Distances below
 * r_min count as r_min, as in R_i, so a ray that hit at distance 0 cannot make the
 * gradient infinite. */
static double inverse_boundary_distance(double r_a, double r_b, double r_min)
{
    return 1 / fmax(fmin(r_a, r_b), r_min);
}

/* Ward and Heckbert's translational gradient. Moving the point by dx along a tangent u
 * makes the scene seen at the edge theta_j- between rings j-1 and j slide inwards by
 * dtheta = dx cos theta / r, so ring j-1 gains ring j's radiance over a strip of
 * projected solid angle sin theta cos^2 theta (2 pi / n) dx / r. Moving by dx along v,
 * across the edge phi_k between sectors k-1 and k, slides sector k's view into sector
 * k-1 over a strip dphi = dx / (r sin theta) wide, of projected solid angle
 * int cos theta sin theta dtheta dphi = (sin theta_j+ - sin theta_j-) dx / r in ring j.
 * Summed over all edges:
 *   grad_t E = sum_k [ u_k (2 pi / n) sum_{j=1}^{m-1} sin theta_j- cos^2 theta_j-
 *                          (L_jk - L_{j-1,k}) / min(r_jk, r_{j-1,k})
 *                    + v_k- sum_{j=0}^{m-1} (sin theta_j+ - sin theta_j-)
 *                          (L_jk - L_{j,k-1}) / min(r_jk, r_{j,k-1}) ],
 * k - 1 modulo n, r the nearer of the two strata's distances (the nearer surface moves
 * the edge fastest), v_k- the unit vector at phi_k + pi / 2, phi_k = 2 pi k / n the
 * sector's edge, and u_k the unit vector at the sector's middle, phi_k + pi / n.
 * Departs from Radiance's posgradient(), which takes u_k at the edge phi_k too: the ring
 * edge of sector k spans [phi_k, phi_k+1] and its outward directions average to the
 * middle; the edge turns the ring term by pi / n (2.8 degrees, 5% of it sideways, at
 * n = 64), which test_cache.c sees on an axis of symmetry. */
static void translational_gradient(int m, int n_phi, const struct stratum_sample *samples,
                                   double r_min, struct vec3 t, struct vec3 b,
                                   struct vec3 grad_t[3])
{
    struct vec3 gx = vec3_zero(), gy = vec3_zero();
    for (int k = 0; k < n_phi; k++) {
        int k_prev = k > 0 ? k - 1 : n_phi - 1;
        struct vec3 ring_sum = vec3_zero(), sector_sum = vec3_zero();
        for (int j = 0; j < m; j++) {
            const struct stratum_sample *s = &samples[j * n_phi + k];
            double sin_lo = sqrt((double)j / m), sin_hi = sqrt((j + 1.0) / m);
            if (j > 0) {
                const struct stratum_sample *in = &samples[(j - 1) * n_phi + k];
                double w = sin_lo * ((double)(m - j) / m) *
                           inverse_boundary_distance(s->distance, in->distance, r_min);
                ring_sum = vec3_madd(ring_sum, vec3_sub(s->radiance, in->radiance), w);
            }
            const struct stratum_sample *before = &samples[j * n_phi + k_prev];
            double w = (sin_hi - sin_lo) *
                       inverse_boundary_distance(s->distance, before->distance, r_min);
            sector_sum = vec3_madd(sector_sum, vec3_sub(s->radiance, before->radiance), w);
        }
        double phi_middle = 2 * PI * (k + 0.5) / n_phi, phi_edge = 2 * PI * k / n_phi;
        ring_sum = vec3_scale(ring_sum, 2 * PI / n_phi);
        gx = vec3_madd(vec3_madd(gx, ring_sum, cos(phi_middle)), sector_sum, -sin(phi_edge));
        gy = vec3_madd(vec3_madd(gy, ring_sum, sin(phi_middle)), sector_sum, cos(phi_edge));
    }
    gradient_to_world(gx, gy, t, b, grad_t);
}

/* R_i no larger than E_i / |grad_t E_i| (luminance), and no smaller than r_min. Departs
 * from Ward and Heckbert (switchable: struct record_reach; --no-gradient-limit), whose
 * R_i is the harmonic mean distance alone: where the
 * irradiance changes fast, a record here reaches only as far as its gradient stays a small
 * correction (at a R_i it moves E_i by at most a E_i), so a lookup does not extend a
 * straight line across a shadow's edge. */
static double gradient_limited_radius(double r, struct vec3 e, const struct vec3 grad_t[3],
                                      double r_min)
{
    struct vec3 grad = vec3(vec3_luminance(vec3(grad_t[0].x, grad_t[1].x, grad_t[2].x)),
                            vec3_luminance(vec3(grad_t[0].y, grad_t[1].y, grad_t[2].y)),
                            vec3_luminance(vec3(grad_t[0].z, grad_t[1].z, grad_t[2].z)));
    double slope = vec3_length(grad), level = vec3_luminance(e);
    if (slope * r <= level)
        return r;
    return fmax(level / slope, r_min);
}

struct irradiance_record irradiance_record_make(struct vec3 p, struct vec3 t, struct vec3 b,
                                                struct vec3 n, int m, int n_phi,
                                                const struct stratum_sample *samples,
                                                double r_min, double r_max)
{
    struct record_reach reach = {r_min, r_max, 1};
    return irradiance_record_of(p, t, b, n, m, n_phi, samples, reach);
}

struct irradiance_record irradiance_record_of(struct vec3 p, struct vec3 t, struct vec3 b,
                                              struct vec3 n, int m, int n_phi,
                                              const struct stratum_sample *samples,
                                              struct record_reach reach)
{
    double r_min = reach.r_min, r_max = reach.r_max;
    assert(m >= 1 && n_phi >= 1 && m <= STRATA_MAX / n_phi);
    assert(r_min > 0 && r_min <= r_max);
    struct irradiance_record record;
    record.p = p;
    record.n = n;
    struct vec3 sum = vec3_zero();
    for (int i = 0; i < m * n_phi; i++)
        sum = vec3_add(sum, samples[i].radiance);
    record.e = vec3_scale(sum, PI / ((double)m * n_phi)); /* E = pi / (m n) sum L_jk */
    record.r = harmonic_mean_distance(m * n_phi, samples, r_min, r_max);
    if (n_phi > 1) {
        rotational_gradient(m, n_phi, samples, t, b, record.grad_r);
        translational_gradient(m, n_phi, samples, r_min, t, b, record.grad_t);
        if (reach.gradient_limit)
            record.r = gradient_limited_radius(record.r, record.e, record.grad_t, r_min);
    } else { /* one sector cannot tell one tangent direction from another */
        for (int c = 0; c < 3; c++)
            record.grad_r[c] = record.grad_t[c] = vec3_zero();
    }
    return record;
}

/* ---- The octree -------------------------------------------------------------------- */

static struct cache_node empty_node(void)
{
    struct cache_node node = {{0, 0, 0, 0, 0, 0, 0, 0}, NULL, 0, 0};
    return node;
}

struct irradiance_cache *irradiance_cache_create(struct aabb bounds, double accuracy)
{
    assert(accuracy > 0);
    struct irradiance_cache *cache = xmalloc(1, sizeof *cache, "irradiance cache");
    /* Any cube is correct (records outside it stay in the root); an empty or
     * flat-to-a-point box gets side 1, and so does one whose side is no finite double (a
     * scene reaching past DBL_MAX), at the origin when its corner is not finite either. */
    double side = vec3_max_component(vec3_sub(bounds.hi, bounds.lo));
    cache->origin = vec3_is_finite(bounds.lo) ? bounds.lo : vec3_zero();
    cache->side = side > 0 && isfinite(side) ? side : 1;
    cache->accuracy = accuracy;
    cache->capacity = NODES_INITIAL;
    cache->nodes = xmalloc(cache->capacity, sizeof *cache->nodes, "irradiance cache nodes");
    cache->nodes[0] = empty_node(); /* the root */
    cache->n_nodes = 1;
    cache->n_records = 0;
    return cache;
}

void irradiance_cache_free(struct irradiance_cache *cache)
{
    if (cache == NULL)
        return;
    for (size_t i = 0; i < cache->n_nodes; i++)
        xfree(cache->nodes[i].records);
    xfree(cache->nodes);
    xfree(cache);
}

static int box_contains(struct vec3 lo, double side, struct vec3 p)
{
    return p.x >= lo.x && p.x <= lo.x + side && p.y >= lo.y && p.y <= lo.y + side &&
           p.z >= lo.z && p.z <= lo.z + side;
}

/* The lower corner of octant i of the node at lo whose children have side half. */
static struct vec3 child_corner(struct vec3 lo, double half, int i)
{
    return vec3(i & 1 ? lo.x + half : lo.x, i & 2 ? lo.y + half : lo.y,
                i & 4 ? lo.z + half : lo.z);
}

/* The octant of the node at lo with the given side that holds p. */
static int octant(struct vec3 lo, double side, struct vec3 p)
{
    double half = side / 2;
    return (p.x >= lo.x + half) | (p.y >= lo.y + half) << 1 | (p.z >= lo.z + half) << 2;
}

static size_t new_node(struct irradiance_cache *cache)
{
    if (cache->n_nodes == cache->capacity) {
        cache->capacity *= 2;
        cache->nodes = xrealloc(cache->nodes, cache->capacity, sizeof *cache->nodes,
                                "irradiance cache nodes");
    }
    cache->nodes[cache->n_nodes] = empty_node();
    return cache->n_nodes++;
}

/* Whether a record of radius r belongs below a node of the given side at the given
 * depth: its child (side / 2) is still at least 2 a r wide, and the depth allows one. */
static int goes_deeper(const struct irradiance_cache *cache, double side, int depth, double r)
{
    return depth < MAX_DEPTH && side / 2 >= 2 * cache->accuracy * r;
}

void irradiance_cache_add(struct irradiance_cache *cache,
                          const struct irradiance_record *record)
{
    assert(vec3_is_finite(record->p) && record->r > 0);
    size_t node = 0;
    struct vec3 lo = cache->origin;
    double side = cache->side;
    if (box_contains(lo, side, record->p)) {
        for (int depth = 0; goes_deeper(cache, side, depth, record->r); depth++) {
            int i = octant(lo, side, record->p);
            lo = child_corner(lo, side / 2, i);
            if (cache->nodes[node].child[i] == 0) {
                size_t child = new_node(cache); /* before taking &nodes[node] again */
                cache->nodes[node].child[i] = child;
            }
            node = cache->nodes[node].child[i];
            side /= 2;
        }
    }
    struct cache_node *at = &cache->nodes[node];
    if (at->n_records == at->capacity) {
        at->capacity = at->capacity > 0 ? 2 * at->capacity : RECORDS_INITIAL;
        at->records = xrealloc(at->records, at->capacity, sizeof *at->records,
                               "irradiance cache records");
    }
    at->records[at->n_records++] = *record;
    cache->n_records++;
}

/* ---- Lookups ----------------------------------------------------------------------- */

/* What a lookup sums: sum_i w_i E_i(p, n) and sum_i w_i. */
struct weighted_sum {
    struct vec3 p, n; /* the query                         */
    double a;         /* the accuracy                      */
    struct vec3 sum;  /* sum of weighted extrapolated E    */
    double weight;    /* sum of weights, 0 while none used */
};

/* Adds the record's value, moved to the query by its gradients, if it is usable there. */
static void add_record(struct weighted_sum *ws, const struct irradiance_record *ri)
{
    struct vec3 d = vec3_sub(ws->p, ri->p);
    double reach = ws->a * ri->r;
    if (!(vec3_length2(d) < reach * reach))
        return; /* epsilon_i >= |p - p_i| / R_i >= a: the test below fails; cheaper here */
    /* Ward 1988: d_i = (p - p_i) . (n + n_i) / 2 < 0 is "in front"; see CACHE_FRONT_TOLERANCE */
    if (vec3_dot(d, vec3_add(ws->n, ri->n)) / 2 < -CACHE_FRONT_TOLERANCE * ri->r)
        return;
    /* Ward 1988: epsilon_i = |p - p_i| / R_i + sqrt(1 - n . n_i); rounding can push
     * n . n_i just above 1, hence fmax. */
    double epsilon = vec3_length(d) / ri->r + sqrt(fmax(0, 1 - vec3_dot(ws->n, ri->n)));
    if (!(epsilon < ws->a))
        return;
    double w = 1 / fmax(epsilon, CACHE_EPSILON_MIN); /* w_i = 1 / epsilon_i, capped */
    /* Ward and Heckbert 1992: E_i + (n_i x n) . grad_r + (p - p_i) . grad_t */
    struct vec3 turn = vec3_cross(ri->n, ws->n);
    struct vec3 change = vec3(vec3_dot(turn, ri->grad_r[0]) + vec3_dot(d, ri->grad_t[0]),
                              vec3_dot(turn, ri->grad_r[1]) + vec3_dot(d, ri->grad_t[1]),
                              vec3_dot(turn, ri->grad_r[2]) + vec3_dot(d, ri->grad_t[2]));
    ws->sum = vec3_madd(ws->sum, vec3_add(ri->e, change), w);
    ws->weight += w;
}

/* Whether p lies in the box at lo of the given side grown by half the side per face. */
static int within_reach(struct vec3 lo, double side, struct vec3 p)
{
    double half = side / 2;
    return box_contains(vec3(lo.x - half, lo.y - half, lo.z - half), 2 * side, p);
}

static void visit_node(const struct irradiance_cache *cache, size_t node, struct vec3 lo,
                       double side, struct weighted_sum *ws)
{
    const struct cache_node *at = &cache->nodes[node];
    for (size_t r = 0; r < at->n_records; r++)
        add_record(ws, &at->records[r]);
    double half = side / 2;
    for (int i = 0; i < 8; i++) {
        if (at->child[i] == 0)
            continue;
        struct vec3 child_lo = child_corner(lo, half, i);
        if (within_reach(child_lo, half, ws->p))
            visit_node(cache, at->child[i], child_lo, half, ws);
    }
}

int irradiance_cache_lookup(const struct irradiance_cache *cache, struct vec3 p,
                            struct vec3 n, double accuracy, struct vec3 *e)
{
    /* A stricter accuracy only shrinks every record's reach, so the octree, placed by the
     * cache's own a, still holds every record that can be usable. */
    assert(accuracy > 0 && accuracy <= cache->accuracy);
    struct weighted_sum ws;
    ws.p = p;
    ws.n = n;
    ws.a = accuracy;
    ws.sum = vec3_zero();
    ws.weight = 0;
    /* The root is read whole: it also holds the records outside the cube. */
    visit_node(cache, 0, cache->origin, cache->side, &ws);
    if (!(ws.weight > 0))
        return 0;
    struct vec3 mean = vec3_scale(ws.sum, 1 / ws.weight); /* weight >= 1 / a > 0 */
    *e = vec3_max(mean, vec3_zero());
    return 1;
}

size_t irradiance_cache_records(const struct irradiance_cache *cache)
{
    return cache->n_records;
}

void irradiance_cache_copy_records(const struct irradiance_cache *cache,
                                   struct irradiance_record *out)
{
    size_t n = 0;
    for (size_t i = 0; i < cache->n_nodes; i++)
        for (size_t r = 0; r < cache->nodes[i].n_records; r++)
            out[n++] = cache->nodes[i].records[r];
    assert(n == cache->n_records);
}

size_t irradiance_cache_bytes(const struct irradiance_cache *cache)
{
    size_t bytes = sizeof *cache + cache->capacity * sizeof *cache->nodes;
    for (size_t i = 0; i < cache->n_nodes; i++)
        bytes += cache->nodes[i].capacity * sizeof(struct irradiance_record);
    return bytes;
}

/* ---- The checker ------------------------------------------------------------------- */

static int aabb_contains(struct aabb box, struct vec3 p)
{
    return p.x >= box.lo.x && p.x <= box.hi.x && p.y >= box.lo.y && p.y <= box.hi.y &&
           p.z >= box.lo.z && p.z <= box.hi.z;
}

/* Checks the subtree of node (its box, at depth) against invariants (1)-(3), adding the
 * records it holds to *count. The boxes are made as irradiance_cache_add() splits them:
 * a child's lower corner is child_corner(), its upper one the parent's middle or upper
 * corner, so a record on a face is judged by the same roundings that placed it. */
static int check_node(const struct irradiance_cache *cache, size_t node, struct aabb box,
                      int depth, size_t *count)
{
    const struct cache_node *at = &cache->nodes[node];
    double side = ldexp(cache->side, -depth); /* halving is exact */
    *count += at->n_records;
    for (size_t r = 0; r < at->n_records; r++) {
        const struct irradiance_record *ri = &at->records[r];
        int inside = aabb_contains(box, ri->p);
        if (node != 0 && (!inside || side < 2 * cache->accuracy * ri->r))
            return 0;
        if (inside && goes_deeper(cache, side, depth, ri->r))
            return 0;
    }
    for (int i = 0; i < 8; i++) {
        size_t child = at->child[i];
        if (child == 0)
            continue;
        struct aabb child_box;
        child_box.lo = child_corner(box.lo, side / 2, i);
        child_box.hi = vec3(i & 1 ? box.hi.x : child_box.lo.x + side / 2,
                            i & 2 ? box.hi.y : child_box.lo.y + side / 2,
                            i & 4 ? box.hi.z : child_box.lo.z + side / 2);
        if (child <= node || child >= cache->n_nodes || depth >= MAX_DEPTH ||
            !check_node(cache, child, child_box, depth + 1, count))
            return 0;
    }
    return 1;
}

int irradiance_cache_check(const struct irradiance_cache *cache)
{
    struct aabb root;
    root.lo = cache->origin;
    root.hi = vec3(root.lo.x + cache->side, root.lo.y + cache->side, root.lo.z + cache->side);
    size_t count = 0;
    return check_node(cache, 0, root, 0, &count) &&
           count == cache->n_records;
}
