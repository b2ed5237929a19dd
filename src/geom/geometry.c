/*
 * geom/geometry.c -- the scene's primitives and the BVH over them (see geometry.h).
 *
 * Primitives live in one array per kind (spheres, triangles, quads, procedural shapes),
 * each record carrying its id and material (shapes report their own); the triangles share
 * their corners through struct mesh (mesh.h). geometry_build() builds the BVH over every
 * primitive that can be hit (degenerate ones, which have no area, are left out) and then
 *   (1) the BVH's items are grouped by kind (bvh_build_groups()): positions
 *       kind_ends[kind - 1] .. kind_ends[kind] - 1 of its leaf order are that kind's (the
 *       first kind's start at 0), so no leaf mixes kinds;
 *   (2) each kind's array is permuted into that leaf order, so a leaf reads consecutive
 *       records, and the records the BVH left out follow at the end of their array: the
 *       BVH's k-th item is record k - kind_ends[kind - 1] of its kind. A leaf test thus
 *       goes from the node straight to its records, where a table of references between
 *       them would cost another wait on memory a leaf on large scenes (tests/bench);
 *   (3) id_refs[id] names primitive id's record the same way, whether or not the BVH holds
 *       it, at every moment: each add appends its entry, and geometry_build() rewrites them
 *       all once (2) has moved the records (geometry_primitive_bounds() reads it), and fits
 *       id_refs[] and the permuted arrays to their counts.
 * A leaf test dispatches on its kind with a switch: spheres, triangles and quads by
 * direct calls, shapes through their struct shape_ops. During traversal a primitive reports only
 * t and its surface parameters; the shading record of the closest one is completed once,
 * at the end (complete_hit).
 *
 * Primitives added after geometry_build() are not seen until it is called again, which
 * rebuilds everything. Owns every array here, the shapes (freed by their ops->free) and
 * the BVH.
 */
#include "geometry.h"

#include <assert.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../base/alloc.h"
#include "bvh.h"
#include "mesh.h"
#include "quad.h"
#include "sphere.h"
#include "triangle.h"

enum kind { KIND_SPHERE, KIND_TRIANGLE, KIND_QUAD, KIND_SHAPE, N_KINDS };

#define REF_KIND_SHIFT 30                 /* 2 bits of kind above 30 bits of index >= 2^28 */
#define REF_INDEX_MASK ((UINT32_C(1) << REF_KIND_SHIFT) - 1)

struct shape {
    const struct shape_ops *ops;  /* borrowed: static operations table             */
    void *data;                   /* owned: released by ops->free                   */
    int id;
    int material;                 /* the material it was added with (its first one)  */
};

struct geometry {
    struct sphere *spheres;       /* owned; n_spheres used of cap_spheres           */
    size_t n_spheres, cap_spheres;
    struct mesh mesh;             /* owned: the triangles and their shared points     */
    struct quad *quads;           /* owned; likewise                                 */
    size_t n_quads, cap_quads;
    struct shape *shapes;         /* owned; likewise                                 */
    size_t n_shapes, cap_shapes;
    struct vec3 *normals;         /* owned: vertex normals, three per triangle given them */
    size_t n_normals, cap_normals;
    size_t n_prims;               /* ids handed out: 0 .. n_prims - 1                */
    uint32_t *id_refs;            /* owned: invariant (3); n_prims used of cap_id_refs */
    size_t cap_id_refs;
    size_t kind_ends[N_KINDS];    /* invariant (1); zero before geometry_build()      */
    struct bvh *bvh;              /* owned; NULL before geometry_build()             */
};

/* One geometry_intersect() or geometry_occluded() call. */
struct query {
    const struct geometry *g;
    struct ray ray;
    struct sheared_ray sheared;   /* for triangles and quads                         */
    struct hit hit;               /* closest so far: t, u, v (a shape's: all fields) */
    uint32_t ref;                 /* its primitive                                   */
};

struct geometry *geometry_create(void)
{
    struct geometry *g = xcalloc(1, sizeof *g, "geometry");
    g->spheres = NULL;   /* calloc's zero bits need not be null pointers */
    mesh_init(&g->mesh);
    g->quads = NULL;
    g->shapes = NULL;
    g->normals = NULL;
    g->id_refs = NULL;
    g->bvh = NULL;
    return g;
}

void geometry_free(struct geometry *g)
{
    if (g == NULL)
        return;
    for (size_t i = 0; i < g->n_shapes; i++)
        g->shapes[i].ops->free(g->shapes[i].data);
    xfree(g->spheres);
    mesh_free(&g->mesh);
    xfree(g->quads);
    xfree(g->shapes);
    xfree(g->normals);
    xfree(g->id_refs);
    bvh_free(g->bvh);
    xfree(g);
}

/* Room for `need` elements of `size` bytes in p (capacity *cap), growing geometrically. */
static void *reserve(void *p, size_t *cap, size_t need, size_t size, const char *what)
{
    if (need <= *cap)
        return p;
    size_t grown = *cap < 16 ? 16 : 2 * *cap;
    *cap = grown > need ? grown : need;
    return xrealloc(p, *cap, size, what);
}

static uint32_t make_ref(enum kind kind, size_t index)
{
    return ((uint32_t)kind << REF_KIND_SHIFT) | (uint32_t)index;
}

/* Hands out the next id to the record of `kind` just appended at `index` (invariant (3)). */
static int next_id(struct geometry *g, enum kind kind, size_t index)
{
    g->id_refs = reserve(g->id_refs, &g->cap_id_refs, g->n_prims + 1, sizeof *g->id_refs,
                         "primitive ids");
    g->id_refs[g->n_prims] = make_ref(kind, index);
    return (int)g->n_prims++;
}

int geometry_add_sphere(struct geometry *g, struct vec3 centre, double radius, int material)
{
    if (g->n_prims >= MAX_PRIMITIVES)
        return -1;
    g->spheres = reserve(g->spheres, &g->cap_spheres, g->n_spheres + 1, sizeof *g->spheres,
                         "spheres");
    g->spheres[g->n_spheres++] = sphere_make(centre, radius, material, (int)g->n_prims);
    return next_id(g, KIND_SPHERE, g->n_spheres - 1);
}

int geometry_add_triangle(struct geometry *g, const struct vec3 v[3], const struct vec3 *normals,
                          int material)
{
    if (g->n_prims >= MAX_PRIMITIVES)
        return -1;
    int first_normal = -1;
    if (normals != NULL) {
        g->normals = reserve(g->normals, &g->cap_normals, g->n_normals + 3, sizeof *g->normals,
                             "vertex normals");
        for (int i = 0; i < 3; i++)
            g->normals[g->n_normals + i] = normals[i];
        first_normal = (int)g->n_normals;   /* < 3 MAX_PRIMITIVES < INT_MAX */
        g->n_normals += 3;
    }
    size_t index = mesh_add(&g->mesh, v, first_normal, material, (int)g->n_prims);
    return next_id(g, KIND_TRIANGLE, index);
}

int geometry_add_quad(struct geometry *g, struct vec3 p0, struct vec3 e1, struct vec3 e2,
                      int material)
{
    if (g->n_prims >= MAX_PRIMITIVES)
        return -1;
    g->quads = reserve(g->quads, &g->cap_quads, g->n_quads + 1, sizeof *g->quads, "quads");
    g->quads[g->n_quads++] = quad_make(p0, e1, e2, material, (int)g->n_prims);
    return next_id(g, KIND_QUAD, g->n_quads - 1);
}

int geometry_add_shape(struct geometry *g, const struct shape_ops *ops, void *shape, int material)
{
    if (g->n_prims >= MAX_PRIMITIVES)
        return -1;
    g->shapes = reserve(g->shapes, &g->cap_shapes, g->n_shapes + 1, sizeof *g->shapes, "shapes");
    struct shape *s = &g->shapes[g->n_shapes++];
    s->ops = ops;
    s->material = material; /* hits report the shape's own materials (shape_ops) */
    s->data = shape;
    s->id = (int)g->n_prims;
    return next_id(g, KIND_SHAPE, g->n_shapes - 1);
}

/* ---- building ---- */

/* Appends the box and ref of every primitive of one kind that can be hit. */
static size_t collect_kind(const struct geometry *g, enum kind kind, struct aabb *bounds,
                           uint32_t *refs, size_t n)
{
    size_t i;
    switch (kind) {
    case KIND_SPHERE:
        for (i = 0; i < g->n_spheres; i++)
            if (!sphere_is_degenerate(&g->spheres[i])) {
                bounds[n] = sphere_bounds(&g->spheres[i]);
                refs[n++] = make_ref(kind, i);
            }
        break;
    case KIND_TRIANGLE:
        for (i = 0; i < g->mesh.n_triangles; i++)
            if (!mesh_is_degenerate(&g->mesh, &g->mesh.triangles[i])) {
                bounds[n] = mesh_bounds(&g->mesh, &g->mesh.triangles[i]);
                refs[n++] = make_ref(kind, i);
            }
        break;
    case KIND_QUAD:
        for (i = 0; i < g->n_quads; i++)
            if (!quad_is_degenerate(&g->quads[i])) {
                bounds[n] = quad_bounds(&g->quads[i]);
                refs[n++] = make_ref(kind, i);
            }
        break;
    default:
        for (i = 0; i < g->n_shapes; i++) {
            bounds[n] = g->shapes[i].ops->bounds(g->shapes[i].data);
            refs[n++] = make_ref(kind, i);
        }
    }
    return n;
}

/* A kind's record array: its base address, element size and count. */
struct record_array {
    char *base;
    size_t size, count;
};

static struct record_array make_record_array(void *base, size_t size, size_t count)
{
    struct record_array a;
    a.base = base;
    a.size = size;
    a.count = count;
    return a;
}

static struct record_array records_of(struct geometry *g, enum kind kind)
{
    switch (kind) {
    case KIND_SPHERE:
        return make_record_array(g->spheres, sizeof *g->spheres, g->n_spheres);
    case KIND_TRIANGLE:
        return make_record_array(g->mesh.triangles, sizeof *g->mesh.triangles,
                                 g->mesh.n_triangles);
    case KIND_QUAD:
        return make_record_array(g->quads, sizeof *g->quads, g->n_quads);
    default:
        return make_record_array(g->shapes, sizeof *g->shapes, g->n_shapes);
    }
}

/* Invariant (2) for one kind: records in leaf order first, then those the BVH left out.
 * leaf_refs[k] is the k-th item's ref; the kind's refs are rewritten to the new places.
 * Returns the new array, exactly as long as the kind's count, and frees the old one. */
static void *permute_kind(struct geometry *g, enum kind kind, uint32_t *leaf_refs, size_t n)
{
    struct record_array a = records_of(g, kind);
    if (a.count == 0)
        return a.base;
    char *sorted = xmalloc(a.count, a.size, "primitives in leaf order");
    unsigned char *placed = xcalloc(a.count, 1, "primitives in leaf order");
    size_t next = 0;
    for (size_t k = 0; k < n; k++) {
        size_t index = leaf_refs[k] & REF_INDEX_MASK;
        if ((enum kind)(leaf_refs[k] >> REF_KIND_SHIFT) != kind)
            continue;
        memcpy(sorted + next * a.size, a.base + index * a.size, a.size);
        placed[index] = 1;
        leaf_refs[k] = make_ref(kind, next++);
    }
    for (size_t i = 0; i < a.count; i++)
        if (!placed[i])
            memcpy(sorted + next++ * a.size, a.base + i * a.size, a.size);
    xfree(placed);
    xfree(a.base);
    return sorted;
}

/* Invariant (3) again after permute_kind() has moved the records. */
static void index_ids(struct geometry *g)
{
    for (size_t i = 0; i < g->n_spheres; i++)
        g->id_refs[g->spheres[i].id] = make_ref(KIND_SPHERE, i);
    for (size_t i = 0; i < g->mesh.n_triangles; i++)
        g->id_refs[g->mesh.triangles[i].id] = make_ref(KIND_TRIANGLE, i);
    for (size_t i = 0; i < g->n_quads; i++)
        g->id_refs[g->quads[i].id] = make_ref(KIND_QUAD, i);
    for (size_t i = 0; i < g->n_shapes; i++)
        g->id_refs[g->shapes[i].id] = make_ref(KIND_SHAPE, i);
}

/* The first BVH position of kind's items (invariant (1)). */
static size_t kind_start(const struct geometry *g, enum kind kind)
{
    return kind > 0 ? g->kind_ends[kind - 1] : 0;
}

void geometry_build(struct geometry *g)
{
    bvh_free(g->bvh);
    size_t n_max = g->n_prims;
    struct aabb *bounds = xmalloc(n_max, sizeof *bounds, "primitive bounds");
    uint32_t *item_refs = xmalloc(n_max, sizeof *item_refs, "primitive refs");
    size_t n = 0;
    for (int kind = 0; kind < N_KINDS; kind++)
        g->kind_ends[kind] = n = collect_kind(g, (enum kind)kind, bounds, item_refs, n);
    g->bvh = bvh_build_groups(bounds, n, g->kind_ends, N_KINDS);
    xfree(bounds);
    uint32_t *leaf_refs = xmalloc(n, sizeof *leaf_refs, "BVH refs");
    for (size_t k = 0; k < n; k++)
        leaf_refs[k] = item_refs[g->bvh->items[k]];
    xfree(item_refs);
    /* The permuted arrays are exactly full: later adds grow them again. */
    g->spheres = permute_kind(g, KIND_SPHERE, leaf_refs, n);
    g->cap_spheres = g->n_spheres;
    g->mesh.triangles = permute_kind(g, KIND_TRIANGLE, leaf_refs, n);
    g->mesh.cap_triangles = g->mesh.n_triangles;
    mesh_finish(&g->mesh);
    g->quads = permute_kind(g, KIND_QUAD, leaf_refs, n);
    g->cap_quads = g->n_quads;
    g->shapes = permute_kind(g, KIND_SHAPE, leaf_refs, n);
    g->cap_shapes = g->n_shapes;
    for (int kind = 0; kind < N_KINDS; kind++)   /* invariant (2), which the queries assume */
        for (size_t k = kind_start(g, (enum kind)kind); k < g->kind_ends[kind]; k++)
            assert(leaf_refs[k] == make_ref((enum kind)kind, k - kind_start(g, (enum kind)kind)));
    xfree(leaf_refs);
    index_ids(g);
    g->id_refs = xrealloc(g->id_refs, g->n_prims, sizeof *g->id_refs, "primitive ids");
    g->cap_id_refs = g->n_prims;
}

/* ---- queries ---- */

static int intersect_record(const struct query *q, enum kind kind, size_t index, double tmax,
                            struct hit *hit)
{
    const struct geometry *g = q->g;
    switch (kind) {
    case KIND_SPHERE:
        return sphere_intersect(&g->spheres[index], q->ray, tmax, hit);
    case KIND_TRIANGLE:
        return mesh_intersect(&g->mesh, &g->mesh.triangles[index], &q->sheared, tmax, hit);
    case KIND_QUAD:
        return quad_intersect(&g->quads[index], &q->sheared, tmax, hit);
    default:
        return g->shapes[index].ops->intersect(g->shapes[index].data, q->ray, tmax, hit);
    }
}

/* The kind of the leaf starting at BVH position first, and in *index its first record
 * (invariants (1) and (2): a leaf lies within its kind's positions). */
static enum kind leaf_kind(const struct geometry *g, size_t first, size_t *index)
{
    int kind = 0;
    while (first >= g->kind_ends[kind])
        kind++;
    *index = first - kind_start(g, (enum kind)kind);
    return (enum kind)kind;
}

static int closest_in_leaf(void *ctx, size_t first, size_t count, double *tmax)
{
    struct query *q = ctx;
    size_t index;
    enum kind kind = leaf_kind(q->g, first, &index);
    int found = 0;
    for (size_t i = index; i < index + count; i++) {
        if (intersect_record(q, kind, i, *tmax, &q->hit)) {
            *tmax = q->hit.t;
            q->ref = make_ref(kind, i);
            found = 1;
        }
    }
    return found;
}

static int any_in_leaf(void *ctx, size_t first, size_t count, double tmax)
{
    struct query *q = ctx;
    size_t index;
    enum kind kind = leaf_kind(q->g, first, &index);
    for (size_t i = index; i < index + count; i++) {
        if (kind == KIND_SHAPE) {
            const struct shape *s = &q->g->shapes[i];
            if (s->ops->occluded(s->data, q->ray, tmax))
                return 1;
        } else if (intersect_record(q, kind, i, tmax, &q->hit)) {
            return 1;
        }
    }
    return 0;
}

/* The closest primitive's shading record, from the t, u, v its test left in q->hit. */
static void complete_hit(const struct query *q, struct hit *hit)
{
    const struct geometry *g = q->g;
    size_t index = q->ref & REF_INDEX_MASK;
    *hit = q->hit;
    switch ((enum kind)(q->ref >> REF_KIND_SHIFT)) {
    case KIND_SPHERE:
        sphere_shade(&g->spheres[index], q->ray, hit);
        hit->prim = g->spheres[index].id;
        break;
    case KIND_TRIANGLE: {
        const struct mesh_triangle *tri = &g->mesh.triangles[index];
        mesh_shade(&g->mesh, tri, tri->normals >= 0 ? &g->normals[tri->normals] : NULL, hit);
        hit->prim = tri->id;
        break;
    }
    case KIND_QUAD:
        quad_shade(&g->quads[index], hit);
        hit->prim = g->quads[index].id;
        break;
    default:
        hit->prim = g->shapes[index].id;   /* the shape filled the rest */
    }
}

static int is_usable(const struct geometry *g, struct ray ray)
{
    return g->bvh != NULL && vec3_length2(ray.dir) > 0;
}

int geometry_intersect(const struct geometry *g, struct ray ray, double tmax, struct hit *hit)
{
    if (!is_usable(g, ray))
        return 0;
    struct query q;
    q.g = g;
    q.ray = ray;
    q.sheared = shear_ray(ray);
    q.ref = 0;
    if (!bvh_intersect(g->bvh, ray, tmax, closest_in_leaf, &q))
        return 0;
    complete_hit(&q, hit);
    return 1;
}

int geometry_occluded(const struct geometry *g, struct ray ray, double tmax)
{
    if (!is_usable(g, ray))
        return 0;
    struct query q;
    q.g = g;
    q.ray = ray;
    q.sheared = shear_ray(ray);
    q.ref = 0;
    return bvh_occluded(g->bvh, ray, tmax, any_in_leaf, &q);
}

/* ---- statistics ---- */

size_t geometry_primitive_count(const struct geometry *g)
{
    return g->n_prims;
}

size_t geometry_bvh_nodes(const struct geometry *g)
{
    return g->bvh != NULL ? g->bvh->n_nodes : 0;
}

size_t geometry_bytes(const struct geometry *g)
{
    size_t bytes = sizeof *g + g->cap_spheres * sizeof *g->spheres
                   + mesh_bytes(&g->mesh) + g->cap_quads * sizeof *g->quads
                   + g->cap_shapes * sizeof *g->shapes + g->cap_normals * sizeof *g->normals
                   + g->cap_id_refs * sizeof *g->id_refs;
    if (g->bvh != NULL)
        bytes += bvh_bytes(g->bvh);
    for (size_t i = 0; i < g->n_shapes; i++)
        bytes += g->shapes[i].ops->bytes(g->shapes[i].data);
    return bytes;
}

/* The box of every primitive of a material (material < 0: of every primitive),
 * degenerate ones included (their points are still in the scene); lo = +inf, hi = -inf
 * when there is none. */
struct aabb geometry_material_bounds(const struct geometry *g, int material)
{
    struct aabb box;
    box.lo = vec3(INFINITY, INFINITY, INFINITY);
    box.hi = vec3(-INFINITY, -INFINITY, -INFINITY);
    for (size_t i = 0; i < g->n_spheres; i++)
        if (material < 0 || g->spheres[i].material == material)
            box = aabb_union(box, sphere_bounds(&g->spheres[i]));
    for (size_t i = 0; i < g->mesh.n_triangles; i++)
        if (material < 0 || g->mesh.triangles[i].material == material)
            box = aabb_union(box, mesh_bounds(&g->mesh, &g->mesh.triangles[i]));
    for (size_t i = 0; i < g->n_quads; i++)
        if (material < 0 || g->quads[i].material == material)
            box = aabb_union(box, quad_bounds(&g->quads[i]));
    for (size_t i = 0; i < g->n_shapes; i++)
        if (material < 0 || g->shapes[i].material == material)
            box = aabb_union(box, g->shapes[i].ops->bounds(g->shapes[i].data));
    return box;
}

struct aabb geometry_bounds(const struct geometry *g)
{
    return geometry_material_bounds(g, -1);
}

struct aabb geometry_primitive_bounds(const struct geometry *g, int prim)
{
    assert(prim >= 0 && (size_t)prim < g->n_prims);
    uint32_t ref = g->id_refs[prim];
    size_t index = ref & REF_INDEX_MASK;
    switch ((enum kind)(ref >> REF_KIND_SHIFT)) {
    case KIND_SPHERE:
        return sphere_bounds(&g->spheres[index]);
    case KIND_TRIANGLE:
        return mesh_bounds(&g->mesh, &g->mesh.triangles[index]);
    case KIND_QUAD:
        return quad_bounds(&g->quads[index]);
    default:
        return g->shapes[index].ops->bounds(g->shapes[index].data);
    }
}

int geometry_primitive_material(const struct geometry *g, int prim)
{
    assert(prim >= 0 && (size_t)prim < g->n_prims);
    uint32_t ref = g->id_refs[prim];
    size_t index = ref & REF_INDEX_MASK;
    switch ((enum kind)(ref >> REF_KIND_SHIFT)) {
    case KIND_SPHERE:
        return g->spheres[index].material;
    case KIND_TRIANGLE:
        return g->mesh.triangles[index].material;
    case KIND_QUAD:
        return g->quads[index].material;
    default:
        return g->shapes[index].material;
    }
}

int geometry_primitive_plane(const struct geometry *g, int prim, struct vec3 *point,
                             struct vec3 *normal)
{
    assert(prim >= 0 && (size_t)prim < g->n_prims);
    uint32_t ref = g->id_refs[prim];
    size_t index = ref & REF_INDEX_MASK;
    struct vec3 n = vec3_zero();
    switch ((enum kind)(ref >> REF_KIND_SHIFT)) {
    case KIND_TRIANGLE: {
        struct vec3 v[3];
        mesh_corners(&g->mesh, &g->mesh.triangles[index], v);
        *point = v[0];
        n = vec3_cross(vec3_sub(v[1], v[0]), vec3_sub(v[2], v[0]));
        break;
    }
    case KIND_QUAD:
        *point = g->quads[index].p0;
        n = g->quads[index].ng;
        break;
    default:
        return 0; /* spheres and procedural shapes are not flat */
    }
    double length = vec3_length(n);
    if (!(length > 0))
        return 0; /* degenerate: no plane */
    *normal = vec3_scale(n, 1.0 / length);
    return 1;
}

double geometry_uv_area(const struct geometry *g, int prim, double u0, double u1, double v0,
                        double v1)
{
    assert(prim >= 0 && (size_t)prim < g->n_prims);
    uint32_t ref = g->id_refs[prim];
    size_t index = ref & REF_INDEX_MASK;
    switch ((enum kind)(ref >> REF_KIND_SHIFT)) {
    case KIND_QUAD: /* p0 + u e1 + v e2: area |e1 x e2| du dv */
        return vec3_length(vec3_cross(g->quads[index].e1, g->quads[index].e2)) * (u1 - u0) *
               (v1 - v0);
    case KIND_SPHERE: { /* u = phi / (2 pi), v = theta / pi: r^2 dphi (cos theta0 - cos theta1) */
        double r = g->spheres[index].radius;
        return r * r * 2 * PI * (u1 - u0) * (cos(PI * v0) - cos(PI * v1));
    }
    default:
        return -1; /* triangles and shapes: no map over their surface here */
    }
}

int geometry_uv_extent(const struct geometry *g, int prim, double *length_u, double *length_v)
{
    assert(prim >= 0 && (size_t)prim < g->n_prims);
    uint32_t ref = g->id_refs[prim];
    size_t index = ref & REF_INDEX_MASK;
    switch ((enum kind)(ref >> REF_KIND_SHIFT)) {
    case KIND_QUAD:
        *length_u = vec3_length(g->quads[index].e1);
        *length_v = vec3_length(g->quads[index].e2);
        return 1;
    case KIND_SPHERE:
        *length_u = 2 * PI * g->spheres[index].radius; /* the equator */
        *length_v = PI * g->spheres[index].radius;     /* a meridian  */
        return 1;
    default:
        return 0;
    }
}

/* ---- the primitives as such ---- */

static void visit_triangle(const struct geometry *g, const struct mesh_triangle *tri,
                           const struct primitive_visitor *v)
{
    struct vec3 corner[3];
    mesh_corners(&g->mesh, tri, corner);
    v->triangle(v->context, corner, tri->normals >= 0 ? &g->normals[tri->normals] : NULL,
                tri->material);
}

void geometry_visit(const struct geometry *g, const struct primitive_visitor *v)
{
    for (size_t id = 0; id < g->n_prims; id++) {
        uint32_t ref = g->id_refs[id];
        size_t index = ref & REF_INDEX_MASK;
        switch ((enum kind)(ref >> REF_KIND_SHIFT)) {
        case KIND_SPHERE: {
            const struct sphere *s = &g->spheres[index];
            if (!sphere_is_degenerate(s))
                v->sphere(v->context, s->centre, s->radius, s->material);
            break;
        }
        case KIND_TRIANGLE:
            if (!mesh_is_degenerate(&g->mesh, &g->mesh.triangles[index]))
                visit_triangle(g, &g->mesh.triangles[index], v);
            break;
        case KIND_QUAD: {
            const struct quad *q = &g->quads[index];
            if (!quad_is_degenerate(q))
                v->quad(v->context, q->p0, q->e1, q->e2, q->material);
            break;
        }
        default: {
            const struct shape *s = &g->shapes[index];
            v->shape(v->context, s->ops->name, s->ops->approximation);
            s->ops->primitives(s->data, v);
            v->shape(v->context, NULL, NULL);
        }
        }
    }
}
