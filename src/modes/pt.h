/*
 * modes/pt.h -- `--mode pt`: the unbiased path tracer, ground truth for every other mode.
 */
#ifndef PHOTON_PT_H
#define PHOTON_PT_H

#include "render.h"

/* Whether the scene has something specular (a material with a delta lobe), so that light
 * reaching a diffuse surface by way of mirrors or glass (caustics) is found only when a
 * path sampled from that surface happens to meet an area light through them: rarely, and
 * at a few dozen samples a pixel so rarely that no spread of them states it (the error
 * bound misses there: reference/suite.md's calibration). */
int pt_finds_caustics_by_chance(const struct scene *scene);

/* The first point light whose caustics pt cannot find, or -1: with something specular in
 * the scene (a material with a delta lobe), light from a point light that reaches a
 * diffuse surface only by way of mirrors or glass is found neither by a light sample
 * (the shadow ray stops at the glass) nor by a sampled direction (a point has no area):
 * probability zero, so those caustics are missing from pt's image, however long it runs
 * (the photon modes find them). */
int pt_unreachable_light(const struct scene *scene);

struct render_result render_pt(const struct scene *scene, const struct render_settings *rs,
                               int want_variance, const struct checkpoint *checkpoint,
                               struct render_counters *counters);

#endif
