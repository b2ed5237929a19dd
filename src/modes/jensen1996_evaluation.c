/*
 * modes/jensen1996_evaluation.c -- Sec. 4's choice between the accurate and the
 * approximate evaluation (jensen1996_evaluation.h).
 */
#include "jensen1996_evaluation.h"

/* Sec. 4's rule: "We use the accurate computation if the surface is seen directly by the
 * eye or perhaps via a few specular reflections. We also use the accurate computation if
 * the distance between the ray origin and the intersection point is below a small
 * threshold value [...]. The approximate evaluation is used if the ray intersecting the
 * surface has been reflected diffusely since it left the eye or if the weight of the ray
 * is low." The few reflections: from an accurate point, with weight --accurate-weight or
 * more. The small threshold, whose value is not specified by the paper: --accurate-distance
 * radii of the global estimate at the ray's end, whose disc reaches back towards the
 * gathering point ("colour bleeding effects in corners"); that end gets the corner
 * evaluation (gathers_soft_indirect()). How deep corners recur is not specified by the
 * paper either: the rays of a gather made at a corner are approximate at any length.
 * Departure, with a switch: a surface seen through a glossy lobe, whose blur hides the
 * global map's, gets the through-gloss evaluation (glossy_corner; off, the paper's:
 * glossy lobes count as specular), sparing a gather and a search of the caustic map for
 * every glossy ray. */
enum evaluation accurate_or_approximate(const struct jensen1996_settings *settings,
                                        const struct arrival *a)
{
    if (a->last == FROM_EYE)
        return ACCURATE;
    if (a->last == DIFFUSE_BOUNCE) {
        double reach = settings->accurate_distance;
        return a->from != CORNER && a->length * a->length < reach * reach * a->radius2
                   ? CORNER
                   : APPROXIMATE;
    }
    if (a->from != ACCURATE || a->weight < settings->accurate_weight)
        return APPROXIMATE;
    return a->glossy && settings->glossy_corner ? THROUGH_GLOSS : ACCURATE;
}

/* An accurate point gathers (4.4). A corner is evaluated accurately, but for the paper's
 * final gather it takes, with corner_photons (--corner-photons, the default), the global
 * map's estimate from its indirect photons, a departure: the paper's gather at the end
 * of a gather's ray costs a gather of its own wherever the cache has no record there,
 * in the creases where the records are smallest, and the global map's disc, of a few
 * radii the ray's length, already stands for the light the corner's gather would find. */
int gathers_soft_indirect(const struct jensen1996_settings *settings, enum evaluation eval)
{
    return eval == ACCURATE || (eval == CORNER && !settings->corner_photons);
}
