/*
 * photon/global_work.c -- the global work of a photon-map render (global_work.h).
 */
#include "global_work.h"

#include <assert.h>

#include "../base/alloc.h"

void global_work_add_maps(struct global_work *work, size_t n_maps)
{
    assert(work->n_maps == 0 && n_maps >= 1);
    work->maps = xcalloc(n_maps, sizeof *work->maps, "photon maps");
    work->n_maps = n_maps;
}

void global_work_keep_cache(struct global_work *work, const struct irradiance_cache *cache)
{
    assert(work->records == NULL);
    work->n_records = irradiance_cache_records(cache);
    if (work->n_records > 0) {
        work->records = xmalloc(work->n_records, sizeof *work->records, "cache records");
        irradiance_cache_copy_records(cache, work->records);
    }
}

void global_work_fill_cache(const struct global_work *work, struct irradiance_cache *cache)
{
    for (size_t i = 0; i < work->n_records; i++)
        irradiance_cache_add(cache, &work->records[i]);
}

void global_work_free(struct global_work *work)
{
    for (size_t i = 0; i < work->n_maps; i++)
        kdtree_free(work->maps[i]);
    xfree(work->maps);
    xfree(work->records);
    illumination_maps_free(work->illumination);
    work->maps = NULL;
    work->n_maps = 0;
    work->records = NULL;
    work->n_records = 0;
    work->illumination = NULL;
}
