/*
 * geom/sphereflake.c -- the sphere flake intersected through its implicit hierarchy.
 *
 * Placement (balls.c of Haines' SPD 3.14, facts checked against balls-s4.nff by
 * tests/test_shapes.c): a sphere (centre c, radius r, unit axis a) has nine children of
 * radius r * (1/3) centred at c + F(a) e_i * r * (1 + 1/3), so each touches its parent, and
 * child i's axis is F(a) e_i. The e_i are nine fixed unit directions (child_directions()):
 * three at polar angle acos(sqrt(2/3)) from +z, azimuths 45, 165 and 285 degrees, and six on
 * the equator at 15, 75, 135, 195, 255 and 315 degrees. F(a) is balls.c's frame of axis a
 * (haines_frame()): the rotation by acos(a.z) about z x a taking +z to a, but the identity
 * when a.z >= 0.9999 and the half turn about y when a.z <= -0.9999. Those thresholds fire
 * for axes exactly +-z from level 2 on and for axes merely near them from level 6 on; we keep
 * them, so every level is balls.c's flake. Across levels 0..10 no axis lies within 9e-10 of
 * a threshold (checked by enumeration), so rounding cannot classify one differently.
 * The top sphere's axis is the orientation parameter: the flake balls.c would make with
 * its initial direction set to it (balls.c starts from +z).
 *
 * Bounds: a sphere with m generations below it lies, with its whole subtree, inside the
 * ball of radius B_m = r * (2 - 3^-m) about its centre. Proof by induction: B_0 = r; a child
 * sits at distance r + r/3 with B_(m-1) = (r/3)(2 - 3^-(m-1)) about it, so
 * B_m = 4r/3 + 2r/3 - r 3^-m = r (2 - 3^-m); the infinite flake fits in 2r.
 *
 * Traversal: a depth-first walk keeps at most 8 * levels + 1 pending spheres; a sphere's
 * children are made from its centre, radius and axis when it is visited (node_children()),
 * children with a subtree are visited nearest bounding-ball entry first, and leaf children
 * are intersected at once. Nothing is stored per sphere: the shape is this struct, O(1),
 * and a walk uses O(levels) stack, so memory is the same at every level.
 */
#include "sphereflake.h"


#include "../base/alloc.h"
#include "sphere.h"

#define N_CHILDREN 9
#define MAX_PENDING (8 * SPHEREFLAKE_MAX_LEVELS + 1) /* pop one, push at most 9, per level */
#define AXIS_SNAP 0.9999 /* balls.c: |a.z| beyond this counts as exactly +-z */

struct sphereflake {
    struct sphereflake_params params; /* as given, orientation made unit                   */
    struct vec3 e[N_CHILDREN];        /* child directions in a sphere's own frame, axis +z  */
    double bound_scale[SPHEREFLAKE_MAX_LEVELS + 1]; /* B_m / r = 2 - 3^-m, m generations   */
    double bound_pad; /* absolute slack on every bounding ball: covers the rounding of
                         child centres (about levels ulps of the flake's coordinates) */
};

/* One sphere of the flake. */
struct node {
    struct vec3 centre;
    struct vec3 axis; /* unit, balls.c's "direction" */
    double radius;
    int depth; /* 0 for the top sphere */
};

/* A sphere waiting to be visited, with its bounding-ball entry distance along the ray. */
struct pending {
    struct node node;
    double t_near;
};

double sphereflake_sphere_count(int levels)
{
    double count = 0, per_level = 1;
    for (int k = 0; k <= levels; k++) {
        count += per_level;
        per_level *= 9;
    }
    return count;
}

/* The nine e_i in balls.c's order: per third of a turn (0, 120, 240 degrees), the upper
 * child at azimuth 45 + 120 s, then equator children at 15 + 120 s and 75 + 120 s. Written
 * with square roots only (correctly rounded everywhere), not with sin and cos. */
static void child_directions(struct vec3 e[N_CHILDREN])
{
    double c15 = (sqrt(6.0) + sqrt(2.0)) / 4, s15 = (sqrt(6.0) - sqrt(2.0)) / 4;
    double h = sqrt(0.5), sin_polar = sqrt(1.0 / 3.0), cos_polar = sqrt(2.0 / 3.0);
    const double azimuth[N_CHILDREN][2] = {
        {h, h},      {c15, s15},   {s15, c15},    /* 45, 15, 75    */
        {-c15, s15}, {-h, h},      {-c15, -s15},  /* 165, 135, 195 */
        {s15, -c15}, {-s15, -c15}, {h, -h}};      /* 285, 255, 315 */
    for (int i = 0; i < N_CHILDREN; i++) {
        double ring = i % 3 == 0 ? sin_polar : 1.0;
        double z = i % 3 == 0 ? cos_polar : 0.0;
        e[i] = vec3(azimuth[i][0] * ring, azimuth[i][1] * ring, z);
    }
}

/* balls.c's frame of unit axis a, as columns fx, fy, fz (F(a) v = fx v.x + fy v.y + fz v.z).
 * Rodrigues' rotation taking +z to a, written without acos: with k = 1 / (1 + a.z),
 * F = [[1 - a.x^2 k, -a.x a.y k, a.x], [-a.x a.y k, 1 - a.y^2 k, a.y], [-a.x, -a.y, a.z]].
 * 1 + a.z > 1e-4 in that branch, so k is bounded. */
static void haines_frame(struct vec3 a, struct vec3 *fx, struct vec3 *fy, struct vec3 *fz)
{
    if (a.z >= AXIS_SNAP) {
        *fx = vec3(1, 0, 0);
        *fy = vec3(0, 1, 0);
        *fz = vec3(0, 0, 1);
    } else if (a.z <= -AXIS_SNAP) { /* balls.c turns by pi about y */
        *fx = vec3(-1, 0, 0);
        *fy = vec3(0, 1, 0);
        *fz = vec3(0, 0, -1);
    } else {
        double k = 1.0 / (1.0 + a.z);
        *fx = vec3(1.0 - a.x * a.x * k, -a.x * a.y * k, -a.x);
        *fy = vec3(-a.x * a.y * k, 1.0 - a.y * a.y * k, -a.y);
        *fz = a;
    }
}

/* The nine children of parent, in balls.c's order. The one place spheres are made: the
 * walk, the visitor and the expansion all get the same doubles from here. */
static void node_children(const struct sphereflake *flake, const struct node *parent,
                          struct node child[N_CHILDREN])
{
    struct vec3 fx, fy, fz;
    haines_frame(parent->axis, &fx, &fy, &fz);
    double scale = parent->radius * (1.0 + 1.0 / 3.0); /* centre distance r + r/3 */
    double radius = parent->radius * (1.0 / 3.0);
    for (int i = 0; i < N_CHILDREN; i++) {
        struct vec3 e = flake->e[i];
        struct vec3 axis = vec3_add(vec3_add(vec3_scale(fx, e.x), vec3_scale(fy, e.y)),
                                    vec3_scale(fz, e.z));
        child[i].centre = vec3_madd(parent->centre, axis, scale);
        child[i].axis = axis;
        child[i].radius = radius;
        child[i].depth = parent->depth + 1;
    }
}

static struct node top_node(const struct sphereflake *flake)
{
    struct node top;
    top.centre = flake->params.centre;
    top.axis = flake->params.orientation;
    top.radius = flake->params.radius;
    top.depth = 0;
    return top;
}

struct sphereflake *sphereflake_create(const struct sphereflake_params *params,
                                       struct error *err)
{
    if (!(isfinite(params->radius) && params->radius > 0)) {
        error_set(err, "", 0, "sphereflake: radius must be positive and finite, got %g",
                  params->radius);
        return NULL;
    }
    if (params->levels < 0 || params->levels > SPHEREFLAKE_MAX_LEVELS) {
        error_set(err, "", 0, "sphereflake: levels must be 0..%d, got %d",
                  SPHEREFLAKE_MAX_LEVELS, params->levels);
        return NULL;
    }
    struct vec3 axis = vec3_normalize(params->orientation); /* zero stays zero */
    if (!vec3_is_finite(params->centre) || !vec3_is_finite(axis) ||
        !(vec3_length2(axis) > 0.5)) {
        error_set(err, "", 0, "sphereflake: centre must be finite and orientation non-zero");
        return NULL;
    }
    struct sphereflake *flake = xmalloc(1, sizeof *flake, "sphere flake");
    flake->params = *params;
    flake->params.orientation = axis;
    child_directions(flake->e);
    flake->bound_scale[0] = 1.0;
    for (int m = 1; m <= SPHEREFLAKE_MAX_LEVELS; m++) /* B_m = 4r/3 + B_(m-1)(r/3) */
        flake->bound_scale[m] = 4.0 / 3.0 + flake->bound_scale[m - 1] / 3.0;
    flake->bound_pad =
        RAY_OFFSET_REL * (2.0 * params->radius + vec3_max_abs(params->centre));
    return flake;
}

void sphereflake_free(struct sphereflake *flake)
{
    xfree(flake);
}

/* ---- ray queries ---------------------------------------------------------------------- */

/* Per-ray constants. a = |d|^2 > 0 is checked by the callers. */
struct flake_ray {
    struct ray ray;
    double a, inv_a;
};

/* Where the ray enters and leaves the ball (centre, radius): 1 and [*t_near, *t_far], or 0.
 * With f = o - centre and b = f.d, the squared distance of the centre from the line is
 * |f - d b/a|^2, computed from that vector rather than as |f|^2 - b^2/a, which cancels. */
static int ball_span(const struct flake_ray *fr, struct vec3 centre, double radius,
                     double *t_near, double *t_far)
{
    struct vec3 f = vec3_sub(fr->ray.origin, centre);
    double b = vec3_dot(f, fr->ray.dir);
    double t_mid = -b * fr->inv_a;
    struct vec3 l = vec3_madd(f, fr->ray.dir, t_mid); /* centre to closest point on line */
    double disc = radius * radius - vec3_length2(l);  /* (half chord length)^2 */
    if (!(disc >= 0))
        return 0;
    double half_chord = sqrt(disc * fr->inv_a);
    *t_near = t_mid - half_chord;
    *t_far = t_mid + half_chord;
    return 1;
}

/* The closest sphere hit so far. */
struct closest {
    double t; /* tmax until a hit is found */
    struct node node;
    int found;
};

/* The sphere test is sphere.c's, so the shape and its expansion agree to the last bit. */
static void try_sphere(const struct flake_ray *fr, const struct node *node, struct closest *c)
{
    struct sphere s = sphere_make(node->centre, node->radius, 0, 0);
    struct hit h;
    if (sphere_intersect(&s, fr->ray, c->t, &h)) {
        c->t = h.t;
        c->node = *node;
        c->found = 1;
    }
}

/* Pushes the children of parent that have subtrees and whose bounding balls the ray enters
 * before c->t, farthest first so that the nearest is popped next. Insertion sort by entry
 * distance, stable, so ties keep balls.c's order. */
static int push_children(const struct sphereflake *flake, const struct flake_ray *fr,
                         const struct node child[N_CHILDREN], const struct closest *c,
                         struct pending *stack, int n_pending)
{
    double bound = child[0].radius * flake->bound_scale[flake->params.levels - child[0].depth];
    bound += flake->bound_pad;
    struct pending near[N_CHILDREN];
    int n_near = 0;
    for (int i = 0; i < N_CHILDREN; i++) {
        double t_near, t_far;
        if (!ball_span(fr, child[i].centre, bound, &t_near, &t_far) || t_far <= 0 ||
            t_near >= c->t)
            continue;
        int k = n_near++;
        for (; k > 0 && near[k - 1].t_near > t_near; k--)
            near[k] = near[k - 1];
        near[k].node = child[i];
        near[k].t_near = t_near;
    }
    while (n_near > 0)
        stack[n_pending++] = near[--n_near];
    return n_pending;
}

/* Depth-first, nearest child first; stops at the first hit when any_hit. */
static void walk_flake(const struct sphereflake *flake, const struct flake_ray *fr,
                       struct closest *c, int any_hit)
{
    struct pending stack[MAX_PENDING];
    int n_pending = 0;
    double t_near, t_far;
    struct node top = top_node(flake);
    double bound = top.radius * flake->bound_scale[flake->params.levels] + flake->bound_pad;
    if (!ball_span(fr, top.centre, bound, &t_near, &t_far) || t_far <= 0 || t_near >= c->t)
        return;
    stack[n_pending].node = top;
    stack[n_pending++].t_near = t_near;
    while (n_pending > 0 && !(any_hit && c->found)) {
        struct pending p = stack[--n_pending];
        if (p.t_near >= c->t)
            continue; /* a nearer hit was found since it was pushed */
        try_sphere(fr, &p.node, c);
        if (p.node.depth == flake->params.levels)
            continue;
        struct node child[N_CHILDREN];
        node_children(flake, &p.node, child);
        if (child[0].depth == flake->params.levels) {
            for (int i = 0; i < N_CHILDREN; i++)
                try_sphere(fr, &child[i], c);
        } else {
            n_pending = push_children(flake, fr, child, c, stack, n_pending);
        }
    }
}

static int flake_ray_init(struct ray ray, struct flake_ray *fr)
{
    fr->ray = ray;
    fr->a = vec3_length2(ray.dir);
    if (!(fr->a > 0) || !isfinite(fr->a))
        return 0; /* no direction: nothing is hit */
    fr->inv_a = 1.0 / fr->a;
    return 1;
}

static int flake_intersect(const void *shape, struct ray ray, double tmax, struct hit *hit)
{
    const struct sphereflake *flake = shape;
    struct flake_ray fr;
    if (!flake_ray_init(ray, &fr))
        return 0;
    struct closest c;
    c.t = tmax;
    c.found = 0;
    walk_flake(flake, &fr, &c, 0);
    if (!c.found)
        return 0;
    struct sphere s = sphere_make(c.node.centre, c.node.radius,
                                  flake->params.materials[c.node.depth], 0);
    hit->t = c.t;
    sphere_shade(&s, ray, hit); /* p, ng = ns outward, u, v, material */
    return 1;
}

static int flake_occluded(const void *shape, struct ray ray, double tmax)
{
    struct flake_ray fr;
    if (!flake_ray_init(ray, &fr))
        return 0;
    struct closest c;
    c.t = tmax;
    c.found = 0;
    walk_flake(shape, &fr, &c, 1);
    return c.found;
}

static struct aabb flake_bounds(const void *shape)
{
    const struct sphereflake *flake = shape;
    double bound = flake->params.radius * flake->bound_scale[flake->params.levels] +
                   flake->bound_pad;
    struct vec3 extent = vec3(bound, bound, bound);
    struct aabb box;
    box.lo = vec3_sub(flake->params.centre, extent);
    box.hi = vec3_add(flake->params.centre, extent);
    return box;
}

static size_t flake_bytes(const void *shape)
{
    (void)shape;
    return sizeof(struct sphereflake);
}

static void flake_free(void *shape)
{
    sphereflake_free(shape);
}

static void flake_primitives(const void *shape, const struct primitive_visitor *v)
{
    sphereflake_spheres(shape, v->sphere, v->context);
}

const struct shape_ops sphereflake_ops = {"sphereflake", flake_bounds, flake_intersect,
                                          flake_occluded, flake_bytes, flake_free,
                                          flake_primitives, NULL};

/* ---- the spheres, one by one ------------------------------------------------------------ */

struct visitor {
    const struct sphereflake *flake;
    void (*visit)(void *context, struct vec3 centre, double radius, int material);
    void *context;
};

/* Recursion depth is at most SPHEREFLAKE_MAX_LEVELS + 1. */
static void visit_subtree(const struct visitor *vis, const struct node *node)
{
    vis->visit(vis->context, node->centre, node->radius,
               vis->flake->params.materials[node->depth]);
    if (node->depth == vis->flake->params.levels)
        return;
    struct node child[N_CHILDREN];
    node_children(vis->flake, node, child);
    for (int i = 0; i < N_CHILDREN; i++)
        visit_subtree(vis, &child[i]);
}

void sphereflake_spheres(const struct sphereflake *flake,
                         void (*visit)(void *context, struct vec3 centre, double radius,
                                       int material),
                         void *context)
{
    struct visitor vis;
    vis.flake = flake;
    vis.visit = visit;
    vis.context = context;
    struct node top = top_node(flake);
    visit_subtree(&vis, &top);
}

struct expansion {
    struct geometry *g;
    int failed;
};

static void add_sphere(void *context, struct vec3 centre, double radius, int material)
{
    struct expansion *ex = context;
    if (!ex->failed && geometry_add_sphere(ex->g, centre, radius, material) < 0)
        ex->failed = 1;
}

int sphereflake_expand(const struct sphereflake *flake, struct geometry *g)
{
    if (sphereflake_sphere_count(flake->params.levels) > (double)MAX_PRIMITIVES)
        return -1;
    struct expansion ex;
    ex.g = g;
    ex.failed = 0;
    sphereflake_spheres(flake, add_sphere, &ex);
    return ex.failed ? -1 : 0;
}
