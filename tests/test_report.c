/*
 * tests/test_report.c -- the instruments of a render, on the built binary: --report (error
 * against time), --time-limit, --variance, and the point light over a plane in pt.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../src/image/image.h"
#include "tests.h"

#define OUT "build/test_report"
#define REPORT_LINE_MAX 256

/* Runs photon with args, stderr to OUT.log; returns the exit status. */
static int photon_quietly(const char *args)
{
    char command[1024];
    if (snprintf(command, sizeof command, "%s --no-progress %s 2>" OUT ".log >/dev/null",
                 photon_binary(), args) >= (int)sizeof command)
        return -1;
    return run_command(command);
}

/* Reads the work and relmse columns of a --report CSV (at most max rows); returns the
 * number of rows, or -1 when the header or a row is malformed. */
static int read_report(const char *name, long long *work, double *relmse, int max)
{
    char line[REPORT_LINE_MAX];
    FILE *f = fopen(name, "rb");
    if (f == NULL)
        return -1;
    int rows = -1;
    if (fgets(line, sizeof line, f) != NULL && strcmp(line, "seconds,work,rmse,relmse\n") == 0)
        for (rows = 0; rows < max && fgets(line, sizeof line, f) != NULL; rows++) {
            double seconds, rmse;
            if (sscanf(line, "%lf,%lld,%lf,%lf", &seconds, &work[rows], &rmse, &relmse[rows])
                    != 4 ||
                !(seconds >= 0 && rmse >= 0 && relmse[rows] >= 0)) {
                rows = -1;
                break;
            }
        }
    fclose(f);
    return rows;
}

/* truth: the --report contract (README): a header, then rows after 1, 2, 4, ... samples per
 *   pixel and one at the end; a report against the image itself ends at error 0.
 * catches: checkpoints at the wrong work, a missing last row, a report left as .tmp. */
static void test_report_rows(struct check *t)
{
    const char *common = "--mode pt --width 16 --height 12 scenes/cornell.scene";
    char args[512];
    sprintf(args, "%s --spp 6 -o " OUT "_ref.pfm", common);
    CHECK(t, photon_quietly(args) == 0);
    sprintf(args, "%s --spp 6 -o " OUT ".pfm --reference " OUT "_ref.pfm --report " OUT ".csv",
            common);
    CHECK(t, photon_quietly(args) == 0);
    long long work[16];
    double relmse[16];
    int rows = read_report(OUT ".csv", work, relmse, 16);
    CHECK(t, rows == 4 && work[0] == 1 && work[1] == 2 && work[2] == 4 && work[3] == 6);
    /* The last image is the reference itself, which holds it rounded to float: relmse is
     * then at most (2^-24)^2, and the earlier, noisier images are far from it. */
    CHECK(t, rows == 4 && relmse[3] <= 1e-14 && relmse[0] > 1e-6);
    sprintf(args, "%s -o " OUT ".pfm --reference " OUT "_ref.pfm --report " OUT ".csv "
                  "--width 8", common);
    CHECK(t, photon_quietly(args) == 2); /* the reference is not the image's size */
}

/* truth: --time-limit stops after the sample pass that crosses it (README), so a limit
 *   of a microsecond takes exactly one pass, and --stats says so.
 * catches: a limit that stops mid-pass (a ragged image), zero passes (a black image). */
static void test_time_limit_takes_whole_passes(struct check *t)
{
    CHECK(t, photon_quietly("--mode pt --width 16 --height 12 --spp 1000 --time-limit 1e-6 "
                            "--stats -o " OUT ".pfm scenes/cornell.scene") == 0);
    FILE *f = fopen(OUT ".log", "rb");
    char line[REPORT_LINE_MAX];
    int spp = -1;
    while (f != NULL && fgets(line, sizeof line, f) != NULL)
        sscanf(line, "spp=%d", &spp);
    if (f != NULL)
        fclose(f);
    CHECK(t, spp == 1);
}

/* truth: the point light over a plane, L = rho Phi h / (4 pi^2 d^3), for the path tracer
 *   (the plane reflects into nothing, so pt must equal the direct light exactly in
 *   expectation); the variance file is the variance of each pixel's mean.
 * tolerance: each pixel within 5 standard errors from the written variance, plus the
 *   spread of L over the pixel (the value is a mean over the pixel's square).
 * catches: a point light double counted by MIS, a variance image of the wrong scale. */
static void test_point_light_in_pt(struct check *t)
{
    CHECK(t, photon_quietly("--mode pt --spp 16 -o " OUT "_pl.pfm --variance " OUT "_plv.pfm "
                            "scenes/analytic/point-over-plane.scene") == 0);
    struct error err;
    struct image *img = pfm_read(OUT "_pl.pfm", &err), *var = pfm_read(OUT "_plv.pfm", &err);
    CHECK(t, img != NULL && var != NULL);
    /* camera at height 3 looking down, 60 degree fov, 32 x 32 (the scene file) */
    double t_half = tan(30 * PI / 180);
    for (int y = 0; img != NULL && var != NULL && y < img->height; y++)
        for (int x = 0; x < img->width; x++) {
            double lo = INFINITY, hi = 0;
            for (int j = 0; j <= 4; j++)
                for (int i = 0; i <= 4; i++) {
                    double sx = (2 * (x + i / 4.0) / 32 - 1) * t_half * 3;
                    double sz = (1 - 2 * (y + j / 4.0) / 32) * t_half * 3;
                    double d = sqrt(sx * sx + sz * sz + 1.0);
                    double l = 0.5 * 1000 / (4 * PI * PI * d * d * d);
                    lo = fmin(lo, l);
                    hi = fmax(hi, l);
                }
            double v = image_get(img, x, y).y, se = sqrt(image_get(var, x, y).y);
            CHECK(t, v >= lo - 5 * se - 1e-12 && v <= hi + 5 * se + 1e-12);
        }
    image_free(var);
    image_free(img);
}

void test_report(struct check *t)
{
    RUN_TEST(t, test_report_rows);
    RUN_TEST(t, test_time_limit_takes_whole_passes);
    RUN_TEST(t, test_point_light_in_pt);
    remove(OUT ".log");
    remove(OUT ".pfm");
    remove(OUT ".png");
    remove(OUT ".csv");
    remove(OUT "_ref.pfm");
    remove(OUT "_ref.png");
    remove(OUT "_pl.pfm");
    remove(OUT "_pl.png");
    remove(OUT "_plv.pfm");
}
