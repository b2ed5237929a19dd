/*
 * tests/test_cli.c -- the photon command as a user runs it: exit statuses, messages,
 * outputs that are whole or absent, determinism of the written file.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/image/image.h"
#include "files.h"
#include "option_words.h"
#include "tests.h"
#include "truths.h"

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

/* truth: the command-line contract (README): --help and --version exit 0; any bad
 *   option exits 2 with a one-line message, and so does an option that means nothing
 *   for the mode (the option table's modes, which --help prints).
 * catches: a bad value accepted (spp 0, a negative size), an unknown option ignored, an
 *   option of another mode silently ignored. */
static void test_options(struct check *t)
{
    CHECK(t, photon("--help all") == 0 && log_contains("--crop") && log_contains("--spp"));
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
             log_contains("-o: expected a file name ending in .pfm, .exr, .png or .ppm, "
                          "got 'out.jpg'"));
    CHECK(t, photon("-o .png scenes/cornell.scene") == 2 && log_contains("-o: expected"));
    CHECK(t, photon("-o out.PNG scenes/cornell.scene") == 2 && log_contains("-o: expected"));
    CHECK(t, photon("--crop 0 0 300 10 scenes/cornell.scene") == 2 && log_contains("--crop"));
    CHECK(t, photon("--crop 5 5 5 10 scenes/cornell.scene") == 2);
    CHECK(t, photon("--crop 5 5 0 10 scenes/cornell.scene") == 2 && log_contains("--crop"));
    CHECK(t, photon("--crop 0 0 0 0 scenes/cornell.scene") == 2 && log_contains("--crop"));
    CHECK(t, photon("--crop 0 10 4 0 scenes/cornell.scene") == 2 && log_contains("--crop"));
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
    CHECK(t, photon("--mode pt --passes 3 --gather 7 scenes/cornell.scene") == 2 &&
             log_contains("--passes: only for --mode 2008 or 2009 (this render is --mode pt)"));
    CHECK(t, photon("--gather 7 scenes/cornell.scene") == 2 &&
             log_contains("--gather: only for --mode photons, 1994 or 1996"));
    CHECK(t, photon("--cone 2 --mode 1994 scenes/cornell.scene") == 2 &&
             log_contains("--cone: only for --mode photons or 1996 (this render is --mode 1994)"));
    CHECK(t, photon("--mode 1994 --caustic-photons 5 scenes/cornell.scene") == 2 &&
             log_contains("--caustic-photons: only for --mode 1996"));
    CHECK(t, photon("--mode 2008 --irradiance-store photon scenes/cornell.scene") == 2 &&
             log_contains("--irradiance-store: only for --mode 1994"));
    CHECK(t, photon("--mode pt --save-photons w.work scenes/cornell.scene") == 2 &&
             log_contains("no global work to save"));
    CHECK(t, photon("--help all") == 0 && log_contains("2008, 2009: photon passes") &&
             log_contains("photons, 1994, 1996: photons emitted") &&
             log_contains("not with 2008 or 2009: also write each pixel's variance") &&
             log_contains("not with 2009: camera samples per pixel"));
    CHECK(t, photon("") == 2 && log_contains("no scene"));
    CHECK(t, photon("a.scene b.scene") == 2 && log_contains("more than one"));
}

/* truth: renders that cannot mean what they say are refused or named: a
 *   variance image of one sample a pixel (all zero) is refused; a scene with no light
 *   (scene.h: lights, emitters and the sky are all lights) renders black, and says so,
 *   while the Cornell box, lit, says nothing of it.
 * catches: the zero variance image written, the warning missing or given for a lit scene. */
static void test_meaningless_renders_named(struct check *t)
{
    CHECK(t, photon("--spp 1 --variance " OUT "_v.pfm --width 4 --height 4 -o " OUT
                    "_x.pfm scenes/cornell.scene") == 2 &&
             log_contains("--variance: needs --spp >= 2"));
    CHECK(t, !file_exists(OUT "_v.pfm"));
    write_text_file(OUT "_dark.scene", "image 4 4\ncamera 0 0 -5  0 0 0  0 1 0  40\n"
                                       "material w lambert 0.5 0.5 0.5\nsphere 0 0 0 1 w\n");
    CHECK(t, photon("--no-progress -o " OUT "_x.pfm " OUT "_dark.scene") == 0 &&
             log_contains("has no light (no light line, no emitting material, no "
                          "background): every mode renders it black"));
    CHECK(t, photon("--no-progress --width 4 --height 4 --spp 1 -o " OUT "_x.pfm "
                    "scenes/cornell.scene") == 0 && !log_contains("no light"));
    remove(OUT "_dark.scene");
    remove(OUT "_x.pfm");
    remove(OUT "_x.png");
}

/* truth: app/suggest.h's rule, worked by hand: --sp is 1 from --spp (an insertion), 2099 1
 *   from 2009 (a swap), comapre 1 from compare (a swap) and no file; --frobnicate and pt's
 *   slip ptt are near nothing (ptt is 1 from pt, whose 2 letters take no slip), and a
 *   scene file named like a command is still rendered as one (scenes/cornell.scene copied
 *   to merg, 1 from merge, in a folder of its own under build/).
 * catches: the suggestion missing, the wrong name suggested, a suggestion for a word near
 *   nothing, a file taken for a command. */
static void test_near_misses(struct check *t)
{
    CHECK(t, photon("--sp 4 scenes/cornell.scene") == 2 &&
             log_contains("unknown option '--sp' (did you mean '--spp'?)"));
    CHECK(t, photon("--mode 2099 scenes/cornell.scene") == 2 &&
             log_contains("unknown mode '2099' (did you mean '2009'?)"));
    CHECK(t, photon("comapre a.pfm b.pfm") == 2 &&
             log_contains("'comapre' is neither a scene file nor a command: did you mean "
                          "'photon compare'?"));
    CHECK(t, photon("--frobnicate scenes/cornell.scene") == 2 && !log_contains("did you mean"));
    CHECK(t, photon("--mode ptt scenes/cornell.scene") == 2 && !log_contains("did you mean"));
    char command[COMMAND_MAX];
    snprintf(command, sizeof command, "rm -rf " OUT "_dir && mkdir " OUT "_dir && cp "
             "scenes/cornell.scene " OUT "_dir/merg && p='%s' && case $p in /*) ;; *) "
             "p=$PWD/$p ;; esac && cd " OUT "_dir && \"$p\" --no-progress --width 4 --height 4 "
             "--spp 1 -o merg.pfm merg > merg.log 2>&1", photon_binary());
    CHECK(t, run_command(command) == 0);
    CHECK(t, run_command("rm -rf " OUT "_dir") == 0);
}

/* truth: an option given that does nothing with the others exits 2 with a message naming
 *   it and the setting that leaves it idle, and writes nothing (app/option_checks.c says
 *   why each is idle); each half alone is taken, and so is the idle option when the
 *   setting comes from --paper and the option is left to it.
 * catches: such a pair taken in silence, a refusal that also fires on one half, on a
 *   preset's or --paper's words, or on a value that still acts (caustic K > 0 with
 *   --radius, --adaptive above 4 samples, a checkpoint before the last pass). */
static void test_idle_options_refused(struct check *t)
{
    static const char *const idle[][2] = {
        {"--mode 1996 --disc-coverage --no-precomputed-irradiance",
         "--disc-coverage: does nothing with --no-precomputed-irradiance, which makes no "
         "records"},
        {"--mode 1996 --paper --disc-coverage",
         "--disc-coverage: does nothing with --no-precomputed-irradiance (from --paper)"},
        {"--mode 2008 --radius 2 --footprints 3",
         "--footprints: does nothing with --radius, which sets R0 in scene units"},
        {"--mode 2009 --fit-radius --radius 2", "--fit-radius: does nothing with --radius"},
        {"--mode 2008 --radius 2 --no-fit-radius --footprints 3", "--no-fit-radius: does"},
        {"--mode 1996 --cache-accuracy 0 --no-bounded-reach",
         "--no-bounded-reach: does nothing with --cache-accuracy 0, which keeps no"},
        {"--mode 1996 --gradient-limit --cache-accuracy 0",
         "--gradient-limit: does nothing with --cache-accuracy 0"},
        {"--mode 1996 --caustic-photons 0 --cone 2",
         "--cone: does nothing with --caustic-photons 0, which makes no caustic map"},
        {"--mode 1996 --caustic-photons 0 --caustic-gather 5",
         "--caustic-gather: does nothing with --caustic-photons 0"},
        {"--mode 1996 --caustic-radius-fraction 1 --caustic-photons 0",
         "--caustic-radius-fraction: does nothing with --caustic-photons 0"},
        {"--mode pt --spp 4 --adaptive 0.1", "--adaptive: does nothing with --spp 4, as no"},
        {"--mode direct --quality preview --adaptive 0.1",
         "--adaptive: does nothing with --spp 4 (from --quality preview)"},
        {"--mode 1996 --paper --spp 2 --specular-spp 4 --adaptive 0.1",
         "--adaptive: does nothing with --specular-spp 4"},
        {"--mode 2008 --passes 8 --checkpoint 8", "--checkpoint: does nothing with --passes 8,"},
        {"--mode 2009 --checkpoint 100000", "--checkpoint: does nothing with --passes "},
    };
    remove(OUT "_idle.pfm"); /* a run stopped before its end may have left them */
    remove(OUT "_idle.png");
    for (size_t i = 0; i < sizeof idle / sizeof idle[0]; i++) {
        char args[COMMAND_MAX];
        snprintf(args, sizeof args, "-o " OUT "_idle.pfm %s scenes/cornell.scene", idle[i][0]);
        int refused = photon(args) == 2 && log_contains(idle[i][1]);
        CHECK(t, refused && !file_exists(OUT "_idle.pfm") && !file_exists(OUT "_idle.png"));
        if (!refused)
            fprintf(stderr, "test_cli: not refused as expected: %s\n", idle[i][0]);
    }
    static const char *const taken[] = {
        "--mode 1996 --disc-coverage", "--mode 1996 --no-precomputed-irradiance",
        "--mode 1996 --no-precomputed-irradiance --no-disc-coverage", "--mode 1996 --paper",
        "--mode 2008 --footprints 3 --no-fit-radius", "--mode 2008 --paper --radius 2",
        "--mode 2009 --paper --radius 2 --disc-coverage",
        "--mode 2008 --radius 2 --caustic-footprints 3", "--mode 1996 --cache-accuracy 0",
        "--mode 1996 --paper --cache-accuracy 0", "--mode 1996 --caustic-photons 0",
        "--mode 1996 --caustic-photons 0 --one-map --cone 2 --caustic-gather 5",
        "--mode pt --spp 8 --adaptive 0.1", "--mode pt --spp 2 --specular-spp 8 --adaptive 0.1",
        "--mode 1996 --spp 1 --adaptive 0.1", "--mode 2008 --passes 8 --checkpoint 7",
    };
    struct options o;
    for (size_t i = 0; i < sizeof taken / sizeof taken[0]; i++)
        CHECK(t, options_of(taken[i], &o) == 0);
    CHECK(t, photon("-o " OUT "_idle.pfm --mode 2008 --no-progress --width 4 --height 4 --spp 1 "
                    "--passes 2 --photons-per-pass 500 --radius 2 scenes/cornell.scene") == 0 &&
             file_exists(OUT "_idle.pfm"));
    remove(OUT "_idle.pfm");
    remove(OUT "_idle.png");
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
    CHECK(t, !file_exists(OUT "_new.pfm") && no_temporaries(OUT "_new.pfm"));
    CHECK(t, !file_exists(OUT "_new.png") && no_temporaries(OUT "_new.png"));
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

/* Writes text to the scene file OUT_name.scene; its path goes to path[COMMAND_MAX]. */
static const char *scene_file(char *path, const char *name, const char *text)
{
    snprintf(path, COMMAND_MAX, OUT "_%s.scene", name);
    write_text_file(path, text);
    return path;
}

/* Whether "PHOTON --mode MODE SMALL SCENE -o OUT_x.pfm", SMALL one sample per pixel and
 * the mode's work cut short (truths.h), exits with status and leaves no image (when
 * status != 0) or one (when 0); the log then holds its stderr. */
static int mode_exits(const char *mode, const char *scene, int status)
{
    char command[COMMAND_MAX];
    remove(OUT "_x.pfm");
    snprintf(command, sizeof command, "--no-progress --mode %s --spp 1 %s %s -o " OUT "_x.pfm",
             mode, mode_work_options(mode), scene);
    int ran = photon(command);
    int written = file_exists(OUT "_x.pfm");
    remove(OUT "_x.pfm");
    remove(OUT "_x.png");
    remove(OUT "_x.ppm");
    return ran == status && written == (status == 0);
}

/* truth: the README's promise: no assertion is reachable from input. Each scene below once reached
 *   one: a light of 1e300 W (the photon record's power, photon.c), a mirror facing the
 *   camera squarely, so that a path comes back through the camera's own position (a
 *   cache record's r_min = 0, irradiance_cache.c), an object reaching past DBL_MAX (the
 *   cache's box, irradiance_cache.c). The first is refused at its line with the limit
 *   (scene.h's MAX_LIGHT_POWER) in every mode, the last at its line as beyond what
 *   double precision resolves (reach.h); the mirror renders.
 * tolerance: none.
 * catches: an abort (status 134) or a crash instead of a message, a partial output. */
static void test_no_assertion_reachable_from_scenes(struct check *t)
{
    static const char *modes[] = {"direct", "pt", "photons", "1994", "1996", "2008"};
    char bright[COMMAND_MAX], retro[COMMAND_MAX], wide[COMMAND_MAX];
    scene_file(bright, "bright",
               "image 8 8\ncamera 0 0 -5 0 0 0 0 1 0 40\n"
               "material w lambert 0.5 0.5 0.5\nsphere 0 0 0 1 w\n"
               "light point 0 0 -4 1e300 1e300 1e300\n");
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        CHECK(t, mode_exits(modes[m], bright, 2));
        CHECK(t, log_contains(OUT "_bright.scene:5: light: the lights' total power would "
                              "exceed 1e+30 W"));
    }
    scene_file(retro, "retro",
               "image 1 1\ncamera 0 0 0 0 0 1 0 1 0 40\n"
               "material w lambert 0.7 0.7 0.7\nmaterial m mirror 1 1 1\n"
               "quad -5 -5 0 -5 5 0 5 5 0 5 -5 0 w\n"
               "quad -5 -5 1 5 -5 1 5 5 1 -5 5 1 m\n"
               "light point 0 0 0.5 1 1 1\n");
    CHECK(t, mode_exits("1994", retro, 0));
    CHECK(t, mode_exits("1996", retro, 0));
    scene_file(wide, "wide",
               "image 4 4\ncamera 0 0 -5 0 0 0 0 1 0 40\n"
               "material w lambert 0.7 0.7 0.7\nsphere 0 0 0 1 w\n"
               "sphere 1.5e308 0 0 1e308 w\nlight point 0 3 -3 10 10 10\n");
    CHECK(t, mode_exits("1994", wide, 2) && log_contains(OUT "_wide.scene:5: reaches"));
    remove(bright);
    remove(retro);
    remove(wide);
}

#define TINY "--no-progress --width 4 --height 4 --spp 1"

/* truth: main.c's exit statuses: an output that cannot be created where it is to go (a
 *   missing directory, a path through a file) is bad input, found before the scene is
 *   read: status 2, the file named, nothing written; the same for each output of the
 *   render (-o, --variance, --report, --save-photons) and of merge -o, compare --diff,
 *   plot -o and probe -o (each given inputs that do not exist, so only a check made
 *   first names the output).
 * catches: the output's directory found missing only after the render (once exit 2 after
 *   all the work), a check that leaves its temporary behind or misses an output. */
static void test_unwritable_output_refused_at_once(struct check *t)
{
    static const char *commands[][2] = {
        {"-o /nonexistent/x.pfm build/no_such.scene", "/nonexistent/x.pfm: cannot create"},
        {"-o " OUT ".log/x.pfm build/no_such.scene", OUT ".log/x.pfm: cannot create"},
        {"-o " OUT "_x.pfm --variance /nonexistent/v.pfm build/no_such.scene",
         "/nonexistent/v.pfm: cannot create"},
        {"-o " OUT "_x.pfm --reference build/no_such.pfm --report /nonexistent/r.csv "
         "build/no_such.scene", "/nonexistent/r.csv: cannot create"},
        {"-o " OUT "_x.pfm --mode photons --save-photons /nonexistent/w build/no_such.scene",
         "/nonexistent/w: cannot create"},
        {"merge -o /nonexistent/x.pfm build/no_such.pfm", "/nonexistent/x.pfm: cannot create"},
        {"compare build/no_such.pfm build/no_such.pfm --diff /nonexistent/d.ppm",
         "/nonexistent/d.ppm: cannot create"},
        {"plot build/no_such.csv -o /nonexistent/p.svg", "/nonexistent/p.svg: cannot create"},
        {"probe build/no_such.scene --line 0 0 0 1 1 1 --samples 2 -o /nonexistent/p.csv",
         "/nonexistent/p.csv: cannot create"},
    };
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++) {
        remove(OUT "_x.pfm");
        CHECK(t, photon(commands[i][0]) == 2 && log_contains(commands[i][1]));
        CHECK(t, !file_exists(OUT "_x.pfm") && no_temporaries(OUT "_x.pfm"));
    }
}

/* Runs "PHOTON args" in a shell whose files may not grow past 2 KiB (ulimit -f 4, in
 * 512-byte blocks; SIGXFSZ ignored, so a longer write fails with EFBIG as on a full disk,
 * after the outputs' check, whose probes are a line each). */
static int photon_small_disk(const char *args)
{
    char command[COMMAND_MAX];
    snprintf(command, sizeof command, "sh -c \"trap '' XFSZ; ulimit -f 4; %s %s\" >%s 2>&1",
             photon_binary(), args, OUT ".log");
    return run_command(command);
}

/* truth: main.c's exit statuses and output.h's all or none: a write that fails after the
 *   work (the disk full for files over 2 KiB) is a machine failure, status 1, naming the
 *   file; and none of the command's outputs is left, neither the one that failed nor
 *   those written whole before it (the PFM, the PNG, the crop's record before the work
 *   file; the tile's PFM before merge's), nor a temporary.
 * catches: a failed write reported as bad input (status 2), a partial file left, the
 *   outputs written before the failure left in place (a PFM without its work file). */
static void test_failed_write_exits_1(struct check *t)
{
    static const char *const left[] = {"_full.pfm", "_full.png", "_full.pfm.window",
                                       "_full.work"};
    CHECK(t, photon("--no-progress --spp 1 --width 32 --height 32 --crop 0 0 32 32 -o " OUT
                    "_tile.pfm scenes/cornell.scene") == 0);
    static const char *const commands[][2] = {
        {TINY " --mode photons --photons 2000 --crop 0 0 4 4 --save-photons " OUT "_full.work"
         " -o " OUT "_full.pfm scenes/cornell.scene", OUT "_full.work: cannot write"},
        {"merge -o " OUT "_full.pfm " OUT "_tile.pfm", OUT "_full.pfm: cannot write"}};
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++) {
        CHECK(t, photon_small_disk(commands[i][0]) == 1 && log_contains(commands[i][1]));
        for (size_t k = 0; k < sizeof left / sizeof left[0]; k++) {
            char name[COMMAND_MAX];
            snprintf(name, sizeof name, OUT "%s", left[k]);
            CHECK(t, !file_exists(name) && no_temporaries(name));
        }
    }
    remove(OUT "_tile.pfm");
    remove(OUT "_tile.png");
    remove(OUT "_tile.pfm.window");
}

/* Whether the log holds only printable ASCII and line ends. */
static int log_is_text(void)
{
    char *log = read_text_file(OUT ".log");
    int text = log != NULL;
    for (const unsigned char *c = (const unsigned char *)log; text && *c != '\0'; c++)
        text = *c == '\n' || (*c >= 0x20 && *c < 0x7F);
    free(log);
    return text;
}

/* truth: base/error.h: a message that echoes input quotes its bytes outside printable
 *   ASCII as \xNN: a scene file's binary garbage (a terminal escape among it), a name of
 *   a missing file, an unknown option given on the command line.
 * catches: raw control bytes on the user's terminal (the escape turned it red). */
static void test_messages_quote_binary_input(struct check *t)
{
    static const unsigned char garbage[] = "sphere \x01\xff\x1b[31m 1 2\n";
    write_bytes_file(OUT "_garbage.scene", garbage, sizeof garbage - 1);
    CHECK(t, photon("-o " OUT "_x.pfm " OUT "_garbage.scene") == 2 && log_is_text() &&
             log_contains(OUT "_garbage.scene:1: sphere: '\\x01\\xff\\x1b[31m' is not a "
                          "number"));
    CHECK(t, photon("-o " OUT "_x.pfm 'build/no\033[31m.scene'") == 2 && log_is_text() &&
             log_contains("build/no\\x1b[31m.scene: cannot open"));
    CHECK(t, photon("'--\001' scenes/cornell.scene") == 2 && log_is_text() &&
             log_contains("unknown option '--\\x01'"));
    CHECK(t, !file_exists(OUT "_x.pfm"));
    remove(OUT "_garbage.scene");
}

/* truth: a file a scene names (include, obj, nff) that cannot be opened is reported at
 *   the line that names it, "scene:line: keyword: cannot open 'path': reason", the path
 *   as resolved beside the scene; status 2, no output.
 * catches: a message naming only the missing file (which scene, which line?). */
static void test_missing_named_file_names_its_line(struct check *t)
{
    static const char *lines[][2] = {
        /* the names are relative to the scene's directory, build/ */
        {"include test_cli_nothere.scene",
         "include: cannot open '" OUT "_nothere.scene': No such"},
        {"obj test_cli_nothere.obj w", "obj: cannot open '" OUT "_nothere.obj': No such"},
        {"nff test_cli_nothere.nff", "nff: cannot open '" OUT "_nothere.nff': No such"},
    };
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        char text[256], expected[256];
        snprintf(text, sizeof text, "camera 0 0 0 0 0 1 0 1 0 40\nmaterial w lambert 1 1 1\n"
                 "%s\n", lines[i][0]);
        write_text_file(OUT "_names.scene", text);
        snprintf(expected, sizeof expected, OUT "_names.scene:3: %s", lines[i][1]);
        CHECK(t, photon("-o " OUT "_x.pfm " OUT "_names.scene") == 2 &&
                 log_contains(expected));
        CHECK(t, !file_exists(OUT "_x.pfm"));
    }
    remove(OUT "_names.scene");
}

/* truth: same scene and seed give a bit-identical PFM (README); the
 *   written files are a valid PFM of the requested size with a PNG beside it; --stats
 *   prints the keys the issue names; compare of a file with itself is all zeros.
 * catches: time- or address-dependent results, a missing PNG, stats keys renamed. */
static void test_render_writes_deterministic_files(struct check *t)
{
    const char *args = "--width 24 --height 16 --spp 2 --stats scenes/cornell.scene";
    char command[COMMAND_MAX];
    snprintf(command, sizeof command, "-o " OUT "_a.pfm %s", args);
    CHECK(t, photon(command) == 0);
    static const char *keys[] = {"mode=pt", "seconds_total=", "seconds_build=", "rays=",
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

/* Whether every "key=value" line of the log has a key no other line has; counts the
 * lines in *n. */
static int stats_keys_unique(size_t *n)
{
    char *log = read_text_file(OUT ".log");
    int unique = log != NULL;
    *n = 0;
    for (char *line = log != NULL ? log : ""; *line != '\0';) {
        size_t length = strcspn(line, "\n"), key = strcspn(line, "=\n");
        if (key < length) {
            (*n)++;
            for (char *other = line + length; (other = strstr(other, "\n")) != NULL;) {
                other++;
                if (strncmp(other, line, key + 1) == 0) {
                    fprintf(stderr, "test_cli: --stats prints '%.*s' twice\n", (int)key, line);
                    unique = 0;
                }
            }
        }
        line += length + (line[length] == '\n');
    }
    free(log);
    return unique;
}

/* truth: --stats prints each key once (README, "Options": each key once), in every mode, and
 *   seconds_render is the whole render's time in every mode. bytes_peak, the allocation
 *   wrapper's high-water mark, is at least bytes_geometry, which geometry.c sums from its
 *   own arrays and which is held throughout the render.
 * tolerance: none.
 * catches: a mode's own figures printed under a key the common ones use (1994 and 1996
 *   once printed seconds_render twice, their final pass's under the whole render's key);
 *   bytes_peak missing in a mode, or counting nothing. */
static void test_stats_keys_once_in_every_mode(struct check *t)
{
    static const char *modes[] = {"direct", "pt", "photons", "1994", "1996", "2008"};
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        char command[COMMAND_MAX];
        snprintf(command, sizeof command, "--no-progress --stats --mode %s --width 16 "
                 "--height 16 --spp 2 %s scenes/cornell-specular.scene -o " OUT "_stats.pfm",
                 modes[m], mode_work_options(modes[m]));
        size_t n = 0;
        CHECK(t, photon(command) == 0 && log_contains("seconds_render="));
        CHECK(t, stats_keys_unique(&n) && n > 10);
        double geometry = file_stat(OUT ".log", "bytes_geometry");
        CHECK(t, geometry > 0 && file_stat(OUT ".log", "bytes_peak") >= geometry);
    }
    remove(OUT "_stats.pfm");
    remove(OUT "_stats.png");
}

/* The number --stats printed for key in the last command's log; -1 when it did not. */
static double logged_stat(const char *key)
{
    return file_stat(OUT ".log", key);
}

/* truth: render.h: in 1994 and 1996 a pixel in which the camera sees a light through
 *   mirrors or glass takes --specular-spp = 64 x --spp samples, every other --spp; the
 *   stats say both and how many pixels take the larger count (spp=16, specular_spp=1024,
 *   specular_pixels=N), and the mean they print must be the two counts' mix,
 *   (16 (1024 - N) + 1024 N) / 1024 on 32 x 32 pixels (to %.3f's rounding); a scene with
 *   nothing specular has no such pixel. The progress line names the two counts apart.
 * tolerance: 0.0005, half the last printed digit of samples_per_pixel.
 * catches: spp printed as the passes run (1024, the specular pixels' count), a count of
 *   specular pixels that is not the one the samples were taken for, a progress line
 *   saying "1024/1024 samples per pixel". */
static void test_specular_pixels_in_stats(struct check *t)
{
    static const char *modes[] = {"1994", "1996"};
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        char command[COMMAND_MAX];
        snprintf(command, sizeof command, "--progress --stats --mode %s --spp 16 --width 32 "
                 "--height 32 %s scenes/cornell-specular.scene -o " OUT "_spec.pfm",
                 modes[m], mode_work_options(modes[m]));
        CHECK(t, photon(command) == 0);
        double n = logged_stat("specular_pixels");
        CHECK(t, logged_stat("spp") == 16 && logged_stat("specular_spp") == 1024 && n > 0);
        double mean = (16 * (1024 - n) + 1024 * n) / 1024;
        CHECK_CLOSE(t, logged_stat("samples_per_pixel"), mean, 0.0005);
        CHECK(t, log_contains("16 samples per pixel, 1024 in the ") &&
                 !log_contains("/1024 samples per pixel"));
    }
    CHECK(t, photon("--no-progress --stats --mode 1994 --spp 16 --width 16 --height 16 "
                    "--photons 20000 --gather-rays 32 scenes/cornell.scene -o " OUT
                    "_spec.pfm") == 0);
    CHECK(t, logged_stat("spp") == 16 && logged_stat("specular_pixels") == 0 &&
             logged_stat("samples_per_pixel") == 16);
    remove(OUT "_spec.pfm");
    remove(OUT "_spec.png");
}

/* truth: an NFF file is a scene of its own (README, "Scene files"): photon renders it by its
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

/* truth: Sec. 4 (Hachisuka 2008): progressive photon mapping keeps only the hit points
 *   and one pass's photons, so its memory does not grow with the passes: 10 and 100
 *   passes of the same photons per pass hold the same peak, to the byte.
 * tolerance: none, byte counts.
 * catches: per-pass memory that is never freed or that accumulates (a list of passes,
 *   photons kept across passes, a leak in the pass loop). */
static void test_ppm_memory_does_not_grow_with_passes(struct check *t)
{
    double peak[2] = {-1, -2};
    static const int passes[2] = {10, 100};
    for (int i = 0; i < 2; i++) {
        char command[COMMAND_MAX];
        snprintf(command, sizeof command, "--no-progress --stats --mode 2008 --width 32 "
                 "--height 32 --photons-per-pass 1000 --passes %d scenes/cornell.scene "
                 "-o " OUT "_passes.pfm", passes[i]);
        CHECK(t, photon(command) == 0 && logged_stat("passes") == passes[i]);
        peak[i] = logged_stat("bytes_peak");
    }
    CHECK(t, peak[0] > 0 && peak[0] == peak[1]);
    remove(OUT "_passes.pfm");
    remove(OUT "_passes.png");
}

void test_cli(struct check *t)
{
    RUN_TEST(t, test_options);
    RUN_TEST(t, test_near_misses);
    RUN_TEST(t, test_meaningless_renders_named);
    RUN_TEST(t, test_idle_options_refused);
    RUN_TEST(t, test_bad_scene_leaves_no_output);
    RUN_TEST(t, test_no_assertion_reachable_from_scenes);
    RUN_TEST(t, test_unwritable_output_refused_at_once);
    RUN_TEST(t, test_failed_write_exits_1);
    RUN_TEST(t, test_messages_quote_binary_input);
    RUN_TEST(t, test_missing_named_file_names_its_line);
    RUN_TEST(t, test_render_writes_deterministic_files);
    RUN_TEST(t, test_stats_keys_once_in_every_mode);
    RUN_TEST(t, test_specular_pixels_in_stats);
    RUN_TEST(t, test_nff_file_is_a_scene);
    RUN_TEST(t, test_ppm_command);
    RUN_TEST(t, test_ppm_memory_does_not_grow_with_passes);
}
