/*
 * tests/jensen1994_cases.c -- the renders of `--mode 1994` its tests make
 * (jensen1994_cases.h).
 */
#include "jensen1994_cases.h"

#include <string.h>

#include "files.h"
#include "truths.h"

/* A small photon map and small records: photons, gather_rays rays, one sample a pixel,
 * seed 1. */
struct j94_case j94_small_case(const char *path, int size, size_t photons, int gather_rays)
{
    struct j94_case c;
    c.path = path;
    c.size = size;
    c.spp = 1;
    c.seed = 1;
    c.window = NULL;
    c.js = jensen1994_settings_default();
    c.js.n_photons = photons;
    c.js.gather_rays = gather_rays;
    return c;
}

struct j94_run j94_render(const struct j94_case *c)
{
    struct j94_run run;
    memset(&run, 0, sizeof run);
    run.image = NULL;
    struct scene *scene = load_test_scene(c->path, c->size, c->size);
    if (scene == NULL)
        return run;
    struct render_settings rs = case_settings(scene, c->seed, c->spp, c->window);
    struct error err;
    struct render_result r = render_jensen1994(scene, &rs, &c->js, 0, &run.counters, &run.stats,
                                               &err);
    run.image = rendered_image(r, &err);
    scene_free(scene);
    return run;
}
