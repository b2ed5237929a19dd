/*
 * tests/test_spd.c -- the spd room: our NFF reader (scene/nff.c) and sphere flake
 * (geom/sphereflake.c) against all 22 files of Eric Haines' Standard Procedural Databases,
 * read from the folder PHOTON_SPD. Not among "every room": `make test-spd SPD=DIR` runs
 * it (run_tests spd). The same truths for the files the repository keeps, and figures for
 * the rest, are in test_import.c and test_shapes.c, which `make test` runs.
 *
 * Truths: the files' census (entity counts, views), counted when the files were made by a
 * strict line-by-line reader that is not ours; balls-s4.nff's spheres as Haines' balls.c
 * printed them.
 */
#include <stdio.h>

#include "../src/base/alloc.h"
#include "spd.h"
#include "tests.h"

/* truth: the census of the 22 files (that reader's table, recounted by a separate
 *   script): prims = s + c + sum over p and pp of (vertices - 2); every pp is a triangle,
 *   gears' "more" polygons have 144 vertices; materials are the distinct `f` lines (by
 *   the script); lights the `l` lines; views and backgrounds as printed.
 * tolerance: none, counts and printed numbers.
 * catches: the one-line `c` swallowing the next entities, the polygon count broken on
 *   any of the shapes the generators write, lights dropped, materials not shared, view
 *   lines read into the wrong fields, a file that no longer loads. */
static void test_spd_census(struct check *t)
{
    static const struct spd_census files[] = {
        {"balls-s2.nff", 91 + 2, 3, 2, SPD_BALLS},
        {"balls-s3.nff", 820 + 2, 3, 2, SPD_BALLS},
        {"balls-s4.nff", 7381 + 2, 3, 2, SPD_BALLS},
        {"mount-s4.nff", 4 + 512, 1, 2, SPD_MOUNT},
        {"mount-s6.nff", 4 + 8192, 1, 2, SPD_MOUNT},
        {"mount-s8.nff", 4 + 131072, 1, 2, SPD_MOUNT},
        {"gears-s3.nff", 3889 * 2 + 54 * 142, 5, 27, SPD_GEARS},
        {"gears-s4.nff", 9217 * 2 + 128 * 142, 5, 63, SPD_GEARS},
        {"rings-s3.nff", 420 + 420 + 2, 3, 7, SPD_RINGS},
        {"rings-s4.nff", 900 + 900 + 2, 3, 7, SPD_RINGS},
        {"rings-s7.nff", 4200 + 4200 + 2, 3, 7, SPD_RINGS},
        {"tetra-s5.nff", 1024, 1, 1, SPD_TETRA},
        {"tetra-s6.nff", 4096, 1, 1, SPD_TETRA},
        {"tree-s5.nff", 63 + 63 + 2, 7, 2, SPD_TREE},
        {"tree-s11.nff", 4095 + 4095 + 2, 7, 2, SPD_TREE},
        {"tree-s14.nff", 32767 + 32767 + 2, 7, 2, SPD_TREE},
        {"teapot-s3.nff", 9 * 2 + 552, 2, 3, SPD_TEAPOT},
        {"teapot-s12.nff", 144 * 2 + 9120, 2, 3, SPD_TEAPOT},
        {"lattice-s6.nff", 343 + 882, 6, 4, SPD_LATTICE},
        {"shells-s4.nff", 2881, 1, 1, SPD_SHELLS},
        {"jacks-s4.nff", 3510 + 1755, 1, 1, SPD_JACKS},
        {"sombrero-s2.nff", 7938, 1, 1, SPD_SOMBRERO},
    };
    const char *folder = spd_folder();
    REQUIRE(t, folder != NULL);
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++)
        check_spd_census(t, folder, &files[i]);
}

/* Reads folder/balls-s4.nff's spheres; NULL when there is no such file. */
static double *balls_s4_printed(size_t *n)
{
    char path[1024];
    const char *folder = spd_folder();
    if (folder == NULL || snprintf(path, sizeof path, "%s/balls-s4.nff", folder) >= 1024)
        return NULL;
    return nff_spheres(path, n);
}

/* truth: Haines' own output, balls-s4.nff (balls.c at size factor 4): 7381 spheres,
 *   centres and radii printed with %g.
 * tolerance: the printing's, 5e-6 relative per number; matched as a set (spd.c).
 * catches: what test_sphereflake_is_balls_s3 catches, at the level SPD benchmarks use. */
static void test_sphereflake_is_balls_s4(struct check *t)
{
    size_t n_printed, n_ours;
    double *printed = balls_s4_printed(&n_printed);
    REQUIRE(t, printed != NULL);
    double *ours = balls_spheres(4, &n_ours);
    check_same_spheres(t, ours, n_ours, printed, n_printed);
    xfree(ours);
    xfree(printed);
}

/* truth: balls-s4.nff itself: the figures spd.h keeps of it (written down once from the
 *   file) are what this file gives.
 * catches: figures copied wrong, a different file in PHOTON_SPD, the digest's text or
 *   rounding rule changed on one side only. */
static void test_balls_s4_figures(struct check *t)
{
    size_t n;
    double *printed = balls_s4_printed(&n);
    REQUIRE(t, printed != NULL);
    CHECK(t, n == BALLS_S4_SPHERES);
    CHECK(t, spheres_digest(printed, n) == BALLS_S4_SPHERE_DIGEST);
    xfree(printed);
}

void test_spd(struct check *t)
{
    if (spd_folder() == NULL)
        fprintf(stderr, "spd: PHOTON_SPD is not set: give it a folder of the SPD .nff files "
                        "(make test-spd SPD=DIR)\n");
    RUN_TEST(t, test_spd_census);
    RUN_TEST(t, test_sphereflake_is_balls_s4);
    RUN_TEST(t, test_balls_s4_figures);
}
