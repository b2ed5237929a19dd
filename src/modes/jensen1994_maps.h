/*
 * modes/jensen1994_maps.h -- pass 1 of `--mode 1994` (Jensen and Christensen 1994, Sec. 3):
 * light path tracing into the irradiance stores the final pass reads (jensen1994_maps.c).
 */
#ifndef PHOTON_JENSEN1994_MAPS_H
#define PHOTON_JENSEN1994_MAPS_H

#include "../scene/scene.h"
#include "jensen1994_settings.h"

struct kdtree;
struct illumination_maps;
struct nearest;
struct irradiance_settings;
struct precomputed_irradiance;

/* The irradiance stores pass 1 fills (Sec. 3.2-3.3): the photon map, and with
 * settings->illumination_maps the illumination maps of the surfaces that have parameters
 * (quads and spheres), which then hold those surfaces' photons instead. */
struct irradiance_stores {
    struct kdtree *photons;                 /* owned: photons holding their surface normal
                                               and the caustic bit (CP: PHOTON_CAUSTIC)  */
    struct kdtree *caustics;                /* owned: copies of the CP photons alone, so
                                               that caustic estimates search only them   */
    struct kdtree *glossy;                  /* owned: the photons keeps_direction()
                                               keeps with their direction                */
    struct illumination_maps *illumination; /* owned, finished; NULL: photon maps only   */
};

/* Pass 1 alone (Sec. 3): settings->n_photons light rays from the scene's lights (finished) with
 * seed, followed for at most max_depth bounces, deposited into *out (which the caller
 * releases with irradiance_stores_free()); fills the photon fields of *stats. Returns 0,
 * or -1 with *err filled and nothing left allocated when more than MAX_PHOTONS would be
 * stored. progress: whether the trace shows a progress line (trace_progress.h). The
 * render's first step, and `photon probe`'s (app/probe.h). */
int jensen1994_trace(const struct scene *scene, uint64_t seed, int max_depth,
                     const struct jensen1994_settings *settings, struct irradiance_stores *out,
                     struct jensen1994_stats *stats, int progress, struct error *err);
void irradiance_stores_free(struct irradiance_stores *stores);

/* Whether a photon landing on primitive prim of material m keeps its direction (in the
 * stores' glossy tree) rather than the normal: on a diffuse-like part that is not
 * Lambertian (a broad lobe: brdf_split()), unless prim has an illumination map. A
 * departure from Sec. 3.3, whose photons hold the normal (Sec. 6 would store the
 * direction, "usable in surfaces with complex BRDF's"), without a switch that --paper
 * turns: the light such a part reflects depends on where it came from. */
int keeps_direction(const struct illumination_maps *illumination, const struct material *m,
                    int prim);

/* The illumination maps' figures (finished maps) into *stats, for --stats. */
void count_illumination(const struct illumination_maps *maps, struct jensen1994_stats *stats);

/* A point of a surface where irradiance is read. */
struct store_query {
    struct vec3 x, n;  /* the point and its unit normal, on the side of the light wanted */
    int prim;          /* the primitive, and where on it (struct hit's u, v)              */
    double u, v;
    const struct irradiance_settings *estimate; /* the photon map's estimate; its kinds
                                                   PHOTON_CAUSTIC asks for caustics only */
    const struct precomputed_irradiance *precomputed; /* NULL, or records of that
                                                         estimate made beforehand     */
};

/* Irradiance at q: from the illumination map of q->prim where it has one (its CI alone
 * for caustics, DI + CI otherwise), else the photon map's estimate (estimate.h), read
 * from the nearest record of q->precomputed that serves q where there is one. nn: the
 * caller's scratch, k_max >= PRECOMPUTED_CANDIDATES with records. */
struct vec3 stored_irradiance(const struct irradiance_stores *stores,
                              const struct store_query *q, struct nearest *nn);

#endif
