/*
 * tests/test_cli.c -- the photon command as a user runs it: exit statuses, messages,
 * outputs that are whole or absent, determinism of the written file.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/image/image.h"
#include "files.h"
#include "tests.h"

#define COMMAND_MAX 1024
#define OUT "build/test_cli"

/* Runs "PHOTON args" with stdout and stderr captured in OUT.log; returns the exit status. */
static int photon(const char *args)
{
    return photon_logged("", args, OUT ".log");
}

/* Whether the captured output contains text. */
static int log_contains(const char *text)
{
    return file_contains(OUT ".log", text);
}

/* truth: the command-line contract (DESIGN.md): --help and --version exit 0; any bad
 *   option exits 2 with a one-line message.
 * catches: a bad value accepted (spp 0, a negative size), an unknown option ignored. */
static void test_options(struct check *t)
{
    CHECK(t, photon("--help") == 0 && log_contains("--crop") && log_contains("--spp"));
    CHECK(t, photon("--version") == 0 && log_contains("photon "));
    CHECK(t, photon("--frobnicate scenes/cornell.scene") == 2 && log_contains("unknown option"));
    CHECK(t, photon("--spp 0 scenes/cornell.scene") == 2 && log_contains("--spp"));
    CHECK(t, photon("--spp 1.5 scenes/cornell.scene") == 2);
    CHECK(t, photon("--width -3 scenes/cornell.scene") == 2);
    CHECK(t, photon("--width 100000 scenes/cornell.scene") == 2);
    CHECK(t, photon("--seed -1 scenes/cornell.scene") == 2);
    CHECK(t, photon("--seed 99999999999999999999999 scenes/cornell.scene") == 2);
    CHECK(t, photon("--mode nosuch scenes/cornell.scene") == 2 && log_contains("--mode"));
    CHECK(t, photon("-o out.jpg scenes/cornell.scene") == 2 &&
             log_contains("-o: expected a file name ending in .pfm, .png or .ppm, got 'out.jpg'"));
    CHECK(t, photon("-o .png scenes/cornell.scene") == 2 && log_contains("-o: expected"));
    CHECK(t, photon("-o out.PNG scenes/cornell.scene") == 2 && log_contains("-o: expected"));
    CHECK(t, photon("--crop 0 0 300 10 scenes/cornell.scene") == 2 && log_contains("--crop"));
    CHECK(t, photon("--crop 5 5 5 10 scenes/cornell.scene") == 2);
    CHECK(t, photon("--crop 1 2 3 scenes/cornell.scene") == 2);
    CHECK(t, photon("--mode 2008 --alpha 1 scenes/cornell.scene") == 2 &&
             log_contains("--alpha"));
    CHECK(t, photon("--mode 2008 --alpha 0 scenes/cornell.scene") == 2);
    CHECK(t, photon("--mode 2008 --passes 0 scenes/cornell.scene") == 2);
    CHECK(t, photon("--mode 2008 --width 4096 --height 4096 --spp 2 scenes/cornell.scene") == 2
             && log_contains("eye rays"));
    CHECK(t, photon("--mode 2008 --variance v.pfm scenes/cornell.scene") == 2 &&
             log_contains("--variance"));
    CHECK(t, photon("--spp 8 --specular-spp 4 scenes/cornell.scene") == 2 &&
             log_contains("--specular-spp"));
    CHECK(t, photon("--mode 2008 --specular-spp 64 scenes/cornell.scene") == 2 &&
             log_contains("--specular-spp"));
    CHECK(t, photon("") == 2 && log_contains("no scene"));
    CHECK(t, photon("a.scene b.scene") == 2 && log_contains("more than one"));
}

/* truth: bad input gets "file:line: message", exit status 2, and no output file: not
 *   created when absent, not truncated when present.
 * catches: an output opened before the scene is read, a partial file left behind. */
static void test_bad_scene_leaves_no_output(struct check *t)
{
    write_text_file(OUT "_bad.scene", "camera 0 0 0 0 0 1 0 1 0 40\nsphere 0 0 5 1 nosuch\n");
    remove(OUT "_new.pfm");
    CHECK(t, photon("-o " OUT "_new.pfm " OUT "_bad.scene") == 2);
    CHECK(t, log_contains(OUT "_bad.scene:2: sphere: undefined material 'nosuch'"));
    CHECK(t, !file_exists(OUT "_new.pfm") && !file_exists(OUT "_new.pfm.tmp"));
    CHECK(t, !file_exists(OUT "_new.png") && !file_exists(OUT "_new.png.tmp"));
    write_text_file(OUT "_old.pfm", "precious");
    CHECK(t, photon("-o " OUT "_old.pfm " OUT "_bad.scene") == 2);
    FILE *f = fopen(OUT "_old.pfm", "rb");
    char buffer[16] = {0};
    if (f != NULL) {
        CHECK(t, fread(buffer, 1, sizeof buffer - 1, f) == 8);
        fclose(f);
    }
    CHECK(t, strcmp(buffer, "precious") == 0);
    CHECK(t, photon("-o " OUT "_new.pfm build/no_such.scene") == 2 &&
             log_contains("build/no_such.scene: cannot open"));
    CHECK(t, photon("-o " OUT "_new.pfm scenes") == 2 && log_contains("scenes: "));
    CHECK(t, photon("-o build/no/such/dir/x.pfm --width 4 --height 4 scenes/cornell.scene")
                 == 2);
    remove(OUT "_bad.scene");
    remove(OUT "_old.pfm");
}

/* truth: same scene and seed give a bit-identical PFM (DESIGN.md, Determinism); the
 *   written files are a valid PFM of the requested size with a PNG beside it; --stats
 *   prints the keys the issue names; compare of a file with itself is all zeros.
 * catches: time- or address-dependent results, a missing PNG, stats keys renamed. */
static void test_render_writes_deterministic_files(struct check *t)
{
    const char *args = "--width 24 --height 16 --spp 2 --stats scenes/cornell.scene";
    char command[COMMAND_MAX];
    snprintf(command, sizeof command, "-o " OUT "_a.pfm %s", args);
    CHECK(t, photon(command) == 0);
    static const char *keys[] = {"mode=direct", "seconds_total=", "seconds_build=", "rays=",
                                 "objects=13", "bvh_nodes=", "bytes_geometry=", "width=24",
                                 "height=16", "spp=2", "seed=1"};
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
        CHECK(t, log_contains(keys[i]));
    snprintf(command, sizeof command, "-o " OUT "_b.pfm %s", args);
    CHECK(t, photon(command) == 0);
    CHECK(t, files_equal(OUT "_a.pfm", OUT "_b.pfm"));
    struct error err;
    struct image *img = pfm_read(OUT "_a.pfm", &err);
    CHECK(t, img != NULL && img->width == 24 && img->height == 16);
    image_free(img);
    CHECK(t, file_exists(OUT "_a.png") && !file_exists(OUT "_a.ppm"));
    CHECK(t, photon("compare " OUT "_a.pfm " OUT "_b.pfm") == 0 && log_contains("rmse=0 "));
    CHECK(t, photon("compare " OUT "_a.pfm scenes/cornell.scene") == 2);
    remove(OUT "_a.pfm");
    remove(OUT "_b.pfm");
    remove(OUT "_a.png");
    remove(OUT "_b.png");
    remove(OUT ".log");
}

/* truth: an NFF file is a scene of its own (README, "NFF files"): photon renders it by its
 *   .nff name, and a bad NFF line is reported as file:line with exit status 2 and no output.
 * catches: .nff files sent to the scene-file parser, an NFF error without its line. */
static void test_nff_file_is_a_scene(struct check *t)
{
    remove(OUT "_nff.pfm");
    CHECK(t, photon("-o " OUT "_nff.pfm --width 16 --height 16 --spp 1 "
                    "scenes/every-primitive.nff") == 0);
    CHECK(t, file_exists(OUT "_nff.pfm") && file_exists(OUT "_nff.png"));
    write_text_file(OUT "_bad.nff", "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 40\n"
                                    "hither 1\nresolution 8 8\nf 1 1 1 1 0 0 0 0\n"
                                    "s 0 0 0 1\ns 0 0 0 nan\n");
    remove(OUT "_bad_nff.pfm");
    CHECK(t, photon("-o " OUT "_bad_nff.pfm " OUT "_bad.nff") == 2);
    CHECK(t, log_contains(OUT "_bad.nff:10: s: number 'nan' is not finite"));
    CHECK(t, !file_exists(OUT "_bad_nff.pfm") && !file_exists(OUT "_bad_nff.png"));
    remove(OUT "_nff.pfm");
    remove(OUT "_nff.png");
    remove(OUT "_bad.nff");
}

/* truth: the 2008 mode's command line: it renders by name, with --checkpoint, and --stats
 *   prints its keys with the counts asked for (test_ppm.c checks the snapshots' timing).
 * catches: the mode not reachable by name, stats missing or miscounted. */
static void test_ppm_command(struct check *t)
{
    remove(OUT "_ppm.pfm");
    CHECK(t, photon("--mode 2008 -o " OUT "_ppm.pfm --width 8 --height 8 --passes 2 "
                    "--photons-per-pass 1000 --checkpoint 1 --stats scenes/cornell.scene")
                 == 0);
    CHECK(t, file_exists(OUT "_ppm.pfm") && file_exists(OUT "_ppm.png"));
    static const char *keys[] = {"mode=2008", "hit_points=", "bytes_per_hit_point=",
                                 "passes=2", "photons_emitted=2000", "mean_radius=", "spp=16"};
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
        CHECK(t, log_contains(keys[i]));
    remove(OUT "_ppm.pfm");
    remove(OUT "_ppm.png");
}

/* Whether the file's first bytes are those of prefix (its '\0' excluded). */
static int starts_with(const char *name, const char *prefix)
{
    char bytes[64] = {0};
    size_t n = strlen(prefix);
    FILE *f = fopen(name, "rb");
    size_t got = f != NULL && n < sizeof bytes ? fread(bytes, 1, n, f) : 0;
    if (f != NULL)
        fclose(f);
    return got == n && memcmp(bytes, prefix, n) == 0;
}

/* Removes the files a render to OUT_NAME may leave: .pfm, .png, .ppm and their temporaries. */
static void remove_outputs(const char *name)
{
    static const char *const endings[] = {".pfm", ".png", ".ppm", ".pfm.tmp", ".png.tmp",
                                          ".ppm.tmp", ".png.pfm", ".ppm.pfm"};
    for (size_t i = 0; i < sizeof endings / sizeof endings[0]; i++) {
        char file[COMMAND_MAX];
        snprintf(file, sizeof file, "%s%s", name, endings[i]);
        remove(file);
    }
}

/* truth: the naming rule of -o (options.h, read_output): NAME.pfm is always written, and
 *   beside it NAME.png, or NAME.ppm when -o names one; nothing else. --checkpoint's
 *   snapshots and photon merge follow the same rule. The PFM does not depend on -o's ending.
 * catches: the display image written over the PFM (x.png holding a PFM), a PNG written
 *   besides the PPM asked for, a snapshot or a merge ignoring the ending, x.png.pfm. */
static void test_output_names(struct check *t)
{
    const char *args = "--width 12 --height 8 --spp 1 scenes/cornell.scene";
    char command[COMMAND_MAX];
    remove_outputs(OUT "_name");
    snprintf(command, sizeof command, "-o " OUT "_name.png %s", args);
    CHECK(t, photon(command) == 0);
    CHECK(t, file_exists(OUT "_name.pfm") && file_exists(OUT "_name.png"));
    CHECK(t, !file_exists(OUT "_name.ppm") && !file_exists(OUT "_name.png.pfm"));
    CHECK(t, starts_with(OUT "_name.png", "\211PNG\r\n\032\n") &&
             starts_with(OUT "_name.pfm", "PF\n"));
    rename(OUT "_name.pfm", OUT "_png.pfm");
    remove(OUT "_name.png");
    snprintf(command, sizeof command, "-o " OUT "_name.ppm %s", args);
    CHECK(t, photon(command) == 0);
    CHECK(t, file_exists(OUT "_name.pfm") && file_exists(OUT "_name.ppm"));
    CHECK(t, !file_exists(OUT "_name.png") && starts_with(OUT "_name.ppm", "P6\n12 8\n255\n"));
    CHECK(t, files_equal(OUT "_name.pfm", OUT "_png.pfm"));
    remove_outputs(OUT "_name");
    CHECK(t, photon("--mode 2008 -o " OUT "_name.ppm --width 8 --height 8 --passes 2 "
                    "--photons-per-pass 1000 --checkpoint 1 scenes/cornell.scene") == 0);
    CHECK(t, file_exists(OUT "_name.ppm") && !file_exists(OUT "_name.png"));
    remove_outputs(OUT "_name");
    CHECK(t, photon("--crop 0 0 12 8 -o " OUT "_tile.png --width 12 --height 8 --spp 1 "
                    "scenes/cornell.scene") == 0);
    CHECK(t, file_exists(OUT "_tile.pfm.window") && !file_exists(OUT "_tile.png.window"));
    CHECK(t, photon("merge -o " OUT "_name.ppm " OUT "_tile.pfm") == 0);
    CHECK(t, files_equal(OUT "_name.pfm", OUT "_png.pfm") && file_exists(OUT "_name.ppm") &&
             !file_exists(OUT "_name.png"));
    CHECK(t, photon("merge -o " OUT "_name.png " OUT "_tile.pfm") == 0);
    CHECK(t, files_equal(OUT "_name.png", OUT "_tile.png"));
    CHECK(t, photon("merge -o " OUT "_name.jpg " OUT "_tile.pfm") == 2 &&
             log_contains("-o: expected a file name ending in .pfm, .png or .ppm"));
    remove_outputs(OUT "_name");
    remove_outputs(OUT "_png");
    remove_outputs(OUT "_tile");
    remove(OUT "_tile.pfm.window");
}

/* truth: with no -o the PFM is named for the scene, without its directory (README), and
 *   the PNG is beside it. Run inside build/ so the files land there.
 * catches: the default naming the PPM, or the PNG put beside the scene file. */
static void test_default_output_names(struct check *t)
{
    const char *binary = photon_binary();
    char command[COMMAND_MAX];
    remove("build/cornell.pfm");
    remove("build/cornell.png");
    snprintf(command, sizeof command, "cd build && %s%s --width 4 --height 4 --spp 1 "
             "../scenes/cornell.scene > /dev/null 2>&1", binary[0] == '/' ? "" : "../", binary);
    CHECK(t, run_command(command) == 0);
    CHECK(t, file_exists("build/cornell.pfm") && file_exists("build/cornell.png"));
    CHECK(t, !file_exists("build/cornell.ppm") && !file_exists("scenes/cornell.png"));
    remove("build/cornell.pfm");
    remove("build/cornell.png");
}

/* truth: outputs are whole or absent (DESIGN.md). Where the PNG cannot be put (its name
 *   is a directory, so the rename of NAME.png.tmp fails after every byte was written), the
 *   render fails with the PNG's name in the message and leaves no NAME.png.tmp; the PFM
 *   was written first, and whole.
 * catches: a failed display write reported as success, its temporary left behind. */
static void test_failed_png_leaves_nothing(struct check *t)
{
    remove_outputs(OUT "_dir");
    CHECK(t, run_command("mkdir -p " OUT "_dir.png") == 0);
    CHECK(t, photon("-o " OUT "_dir.png --width 4 --height 4 --spp 1 scenes/cornell.scene")
                 == 2);
    CHECK(t, log_contains(OUT "_dir.png: cannot write output file"));
    CHECK(t, !file_exists(OUT "_dir.png.tmp") && run_command("test -d " OUT "_dir.png") == 0);
    struct error err;
    struct image *img = pfm_read(OUT "_dir.pfm", &err);
    CHECK(t, img != NULL && img->width == 4 && img->height == 4);
    image_free(img);
    CHECK(t, run_command("rmdir " OUT "_dir.png") == 0);
    remove_outputs(OUT "_dir");
}

void test_cli(struct check *t)
{
    RUN_TEST(t, test_options);
    RUN_TEST(t, test_bad_scene_leaves_no_output);
    RUN_TEST(t, test_render_writes_deterministic_files);
    RUN_TEST(t, test_nff_file_is_a_scene);
    RUN_TEST(t, test_ppm_command);
    RUN_TEST(t, test_output_names);
    RUN_TEST(t, test_default_output_names);
    RUN_TEST(t, test_failed_png_leaves_nothing);
}
