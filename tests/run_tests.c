/*
 * tests/run_tests.c -- runs every room's tests and prints "N passed, N failed".
 * Exit status 1 when anything failed. Run from the top of the repository (make test),
 * since tests read scenes/ and run the photon binary (environment PHOTON).
 */
#include "check.h"
#include "tests.h"

int main(void)
{
    struct check t = {0, 0, 0, 0};
    test_base(&t);
    test_image(&t);
    test_compare(&t);
    test_plot(&t);
    test_geom(&t);
    test_scene(&t);
    test_brdf(&t);
    test_shapes(&t);
    test_import(&t);
    test_photon(&t);
    test_trace(&t);
    test_projection(&t);
    test_ppm(&t);
    test_cache(&t);
    test_render(&t);
    test_pt(&t);
    test_jensen1996(&t);
    test_report(&t);
    test_cli(&t);
    printf("%d passed, %d failed\n", t.passed, t.failed);
    return t.failed == 0 ? 0 : 1;
}
