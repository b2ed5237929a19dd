/*
 * scene/brdf_sample.h -- one sampled direction: what brdf_sample() (brdf.h) returns and
 * each glossy model's X_sample() (brdf_models.h) fills.
 *
 * A header of its own because both sides use it: brdf.c calls the models, so their header
 * takes the struct from here rather than from brdf.h, and the two need not include each
 * other.
 */
#ifndef PHOTON_BRDF_SAMPLE_H
#define PHOTON_BRDF_SAMPLE_H

#include "../base/vec3.h"

struct brdf_sample {
    struct vec3 wi;     /* unit, away from the surface                                    */
    struct vec3 weight; /* the throughput multiplier: f cos_i / pdf for a non-delta
                           sample; reflectance / probability for a delta one; both
                           include 1 / eta^2 for radiance refracted by glass            */
    double pdf;         /* non-delta: solid-angle pdf of wi, equal to brdf_pdf(wo, wi);
                           delta: the probability of having chosen that lobe            */
    int delta;          /* 1 if wi came from a mirror or refraction lobe                 */
    int transmitted;    /* 1 if wi crosses the surface (refraction)                      */
};

#endif
