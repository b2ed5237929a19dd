/*
 * tests/test_foreign_files.c -- the files beside a command's outputs that photon did not
 * make: a user's file where a temporary might go, a scene or a directory named like a crop
 * record, the previous outputs a failed publish must give back, another run writing the
 * same -o, a signal at any moment, and FIFOs wherever a file is read or written. photon
 * writes and removes only what it made (base/output.h, base/undo.h, app/tile.h), and waits
 * for no FIFO (base/input.h).
 */
#include <signal.h>
#include <stdio.h>
#include <string.h>

#include "../src/base/output.h"
#include "files.h"
#include "tests.h"

#define COMMAND_MAX 4096
#define OUT "build/test_foreign"
#define TINY "--no-progress --width 4 --height 4 --spp 2 --mode pt"
#define SCENE "scenes/cornell.scene"
/* A render with a report, so that a temporary (the report's) is on disk from its start. */
#define REPORTED "--no-progress --mode pt --width 32 --height 32 --reference " OUT "_ref.pfm"

/* Runs "ENV PHOTON args" (env: variable assignments, or "") with its output in OUT.log,
 * under timeout(1). */
static int photon(const char *env, const char *args)
{
    char command[COMMAND_MAX];
    snprintf(command, sizeof command, "%s timeout 60 %s %s >" OUT ".log 2>&1", env,
             photon_binary(), args);
    return run_command(command);
}

static void clean(void)
{
    run_command("rm -rf " OUT "_*");
}

/* Whether the files named build/test_foreign_* are exactly names (a space after each,
 * without the build/test_foreign_ prefix, in the C locale's order). */
static int files_are(const char *names)
{
    char command[COMMAND_MAX];
    snprintf(command, sizeof command, "test \"$(cd build && LC_ALL=C ls -d test_foreign_* | "
             "sed 's/^test_foreign_//' | tr '\\n' ' ')\" = '%s'", names);
    return run_command(command) == 0;
}

/* The reference the reported renders compare with (32 x 32, 4 samples). */
static void make_reference(void)
{
    photon("", "--no-progress --mode pt --width 32 --height 32 --spp 4 -o " OUT "_ref.pfm "
           SCENE);
    remove(OUT "_ref.png");
}

/* truth: output.h: a temporary is a new file photon creates beside its output, under a
 *   name no file had (NAME.XXXXXXXX.tmp, created exclusively: never an existing file,
 *   never through a symbolic link), and photon removes only such files. So every file the
 *   user had beside the outputs keeps its bytes and its kind, whether the render succeeds
 *   or fails: NAME.tmp, photon's old temporary name (a file, a link to another file, the
 *   scene itself); and, with PHOTON_TEMPORARY_MARK fixing the names a run tries (its mark,
 *   then the mark + 1, ...), a file, a link and a dangling link at the very names it tries
 *   first, which it passes over for the next free one.
 * catches: out.pfm.tmp deleted by any render to out.pfm; photon s.pfm.tmp -o s.pfm
 *   deleting its scene before reading it ("No such file"); a write through a link at the
 *   temporary's name (the linked file overwritten, or created for a dangling link). */
static void test_user_files_beside_outputs_kept(struct check *t)
{
    clean();
    write_text_file(OUT "_victim", "victim\n");
    write_text_file(OUT "_o.pfm.tmp", "mine\n");
    run_command("ln -s test_foreign_victim " OUT "_o.png.tmp && cp " SCENE " " OUT
                "_s.pfm.tmp");
    CHECK(t, photon("", TINY " -o " OUT "_o.pfm " SCENE) == 0);
    CHECK(t, photon("", TINY " -o " OUT "_o.pfm build/no_such.scene") == 2);
    CHECK(t, photon("", TINY " -o " OUT "_s.pfm " OUT "_s.pfm.tmp") == 0);
    CHECK(t, file_equals_text(OUT "_o.pfm.tmp", "mine\n") &&
             file_equals_text(OUT "_victim", "victim\n") &&
             run_command("test -L " OUT "_o.png.tmp") == 0);
    CHECK(t, files_equal(OUT "_s.pfm.tmp", SCENE) && files_equal(OUT "_s.pfm", OUT "_o.pfm"));
    CHECK(t, files_are("o.pfm o.pfm.tmp o.png o.png.tmp s.pfm s.pfm.tmp s.png victim "));

    write_text_file(OUT "_m.pfm.00001000.tmp", "mine 0\n");
    run_command("ln -s test_foreign_victim " OUT "_m.pfm.00001001.tmp && "
                "ln -s test_foreign_victim " OUT "_m.png.00001000.tmp && "
                "ln -s test_foreign_nowhere " OUT "_m.png.00001001.tmp");
    CHECK(t, photon("PHOTON_TEMPORARY_MARK=00001000", TINY " -o " OUT "_m.pfm "
                    "build/no_such.scene") == 2);
    CHECK(t, photon("PHOTON_TEMPORARY_MARK=00001000", TINY " -o " OUT "_m.pfm " SCENE) == 0);
    CHECK(t, files_equal(OUT "_m.pfm", OUT "_o.pfm") &&
             files_equal(OUT "_m.png", OUT "_o.png"));
    CHECK(t, file_equals_text(OUT "_m.pfm.00001000.tmp", "mine 0\n") &&
             file_equals_text(OUT "_victim", "victim\n"));
    CHECK(t, run_command("test -L " OUT "_m.pfm.00001001.tmp && test -L " OUT
                         "_m.png.00001000.tmp && test -L " OUT "_m.png.00001001.tmp") == 0);
    CHECK(t, files_are("m.pfm m.pfm.00001000.tmp m.pfm.00001001.tmp m.png m.png.00001000.tmp "
                       "m.png.00001001.tmp o.pfm o.pfm.tmp o.png o.png.tmp s.pfm s.pfm.tmp "
                       "s.png victim "));
    clean();
}

/* truth: tile.h: a whole render removes NAME.pfm.window only when it is a record photon
 *   wrote (it reads as one, tile.h's six lines); any other file or directory of that
 *   name is the user's and stays: a scene (here the very scene rendered), a note, an empty
 *   directory. A crop's record is still removed by a whole render to the same name.
 * catches: remove() on NAME.pfm.window without looking: the scene deleted, the empty
 *   directory removed. */
static void test_only_crop_records_removed(struct check *t)
{
    clean();
    run_command("cp " SCENE " " OUT "_w.pfm.window && mkdir " OUT "_d.pfm.window && "
                "echo notes > " OUT "_n.pfm.window");
    CHECK(t, photon("", TINY " -o " OUT "_w.pfm " OUT "_w.pfm.window") == 0);
    CHECK(t, photon("", TINY " -o " OUT "_d.pfm " SCENE) == 0);
    CHECK(t, photon("", TINY " -o " OUT "_n.pfm " SCENE) == 0);
    CHECK(t, files_equal(OUT "_w.pfm.window", SCENE) &&
             run_command("test -d " OUT "_d.pfm.window") == 0 &&
             file_equals_text(OUT "_n.pfm.window", "notes\n"));
    CHECK(t, photon("", TINY " --crop 0 0 2 2 -o " OUT "_c.pfm " SCENE) == 0 &&
             file_exists(OUT "_c.pfm.window"));
    CHECK(t, photon("", TINY " -o " OUT "_c.pfm " SCENE) == 0 &&
             !file_exists(OUT "_c.pfm.window"));
    clean();
}

/* truth: output.h: a failed publish gives back what was there: an output already put in
 *   place is replaced again by the file it replaced (its bytes), and one that replaced
 *   nothing is removed; no temporary is left. Here the last output's name becomes a
 *   directory after the check, so its rename fails after the others' succeeded; the
 *   message names that output and the reason, "Is a directory".
 * catches: the rollback removing the outputs it had renamed, the user's previous file
 *   with them: nothing new and nothing old left; the message naming the temporary
 *   ("d2.pfm: Is a directory" said of d2.pfm.tmp). */
static void test_failed_publish_gives_back(struct check *t)
{
    static const char *const names[] = {OUT "_first.txt", OUT "_third.txt",
                                        OUT "_second.txt"};
    struct error err;
    clean();
    outputs_abandon(); /* the inputs earlier tests of this process read are forgotten */
    write_text_file(OUT "_first.txt", "old first\n");
    write_text_file(OUT "_second.txt", "old second\n");
    for (int i = 0; i < 3; i++)
        output_declare(names[i], "an output");
    REQUIRE(t, outputs_check(&err) == 0);
    for (int i = 0; i < 3; i++) {
        FILE *f = output_open(names[i], &err);
        REQUIRE(t, f != NULL);
        fputs("new\n", f);
        CHECK(t, output_commit(f, &err) == 0);
    }
    run_command("rm " OUT "_second.txt && mkdir " OUT "_second.txt && touch " OUT
                "_second.txt/inside");
    CHECK(t, outputs_publish(&err) < 0 && err.failed_write);
    CHECK(t, strcmp(err.file, OUT "_second.txt") == 0 &&
             strcmp(err.message, "cannot write output file: Is a directory") == 0);
    CHECK(t, file_equals_text(OUT "_first.txt", "old first\n") &&
             !file_exists(OUT "_third.txt"));
    CHECK(t, files_are("first.txt second.txt "));
    outputs_abandon();
    clean();
}

/* truth: output.h: no file of ours takes the name of a declared output, even one not yet
 *   on disk. Here --save-photons is named as -o's previous PFM would wait aside (the run's
 *   mark fixed, so the name NAME.XXXXXXXX.tmp is known: the temporary takes the mark, the
 *   place aside the mark + 1): every output is written, the work file with the bytes a run
 *   saving it under another name writes; -o's previous PFM is replaced; nothing else left.
 * catches: the replaced PFM kept aside under the work file's name, then removed once the
 *   publish succeeded: the work file gone, status 0. */
static void test_output_named_like_a_file_of_ours(struct check *t)
{
    clean();
    CHECK(t, photon("", "--no-progress --mode photons --photons 1000 --width 4 --height 4 -o "
                    OUT "_a.pfm --save-photons " OUT "_plain.work " SCENE) == 0);
    CHECK(t, photon("PHOTON_TEMPORARY_MARK=0000abcc", "--no-progress --mode photons --photons "
                    "1000 --width 4 --height 4 -o " OUT "_a.pfm --save-photons " OUT
                    "_a.pfm.0000abcd.tmp " SCENE) == 0);
    CHECK(t, files_equal(OUT "_a.pfm.0000abcd.tmp", OUT "_plain.work"));
    CHECK(t, files_are("a.pfm a.pfm.0000abcd.tmp a.png plain.work "));
    clean();
}

/* truth: output.h: what cannot be put in place is refused before the work, status 2: here
 *   a PNG of another owner in a sticky directory (mode 1777, as /tmp), which the user may
 *   write (mode 666) but not replace ("cannot be replaced"; or "cannot be written" where
 *   the kernel's fs.protected_regular forbids the write too). The user's previous PFM
 *   beside it and the PNG keep their bytes. Run as nobody (setpriv, util-linux) since the
 *   tests run as root, who may replace any file; skipped otherwise, as only root can make
 *   another owner's file.
 * catches: the PFM put in place, the PNG's rename refused after the work, and the
 *   rollback removing the PFM: the user's previous PFM lost, status 1. */
static void test_unreplaceable_output_refused(struct check *t)
{
    char command[COMMAND_MAX];
    if (run_command("test $(id -u) = 0") != 0) {
        printf("  (test_unreplaceable_output_refused: not root, skipped)\n");
        return;
    }
    clean();
    run_command("mkdir -m 1777 " OUT "_sticky && cp " SCENE " " OUT "_sticky/s.scene && "
                "chmod 644 " OUT "_sticky/s.scene && echo precious > " OUT "_sticky/x.png && "
                "chmod 666 " OUT "_sticky/x.png");
    snprintf(command, sizeof command, "cd " OUT "_sticky && setpriv --reuid=nobody "
             "--regid=nogroup --clear-groups sh -c 'echo old > x.pfm && %s%s " TINY
             " -o x.pfm s.scene' > ../test_foreign.log 2>&1",
             photon_binary()[0] == '/' ? "" : "../../", photon_binary());
    CHECK(t, run_command(command) == 2 &&
             file_contains(OUT ".log", "x.png: the file exists and cannot be"));
    CHECK(t, file_equals_text(OUT "_sticky/x.pfm", "old\n") &&
             file_equals_text(OUT "_sticky/x.png", "precious\n"));
    CHECK(t, run_command("test \"$(cd " OUT "_sticky && LC_ALL=C ls | tr '\\n' ' ')\" = "
                         "'s.scene x.pfm x.png '") == 0);
    clean();
}

/* truth: output.h: each run writes its own temporaries, even two runs that try the same
 *   names (PHOTON_TEMPORARY_MARK the same in both, as two runs started in one clock tick
 *   without address randomisation would). Two renders of different seeds to the same -o
 *   and --report at the same time both succeed, and each file left is whole: the PFM and
 *   the PNG hold one run's bytes (as a lone run of that seed writes them), the report one
 *   run's rows (work and errors; the seconds vary). The lone runs differ, so the test
 *   can tell.
 * catches: one NAME.tmp shared by both runs: rows of both in one report, a truncated
 *   file, or the second run's rename failing (status 1) after the first moved the file. */
static void test_two_runs_one_output(struct check *t)
{
    clean();
    make_reference();
    CHECK(t, photon("", REPORTED " --spp 256 --seed 1 -o " OUT "_a.pfm --report " OUT "_a.csv "
                    SCENE) == 0);
    CHECK(t, photon("", REPORTED " --spp 256 --seed 2 -o " OUT "_b.pfm --report " OUT "_b.csv "
                    SCENE) == 0);
    char command[COMMAND_MAX];
    snprintf(command, sizeof command,
             "for s in 1 2; do (PHOTON_TEMPORARY_MARK=00002000 timeout 60 %s " REPORTED
             " --spp 256 --seed $s -o " OUT "_t.pfm --report " OUT "_t.csv " SCENE " >" OUT
             "_log$s 2>&1; echo $? > " OUT "_status$s) & done; wait", photon_binary());
    run_command(command);
    CHECK(t, file_equals_text(OUT "_status1", "0\n") &&
             file_equals_text(OUT "_status2", "0\n"));
    CHECK(t, !files_equal(OUT "_a.pfm", OUT "_b.pfm") &&
             !files_equal(OUT "_a.png", OUT "_b.png"));
    CHECK(t, files_equal(OUT "_t.pfm", OUT "_a.pfm") ||
             files_equal(OUT "_t.pfm", OUT "_b.pfm"));
    CHECK(t, files_equal(OUT "_t.png", OUT "_a.png") ||
             files_equal(OUT "_t.png", OUT "_b.png"));
    run_command("for r in a b t; do cut -d, -f2- " OUT "_$r.csv > " OUT "_$r.rows; done");
    CHECK(t, !files_equal(OUT "_a.rows", OUT "_b.rows"));
    CHECK(t, files_equal(OUT "_t.rows", OUT "_a.rows") ||
             files_equal(OUT "_t.rows", OUT "_b.rows"));
    CHECK(t, no_temporaries(OUT "_t.pfm") && no_temporaries(OUT "_t.png") &&
             no_temporaries(OUT "_t.csv"));
    clean();
}

/* Sets the previous outputs of the render to OUT_k.pfm. */
static void previous_outputs(void)
{
    write_text_file(OUT "_k.pfm", "old pfm\n");
    write_text_file(OUT "_k.png", "old png\n");
    write_text_file(OUT "_k.csv", "old csv\n");
}

/* Whether the render to OUT_k.pfm ended with status (in OUT_status), left no file of its
 * own, and its previous outputs all keep their bytes. */
static int stopped_cleanly(int status)
{
    char text[16];
    snprintf(text, sizeof text, "%d\n", status);
    return file_equals_text(OUT "_status", text) &&
           files_are("k.csv k.pfm k.png ref.pfm status ") &&
           file_equals_text(OUT "_k.pfm", "old pfm\n") &&
           file_equals_text(OUT "_k.png", "old png\n") &&
           file_equals_text(OUT "_k.csv", "old csv\n");
}

/* truth: undo.h: a signal that ends photon leaves no file photon made, whenever it comes,
 *   and the previous outputs keep their bytes: SIGINT, SIGTERM and SIGHUP sent before the
 *   outputs are checked or during the render (8192 samples: seconds; the report's
 *   temporary is on disk from its start), and SIGXFSZ raised by the write of the PFM itself
 *   when files may not grow past 2 KiB (ulimit -f 4), the report and its temporary already
 *   written. The status is 128 + the signal's number (Linux's numbers): the signal still
 *   ends photon, as its default action would.
 * catches: temporaries left by a signal (its default action ends photon without atexit);
 *   a signal turned into a normal exit (status 0, 1 or 2). */
static void test_signals_leave_nothing(struct check *t)
{
    static const struct {
        const char *name;
        int number;
        const char *delay;
    } stops[] = {{"INT", 2, "0.01"}, {"TERM", 15, "0.1"}, {"HUP", 1, "0.4"}, {"INT", 2, "0.8"},
                 {"TERM", 15, "1.2"}};
    char command[COMMAND_MAX];
    clean();
    make_reference();
    for (size_t i = 0; i < sizeof stops / sizeof stops[0]; i++) {
        previous_outputs();
        snprintf(command, sizeof command, "timeout --preserve-status -s %s %s %s " REPORTED
                 " --spp 8192 -o " OUT "_k.pfm --report " OUT "_k.csv " SCENE " >" OUT
                 ".log 2>&1; echo $? > " OUT "_status", stops[i].name, stops[i].delay,
                 photon_binary());
        run_command(command);
        CHECK(t, stopped_cleanly(128 + stops[i].number));
    }
    previous_outputs();
#ifdef SIGXFSZ
    signal(SIGXFSZ, SIG_DFL); /* as photon would be started: not ignored (Python ignores it) */
#endif
    snprintf(command, sizeof command, "sh -c 'ulimit -f 4; %s " REPORTED " --spp 4 -o " OUT
             "_k.pfm --report " OUT "_k.csv " SCENE " >" OUT ".log 2>&1; echo $? > " OUT
             "_status'", photon_binary());
    run_command(command);
    CHECK(t, stopped_cleanly(128 + 25));
    clean();
}

/* truth: undo.h: a second signal while the first is being handled waits for it, so
 *   nothing is left however close the two come: 120 renders, each sent SIGINT by timeout
 *   1 to 9 ms after its start (while it starts, checks its outputs and makes its
 *   temporaries), which signals photon and then its process group, so twice; each run
 *   ends with status 130 and leaves the previous outputs alone and nothing of its own.
 * catches: a handler the first signal turns back into the default action (C99's signal()
 *   under glibc, System V's rule), so that the second ends photon while it puts the files
 *   right: one run in 40 left a temporary, and this failed in each of 3 tries. */
static void test_two_signals_leave_nothing(struct check *t)
{
    char command[COMMAND_MAX];
    clean();
    make_reference();
    previous_outputs();
    snprintf(command, sizeof command, "for i in $(seq 0 119); do timeout --preserve-status "
             "-s INT 0.00$((i %% 9 + 1)) %s " REPORTED " --spp 8192 -o " OUT "_k.pfm "
             "--report " OUT "_k.csv " SCENE " >" OUT ".log 2>&1; s=$?; test $s = 130 || "
             "break; test \"$(ls -d " OUT "_* | wc -l)\" = 4 || break; done; echo $s > "
             OUT "_status", photon_binary());
    run_command(command);
    CHECK(t, stopped_cleanly(130));
    clean();
}

/* Runs "ENV PHOTON args" as photon() does, but gives it 10 seconds: a read or write that
 * waits for a FIFO's other end shows as timeout's status 124. */
static int photon_briefly(const char *env, const char *args)
{
    char command[COMMAND_MAX];
    snprintf(command, sizeof command, "%s timeout 10 %s %s >" OUT ".log 2>&1", env,
             photon_binary(), args);
    return run_command(command);
}

#define FIFOS "f.scene f.pfm f.csv f.work o.pfm o.pbrt t.pfm.window w.pfm.window " \
              "n.pfm.00003000.tmp"

/* truth: input.h and output.h: photon reads and writes regular files only, and a FIFO
 *   (made by mkfifo(1), nothing at its other end) is told from one without waiting for that
 *   end: each reader refuses it as bad input naming it (status 2): a scene, an include, a
 *   --load-photons file, a --reference, compare's and plot's inputs, a tile's record; so
 *   does each writer (-o of a render and of export). Where a FIFO stands at a name photon
 *   only looks at (a crop record beside a whole render, a temporary's name) the render goes
 *   on (status 0). Every FIFO is left a FIFO. Skipped without mkfifo(1).
 * catches: fopen(NAME, "rb") before the check, which waits for a writer that never comes
 *   (timeout's 124): in input_open(), in the output checks, in the temporaries' test for a
 *   taken name, in the crop record's reading before its removal. */
static void test_fifos_refused_without_waiting(struct check *t)
{
    static const struct {
        const char *env, *args, *named;
        int status;
    } cases[] = {
        {"", TINY " -o " OUT "_x.pfm " OUT "_f.scene", "test_foreign_f.scene", 2},
        {"", TINY " -o " OUT "_x.pfm " OUT "_inc.scene", "test_foreign_f.scene", 2},
        {"", "--no-progress --width 4 --height 4 --mode photons --load-photons " OUT
         "_f.work -o " OUT "_x.pfm " SCENE, "test_foreign_f.work", 2},
        {"", TINY " --reference " OUT "_f.pfm --report " OUT "_x.csv -o " OUT "_x.pfm " SCENE,
         "test_foreign_f.pfm", 2},
        {"", "compare " OUT "_f.pfm " OUT "_f.pfm", "test_foreign_f.pfm", 2},
        {"", "plot " OUT "_f.csv -o " OUT "_x.svg", "test_foreign_f.csv", 2},
        {"", "merge -o " OUT "_x.pfm " OUT "_t.pfm", "test_foreign_t.pfm.window", 2},
        {"", TINY " -o " OUT "_o.pfm " SCENE, "test_foreign_o.pfm", 2},
        {"", "export --format pbrt " SCENE " -o " OUT "_o.pbrt", "test_foreign_o.pbrt", 2},
        {"", TINY " -o " OUT "_w.pfm " SCENE, "", 0},
        {"PHOTON_TEMPORARY_MARK=00003000", TINY " -o " OUT "_n.pfm " SCENE, "", 0},
    };
    if (run_command("command -v mkfifo >/dev/null") != 0) {
        printf("  (test_fifos_refused_without_waiting: no mkfifo, skipped)\n");
        return;
    }
    clean();
    run_command("cd build && for f in " FIFOS "; do mkfifo test_foreign_$f; done && "
                "echo 'include test_foreign_f.scene' > test_foreign_inc.scene");
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        int status = photon_briefly(cases[i].env, cases[i].args);
        int refused = status == cases[i].status &&
                      (status == 0 || (file_contains(OUT ".log", cases[i].named) &&
                                       file_contains(OUT ".log", "FIFO")));
        CHECK(t, refused);
        if (!refused)
            fprintf(stderr, "test_foreign_files: '%s': status %d, not %d naming %s\n",
                    cases[i].args, status, cases[i].status, cases[i].named);
    }
    CHECK(t, run_command("cd build && for f in " FIFOS "; do test -p test_foreign_$f || "
                         "exit 1; done") == 0);
    CHECK(t, files_are("f.csv f.pfm f.scene f.work inc.scene n.pfm n.pfm.00003000.tmp n.png "
                       "o.pbrt o.pfm t.pfm.window w.pfm w.pfm.window w.png "));
    clean();
}

void test_foreign_files(struct check *t)
{
    RUN_TEST(t, test_user_files_beside_outputs_kept);
    RUN_TEST(t, test_only_crop_records_removed);
    RUN_TEST(t, test_failed_publish_gives_back);
    RUN_TEST(t, test_output_named_like_a_file_of_ours);
    RUN_TEST(t, test_unreplaceable_output_refused);
    RUN_TEST(t, test_two_runs_one_output);
    RUN_TEST(t, test_signals_leave_nothing);
    RUN_TEST(t, test_two_signals_leave_nothing);
    RUN_TEST(t, test_fifos_refused_without_waiting);
}
