/*
 * photon/trace.h -- photon tracing: shooting photons from the lights, following them
 * through the scene and storing them where they hit (Jensen 1996, Sec. 3).
 *
 * trace_photons() emits N photons, light by light in proportion to power (or through
 * projection maps, Jensen and Christensen 1994: projection_map.h), and follows each one
 * as the paper says: "every time a photon hits a surface it is stored ... and
 * Russian roulette is used to determine whether the photon is absorbed or reflected".
 * The result is an array of 20-byte photons (photon.h) in the order they were stored,
 * ready for balance_kdtree(). Photon i of a trace draws every random number from
 * rng_stream(seed, STREAM_PHOTON, pass, i) and from nothing else, so the array does not
 * depend on the order in which photons are traced.
 *
 * Each stored photon carries in its flags the path that brought it (photon.h):
 *   PHOTON_DIRECT    the first surface hit after leaving the light;
 *   PHOTON_CAUSTIC   L S+ D: only specular (delta) bounces since the light;
 *   PHOTON_INDIRECT  at least one bounce off a non-delta lobe;
 *   PHOTON_SHADOW    Jensen and Christensen 1995: a surface behind the first hit along
 *                    the emitted ray, where the light is blocked. Shadow photons carry
 *                    ZERO power and the direction towards the light; a map used for
 *                    radiance estimates must not contain them (they would shrink the
 *                    gathering radius without adding flux), so a mode that wants them
 *                    keeps them apart (e.g. splits the array by flag before balancing).
 * Which of these are stored is the caller's choice (trace_settings.store); the global
 * map stores the first three, the caustic map only PHOTON_CAUSTIC.
 */
#ifndef PHOTON_TRACE_H
#define PHOTON_TRACE_H

#include <stddef.h>
#include <stdint.h>

#include "../base/error.h"
#include "../base/watch.h"
#include "../scene/emit.h"
#include "../scene/scene.h"
#include "photon.h"

/* Documented limit on photons emitted by one trace and on photons stored by one: 10^8
 * records are 2 GB, and balancing copies them once more. Beyond it a request is bad
 * input, refused with a message, never an allocation failure. */
#define MAX_PHOTONS 100000000

/* Classes stored for the two maps of Jensen 1996, Sec. 3. */
#define PHOTON_MAP_GLOBAL (PHOTON_DIRECT | PHOTON_CAUSTIC | PHOTON_INDIRECT)
#define PHOTON_MAP_CAUSTIC PHOTON_CAUSTIC

struct projection_maps;


#define TRACE_WATCH_EVERY 4096 /* photons: a few milliseconds of tracing, often enough for
                                  a line a second, too seldom to cost anything          */

struct trace_settings {
    uint64_t seed;                          /* the run's seed                             */
    uint64_t pass;                          /* photon i uses rng_stream(seed,
                                               STREAM_PHOTON, pass, i)                    */
    size_t n_emit;                          /* N, photons emitted: 0..MAX_PHOTONS          */
    size_t max_stored;                      /* more stored than this is refused: the
                                               trace fails; 1..MAX_PHOTONS                 */
    unsigned store;                         /* PHOTON_DIRECT | PHOTON_CAUSTIC |
                                               PHOTON_INDIRECT | PHOTON_SHADOW bits: the
                                               classes stored (PHOTON_SHADOW turns shadow
                                               photons on)                                 */
    int max_depth;                          /* bounces followed after the first hit (>= 0);
                                               also the most surfaces a shadow ray crosses
                                               behind the first hit                        */
    const struct emission_targets *targets; /* borrowed; NULL: emit into all directions
                                               (light_emit); else directed emission
                                               towards these spheres (light_emit_towards)  */
    const struct projection_maps *projection; /* borrowed; NULL: as targets says; else
                                               emission through these maps, built for this
                                               scene (projection_emit, Jensen and
                                               Christensen 1994), and targets is unused    */
    int by_parts;                           /* 1: each bounce leaves through f_r,d or f_r,s
                                               (brdf_split()), and a caustic path is one
                                               whose every bounce took f_r,s, glossy lobes
                                               included (Jensen 1996, Eq. 2); 0: one whose
                                               every bounce took a delta lobe            */
    const struct work_watch *watch; /* borrowed; NULL: none. Told how far the trace has
                                       gone (base/watch.h), its work the photons
                                       emitted, before photon i whenever i is a positive
                                       multiple of TRACE_WATCH_EVERY                    */
};

/* The traced photons and what it took to make them. */
struct photon_trace {
    struct photon *photons; /* owned; n_photons of them in the order stored, photon 0's
                               path first; powers in watts with the 1 / N already in:
                               Phi_l weight / (p_pick N) times the path's throughput    */
    size_t n_photons;       /* photons stored, <= max_stored                           */
    size_t capacity;        /* records allocated, >= n_photons                         */
    size_t n_emitted;       /* N: photons emitted (including those that hit nothing)   */
    size_t n_direct, n_caustic, n_indirect, n_shadow; /* stored, by class               */
    unsigned long long rays; /* rays cast                                               */
};

/* A photon at the moment it is stored, in full precision: what a sink receives. */
struct photon_event {
    struct vec3 position; /* where it hit                                              */
    struct vec3 normal;   /* unit geometric normal on the side it arrived from         */
    struct vec3 wi;       /* unit, back towards where it came from                      */
    struct vec3 power;    /* W per channel, the 1 / N already in (zero for shadow ones) */
    unsigned kind;        /* one of PHOTON_DIRECT, _CAUSTIC, _INDIRECT, _SHADOW          */
    int light;            /* the light that emitted it (index into scene->lights)       */
    int prim;             /* the primitive it hit, and where on it: struct hit's u, v   */
    double u, v;
    int back;             /* 1: it arrived on the primitive's back (PHOTON_BACK)        */
    unsigned batch;       /* its path's emission index modulo PHOTON_BATCHES            */
};

/* Where stored photons go: a photon map packs them (trace_photons), progressive photon
 * mapping adds them to hit points at once and keeps none. store() returns 0, or -1 to
 * stop the trace (a full map). */
struct photon_sink {
    int (*store)(void *context, const struct photon_event *photon);
    void *context;
};

/* Traces ts->n_emit photons as trace_photons() does, handing each photon of a class in
 * ts->store to the sink in the order they are stored (ts->max_stored is the sink's
 * business, unused here). Adds the rays cast to *rays. Returns 0, or -1 as soon as the
 * sink returns -1. */
int trace_photons_into(const struct scene *scene, const struct trace_settings *ts,
                       const struct photon_sink *sink, unsigned long long *rays);

/* Packs photon e into out (which starts zeroed: memset 0) and counts it by class,
 * growing the array; -1 (nothing stored) when out already holds max_stored photons.
 * trace_photons() stores with it; a sink that splits photons among several maps calls
 * it for each. */
int photon_trace_store(struct photon_trace *out, size_t max_stored, const struct photon_event *e);

/* Traces ts->n_emit photons through the scene (finished; it need not have lights: then
 * nothing is stored) and fills *out, which the caller releases with
 * photon_trace_free(). Fails with -1, *err filled and *out empty when more than
 * ts->max_stored photons would be stored (a white furnace stores about N max_depth);
 * nothing is then left allocated. Returns 0 on success. */
int trace_photons(const struct scene *scene, const struct trace_settings *ts,
                  struct photon_trace *out, struct error *err);

/* Whether a photon travelling along dir that makes hit would be stored there: the
 * surface has a non-delta part that reflects something (a black emitter holds none). */
int photons_land_at(const struct scene *scene, const struct hit *hit, struct vec3 dir);

/* Releases out->photons (NULL allowed: after balance_kdtree() took them) and empties
 * *out. */
void photon_trace_free(struct photon_trace *out);

#endif
