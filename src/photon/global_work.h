/*
 * photon/global_work.h -- the global work of a photon-map render: what a mode computes
 * before its final pass, the same whatever window is rendered.
 *
 * The photons, 1994 and 1996 modes trace their photon maps over the whole scene (1994
 * with --irradiance-store illumination its illumination maps too, sized by a pretrace
 * of the whole image), and 1994 and 1996 fill their irradiance cache in a pre-pass over
 * the whole image (modes/cache_pass.h), so that a crop equals the same window of the
 * whole render. Every tile of an image would repeat that work; this record lets it be
 * done once, saved (--save-photons, app/work_file.h) and loaded by every tile
 * (--load-photons).
 *
 * Life of a record: the caller zeroes it and hands it to the mode's render. Empty
 * (n_maps == 0), the mode builds its work into it; full (read from a file), the mode uses
 * what it holds instead. Either way the mode only borrows it, and the caller releases it
 * with global_work_free(). Which map is which is the mode's business (its render says).
 */
#ifndef PHOTON_GLOBAL_WORK_H
#define PHOTON_GLOBAL_WORK_H

#include <stddef.h>

#include "illumination_map.h"
#include "irradiance_cache.h"
#include "kdtree.h"

struct global_work {
    struct kdtree **maps;              /* owned array of n_maps, each map owned; an entry
                                          is NULL for a map the scene does not need (no
                                          caustic map without specular objects)          */
    size_t n_maps;                     /* 0: empty, for the mode to fill                 */
    struct irradiance_record *records; /* owned; the irradiance cache's records in the
                                          order irradiance_cache_copy_records() gives;
                                          NULL when n_records is 0                       */
    size_t n_records;
    struct illumination_maps *illumination; /* owned, finished: 1994's with
                                               --irradiance-store illumination; else NULL */
};

/* Makes room for n_maps maps, all NULL, in an empty record (n_maps >= 1). */
void global_work_add_maps(struct global_work *work, size_t n_maps);

/* Keeps a copy of the records of cache (which stays the caller's) in work. */
void global_work_keep_cache(struct global_work *work, const struct irradiance_cache *cache);

/* Adds work's records to cache (empty, made with the bounds and accuracy of the render
 * that saved them), so that it answers every lookup as that render's did. */
void global_work_fill_cache(const struct global_work *work, struct irradiance_cache *cache);

/* Releases what work owns and leaves it empty; an empty record is a no-op. */
void global_work_free(struct global_work *work);

#endif
