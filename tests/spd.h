/*
 * tests/spd.h -- Eric Haines' Standard Procedural Databases (SPD 3.14, NFF files) in the
 * tests: where the files are, what a file must load as, its spheres, and the figures kept
 * of files the repository does not hold.
 *
 * Three small files are in tests/data/spd/ (tests/data/README.md: source, licence,
 * SHA-256). The whole set of 22 is read from the folder named by the environment variable
 * PHOTON_SPD, only by the room spd (make test-spd SPD=DIR).
 */
#ifndef PHOTON_TEST_SPD_H
#define PHOTON_TEST_SPD_H

#include <stddef.h>
#include <stdint.h>

#include "../src/geom/ray.h"
#include "check.h"

#define SPD_DATA "tests/data/spd" /* from the top of the repository, where tests run */

/* balls-s4.nff (`balls -s 4`, 305,317 bytes, SHA-256 ca955919...8be9b4): its 7,381 "s"
 * lines summed by spheres_digest(). Computed once from the file by reading each line's
 * four numbers as doubles and following spheres_digest() in Python (its "%g" is C's):
 *   sum(fnv1a64(" ".join("%g" % (0.0 if abs(v) < 1e-12 else v) for v in line)))
 *   modulo 2^64, over the file's s lines. test_spd.c checks it against the file. */
#define BALLS_S4_SPHERES 7381
#define BALLS_S4_SPHERE_DIGEST UINT64_C(0xe9400b4b2654f297)

/* The folder named by PHOTON_SPD, or NULL when it is not set or empty. */
const char *spd_folder(void);

/* An SPD file's `v` and `b` lines, as its generator printed them. */
struct spd_view {
    struct vec3 from, at, up;
    double angle;
    int width, height;
    struct vec3 background;
};

/* The view each generator writes (it does not depend on the size factor). */
enum spd_generator {
    SPD_BALLS, SPD_GEARS, SPD_MOUNT, SPD_RINGS, SPD_TETRA, SPD_TREE, SPD_TEAPOT,
    SPD_LATTICE, SPD_SHELLS, SPD_JACKS, SPD_SOMBRERO
};
extern const struct spd_view spd_views[];

/* What one SPD file must load as. */
struct spd_census {
    const char *file;         /* the name in its folder, e.g. "balls-s4.nff"                 */
    size_t prims;             /* spheres + cones + sum over polygons of (vertices - 2)        */
    size_t lights;
    size_t materials;         /* distinct `f` lines                                           */
    enum spd_generator view;
};

/* Loads folder/file with our NFF reader and checks primitives, lights, materials, view
 * and background against c; a file that does not load is one failed check, its error
 * printed. */
void check_spd_census(struct check *t, const char *folder, const struct spd_census *c);

/* The "s x y z r" lines of an NFF file as x, y, z, r (4 doubles a sphere, malloc'd, the
 * caller frees), their number in *n; NULL when the file cannot be read. */
double *nff_spheres(const char *path, size_t *n);

/* Our sphere flake placed as balls.c places it (centre 0, radius 0.5, axis +z) at levels
 * (balls -s levels), as x, y, z, r like nff_spheres(). */
double *balls_spheres(int levels, size_t *n);

/* Checks that ours and printed (an NFF file's spheres) are the same set within what %g's
 * six significant digits allow: equal counts, each printed sphere matching exactly one of
 * ours. */
void check_same_spheres(struct check *t, const double *ours, size_t n_ours,
                        const double *printed, size_t n_printed);

/* An order-free digest of spheres as a generator prints them: FNV-1a 64 of each sphere's
 * text "%g %g %g %g" (x, y, z, r; values under 1e-12 in size written as 0, since the
 * generator prints rounding noise such as 1.11022e-16 where ours may be exactly 0), the
 * hashes summed modulo 2^64. */
uint64_t spheres_digest(const double *spheres, size_t n);

#endif
