/*
 * modes/render_counters.h -- what a render counts as it goes: rays, samples, passes and
 * the pixels that take specular_spp samples (render.h says what those are); --stats
 * prints them.
 *
 * A header of its own because the surface helpers (surface.h) count the rays they cast
 * into it, and the pixel loop (render.c) uses those helpers: both take the counters from
 * here, so surface.h need not include render.h.
 */
#ifndef PHOTON_RENDER_COUNTERS_H
#define PHOTON_RENDER_COUNTERS_H

#include <stddef.h>

struct render_counters {
    unsigned long long rays;              /* rays cast: camera, secondary and shadow     */
    unsigned long long nonfinite_samples; /* samples dropped for NaN or Inf: always 0
                                             unless a bug lets one through              */
    unsigned long long samples;           /* camera samples taken, over all pixels of the
                                             window (added to, like rays): divided by
                                             the window's pixels, the mean spp          */
    int passes;                           /* sample passes run: the most samples a pixel
                                             took (spp reached when adaptive is off;
                                             specular_spp when specular_pixels > 0)     */
    size_t specular_pixels;               /* pixels of the window that take specular_spp
                                             samples: the camera sees a light through
                                             mirrors or glass in them (set, not added)  */
    int target_blocks, target_within;     /* with a target error (render.h): the blocks
                                             judged at the last pass, and those within
                                             it (set, not added)                        */
    int target_missed_x, target_missed_y; /* the first block not within, by its top
                                             left pixel in the whole image; -1 if none  */
};

#endif
