/*
 * photon/projection_map.h -- projection maps (Jensen and Christensen 1994, Sec. 3 and 3.1):
 * where photons leave the lights, which directions from there can reach an object, and
 * stratified emission over those directions, raised towards specular objects.
 *
 * Sec. 3: "rays are emitted from different positions on each light source. The number of
 * positions are determined by the size of the light source compared to the dimensions of
 * the scene. At each position a projection map is created", a (theta, phi) map "of the
 * hemisphere" in which "the directions containing specular and diffuse surfaces are
 * recorded", filled from each object's bounding sphere with "the maximum radius of the
 * circle" so that "nothing is missed". Emission uses "stratified sampling": directions
 * holding only diffuse objects get "a certain number of rays"; those holding specular
 * objects more, "raised based upon the specularity of the objects seen".
 *
 * Here (projection_map.c gives the geometry and the proofs):
 *   emission positions  a point light has one, its position; an area light is cut into
 *                       patches of equal area (a quad into a grid of parallelograms, a
 *                       triangle into n^2 triangles, a sphere into a z-phi grid), each
 *                       with its own map. A photon's origin is uniform over its patch,
 *                       so the light's area is sampled exactly.
 *   the map             n_theta x n_phi cells over the hemisphere about the patch's normal
 *                       (2 n_theta x n_phi over the whole sphere for a point light, theta
 *                       from +z, phi from +x towards +y), in equal steps of theta and
 *                       phi. A cell is marked when some object's bounding sphere, widened
 *                       so that the mark holds from every origin in the patch, may be
 *                       seen through it; it keeps the largest specularity s in [0, 1] of
 *                       the objects marked in it (0 when all are diffuse).
 *   emission            one distribution over the marked cells of every map of every
 *                       light: cell c of patch k of light l has probability
 *                         P_c = lum(Phi_l) a_k F_c (1 + boost s_c) / total,
 *                       a_k the patch's share of the light's area, F_c the exact share of
 *                       the patch's power leaving through c. Photon i of N takes the cell
 *                       at u = (i + xi) / N of the cumulative distribution (stratified),
 *                       its origin uniform in the patch and its direction by the light's
 *                       own emission density restricted to the cell. It carries
 *                         Phi_l a_k F_c / (P_c N)
 *                           = Phi_l total / (lum(Phi_l) (1 + boost s_c) N),
 *                       so the expected power through any direction of a marked cell is
 *                       exactly the light's.
 * Directions in unmarked cells are never emitted. That is exact only because nothing
 * lies there: a photon sent that way would leave the scene without being stored. A
 * marked cell is emitted into whole, including its directions that miss everything (the
 * bounding spheres' over-estimate, which the paper accepts: it costs photons, never
 * correctness).
 *
 * Departs from Sec. 3.1 where the paper gives no rule: the number of positions per light
 * (projection_map.c, PATCH_FRACTION), the specularity of a material (the reflectance of
 * its specular part, for materials with a delta lobe), and the raise, (1 + boost s).
 */
#ifndef PHOTON_PROJECTION_MAP_H
#define PHOTON_PROJECTION_MAP_H

#include <stddef.h>

#include "../scene/emit.h"
#include "../scene/scene.h"

/* Defaults for struct projection_settings. 32 x 64 cells over a hemisphere are steps of
 * 2.8 degrees in theta and 5.6 in phi: an object 15 degrees across covers a few tens of
 * cells with its outline, so the map stays tight around it, while a map has 2048 cells
 * (at most 48 kB). boost 4: a perfect mirror's directions get five times the photons per
 * unit of power of diffuse ones, each carrying a fifth of the power. The raise is
 * bounded so that specular objects cannot starve the rest: if they take a fifth of the
 * marked power, they get 5 x 0.2 / (5 x 0.2 + 0.8) = 56% of the photons and the diffuse
 * directions keep the other 44%. */
#define PROJECTION_N_THETA_DEFAULT 32
#define PROJECTION_N_PHI_DEFAULT 64
#define PROJECTION_BOOST_DEFAULT 4.0

/* Documented limit on n_theta * n_phi: 65536 cells per hemisphere. A marked cell costs 24
 * bytes and an unmarked one nothing, so a map holds at most 1.5 MB (3 MB for a point
 * light's sphere), and a light at most 128 of them (projection_map.c). Options refuse more
 * as absurd input before projection_maps_build() is called. */
#define PROJECTION_MAX_CELLS 65536

struct projection_settings {
    int n_theta;  /* rows of cells in theta over a hemisphere, >= 1; a point light's whole
                     sphere has 2 n_theta rows, so its cells are as large                */
    int n_phi;    /* columns of cells in phi around the axis, >= 1, and
                     n_theta n_phi <= PROJECTION_MAX_CELLS                                */
    double boost; /* the raise for specular directions: a cell of specularity s gets
                     photons in proportion to F (1 + boost s); finite, >= 0 (0: photons
                     in proportion to power, as light_emit() but only where they can hit) */
};

/* What the maps hold, for --stats. */
struct projection_stats {
    size_t n_maps;         /* emission positions (patches) over all lights              */
    size_t n_cells;        /* cells over all maps                                       */
    size_t n_marked;       /* of them, those through which some object may be seen     */
    size_t bytes;          /* memory the maps hold                                      */
    double marked_fraction; /* the share of the lights' power (luminance) that leaves
                              through marked cells: the photons' total, in [0, 1]       */
};

struct projection_maps;

/* Builds the maps of every light of scene (finished: its BVH built) with ps (checked by
 * the caller against the limits above: absurd values are refused where options are read).
 * Lights of zero power get no maps. Never fails (out of memory is fatal()); a scene with
 * nothing a light can reach gets maps with no marked cell, and projection_emit() then emits
 * nothing. Time: maps x primitives x the cells each primitive's cone covers
 * (src/modes/measured.md has a figure). An area light's own primitive is
 * left out of its maps (light leaves it and never comes back to it: it is flat or
 * convex). */
struct projection_maps *projection_maps_build(const struct scene *scene,
                                              const struct projection_settings *ps);
void projection_maps_free(struct projection_maps *pm); /* NULL is a no-op */

struct projection_stats projection_maps_stats(const struct projection_maps *pm);

/* Emits one photon through the maps of the scene they were built for, with five uniform
 * numbers in [0, 1): u[0] picks the cell (the caller stratifies it: (i + xi) / N for photon
 * i of N), u[1], u[2] the origin in the cell's patch, u[3], u[4] the direction in the cell.
 * Returns the emitting light's index and fills *e, whose weight here includes the choice
 * of light: of N photons emitted together from all lights, this one carries
 * Phi_l e->weight / N (Phi_l = light_power() of the returned light). Returns -1 (*e
 * unspecified) when no cell is marked: no photon can hit anything. */
int projection_emit(const struct projection_maps *pm, const struct scene *scene,
                    const double u[5], struct emission *e);

/* For checking a map against the scene: a point of map's patch (map < n_maps) from two
 * uniform numbers, as projection_emit() draws it, with its unit front normal (zero for a
 * point light), in e->origin and e->normal; e->dir and e->weight are left alone. */
void projection_origin(const struct projection_maps *pm, const struct scene *scene, size_t map,
                       const double u[2], struct emission *e);

/* The specularity (in [0, 1]) of the cell of map's map through which unit e->dir leaves
 * e->origin (a point of the patch, e->normal its normal as projection_origin() gives), or
 * -1 when the cell is not marked or e->dir is not in the map (behind an area light's
 * front): projection_emit() never sends a photon that way. */
double projection_specularity(const struct projection_maps *pm, size_t map,
                              const struct emission *e);

#endif
