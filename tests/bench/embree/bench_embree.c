/*
 * tests/bench/embree/bench_embree.c -- `make bench-embree`: the rays workload of
 * tests/bench/README.md cast through Embree 3 beside photon, in one run.
 *
 * A development tool, never part of photon (which links no outside library): it needs
 * Embree 3's headers and library (Debian's libembree-dev) and is built only by its make
 * target. For each scene of the rays workload (bench_ray_scenes(): balls-s4 and mount-s6
 * from PHOTON_SPD, terrain1m, cornell) it builds photon's geometry, makes the workload's
 * two ray sets from it exactly as `make bench` does, hands every primitive the geometry
 * holds (geometry_visit) to one Embree scene, and casts each set through both:
 * geometry_intersect() for photon, rtcIntersect1() for Embree, one thread each
 * ("threads=1"), the two alternating EMBREE_REPEATS times so that a drift of the shared
 * machine's speed falls on both. The ratio is the median of the repetitions' ratios.
 *
 * Embree's side, and why:
 *   - two scenes: Embree's defaults (rtcNewScene() as it comes: medium build quality, no
 *     flags), the settings a renderer starts from and the fastest here, and the same with
 *     RTC_SCENE_FLAG_ROBUST, Embree's mode for exact hits (conservative box tests and
 *     watertight triangles), which is what photon's caster is. Ratios are printed against
 *     both; the robust scene's checksums must agree with photon's;
 *   - triangles as RTC_GEOMETRY_TYPE_TRIANGLE, quads as RTC_GEOMETRY_TYPE_QUAD, spheres as
 *     its built-in RTC_GEOMETRY_TYPE_SPHERE_POINT (centre and radius as one float4), whose
 *     hits agree with photon's to the checksums' precision, so no slower user geometry is
 *     needed;
 *   - everything in float, as Embree computes: each double vertex, centre, radius, ray
 *     origin and direction rounded to the nearest float. The checksums therefore agree to
 *     float precision, not bit for bit: the sums of distances differ in their seventh
 *     digit. The robust scene must agree within EMBREE_AGREE (relative) on the hit counts
 *     and on the sums, or the tool exits with status 1; the default scene's checksums are
 *     printed for what they show (its traversal is not watertight and loses a few hits).
 *
 * A third set, shuffled, is the primary rays in a fixed pseudo-random order: the same work
 * without the coherence of neighbouring pixels, which shows how much of a caster's speed on
 * primary rays comes from that coherence (secondary rays, one per pixel in a random
 * direction, have little of it).
 *
 * Prints, with SCENE as in the rays workload and SET primary, secondary or shuffled:
 * embree.SCENE.photon_SET_mrays, embree_SET_mrays, embree_robust_SET_mrays, SET_ratio and
 * SET_ratio_robust (photon's rays a second over Embree's: the median over the repetitions),
 * the checksums photon_SET_hits, embree_SET_hits, embree_robust_SET_hits and the same for
 * _tsum, checksums_agree (the robust scene's), primitives, and the bytes: photon_bytes
 * (geometry_bytes()) and embree_bytes (what Embree's memory monitor counts after building
 * the default scene: its BVH and its copies of the primitives).
 */
#include <embree3/rtcore.h>
#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../../../src/base/alloc.h"
#include "../bench.h"
#include "../bench_rays.h"

#define EMBREE_REPEATS 5   /* alternating casts of each side, per ray set                 */
#define EMBREE_AGREE 1e-5  /* relative difference allowed in a hit count or a sum of t    */

/* The primitives of photon's geometry in Embree's layout, collected by geometry_visit(). */
struct embree_prims {
    float *spheres;     /* owned: x, y, z, radius per sphere                     */
    size_t n_spheres, cap_spheres;
    float *triangles;   /* owned: 3 vertices of x, y, z per triangle            */
    size_t n_triangles, cap_triangles;
    float *quads;       /* owned: 4 corners of x, y, z per quad, in order around */
    size_t n_quads, cap_quads;
};

/* Room for one more record of `floats` floats in *array (n records of cap). */
static float *grow(float *array, size_t n, size_t *cap, size_t floats)
{
    if (n < *cap)
        return array;
    *cap = *cap < 64 ? 64 : 2 * *cap;
    return xrealloc(array, *cap * floats, sizeof *array, "Embree primitives");
}

static void put_point(float *out, struct vec3 p)
{
    out[0] = (float)p.x;
    out[1] = (float)p.y;
    out[2] = (float)p.z;
}

static void visit_sphere(void *context, struct vec3 centre, double radius, int material)
{
    struct embree_prims *p = context;
    (void)material;
    p->spheres = grow(p->spheres, p->n_spheres, &p->cap_spheres, 4);
    float *s = p->spheres + 4 * p->n_spheres++;
    put_point(s, centre);
    s[3] = (float)radius;
}

static void visit_triangle(void *context, const struct vec3 v[3], const struct vec3 *normals,
                           int material)
{
    struct embree_prims *p = context;
    (void)normals;
    (void)material;
    p->triangles = grow(p->triangles, p->n_triangles, &p->cap_triangles, 9);
    float *t = p->triangles + 9 * p->n_triangles++;
    for (int i = 0; i < 3; i++)
        put_point(t + 3 * i, v[i]);
}

static void visit_quad(void *context, struct vec3 p0, struct vec3 e1, struct vec3 e2,
                       int material)
{
    struct embree_prims *p = context;
    (void)material;
    p->quads = grow(p->quads, p->n_quads, &p->cap_quads, 12);
    float *q = p->quads + 12 * p->n_quads++;
    put_point(q, p0);
    put_point(q + 3, vec3_add(p0, e1));
    put_point(q + 6, vec3_add(vec3_add(p0, e1), e2));
    put_point(q + 9, vec3_add(p0, e2));
}

static void visit_shape(void *context, const char *name, const char *approximation)
{
    (void)context;
    if (name != NULL && approximation != NULL)
        fprintf(stderr, "bench-embree: shape %s reaches Embree as %s\n", name, approximation);
}

/* One Embree geometry of `count` primitives of `vertices` corners each (1 for spheres,
 * whose "vertex" is a float4), the corners copied from data and indexed 0, 1, 2, ... */
static void attach(RTCDevice device, RTCScene scene, enum RTCGeometryType type,
                   const float *data, size_t count, unsigned vertices)
{
    if (count == 0)
        return;
    RTCGeometry geom = rtcNewGeometry(device, type);
    unsigned floats = type == RTC_GEOMETRY_TYPE_SPHERE_POINT ? 4 : 3;
    enum RTCFormat vertex_format = floats == 4 ? RTC_FORMAT_FLOAT4 : RTC_FORMAT_FLOAT3;
    float *vb = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, vertex_format,
                                        floats * sizeof(float), count * vertices);
    for (size_t i = 0; i < count * vertices * floats; i++)
        vb[i] = data[i];
    if (type != RTC_GEOMETRY_TYPE_SPHERE_POINT) {
        enum RTCFormat index_format = vertices == 3 ? RTC_FORMAT_UINT3 : RTC_FORMAT_UINT4;
        unsigned *ib = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, index_format,
                                               vertices * sizeof(unsigned), count);
        for (size_t i = 0; i < count * vertices; i++)
            ib[i] = (unsigned)i;
    }
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
}

/* Adds to *user (a long long) the bytes Embree takes (frees come negative). */
static bool count_bytes(void *user, ssize_t bytes, bool post)
{
    (void)post;
    *(long long *)user += bytes;
    return true;
}

/* An Embree scene of g's primitives, with the given scene flags. */
static RTCScene embree_scene(RTCDevice device, const struct geometry *g, enum RTCSceneFlags flags)
{
    struct embree_prims p = {NULL, 0, 0, NULL, 0, 0, NULL, 0, 0};
    struct primitive_visitor v = {&p, visit_sphere, visit_triangle, visit_quad, visit_shape};
    geometry_visit(g, &v);
    RTCScene scene = rtcNewScene(device);
    rtcSetSceneFlags(scene, flags);
    attach(device, scene, RTC_GEOMETRY_TYPE_SPHERE_POINT, p.spheres, p.n_spheres, 1);
    attach(device, scene, RTC_GEOMETRY_TYPE_TRIANGLE, p.triangles, p.n_triangles, 3);
    attach(device, scene, RTC_GEOMETRY_TYPE_QUAD, p.quads, p.n_quads, 4);
    rtcCommitScene(scene);
    xfree(p.spheres);
    xfree(p.triangles);
    xfree(p.quads);
    return scene;
}

/* Casts the set through Embree, setting its n_hits and t_sum; returns the CPU seconds. */
static double embree_cast(RTCScene scene, struct ray_set *set)
{
    struct RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    size_t n_hits = 0;
    double t_sum = 0.0;
    double start = bench_seconds();
    for (size_t k = 0; k < set->n_rays; k++) {
        const struct ray *r = &set->rays[k];
        struct RTCRayHit rh;
        rh.ray.org_x = (float)r->origin.x;
        rh.ray.org_y = (float)r->origin.y;
        rh.ray.org_z = (float)r->origin.z;
        rh.ray.tnear = 0.0f;
        rh.ray.dir_x = (float)r->dir.x;
        rh.ray.dir_y = (float)r->dir.y;
        rh.ray.dir_z = (float)r->dir.z;
        rh.ray.time = 0.0f;
        rh.ray.tfar = INFINITY;
        rh.ray.mask = ~0u;
        rh.ray.id = 0;
        rh.ray.flags = 0;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &context, &rh);
        if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
            n_hits++;
            t_sum += rh.ray.tfar;
        }
    }
    double seconds = bench_seconds() - start;
    set->n_hits = n_hits;
    set->t_sum = t_sum;
    return seconds;
}

/* The primary rays in a fixed pseudo-random order (Fisher-Yates driven by xorshift64): the
 * same rays and work, without the coherence of neighbouring pixels. The caller frees it. */
static struct ray_set shuffled(const struct ray_set *set)
{
    struct ray_set out = *set;
    out.rays = xmalloc(set->n_rays, sizeof *out.rays, "shuffled rays");
    memcpy(out.rays, set->rays, set->n_rays * sizeof *out.rays);
    uint64_t x = UINT64_C(88172645463325252);
    for (size_t i = set->n_rays; i > 1; i--) {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        size_t j = (size_t)(x % i);
        struct ray swap = out.rays[i - 1];
        out.rays[i - 1] = out.rays[j];
        out.rays[j] = swap;
    }
    return out;
}

static int agree(const struct ray_set *a, const struct ray_set *b)
{
    double hits = fmax(1.0, (double)a->n_hits);
    double d_hits = fabs((double)a->n_hits - (double)b->n_hits) / hits;
    double d_tsum = fabs(a->t_sum - b->t_sum) / fmax(1e-300, fabs(a->t_sum));
    return d_hits <= EMBREE_AGREE && d_tsum <= EMBREE_AGREE;
}

/* One ray set cast by photon and the two Embree scenes in turn; prints the figures and
 * returns whether the robust scene's checksums agree with photon's. */
static int compare_set(const char *scene_name, const char *set_name, const struct geometry *g,
                       RTCScene fast, RTCScene robust, struct ray_set *set)
{
    double ours[EMBREE_REPEATS], theirs[EMBREE_REPEATS], theirs_robust[EMBREE_REPEATS];
    double ratio[EMBREE_REPEATS], ratio_robust[EMBREE_REPEATS];
    struct ray_set embree = *set, embree_robust = *set;
    for (int r = 0; r < EMBREE_REPEATS; r++) {
        ours[r] = bench_cast_rays(g, set);
        theirs[r] = embree_cast(fast, &embree);
        theirs_robust[r] = embree_cast(robust, &embree_robust);
        ratio[r] = theirs[r] / ours[r];   /* photon's rays/s over Embree's */
        ratio_robust[r] = theirs_robust[r] / ours[r];
    }
    double n = (double)set->n_rays * 1e-6;
    const char *s = scene_name, *k = set_name;
    printf("embree.%s.photon_%s_mrays=%.3f\n", s, k, n / bench_median(ours, EMBREE_REPEATS));
    printf("embree.%s.embree_%s_mrays=%.3f\n", s, k, n / bench_median(theirs, EMBREE_REPEATS));
    printf("embree.%s.embree_robust_%s_mrays=%.3f\n", s, k,
           n / bench_median(theirs_robust, EMBREE_REPEATS));
    printf("embree.%s.%s_ratio=%.3f\n", s, k, bench_median(ratio, EMBREE_REPEATS));
    printf("embree.%s.%s_ratio_robust=%.3f\n", s, k, bench_median(ratio_robust, EMBREE_REPEATS));
    printf("embree.%s.photon_%s_hits=%zu\n", s, k, set->n_hits);
    printf("embree.%s.embree_%s_hits=%zu\n", s, k, embree.n_hits);
    printf("embree.%s.embree_robust_%s_hits=%zu\n", s, k, embree_robust.n_hits);
    printf("embree.%s.photon_%s_tsum=%.9g\n", s, k, set->t_sum);
    printf("embree.%s.embree_%s_tsum=%.9g\n", s, k, embree.t_sum);
    printf("embree.%s.embree_robust_%s_tsum=%.9g\n", s, k, embree_robust.t_sum);
    return agree(set, &embree_robust);
}

/* What the scene's workload needs beyond bench_ray_scenes()' arguments. */
struct comparison {
    RTCDevice device;
    long long embree_bytes;   /* the memory monitor's count */
    int all_agree;
};

static struct comparison comparison;

static void embree_workload(const char *scene_name, struct geometry *(*build)(void *ctx),
                            void *ctx, const struct bench_camera *camera)
{
    struct comparison *c = &comparison;
    struct geometry *g = build(ctx);
    c->embree_bytes = 0;
    RTCScene fast = embree_scene(c->device, g, RTC_SCENE_FLAG_NONE);
    long long fast_bytes = c->embree_bytes;
    RTCScene robust = embree_scene(c->device, g, RTC_SCENE_FLAG_ROBUST);
    struct ray_set primary = bench_primary_rays(camera);
    struct ray_set secondary = bench_secondary_rays(g, &primary);
    int agree = compare_set(scene_name, "primary", g, fast, robust, &primary);
    agree &= compare_set(scene_name, "secondary", g, fast, robust, &secondary);
    struct ray_set scattered = shuffled(&primary);
    agree &= compare_set(scene_name, "shuffled", g, fast, robust, &scattered);
    xfree(scattered.rays);
    printf("embree.%s.checksums_agree=%d\n", scene_name, agree);
    printf("embree.%s.primitives=%zu\n", scene_name, geometry_primitive_count(g));
    printf("embree.%s.photon_bytes=%zu\n", scene_name, geometry_bytes(g));
    printf("embree.%s.embree_bytes=%lld\n", scene_name, fast_bytes);
    fflush(stdout);
    c->all_agree &= agree;
    rtcReleaseScene(fast);
    rtcReleaseScene(robust);
    xfree(secondary.rays);
    xfree(primary.rays);
    geometry_free(g);
}

int main(void)
{
    comparison.device = rtcNewDevice("threads=1");
    if (comparison.device == NULL) {
        fprintf(stderr, "bench-embree: rtcNewDevice failed (error %d)\n", rtcGetDeviceError(NULL));
        return 2;
    }
    comparison.all_agree = 1;
    rtcSetDeviceMemoryMonitorFunction(comparison.device, count_bytes, &comparison.embree_bytes);
    printf("embree.version=%s\n", RTC_VERSION_STRING);
    bench_ray_scenes(embree_workload);
    rtcReleaseDevice(comparison.device);
    if (!comparison.all_agree)
        fprintf(stderr, "bench-embree: photon's and robust Embree's checksums disagree\n");
    return comparison.all_agree ? 0 : 1;
}
