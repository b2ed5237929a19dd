/*
 * photon/illumination_map.h -- illumination maps: irradiance stored as a texture over a
 * surface that can be parameterised (Arvo 1986), in the two levels of Jensen and
 * Christensen 1994, Sec. 3.2.
 *
 * A primitive whose surface has parameters (u, v) in [0, 1]^2 and an area for every
 * (u, v) rectangle (geometry_uv_area(): quads and spheres) gets a diffuse illumination
 * map, DI: a grid of elements over (u, v), holding the energy of the photons that are
 * not part of a caustic. "CI requires high precision while DI can use a much lower
 * precision since it is not seen directly by the eye", so each DI element may hold a
 * caustic sub-map, CI, of finer elements, created only when a
 * caustic photon first lands in it ("we avoid this problem by not creating the caustic
 * maps until caustics are actually occurring"). A photon's energy goes wholly to the
 * element holding its (u, v): the box kernel the paper used, whose noise it reports.
 * After the photons, illumination_maps_finish() divides every element's energy by its
 * area, which makes it irradiance (W / m^2 per channel in the scene's units).
 *
 * Resolutions. DI (departs from Sec. 3.2, which sizes DI by "the relative size with
 * respect to the light sources" without a rule): elements about
 * 1/ILLUMINATION_DI_PER_DIAGONAL of the scene's diagonal across along the surface's
 * parameter lines (geometry_uv_extent()), at most ILLUMINATION_MAX_SIDE along one.
 * Elements along a parameter line are equal in parameter, so a sphere's shrink towards
 * its poles. CI (Sec. 3.2: "determined by a simple pretracing of the scene ... the
 * distance between rays going through adjacent pixels and striking the same object"):
 * elements about the footprint the caller measured for the surface across, at most
 * ILLUMINATION_CI_MAX_SIDE to a DI element's side (256 times DI's elements; the paper
 * found "25-100 times" typical); a surface no pixel sees gets CI elements of DI's size.
 *
 * Saved (--save-photons, app/work_file.h), finished maps are these bytes, every number
 * lowest byte first and each irradiance the IEEE 754 bits of a double (base/binary.h):
 *
 *   bytes            field
 *   4                P, the primitives of the scene the maps were made for
 *   then P entries, primitive by primitive:
 *     1              1 when it has a DI map, 0 when not (nothing more)
 *     2, 2           res_u, res_v: DI elements along u and v, 1..ILLUMINATION_MAX_SIDE
 *     1              ci_side: a CI sub-map's elements along u and v, 1..ILLUMINATION_CI_MAX_SIDE
 *     24 res_u res_v the DI elements' irradiances, R G B, row by row (v the row)
 *     then for each DI element, in the same order:
 *       1            1 when it has a CI sub-map, 0 when not (nothing more)
 *       24 ci_side^2 the sub-map's elements' irradiances, R G B, row by row
 *
 * which is all a finished map holds, so maps read back answer every lookup as the maps
 * written did, bit for bit.
 */
#ifndef PHOTON_ILLUMINATION_MAP_H
#define PHOTON_ILLUMINATION_MAP_H

#include <stddef.h>

#include "../base/error.h"
#include "../base/vec3.h"
#include "../geom/geometry.h"

#define ILLUMINATION_DI_PER_DIAGONAL 64 /* DI element side: the scene's diagonal / 64    */
#define ILLUMINATION_CI_MAX_SIDE 16     /* a CI sub-map: at most 16 x 16 elements        */
#define ILLUMINATION_MAX_SIDE 1024      /* DI elements along one parameter, at most      */

struct illumination_maps;

/* What the maps hold, for --stats. */
struct illumination_stats {
    size_t n_maps;        /* primitives with a DI map                                   */
    size_t di_elements;   /* over all DI maps                                           */
    size_t ci_maps;       /* CI sub-maps created (DI elements a caustic reached)        */
    size_t bytes;
};

/* Empty maps for every primitive of g (built) that has surface parameters and can hold
 * photons (receives: one entry per primitive, nonzero where a photon can be stored, e.g.
 * not on a mirror; NULL: everywhere), with DI elements about diagonal /
 * ILLUMINATION_DI_PER_DIAGONAL across (diagonal > 0, finite) and CI elements about
 * footprint[prim] across (footprint: one entry per primitive, 0 for one no pixel sees;
 * NULL: CI elements of DI's size everywhere). */
struct illumination_maps *illumination_maps_create(const struct geometry *g, double diagonal,
                                                   const double *footprint,
                                                   const unsigned char *receives);
void illumination_maps_free(struct illumination_maps *maps); /* NULL is a no-op */

/* Whether primitive prim has a map (a photon landing on it belongs there). */
int illumination_covers(const struct illumination_maps *maps, int prim);

/* Adds a photon's energy (W per channel) at (u, v) of prim (covered): to its DI element,
 * or, for a caustic photon, to the CI element under (u, v), creating the sub-map. Before
 * illumination_maps_finish() only. */
void illumination_deposit(struct illumination_maps *maps, int prim, double u, double v,
                          struct vec3 energy, int caustic);

/* Turns every element's energy into irradiance: energy / the element's area on the
 * surface (geometry_uv_area()); elements of no area keep 0. Called once. */
void illumination_maps_finish(struct illumination_maps *maps, const struct geometry *g);

/* Irradiance at (u, v) of prim (covered), after illumination_maps_finish(): of the
 * caustic photons alone (the CI element; 0 where no caustic reached the DI element), or
 * of all photons (the DI element plus the CI element). */
struct vec3 illumination_irradiance(const struct illumination_maps *maps, int prim, double u,
                                    double v, int caustic_only);

struct illumination_stats illumination_maps_stats(const struct illumination_maps *maps);

struct binary_writer;
struct binary_reader;

/* Writes maps (finished) to w in the layout drawn above. */
void illumination_maps_write(const struct illumination_maps *maps, struct binary_writer *w);

/* Finished maps read from r in the layout drawn above. NULL with *err ("FILE: message"),
 * and nothing left allocated, when the file ends inside them or a side is out of range or
 * an irradiance is not finite or is negative (every count is checked against the bytes left before it is
 * allocated). */
struct illumination_maps *illumination_maps_read(struct binary_reader *r, struct error *err);

#endif
