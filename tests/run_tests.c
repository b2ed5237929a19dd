/*
 * tests/run_tests.c -- runs every room's tests and prints "N passed, N failed".
 * Exit status 1 when anything failed. Run from the top of the repository (make test),
 * since tests read scenes/ and run the photon binary (environment PHOTON).
 * `run_tests ROOM...` runs only the named rooms (e.g. `run_tests trace cache`), for a
 * quicker loop while working on one of them.
 */
#include <string.h>

#include "check.h"
#include "tests.h"

struct room {
    const char *name;
    void (*run)(struct check *t);
};

static const struct room rooms[] = {
    {"base", test_base},         {"image", test_image},         {"compare", test_compare},
    {"plot", test_plot},         {"geom", test_geom},           {"scene", test_scene},
    {"brdf", test_brdf},         {"shapes", test_shapes},       {"import", test_import},
    {"photon", test_photon},     {"projection", test_projection}, {"trace", test_trace},
    {"precomputed", test_precomputed}, {"ppm", test_ppm},         {"cache", test_cache},
    {"render", test_render},
    {"pt", test_pt},             {"jensen1994", test_jensen1994}, {"jensen1996", test_jensen1996},
    {"report", test_report},     {"merge", test_merge},         {"cli", test_cli},
};

/* Whether the command line asks for room (no names: every room). */
static int wanted(const char *room, int argc, char **argv)
{
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], room) == 0)
            return 1;
    return argc < 2;
}

int main(int argc, char **argv)
{
    struct check t = {0, 0, 0, 0};
    for (size_t i = 0; i < sizeof rooms / sizeof rooms[0]; i++)
        if (wanted(rooms[i].name, argc, argv))
            rooms[i].run(&t);
    printf("%d passed, %d failed\n", t.passed, t.failed);
    return t.failed == 0 ? 0 : 1;
}
