/*
 * modes/jensen1996_evaluation.h -- Sec. 4's rule of `--mode 1996` (Jensen 1996): which
 * surfaces are evaluated accurately and which approximately (jensen1996_evaluation.c).
 * What each evaluation computes is jensen1996.c's (the top of that file).
 */
#ifndef PHOTON_JENSEN1996_EVALUATION_H
#define PHOTON_JENSEN1996_EVALUATION_H

#include "jensen1996_settings.h"

/* How a surface is evaluated. */
enum evaluation { ACCURATE, CORNER, THROUGH_GLOSS, APPROXIMATE };

/* A ray reaching a surface, as accurate_or_approximate() sees it: after a bounce, how the
 * surface it left was evaluated; after a specular bounce, whether by a glossy lobe (not a
 * delta one) and its throughput's luminance; after a diffuse bounce (a gather ray), its
 * length and the squared radius of the global estimate where it ends (0: none, no
 * diffuse part). */
enum bounce { FROM_EYE, SPECULAR_BOUNCE, DIFFUSE_BOUNCE };
struct arrival {
    enum bounce last; /* the bounce it comes from; FROM_EYE: none, a camera ray */
    enum evaluation from;
    int glossy;
    double weight;
    double length, radius2;
};

/* Sec. 4's rule, as settings tune it (jensen1996_evaluation.c quotes it). */
enum evaluation accurate_or_approximate(const struct jensen1996_settings *settings,
                                        const struct arrival *a);

/* Whether a surface evaluated as eval takes its soft indirect light from a final gather
 * (else from the global map's indirect photons: a corner's by default). */
int gathers_soft_indirect(const struct jensen1996_settings *settings, enum evaluation eval);

#endif
