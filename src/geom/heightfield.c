/*
 * geom/heightfield.c -- the fractal heightfield, intersected through a min/max pyramid.
 *
 * Storage: y[j * n + i], the n x n sample heights (heightfield.h gives x, z and y of a
 * sample), and a pyramid over the (n - 1) x (n - 1) cells: level 0 is the cells themselves
 * (their ranges are the min and max of their four corners, computed when needed); node
 * (a, b) of level k >= 1 covers cells [a 2^k, (a + 1) 2^k) x [b 2^k, (b + 1) 2^k), clipped
 * to the grid, and stores the min and max height of every sample of those cells. Level k
 * has side[k] = ceil(side[k - 1] / 2) nodes a side; the top level has one node.
 * heightfield_check() verifies each stored range against the samples it covers.
 *
 * Traversal ("walking the grid with a min/max hierarchy", done hierarchically, as a
 * kd-tree is walked): a depth-first descent of the pyramid carrying [t0, t1], the part of
 * the ray inside the node's box. The box is the node's cells in x and z and its height
 * range in y, so a child's part is its parent's split at the two planes between the
 * children (split_interval()) and clipped to the child's height range. The ray, monotone in
 * x and z, meets the children in a known order: the quadrant it comes from, then across the
 * nearer plane, then the farther; they are visited in that order and a child is skipped
 * once its part starts beyond the nearest hit, so hits are found near to far and the rest
 * is pruned. A cell clips its part to the heights of its four corners and tests its two
 * triangles with triangle.c's watertight test (Woop, Benthin, Wald, JCGT 2013) on the same
 * vertex doubles its neighbours use: no ray slips between cells, and the shape and its
 * expansion compute the same t.
 *
 * Intervals are widened by the rounding of every distance (near_end(), far_end()), and
 * every plane and box face is the very coordinate of the samples on it, so rounding never
 * skips a cell the ray touches. Memory: 8 n^2 bytes of heights and 16 bytes per pyramid
 * node, about a third of the cells: ~13.3 n^2 bytes; nothing per triangle.
 */
#include "heightfield.h"

#include <float.h>

#include "../base/alloc.h"
#include "triangle.h"

#define PYRAMID_MAX_LEVELS 14 /* ceil(log2(HEIGHTFIELD_MAX_RESOLUTION - 1)) = 13, and one */
#define MAX_PENDING (3 * PYRAMID_MAX_LEVELS + 1) /* pop one, push at most 4, per level */
/* 1 +- 2 gamma_3 (see near_end()), rounded outwards: 2 gamma_3 < 3.4e-16 < 4 DBL_EPSILON */
#define ROBUST_FAR (1.0 + 4.0 * DBL_EPSILON)
#define ROBUST_NEAR (1.0 - 4.0 * DBL_EPSILON)

struct heightfield {
    struct heightfield_params params;
    int n;             /* samples a side: params.resolution                                 */
    double spacing;    /* size / (n - 1), > 0                                              */
    double *y;         /* n * n heights, y[j * n + i]; owned                               */
    int n_levels;      /* top level of the pyramid: side[n_levels] = 1                     */
    int side[PYRAMID_MAX_LEVELS + 1];       /* nodes a side; side[0] = n - 1 cells        */
    size_t offset[PYRAMID_MAX_LEVELS + 1];  /* level k >= 1 starts at range[2 offset[k]] */
    double *range;     /* (min, max) height per node of levels 1..n_levels; owned          */
    size_t n_range;    /* nodes in range[]                                                 */
};

/* A node of the pyramid: level 0 is a cell. */
struct node {
    int level, a, b;
};

static double sample_y(const struct heightfield *hf, int i, int j)
{
    return hf->y[(size_t)j * (size_t)hf->n + (size_t)i];
}

/* Sample (i, j): the one place vertex coordinates are computed. */
static struct vec3 vertex(const struct heightfield *hf, int i, int j)
{
    const struct vec3 o = hf->params.origin;
    return vec3(o.x + i * hf->spacing, sample_y(hf, i, j), o.z + j * hf->spacing);
}

/* Central differences of the heights, one-sided on the border:
 * n = unit(-dy/dx, 1, -dy/dz); the index gap i1 - i0 is 1 or 2, never 0, as n >= 2. */
static struct vec3 vertex_normal(const struct heightfield *hf, int i, int j)
{
    int i0 = i > 0 ? i - 1 : 0, i1 = i < hf->n - 1 ? i + 1 : i;
    int j0 = j > 0 ? j - 1 : 0, j1 = j < hf->n - 1 ? j + 1 : j;
    double dydx = (sample_y(hf, i1, j) - sample_y(hf, i0, j)) / ((i1 - i0) * hf->spacing);
    double dydz = (sample_y(hf, i, j1) - sample_y(hf, i, j0)) / ((j1 - j0) * hf->spacing);
    return unit_normal(vec3(-dydx, 1.0, -dydz));
}

/* Triangle t (0 or 1) of cell (i, j): its corners are samples (i + di, j + dj) with
 * (di, dj) from these tables, in the order heightfield.h gives. */
static const int corner_di[2][3] = {{0, 0, 1}, {0, 1, 1}};
static const int corner_dj[2][3] = {{0, 1, 1}, {0, 1, 0}};

static void cell_triangle(const struct heightfield *hf, int i, int j, int t, struct vec3 v[3])
{
    for (int k = 0; k < 3; k++)
        v[k] = vertex(hf, i + corner_di[t][k], j + corner_dj[t][k]);
}

static void cell_normals(const struct heightfield *hf, int i, int j, int t, struct vec3 n[3])
{
    for (int k = 0; k < 3; k++)
        n[k] = vertex_normal(hf, i + corner_di[t][k], j + corner_dj[t][k]);
}

/* ---- the pyramid -------------------------------------------------------------------- */

static void node_range(const struct heightfield *hf, struct node nd, double *lo, double *hi)
{
    if (nd.level == 0) {
        double y00 = sample_y(hf, nd.a, nd.b), y10 = sample_y(hf, nd.a + 1, nd.b);
        double y01 = sample_y(hf, nd.a, nd.b + 1), y11 = sample_y(hf, nd.a + 1, nd.b + 1);
        *lo = fmin(fmin(y00, y10), fmin(y01, y11));
        *hi = fmax(fmax(y00, y10), fmax(y01, y11));
        return;
    }
    size_t k = hf->offset[nd.level] + (size_t)nd.b * (size_t)hf->side[nd.level] + (size_t)nd.a;
    *lo = hf->range[2 * k];
    *hi = hf->range[2 * k + 1];
}

/* Level k's ranges from level k - 1's: the min and max over the (up to) four children. */
static void build_level(struct heightfield *hf, int k)
{
    for (int b = 0; b < hf->side[k]; b++) {
        for (int a = 0; a < hf->side[k]; a++) {
            double lo = INFINITY, hi = -INFINITY;
            for (int c = 0; c < 4; c++) {
                struct node child = {k - 1, 2 * a + (c & 1), 2 * b + (c >> 1)};
                if (child.a >= hf->side[k - 1] || child.b >= hf->side[k - 1])
                    continue;
                double child_lo, child_hi;
                node_range(hf, child, &child_lo, &child_hi);
                lo = fmin(lo, child_lo);
                hi = fmax(hi, child_hi);
            }
            size_t at = hf->offset[k] + (size_t)b * (size_t)hf->side[k] + (size_t)a;
            hf->range[2 * at] = lo;
            hf->range[2 * at + 1] = hi;
        }
    }
}

static void build_pyramid(struct heightfield *hf)
{
    hf->side[0] = hf->n - 1;
    hf->n_levels = 0;
    hf->n_range = 0;
    while (hf->side[hf->n_levels] > 1) {
        int k = ++hf->n_levels;
        hf->side[k] = (hf->side[k - 1] + 1) / 2;
        hf->offset[k] = hf->n_range;
        hf->n_range += (size_t)hf->side[k] * (size_t)hf->side[k];
    }
    hf->range = xmalloc(2 * hf->n_range + 1, sizeof *hf->range, "heightfield pyramid");
    for (int k = 1; k <= hf->n_levels; k++)
        build_level(hf, k);
}

/* The samples covered by node nd: [*i0, *i1] x [*j0, *j1]. */
static void node_samples(const struct heightfield *hf, struct node nd, int *i0, int *i1,
                         int *j0, int *j1)
{
    *i0 = nd.a << nd.level;
    *j0 = nd.b << nd.level;
    *i1 = (nd.a + 1) << nd.level;
    *j1 = (nd.b + 1) << nd.level;
    if (*i1 > hf->n - 1)
        *i1 = hf->n - 1;
    if (*j1 > hf->n - 1)
        *j1 = hf->n - 1;
}

static int node_range_is_exact(const struct heightfield *hf, struct node nd)
{
    int i0, i1, j0, j1;
    node_samples(hf, nd, &i0, &i1, &j0, &j1);
    double lo = INFINITY, hi = -INFINITY;
    for (int j = j0; j <= j1; j++) {
        for (int i = i0; i <= i1; i++) {
            lo = fmin(lo, sample_y(hf, i, j));
            hi = fmax(hi, sample_y(hf, i, j));
        }
    }
    double stored_lo, stored_hi;
    node_range(hf, nd, &stored_lo, &stored_hi);
    return stored_lo == lo && stored_hi == hi;
}

int heightfield_check(const struct heightfield *hf)
{
    if (hf->side[hf->n_levels] != 1)
        return 0;
    for (int k = 1; k <= hf->n_levels; k++) {
        for (int b = 0; b < hf->side[k]; b++) {
            for (int a = 0; a < hf->side[k]; a++) {
                struct node nd = {k, a, b};
                if (!node_range_is_exact(hf, nd))
                    return 0;
            }
        }
    }
    return 1;
}

/* ---- creation ----------------------------------------------------------------------- */

static int check_params(const struct heightfield_params *p, struct error *err)
{
    if (!(isfinite(p->size) && p->size > 0) || !vec3_is_finite(p->origin))
        return error_set(err, "", 0, "heightfield: size must be positive and finite, origin "
                                     "finite (size %g)", p->size);
    if (p->resolution < HEIGHTFIELD_MIN_RESOLUTION || p->resolution > HEIGHTFIELD_MAX_RESOLUTION)
        return error_set(err, "", 0, "heightfield: resolution must be %d..%d samples, got %d",
                         HEIGHTFIELD_MIN_RESOLUTION, HEIGHTFIELD_MAX_RESOLUTION, p->resolution);
    if (p->octaves < 1 || p->octaves > HEIGHTFIELD_MAX_OCTAVES)
        return error_set(err, "", 0, "heightfield: octaves must be 1..%d, got %d",
                         HEIGHTFIELD_MAX_OCTAVES, p->octaves);
    if (!(p->roughness > 0 && p->roughness <= 1))
        return error_set(err, "", 0, "heightfield: roughness must be in (0, 1], got %g",
                         p->roughness);
    if (!(p->frequency > 0 && p->frequency <= HEIGHTFIELD_MAX_FREQUENCY))
        return error_set(err, "", 0, "heightfield: frequency must be in (0, %g], got %g",
                         HEIGHTFIELD_MAX_FREQUENCY, p->frequency);
    if (!(isfinite(p->height) && p->height >= 0))
        return error_set(err, "", 0, "heightfield: height must be finite and >= 0, got %g",
                         p->height);
    double spacing = p->size / (p->resolution - 1); /* resolution >= 2 */
    if (!(spacing > 1e-12 * (vec3_max_abs(p->origin) + p->size)))
        return error_set(err, "", 0, "heightfield: cells of %g are too small to resolve at "
                                     "coordinates of %g", spacing, vec3_max_abs(p->origin));
    return 0;
}

struct heightfield *heightfield_create(const struct heightfield_params *params,
                                       struct error *err)
{
    if (check_params(params, err) != 0)
        return NULL;
    struct heightfield *hf = xmalloc(1, sizeof *hf, "heightfield");
    hf->params = *params;
    hf->n = params->resolution;
    hf->spacing = params->size / (hf->n - 1); /* n >= 2 */
    hf->y = xmalloc((size_t)hf->n * (size_t)hf->n, sizeof *hf->y, "heightfield samples");
    struct fbm f = fbm_make(params->seed, params->octaves, params->roughness);
    double to_noise = params->frequency / (hf->n - 1);
    for (int j = 0; j < hf->n; j++) {
        for (int i = 0; i < hf->n; i++) {
            double y = params->height * fbm2(&f, i * to_noise, j * to_noise);
            hf->y[(size_t)j * (size_t)hf->n + (size_t)i] = params->origin.y + y;
        }
    }
    build_pyramid(hf);
    return hf;
}

void heightfield_free(struct heightfield *hf)
{
    if (hf == NULL)
        return;
    xfree(hf->range);
    xfree(hf->y);
    xfree(hf);
}

/* ---- ray queries -------------------------------------------------------------------- */

struct hf_ray {
    struct ray ray;
    struct sheared_ray sheared; /* for triangle_intersect()                              */
    double o[3];                /* ray.origin                                            */
    double inv_dir[3];          /* 1 / d per axis; +inf where d is 0 (see near_end())      */
    int negative[3];            /* d < 0: the ray enters slab k through hi, not lo         */
};

static void hf_ray_init(struct ray ray, struct hf_ray *r)
{
    double d[3] = {ray.dir.x, ray.dir.y, ray.dir.z};
    r->ray = ray;
    r->sheared = shear_ray(ray);
    r->o[0] = ray.origin.x;
    r->o[1] = ray.origin.y;
    r->o[2] = ray.origin.z;
    for (int k = 0; k < 3; k++) {
        r->inv_dir[k] = d[k] != 0 ? 1.0 / d[k] : INFINITY;
        r->negative[k] = d[k] < 0;
    }
}

/* Interval arithmetic on the ray parameter. A distance to a plane, t = (plane - o) / d, is
 * computed with at most three roundings (1 / d, the difference, the product), so its
 * relative error is below gamma_3 (gamma_n = n u / (1 - n u), u = DBL_EPSILON / 2). Moving a
 * near end down and a far end up by 2 gamma_3 (ROBUST_NEAR, ROBUST_FAR; Ize, "Robust BVH Ray
 * Traversal", JCGT 2013) keeps every interval a superset of the exact one, so no cell the
 * ray touches is skipped. Ends below 0 are never used (intervals start at t = 0). Where
 * d = 0 the distance is +-inf (the ray never leaves or never enters the half-space) or NaN
 * with o on the plane; the comparisons below ignore NaN, keeping the interval. */
static double near_end(double t)
{
    return t > 0 ? t * ROBUST_NEAR : t;
}

static double far_end(double t)
{
    return t > 0 ? t * ROBUST_FAR : t;
}

/* Clips [*t0, *t1] to the slab lo <= p[k] <= hi; returns whether anything is left. */
static int clip_slab(const struct hf_ray *r, int k, double lo, double hi, double *t0,
                     double *t1)
{
    double enter = r->negative[k] ? hi : lo, leave = r->negative[k] ? lo : hi;
    double ta = near_end((enter - r->o[k]) * r->inv_dir[k]);
    double tb = far_end((leave - r->o[k]) * r->inv_dir[k]);
    *t0 = ta > *t0 ? ta : *t0;
    *t1 = tb < *t1 ? tb : *t1;
    return *t0 <= *t1;
}

/* A node waiting to be visited, with the part [t0, t1] of the ray inside its box. */
struct pending {
    struct node node;
    double t0, t1;
};

/* The nearest triangle hit so far. */
struct closest {
    double t;    /* tmax until a hit is found */
    double u, v; /* barycentrics of vertices 1 and 2 (triangle_intersect()) */
    int i, j, triangle;
    int found;
};

/* Cell (i, j), which the ray crosses over [t0, t1] in x and z: clipped to its height range
 * (its four corners), then its two triangles. */
static void visit_cell(const struct heightfield *hf, const struct hf_ray *r,
                       const struct pending *p, struct closest *c)
{
    int i = p->node.a, j = p->node.b;
    struct vec3 corner[2][2]; /* corner[di][dj] = sample (i + di, j + dj) */
    double y_lo = INFINITY, y_hi = -INFINITY, t0 = p->t0, t1 = p->t1;
    for (int k = 0; k < 4; k++) {
        struct vec3 v = vertex(hf, i + (k & 1), j + (k >> 1));
        corner[k & 1][k >> 1] = v;
        y_lo = v.y < y_lo ? v.y : y_lo;
        y_hi = v.y > y_hi ? v.y : y_hi;
    }
    if (!clip_slab(r, 1, y_lo, y_hi, &t0, &t1))
        return;
    for (int t = 0; t < 2; t++) {
        struct vec3 v[3];
        for (int k = 0; k < 3; k++)
            v[k] = corner[corner_di[t][k]][corner_dj[t][k]];
        struct triangle tri = triangle_make(v, -1, hf->params.material, 0);
        struct hit h;
        if (!triangle_intersect(&tri, &r->sheared, c->t, &h))
            continue;
        c->t = h.t;
        c->u = h.u;
        c->v = h.v;
        c->i = i;
        c->j = j;
        c->triangle = t;
        c->found = 1;
    }
}

/* The parts of p's interval in the low (offset 0) and high (offset 1) half of node p along
 * axis k (0: x, 2: z): bounds[half] = {start, end}. The ray, monotone along the axis, is in
 * one half before it crosses the plane between them and in the other after. Both halves
 * keep the whole interval when there is no plane (one child along the axis: the other is
 * off the grid) or when the ray lies in the plane (o on it and d[k] = 0: NaN distance).
 * Returns the distance to the plane (+inf without one), which orders the children. */
static double split_interval(const struct heightfield *hf, const struct hf_ray *r,
                             const struct pending *p, int k, double bounds[2][2])
{
    bounds[0][0] = bounds[1][0] = p->t0;
    bounds[0][1] = bounds[1][1] = p->t1;
    int index = k == 0 ? p->node.a : p->node.b;
    int mid = (2 * index + 1) << (p->node.level - 1); /* first sample of the high half */
    if (mid >= hf->n - 1)
        return INFINITY;
    double plane = (k == 0 ? hf->params.origin.x : hf->params.origin.z) + mid * hf->spacing;
    double t_plane = (plane - r->o[k]) * r->inv_dir[k]; /* plane: as vertex() computes it */
    if (t_plane != t_plane)
        return t_plane;
    int first = r->negative[k]; /* the half the ray is in before the plane */
    double end = far_end(t_plane), start = near_end(t_plane);
    bounds[first][1] = end < p->t1 ? end : p->t1;
    bounds[!first][0] = start > p->t0 ? start : p->t0;
    return t_plane;
}

/* Child q (offset q & 1 in x, q >> 1 in z) of p with the part of the ray inside its box:
 * 1, or 0 when it is off the grid or the ray misses it before c->t. Cells are clipped to
 * their heights when visited. */
static int child_span(const struct heightfield *hf, const struct hf_ray *r,
                      const struct pending *p, int q, double x[2][2], double z[2][2],
                      double t_max, struct pending *e)
{
    const double *xq = x[q & 1], *zq = z[q >> 1];
    int side = hf->side[p->node.level - 1];
    e->node.level = p->node.level - 1;
    e->node.a = 2 * p->node.a + (q & 1);
    e->node.b = 2 * p->node.b + (q >> 1);
    e->t0 = xq[0] > zq[0] ? xq[0] : zq[0];
    e->t1 = xq[1] < zq[1] ? xq[1] : zq[1];
    e->t1 = e->t1 < t_max ? e->t1 : t_max;
    if (e->node.a >= side || e->node.b >= side || !(e->t0 <= e->t1))
        return 0;
    if (e->node.level == 0)
        return 1;
    double y_lo, y_hi;
    node_range(hf, e->node, &y_lo, &y_hi);
    return clip_slab(r, 1, y_lo, y_hi, &e->t0, &e->t1);
}

/* The children of p in the order the ray meets them: it starts in the halves it comes
 * from, crosses the nearer of the two planes, then the other. Cells are visited at once;
 * other children are pushed farthest first, so the nearest pops next. */
static int visit_children(const struct heightfield *hf, const struct hf_ray *r,
                          const struct pending *p, struct closest *c,
                          struct pending *stack, int n_pending)
{
    double x[2][2], z[2][2];
    double tx = split_interval(hf, r, p, 0, x), tz = split_interval(hf, r, p, 2, z);
    int before = r->negative[0] | r->negative[2] << 1;  /* child offsets before crossing */
    int cross_first = tx < tz ? 1 : 2, cross_second = 3 - cross_first; /* bit crossed */
    const int order[4] = {before, before ^ cross_first, before ^ cross_second, before ^ 3};
    if (p->node.level == 1) {
        for (int k = 0; k < 4; k++) {
            struct pending e;
            if (child_span(hf, r, p, order[k], x, z, c->t, &e))
                visit_cell(hf, r, &e, c);
        }
        return n_pending;
    }
    for (int k = 3; k >= 0; k--) {
        struct pending e;
        if (child_span(hf, r, p, order[k], x, z, c->t, &e))
            stack[n_pending++] = e;
    }
    return n_pending;
}

/* Depth-first, nearest child first; stops at the first hit when any_hit. */
static void walk_pyramid(const struct heightfield *hf, const struct hf_ray *r,
                         struct closest *c, int any_hit)
{
    struct pending stack[MAX_PENDING];
    struct pending top = {{hf->n_levels, 0, 0}, 0.0, c->t};
    struct vec3 lo = vertex(hf, 0, 0), hi = vertex(hf, hf->n - 1, hf->n - 1);
    double y_lo, y_hi;
    node_range(hf, top.node, &y_lo, &y_hi);
    if (!clip_slab(r, 0, lo.x, hi.x, &top.t0, &top.t1) ||
        !clip_slab(r, 2, lo.z, hi.z, &top.t0, &top.t1) ||
        !clip_slab(r, 1, y_lo, y_hi, &top.t0, &top.t1))
        return;
    int n_pending = 0;
    stack[n_pending++] = top;
    while (n_pending > 0 && !(any_hit && c->found)) {
        struct pending p = stack[--n_pending];
        if (p.t0 > c->t)
            continue; /* a nearer hit was found since it was pushed */
        if (p.node.level == 0)
            visit_cell(hf, r, &p, c); /* a grid of one cell */
        else
            n_pending = visit_children(hf, r, &p, c, stack, n_pending);
    }
}

static int hf_intersect(const void *shape, struct ray ray, double tmax, struct hit *hit)
{
    const struct heightfield *hf = shape;
    if (vec3_length2(ray.dir) == 0)
        return 0; /* shear_ray() needs a direction */
    struct hf_ray r;
    hf_ray_init(ray, &r);
    struct closest c;
    c.t = tmax;
    c.found = 0;
    walk_pyramid(hf, &r, &c, 0);
    if (!c.found)
        return 0;
    struct vec3 v[3], normals[3];
    cell_triangle(hf, c.i, c.j, c.triangle, v);
    cell_normals(hf, c.i, c.j, c.triangle, normals);
    struct triangle tri = triangle_make(v, -1, hf->params.material, 0);
    hit->t = c.t;
    hit->u = c.u;
    hit->v = c.v;
    triangle_shade(&tri, normals, hit); /* p, ng, ns, material, as for the expansion */
    double inv_size = 1.0 / hf->params.size; /* size > 0 (check_params) */
    hit->u = fmin(1.0, fmax(0.0, (hit->p.x - hf->params.origin.x) * inv_size));
    hit->v = fmin(1.0, fmax(0.0, (hit->p.z - hf->params.origin.z) * inv_size));
    return 1;
}

static int hf_occluded(const void *shape, struct ray ray, double tmax)
{
    if (vec3_length2(ray.dir) == 0)
        return 0;
    struct hf_ray r;
    hf_ray_init(ray, &r);
    struct closest c;
    c.t = tmax;
    c.found = 0;
    walk_pyramid(shape, &r, &c, 1);
    return c.found;
}

static struct aabb hf_bounds(const void *shape)
{
    const struct heightfield *hf = shape;
    struct node top = {hf->n_levels, 0, 0};
    double lo, hi;
    node_range(hf, top, &lo, &hi);
    struct aabb box;
    box.lo = vertex(hf, 0, 0);
    box.hi = vertex(hf, hf->n - 1, hf->n - 1);
    box.lo.y = lo;
    box.hi.y = hi;
    return box;
}

static size_t hf_bytes(const void *shape)
{
    const struct heightfield *hf = shape;
    size_t n_samples = (size_t)hf->n * (size_t)hf->n;
    return sizeof *hf + n_samples * sizeof *hf->y + 2 * hf->n_range * sizeof *hf->range;
}

static void hf_free(void *shape)
{
    heightfield_free(shape);
}

static void hf_primitives(const void *shape, const struct primitive_visitor *v)
{
    heightfield_triangles(shape, v->triangle, v->context);
}

const struct shape_ops heightfield_ops = {"heightfield", hf_bounds, hf_intersect, hf_occluded,
                                          hf_bytes, hf_free, hf_primitives, NULL};

/* ---- the triangles, one by one ----------------------------------------------------- */

void heightfield_triangles(const struct heightfield *hf,
                           void (*visit)(void *context, const struct vec3 v[3],
                                         const struct vec3 normals[3], int material),
                           void *context)
{
    for (int j = 0; j < hf->n - 1; j++) {
        for (int i = 0; i < hf->n - 1; i++) {
            for (int t = 0; t < 2; t++) {
                struct vec3 v[3], normals[3];
                cell_triangle(hf, i, j, t, v);
                cell_normals(hf, i, j, t, normals);
                visit(context, v, normals, hf->params.material);
            }
        }
    }
}

struct expansion {
    struct geometry *g;
    int failed;
};

static void add_triangle(void *context, const struct vec3 v[3], const struct vec3 normals[3],
                         int material)
{
    struct expansion *ex = context;
    if (!ex->failed && geometry_add_triangle(ex->g, v, normals, material) < 0)
        ex->failed = 1;
}

int heightfield_expand(const struct heightfield *hf, struct geometry *g)
{
    double n_cells = (double)(hf->n - 1) * (double)(hf->n - 1);
    if (2 * n_cells > (double)MAX_PRIMITIVES)
        return -1;
    struct expansion ex;
    ex.g = g;
    ex.failed = 0;
    heightfield_triangles(hf, add_triangle, &ex);
    return ex.failed ? -1 : 0;
}
