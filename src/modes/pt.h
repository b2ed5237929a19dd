/*
 * modes/pt.h -- `--mode pt`: the unbiased path tracer, ground truth for every other mode.
 */
#ifndef PHOTON_PT_H
#define PHOTON_PT_H

#include "render.h"

struct render_result render_pt(const struct scene *scene, const struct render_settings *rs,
                               int want_variance, const struct checkpoint *checkpoint,
                               struct render_counters *counters);

#endif
