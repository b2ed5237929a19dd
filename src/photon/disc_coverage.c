/*
 * photon/disc_coverage.c -- the share of an estimate's disc that can hold photons
 * (disc_coverage.h).
 *
 * The probes sit at the centres of equal-area cells: ring i of DISC_RINGS at radius
 * r sqrt((i + 1/2) / DISC_RINGS), each ring's DISC_SPOKES points turned by half a step
 * from the ring inside it, so every probe stands for 1 / (rings x spokes) of pi r^2 and a
 * straight edge through x leaves half of them on each side. A probe starts r / 2 above
 * the plane, not on it, so that a surface that curves away below the plane (a sphere) or
 * rises a little above it is still found; it looks r deep, to r / 2 below the plane.
 * The test "turned less than 60 degrees, either way" is the 2008 mode's wall test
 * (ppm_radius.c, disc_clear_of_walls()), read the other way: there a surface turned more is
 * a wall that ends the disc; here one turned less continues it.
 */
#include "disc_coverage.h"

#include <assert.h>

#include "../scene/brdf.h"
#include "trace.h"

#define DISC_PROBE_HITS 4         /* surfaces a probe may meet: mirrors and glass it passes,
                                     one more where it stops                             */

/* Whether the probe ray from above point q finds a surface that holds photons within
 * depth of the plane. It passes through mirrors and glass (all-delta surfaces, which
 * photons leave at once: the floor under the glass ball, a hair's breadth below it,
 * holds the caustic), and stops at anything else. */
static int probe_finds_surface(const struct scene *scene, struct vec3 q, struct vec3 n,
                               double depth)
{
    struct ray ray = make_ray(vec3_madd(q, n, depth), vec3_neg(n));
    double left = 2 * depth;
    for (int k = 0; k < DISC_PROBE_HITS; k++) {
        struct hit hit;
        if (!scene_intersect(scene, ray, left, &hit))
            return 0;
        if (!brdf_is_delta(&scene->materials[hit.material]))
            return fabs(vec3_dot(hit.ng, n)) >= DISC_SAME_SURFACE_COS &&
                   photons_land_at(scene, &hit, ray.dir);
        left -= hit.t;
        ray = make_ray(offset_origin(hit.p, ray.dir), ray.dir);
    }
    return 0;
}

int disc_probe(const struct scene *scene, struct vec3 x, struct vec3 n, double r, double u,
               double phi)
{
    struct vec3 t, b;
    vec3_frame(n, &t, &b);
    double rho = r * sqrt(u);
    struct vec3 q = vec3_madd(vec3_madd(x, t, rho * cos(phi)), b, rho * sin(phi));
    return probe_finds_surface(scene, q, n, DISC_DEPTH * r);
}

int disc_probe_beside(const struct scene *scene, struct vec3 x, struct vec3 n, double r,
                      double u, double phi)
{
    if (!disc_probe(scene, x, n, r, u, phi))
        return 0;
    struct vec3 t, b;
    vec3_frame(n, &t, &b);
    double rho = r * sqrt(u);
    struct hit hit;
    struct ray across = make_ray(vec3_madd(x, n, DISC_DEPTH * r),
                                 vec3_add(vec3_scale(t, cos(phi)), vec3_scale(b, sin(phi))));
    return rho <= 0 || !(scene_intersect(scene, across, rho, &hit) &&
                         fabs(vec3_dot(hit.ng, n)) < DISC_SAME_SURFACE_COS);
}

double disc_coverage(const struct scene *scene, struct vec3 x, struct vec3 n, double r)
{
    int covered = 0;
    for (int i = 0; i < DISC_RINGS; i++)
        for (int j = 0; j < DISC_SPOKES; j++)
            covered += disc_probe(scene, x, n, r, (i + 0.5) / DISC_RINGS,
                                  2 * PI * (j + 0.5 * (i % 2)) / DISC_SPOKES);
    return fmax(DISC_COVERAGE_FLOOR, (double)covered / (DISC_RINGS * DISC_SPOKES));
}

int disc_rim_covered(const struct scene *scene, struct vec3 x, struct vec3 n, double r)
{
    for (int j = 0; j < DISC_SPOKES; j++)
        if (!disc_probe(scene, x, n, r, 1.0, 2 * PI * j / DISC_SPOKES))
            return 0;
    return 1;
}

struct vec3 covered_irradiance_estimate(const struct kdtree *map, const struct scene *scene,
                                        struct vec3 x, struct vec3 n,
                                        const struct irradiance_settings *is,
                                        struct nearest *nn)
{
    assert(is->run == 0);
    locate_photons(map, x, is->max_r2, is->n, nn);
    if (nn->found == 0 || !(nn->r2 > 0))
        return vec3_zero(); /* no photons, or all exactly at x: no area */
    int rim = is->exclude_rim && nn->found == is->n; /* as radiance_estimate() */
    double depth = DISC_DEPTH * sqrt(nn->r2);
    struct vec3 sum = vec3_zero();
    for (size_t i = 0; i < nn->found; i++) {
        const struct photon *p = nn->photon[i];
        if (rim && nn->d2[i] == nn->r2) {
            rim = 0;
            continue; /* it marks the radius */
        }
        struct vec3 offset = vec3_sub(photon_position(p), x);
        if (fabs(vec3_dot(offset, n)) <= depth && vec3_dot(photon_direction(p), n) > 0)
            sum = vec3_add(sum, photon_power(p));
    }
    double area = PI * nn->r2 * disc_coverage(scene, x, n, sqrt(nn->r2));
    return vec3_scale(sum, 1.0 / area);
}
