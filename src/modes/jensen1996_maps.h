/*
 * modes/jensen1996_maps.h -- pass 1 of `--mode 1996` (Jensen 1996, Sec. 3): the photon
 * maps, traced into the render's global work or borrowed from it.
 *
 * Two maps are traced: a caustic map of photons emitted towards the specular objects and
 * stored on diffuse surfaces after bounces through the specular part f_r,s only (L S+ D, S
 * a delta or a glossy lobe: Eq. 2's "highly glossy and ideal specular"), and a global map of
 * photons emitted towards everything and stored at every diffuse hit, with shadow photons
 * behind each first hit (Jensen and Christensen 1995) kept in one visibility map per
 * light, which pass 2's direct light asks whether a light is seen (Sec. 4.1). Pass 2 lives
 * in jensen1996.c.
 */
#ifndef PHOTON_JENSEN1996_MAPS_H
#define PHOTON_JENSEN1996_MAPS_H

#include "../photon/kdtree.h"
#include "../scene/scene.h"
#include "jensen1996_settings.h"
#include "render.h"
#include "surface.h"

/* The maps pass 2 reads, borrowed from the render's global work (jensen1996_settings.h). */
struct photon_maps {
    struct kdtree *global;      /* L (S|D)* D, without shadow photons                     */
    struct kdtree *caustic;     /* L S+ D; NULL without specular objects or with one_map  */
    struct kdtree **visibility; /* per light, its direct and shadow photons; NULL without
                                   shadow photons                                         */
    size_t n_lights;
    struct kdtree *records;     /* the records of precomputed irradiance: every N-th photon
                                   of the global map, with its surface normal in place of
                                   its direction (photon/precomputed_irradiance.h); NULL
                                   with precomputed_irradiance 0                          */
};

/* Pass 1 into settings->work, which is empty: maps[0] the global map, maps[1] the caustic map
 * (NULL when not built), maps[2 ..] the lights' visibility maps, then the records when
 * settings->precomputed_irradiance >= 1. On failure (more than
 * MAX_PHOTONS photons would be stored) -1 with *err filled, and settings->work left empty. */
int build_photon_maps(const struct scene *scene, const struct render_settings *rs,
                      const struct jensen1996_settings *settings,
                      struct jensen1996_stats *stats, struct error *err);

/* The maps of settings->work, borrowed into *maps, after checking that they are the ones this
 * scene and these settings make (a visibility map per light with shadow photons, no
 * caustic map with one_map); the stats' map figures. -1 with *err filled when they are
 * not. */
int borrow_photon_maps(const struct scene *scene, const struct jensen1996_settings *settings,
                       struct photon_maps *maps, struct jensen1996_stats *stats,
                       struct error *err);

/* Whether a light is seen from s, as its shadow photons say (Jensen and Christensen 1995):
 * its nearest direct and shadow photons in its visibility map, within max_r2 of s and on
 * this side of the surface (nn the search's scratch). All direct: VISIBLE; all shadow:
 * OCCLUDED; a mixture, or fewer than half of J96_VISIBILITY_PHOTONS within reach:
 * UNDECIDED, for a shadow ray to settle. */
enum visibility { VISIBLE, OCCLUDED, UNDECIDED };
enum visibility shadow_photon_visibility(const struct kdtree *visibility,
                                         const struct surface *s, double max_r2,
                                         struct nearest *nn);

#endif
