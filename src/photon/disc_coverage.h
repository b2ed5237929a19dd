/*
 * photon/disc_coverage.h -- how much of an estimate's disc lies on a surface that can hold
 * photons.
 *
 * A photon map's estimate divides the flux of the photons found within r of x by the
 * disc's area, pi r^2, which assumes that surface fills the disc. Where the disc reaches
 * past an open edge (the Cornell box's floor ends at the open front), past a corner into
 * a wall, or over a part of the surface where no photon is stored (the black emitter
 * under the light), photons can land on only part of it, and the estimate is dark there
 * by that part: half at an open edge. Dividing by the area the surface covers instead
 * needs that part; it is found here from the geometry, by probing, not from the photons,
 * whose own spread within the disc is also the light's (a shadow's edge).
 */
#ifndef PHOTON_DISC_COVERAGE_H
#define PHOTON_DISC_COVERAGE_H

#include "../scene/scene.h"
#include "estimate.h"

/* Probe rays of one coverage: DISC_RINGS rings of equal area, DISC_SPOKES points each. */
#define DISC_RINGS 4
#define DISC_SPOKES 8
/* The least coverage returned: an estimate is never divided by less than this share of
 * pi r^2, which bounds how far a wrong probe (a thin sliver of surface) can brighten it. */
#define DISC_COVERAGE_FLOOR 0.25
/* The disc's depth: surfaces, and photons, within DISC_DEPTH r of its plane are on it. A
 * sphere of radius R stays within it over a disc of radius sqrt(2 R DISC_DEPTH r), all of
 * the disc while r <= 2 R DISC_DEPTH (22 mm on the Cornell box's balls); a wall across
 * the disc puts photons in it only along a strip this deep. */
#define DISC_DEPTH 0.125
/* A surface turned less than 60 degrees from the disc's plane, either way, continues it. */
#define DISC_SAME_SURFACE_COS 0.5

/* The share of the disc of radius r > 0 around x, in the plane with unit normal n, over
 * which a surface that holds photons (trace.h: a non-delta part that reflects) lies within
 * DISC_DEPTH r of the plane, in [DISC_COVERAGE_FLOOR, 1]. At each of the DISC_RINGS x
 * DISC_SPOKES points q of the disc (the centres of equal-area cells, in a frame fixed by
 * n) a ray from DISC_DEPTH r above q along -n looks for such a surface down to as far
 * below, passing through mirrors and glass; a surface turned less than 60 degrees from the
 * plane, either way, counts, so a gently curved one (a sphere seen from a disc smaller
 * than itself) is the same surface. Deterministic: no random numbers. */
double disc_coverage(const struct scene *scene, struct vec3 x, struct vec3 n, double r);

/* Whether a surface that holds photons lies under the point of the disc of radius r > 0
 * around x (unit normal n) at distance r sqrt(u) from x and angle phi in a frame fixed by
 * n, found as disc_coverage() finds one: for u uniform in [0, 1) and phi in [0, 2 pi) the
 * point is uniform over the disc, so the share of such probes that find one estimates
 * the disc's coverage without bias (--mode 2009 spreads them over its passes). */
int disc_probe(const struct scene *scene, struct vec3 x, struct vec3 n, double r, double u,
               double phi);

/* As disc_probe(), and the point is not behind a wall: no surface turned 60 degrees or
 * more from the plane crosses the segment from x to the point, DISC_DEPTH r above the
 * plane. A disc that reaches past a wall finds the floor going on behind it, where no
 * photon of the hit point's side lands; counted as covered, it darkened the pixels along
 * closed-box's edges by 2-15% (--mode 2009 probes with this; the 2008 radius fit, which
 * looks for surface past a wall, with disc_probe()). */
int disc_probe_beside(const struct scene *scene, struct vec3 x, struct vec3 n, double r,
                      double u, double phi);

/* Whether a photon at `position`, arrived on a surface with unit normal `normal` on its
 * side, lies on the disc of radius r around x with unit normal n as the probes see the
 * disc: within DISC_DEPTH r of its plane, on a surface that continues the plane (turned
 * less than 60 degrees, facing the same way). The photons such a test keeps, over the
 * covered part of pi r^2, are an estimate that does not darken by the disc's edges. */
static inline int disc_holds_photon(struct vec3 x, struct vec3 n, double r,
                                    struct vec3 position, struct vec3 normal)
{
    return fabs(vec3_dot(vec3_sub(position, x), n)) <= DISC_DEPTH * r &&
           vec3_dot(normal, n) >= DISC_SAME_SURFACE_COS;
}

/* Whether a surface that holds photons lies under each of DISC_SPOKES points on the rim
 * of the disc of radius r > 0 around x (unit normal n), found as disc_coverage() finds
 * one. A disc that passes reaches past no open edge (a surface that just ends, as the
 * Cornell box's floor at its open front) on any of those spokes. */
int disc_rim_covered(const struct scene *scene, struct vec3 x, struct vec3 n, double r);

/* The irradiance estimate (estimate.h, irradiance_estimate(), without differential
 * checking: is->run 0) from the photons of the disc alone, over the part of it that can
 * hold them: of the is->n nearest photons, those within DISC_DEPTH r of the plane through
 * x with unit normal n that arrived from n's side (the rim photon left out with
 * is->exclude_rim), divided by pi r^2 disc_coverage(). Photons of another surface that
 * crosses the sphere of radius r, which Eq. 3 would count where they face n, are left
 * out as the coverage leaves out their part of the disc. nn: scratch, k_max >= is->n. */
struct vec3 covered_irradiance_estimate(const struct kdtree *map, const struct scene *scene,
                                        struct vec3 x, struct vec3 n,
                                        const struct irradiance_settings *is,
                                        struct nearest *nn);

#endif
