/*
 * modes/ppm_radius.c -- the initial radius of a progressive estimate (see ppm_radius.h).
 *
 * R0 is a number of pixel footprints, the width a pixel covers at the surface's distance
 * along its eye path, d 2 tan(fov / 2) / height: so it scales with the scene (millimetres
 * or kilometres alike) and is the surface point's own, and a crop starts with the radii
 * the whole image has. Mirrors and lenses change a pixel's real footprint; this ignores
 * that, which only moves the start.
 *
 * Noise falls as the disc holds more photons, bias grows where the light changes within
 * it: where a wall meets the surface (a corner) or the surface ends (an open edge), no
 * photon lands in the part of the disc beyond it, though pi R^2 counts it. So R0 is
 * shortened until the disc lies on its surface: to the nearest wall that rays along the
 * tangent plane find, then halved until a surface lies under the rim of a disc twice as
 * wide (the light falls off towards an open edge over a disc's width).
 *
 * With --disc-coverage (--mode 2009) the estimate itself divides by the part of the disc
 * its surface covers, so corners and open edges do not darken it, and a short radius
 * would only cost noise. A wall is then a fault only where the surface goes on past it
 * (the ceiling inside a lamp's shroud, the floor under a ball): there the disc would take
 * photons from the far side, which the coverage counts as its own. So R0 stops short of
 * such walls alone, by a footprint more, since the pixel's later hit points, which share
 * its radius, lie up to about a footprint from the first.
 */
#include "ppm_radius.h"

#include "../photon/disc_coverage.h"

#define PPM_WALL_PROBES 8   /* tangent directions searched for a wall across the disc */
#define PPM_WALL_COS 0.5    /* a wall's normal is more than 60 degrees from the surface's */
#define PPM_WALL_RISE 0.125 /* wall probes run this part of R0 above the tangent plane */
#define PPM_WALL_FLOOR 0.25 /* the shortest fitted initial radius, in footprints     */

/* The radius r0, shortened to `margin` short of the nearest wall across the disc at s:
 * PPM_WALL_PROBES rays along the surface's tangent plane, each as long as the radius so
 * far and the margin. A wall is a surface turned more than 60 degrees from this one; a
 * surface that curves gently up to meet the ray (the inside of a sphere) is the same
 * surface, whose photons the disc rightly counts. With past_walls_only, a wall counts only
 * where the surface goes on beyond it, under the disc's rim in that direction. */
static double disc_clear_of_walls(const struct scene *scene, struct render_counters *counters,
                                  const struct surface *s, double r0, double margin,
                                  int past_walls_only)
{
    struct vec3 t, b;
    vec3_frame(s->ng, &t, &b);
    struct vec3 origin = vec3_madd(offset_origin(s->p, s->ng), s->ng, PPM_WALL_RISE * r0);
    double r = r0;
    for (int k = 0; k < PPM_WALL_PROBES; k++) {
        double phi = 2 * PI * k / PPM_WALL_PROBES;
        struct vec3 along = vec3_add(vec3_scale(t, cos(phi)), vec3_scale(b, sin(phi)));
        struct hit hit;
        counters->rays++;
        if (scene_intersect(scene, make_ray(origin, along), r + margin, &hit) &&
            fabs(vec3_dot(hit.ng, s->ng)) < PPM_WALL_COS &&
            (!past_walls_only || disc_probe(scene, s->p, s->ng, r0, 1.0, phi)))
            r = hit.t - margin;
    }
    return r;
}

double ppm_initial_radius(const struct scene *scene, const struct progressive_settings *ps,
                          int past_walls_only, struct render_counters *counters,
                          const struct surface *s, double distance)
{
    if (ps->radius > 0)
        return ps->radius;
    double footprint = distance * camera_footprint(&scene->camera);
    double r = ps->footprints * footprint;
    if (!ps->fit_radius)
        return r;
    double least = PPM_WALL_FLOOR * footprint;
    if (past_walls_only)
        return fmax(disc_clear_of_walls(scene, counters, s, r, footprint, 1), least);
    r = disc_clear_of_walls(scene, counters, s, r, 0.0, 0);
    while (r > least && !disc_rim_covered(scene, s->p, s->ng, 2 * r))
        r *= 0.5;
    return fmax(r, least);
}
