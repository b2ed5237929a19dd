/*
 * tests/run_tests.c -- runs every room's tests and prints "N passed, N failed".
 * Exit status 1 when anything failed. Run from the top of the repository (make test),
 * since tests read scenes/ and tests/data/ and run the photon binary (environment PHOTON).
 * `run_tests ROOM...` runs only the named rooms (e.g. `run_tests trace cache`), for a
 * quicker loop while working on one of them. The room spd runs only when named: it reads
 * the Standard Procedural Databases' files from the folder PHOTON_SPD (make test-spd).
 */
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "tests.h"

struct room {
    const char *name;
    void (*run)(struct check *t);
    int when_named; /* 1: not among "every room" (needs files from outside the repository) */
};

static const struct room rooms[] = {
    {"base", test_base, 0},       {"image", test_image, 0},         {"compare", test_compare, 0},
    {"compare_verdict", test_compare_verdict, 0},
    {"png", test_png, 0},       {"exr", test_exr, 0},         {"deflate", test_deflate, 0},
    {"convert", test_convert, 0},
    {"plot", test_plot, 0},       {"geom", test_geom, 0},
    {"geom_primitives", test_geom_primitives, 0}, {"bvh", test_bvh, 0},
    {"scene", test_scene, 0},
    {"brdf", test_brdf, 0},       {"brdf_glass", test_brdf_glass, 0},
    {"brdf_conventions", test_brdf_conventions, 0},
    {"shapes", test_shapes, 0},   {"shapes_heightfield", test_shapes_heightfield, 0},
    {"import", test_import, 0},   {"import_geom", test_import_geom, 0},
    {"import_obj", test_import_obj, 0},
    {"photon", test_photon, 0},   {"projection", test_projection, 0},
    {"projection_cells", test_projection_cells, 0},
    {"trace_emission", test_trace_emission, 0}, {"trace", test_trace, 0},
    {"trace_estimates", test_trace_estimates, 0},
    {"trace_photons_mode", test_trace_photons_mode, 0},
    {"ppm", test_ppm, 0},         {"cache", test_cache, 0},
    {"cache_lookup", test_cache_lookup, 0}, {"render", test_render, 0},
    {"pt", test_pt, 0},           {"error", test_error, 0},
    {"error_2009", test_error_2009, 0}, {"error_2008", test_error_2008, 0},
    {"error_photons", test_error_photons, 0},
    {"jensen1994", test_jensen1994, 0}, {"jensen1994_caustics", test_jensen1994_caustics, 0},
    {"jensen1996", test_jensen1996, 0}, {"report", test_report, 0}, {"merge", test_merge, 0},
    {"merge_work_file", test_merge_work_file, 0},
    {"progress", test_progress, 0},
    {"cli", test_cli, 0},         {"presets", test_presets, 0},     {"docs", test_docs, 0},
    {"precomputed", test_precomputed, 0}, {"paper", test_paper, 0},
    {"hit_points", test_hit_points, 0}, {"tte_fit", test_tte_fit, 0},
    {"switches", test_switches, 0}, {"ppm_departures", test_ppm_departures, 0},
    {"export", test_export, 0},   {"export_blender", test_export_blender, 0},
    {"export_output", test_export_output, 0}, {"help", test_help, 0},
    {"sppm", test_sppm, 0},       {"literal", test_literal, 0},
    {"outputs", test_outputs, 0},
    {"foreign_files", test_foreign_files, 0},
    {"numbers", test_numbers, 0}, {"number_syntax", test_number_syntax, 0},
    {"given_once", test_given_once, 0}, {"messages", test_messages, 0},
    {"sky", test_sky, 0},
    {"shading", test_shading, 0}, {"lens", test_lens, 0},
    {"spd", test_spd, 1},
};

/* Whether the command line asks for the room (no names: every room not run only by name). */
static int wanted(const struct room *room, int argc, char **argv)
{
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], room->name) == 0)
            return 1;
    return argc < 2 && !room->when_named;
}

/* Static, so that the summary printed at exit sees it even when a test ends the program. */
static struct check t;

static void summary_at_exit(void)
{
    check_summary(&t);
}

/* Whether every name on the command line is a room's (a misspelt one would run nothing). */
static int all_rooms_known(int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        size_t k = 0;
        while (k < sizeof rooms / sizeof rooms[0] && strcmp(argv[i], rooms[k].name) != 0)
            k++;
        if (k == sizeof rooms / sizeof rooms[0]) {
            fprintf(stderr, "run_tests: no room named '%s'\n", argv[i]);
            return 0;
        }
    }
    return 1;
}

int main(int argc, char **argv)
{
    if (!all_rooms_known(argc, argv))
        return 2;
    atexit(summary_at_exit);
    for (size_t i = 0; i < sizeof rooms / sizeof rooms[0]; i++)
        if (wanted(&rooms[i], argc, argv))
            rooms[i].run(&t);
    return t.failed == 0 ? 0 : 1;
}
