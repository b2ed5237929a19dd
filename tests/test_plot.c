/*
 * tests/test_plot.c -- `photon plot`: the log axes' decades, where points land in the
 * SVG, the legend, CSV input that must be refused (with file:line, and nothing written),
 * and the command line on the built binary.
 *
 * Files go to /tmp under names unique to the run (temp_name, files.c) and are removed by
 * the test that made them. The SVG is checked as text: the frame rectangle (id="frame")
 * and the polylines' points are read back with sscanf.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/image/plot.h"
#include "check.h"
#include "files.h"
#include "tests.h"

#define NAME_MAX_BYTES 256
#define COMMAND_MAX 1024
#define HEADER "seconds,work,rmse,relmse\n"
#define POINT_TOLERANCE 0.006 /* the SVG prints coordinates with two decimals */

static int count_of(const char *text, const char *word)
{
    int n = 0;
    for (const char *p = strstr(text, word); p != NULL; p = strstr(p + 1, word))
        n++;
    return n;
}

/* truth: the definition in plot.h worked by hand: floor(log10 lo) .. ceil(log10 hi), a
 *   range of one power of ten padded a decade each way; values exactly on decades
 *   (1e-3, 1, 10, 1e-9 .. 1e3) must not grow an empty decade.
 * tolerance: none; whole numbers.
 * catches: floor and ceil swapped, rounding of log10 adding an empty decade at 1e-3,
 *   a one-point plot with a zero-width axis (a division by zero in the mapping), the far
 *   ends of the double range (subnormal 4.9e-324, 1.7e308) overflowing an int or pow. */
static void test_log_axis_fit(struct check *t)
{
    static const struct {
        double lo, hi;
        int k_lo, k_hi;
    } cases[] = {
        {0.05, 0.05, -2, -1}, {1e-3, 1e-3, -4, -2}, {1, 1, -1, 1}, {2.5, 2.5, 0, 1},
        {1e-9, 1e3, -9, 3}, {0.1, 0.2, -1, 0}, {1, 10, 0, 1}, {0.011, 0.099, -2, -1},
        {0.3, 30, -1, 2}, {4.9e-324, 1.7e308, -324, 309}, {1e300, 1e300, 299, 301},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        struct log_axis a = log_axis_fit(cases[i].lo, cases[i].hi);
        CHECK(t, a.k_lo == cases[i].k_lo && a.k_hi == cases[i].k_hi);
        if (a.k_lo != cases[i].k_lo || a.k_hi != cases[i].k_hi)
            fprintf(stderr, "  [%g, %g]: got 10^%d .. 10^%d\n", cases[i].lo, cases[i].hi,
                    a.k_lo, a.k_hi);
    }
}

/* truth: the definition in plot.h worked by hand: the least step of 1, 2 or 5 x 10^k
 *   that is at least a range's eighth, the ends rounded out to its multiples; an empty
 *   range widened by half its value (by 1 at 0).
 * tolerance: 1e-12 relative; multiples of 0.1 are not exact in binary.
 * catches: the step's mantissas skipped or tried in the wrong order, ends rounded inwards
 *   (a point off the frame), a zero-width range (a division by zero in the mapping),
 *   a negative range rounded the wrong way. */
static void test_linear_axis_fit(struct check *t)
{
    static const struct {
        double lo, hi, axis_lo, axis_hi, step;
    } cases[] = {
        {0, 0.53, 0, 0.6, 0.1},   {-0.9, 0.9, -1, 1, 0.5}, {3, 3, 1.5, 4.5, 0.5},
        {0, 0, -1, 1, 0.5},       {0, 8, 0, 8, 1},         {0, 8.0001, 0, 10, 2},
        {-5, -3, -5, -3, 0.5},    {2e6, 3e6, 2e6, 3e6, 2e5},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        struct linear_axis a = linear_axis_fit(cases[i].lo, cases[i].hi);
        double scale = 1e-12 * fmax(1.0, fabs(cases[i].axis_hi) + fabs(cases[i].axis_lo));
        int ok = fabs(a.lo - cases[i].axis_lo) <= scale && fabs(a.hi - cases[i].axis_hi)
                 <= scale && fabs(a.step - cases[i].step) <= 1e-12 * cases[i].step;
        CHECK(t, ok);
        if (!ok)
            fprintf(stderr, "  [%g, %g]: got %g .. %g step %g\n", cases[i].lo, cases[i].hi,
                    a.lo, a.hi, a.step);
    }
}

/* The frame rectangle of an SVG written by plot.c; 0 when it is not there. */
static int read_frame(const char *svg, double *x, double *y, double *w, double *h)
{
    const char *p = strstr(svg, "<rect id=\"frame\"");
    return p != NULL && sscanf(p, "<rect id=\"frame\" x=\"%lf\" y=\"%lf\" width=\"%lf\" "
                                  "height=\"%lf\"", x, y, w, h) == 4;
}

/* The points of the n-th polyline (0-based) into xy[2 * max]; returns how many. */
static int read_polyline(const char *svg, int n, double *xy, int max)
{
    const char *p = svg;
    for (int i = 0; i <= n && p != NULL; i++)
        p = strstr(i == 0 ? p : p + 1, "<polyline");
    p = p != NULL ? strstr(p, "points=\"") : NULL;
    if (p == NULL)
        return 0;
    p += strlen("points=\"");
    int count = 0, used = 0;
    while (count < max && sscanf(p, "%lf,%lf%n", &xy[2 * count], &xy[2 * count + 1], &used)
           == 2) {
        count++;
        p += used;
    }
    return count;
}

/* Writes csv_text to a CSV, plots it alone, returns the SVG text (caller frees) or NULL. */
static char *plot_one(const char *csv_text)
{
    const struct plot_spec errors = plot_spec_errors();
    char csv[NAME_MAX_BYTES], svg[NAME_MAX_BYTES];
    temp_name(csv, sizeof csv, "plot", "one.csv");
    temp_name(svg, sizeof svg, "plot", "one.svg");
    write_text_file(csv, csv_text);
    const char *files[1] = {csv};
    struct error err;
    char *text = plot_files(files, 1, &errors, svg, &err) == 0 ? read_text_file(svg) : NULL;
    remove(csv);
    remove(svg);
    return text;
}

/* Checks that point i of xy is at (x, y). */
static void check_point(struct check *t, const double *xy, int i, double x, double y)
{
    CHECK_CLOSE(t, xy[2 * i], x, POINT_TOLERANCE);
    CHECK_CLOSE(t, xy[2 * i + 1], y, POINT_TOLERANCE);
}

/* truth: closed form; points on decades land on the frame's corners and centre: with
 *   (seconds, relmse) = (1, 1), (10, 0.1), (100, 0.01) the axes are 10^0..10^2 and
 *   10^-2..10^0, so the line runs from the top left corner through the centre to the
 *   bottom right; a single point (2.5, 0.03) sits on axes padded to whole decades at
 *   x = log10(2.5) and y = 1 - (log10(0.03) + 2) of the frame.
 * tolerance: 0.006 units; coordinates are printed with two decimals.
 * catches: y growing downwards uncorrected, no log10, axes off by a decade, points out
 *   of order, extra columns or reordered columns read by position, CR LF or spaces or
 *   a missing last newline refused, a marker per point missing. */
static void test_points_land_on_decades(struct check *t)
{
    static const char *forms[] = {
        HEADER "1,5,0.5,1\n10,50,0.2,0.1\n100,500,0.1,0.01\n",
        "relmse , extra,seconds\r\n1,7,1\r\n\r\n 0.1 ,7, 10\r\n0.01,7,100\r\n\r\n",
        HEADER "\n1,5,0.5,1\n10,50,0.2,0.1\n\n100,500,0.1,0.01",
    };
    double xy[2 * 8], x, y, w, h;
    for (size_t i = 0; i < sizeof forms / sizeof forms[0]; i++) {
        char *svg = plot_one(forms[i]);
        CHECK(t, svg != NULL);
        if (svg == NULL)
            continue;
        CHECK(t, read_frame(svg, &x, &y, &w, &h) && w > 0 && h > 0);
        CHECK(t, read_polyline(svg, 0, xy, 8) == 3);
        check_point(t, xy, 0, x, y);
        check_point(t, xy, 1, x + 0.5 * w, y + 0.5 * h);
        check_point(t, xy, 2, x + w, y + h);
        CHECK(t, count_of(svg, "<use xlink:href=\"#marker0\"") == 3 + 1); /* + legend */
        free(svg);
    }
    char *svg = plot_one(HEADER "2.5,1,1,0.03\n");
    CHECK(t, svg != NULL && read_frame(svg, &x, &y, &w, &h));
    CHECK(t, svg != NULL && read_polyline(svg, 0, xy, 8) == 1);
    check_point(t, xy, 0, x + log10(2.5) * w, y + (1.0 - (log10(0.03) + 2.0)) * h);
    free(svg);
}

/* truth: closed form; on linear axes fitted by hand (x: -1 .. 1 by 0.5, y: 0 .. 1 by
 *   0.2), column a's points (-1, 0), (0, 0.5), (1, 1) run from the bottom left corner
 *   through the centre to the top right, column b's the other way; with one file the
 *   runs are labelled by column, the y axis "value" and the x axis by its column.
 * tolerance: 0.006 units; coordinates are printed with two decimals.
 * catches: log10 applied on a linear axis, columns swapped or read by position, a
 *   second --y column dropped, labels naming the file instead of the columns. */
static void test_linear_profile(struct check *t)
{
    char csv[NAME_MAX_BYTES], svg_name[NAME_MAX_BYTES];
    temp_name(csv, sizeof csv, "plot", "profile.csv");
    temp_name(svg_name, sizeof svg_name, "plot", "profile.svg");
    write_text_file(csv, "b,z,a\n1,-1,0\n0.5,0,0.5\n0,1,1\n");
    struct plot_spec spec = plot_spec_errors();
    spec.linear = 1;
    spec.x = "z";
    spec.y[0] = "a";
    spec.y[1] = "b";
    spec.n_y = 2;
    const char *files[1] = {csv};
    struct error err;
    CHECK(t, plot_files(files, 1, &spec, svg_name, &err) == 0);
    char *svg = read_text_file(svg_name);
    double xy[2 * 8], x, y, w, h;
    CHECK(t, svg != NULL && read_frame(svg, &x, &y, &w, &h));
    if (svg != NULL) {
        CHECK(t, read_polyline(svg, 0, xy, 8) == 3);
        check_point(t, xy, 0, x, y + h);
        check_point(t, xy, 1, x + 0.5 * w, y + 0.5 * h);
        check_point(t, xy, 2, x + w, y);
        CHECK(t, read_polyline(svg, 1, xy, 8) == 3);
        check_point(t, xy, 0, x, y);
        check_point(t, xy, 2, x + w, y + h);
        CHECK(t, strstr(svg, ">a</text>") && strstr(svg, ">b</text>"));
        CHECK(t, strstr(svg, ">z</text>") && strstr(svg, ">value</text>"));
        CHECK(t, strstr(svg, ">-0.5</text>") && strstr(svg, ">0.8</text>"));
    }
    free(svg);
    remove(csv);
    remove(svg_name);
}

/* truth: the legend rules in plot.c: each run is labelled with its file's base name
 *   without ".csv", XML-escaped; rows with seconds or relmse 0 are left out and counted
 *   in the legend; the document is one SVG 1.1 element with a viewBox, white behind.
 * tolerance: none; text.
 * catches: a raw '&' or '<' making the file invalid XML, the directory left in the label,
 *   zero rows drawn (log10(0) = -Inf in the points) or silently dropped, a run missing. */
static void test_legend_and_skipped_rows(struct check *t)
{
    const struct plot_spec errors = plot_spec_errors();
    char a[NAME_MAX_BYTES], b[NAME_MAX_BYTES], svg_name[NAME_MAX_BYTES];
    temp_name(a, sizeof a, "plot", "x&y<z>.csv");
    temp_name(b, sizeof b, "plot", "zeros.csv");
    temp_name(svg_name, sizeof svg_name, "plot", "legend.svg");
    write_text_file(a, HEADER "1,1,1,0.5\n2,1,1,0.2\n");
    write_text_file(b, HEADER "0,1,1,0.5\n1,1,1,0.1\n2,1,1,0\n4,1,1,0.05\n");
    const char *files[2] = {a, b};
    struct error err;
    CHECK(t, plot_files(files, 2, &errors, svg_name, &err) == 0);
    char *svg = read_text_file(svg_name);
    CHECK(t, svg != NULL);
    if (svg != NULL) {
        double xy[2 * 8];
        CHECK(t, strncmp(svg, "<?xml version=\"1.0\"", 19) == 0);
        CHECK(t, strstr(svg, "viewBox=\"0 0 ") != NULL && strstr(svg, "version=\"1.1\""));
        CHECK(t, strcmp(svg + strlen(svg) - 7, "</svg>\n") == 0);
        CHECK(t, count_of(svg, "<polyline") == 2 && read_polyline(svg, 1, xy, 8) == 2);
        CHECK(t, strstr(svg, "_x&amp;y&lt;z&gt;</text>") != NULL && !strstr(svg, "x&y"));
        CHECK(t, strstr(svg, "_zeros (2 rows at 0 not shown)</text>") != NULL);
        CHECK(t, strstr(svg, "/tmp/") == NULL && strstr(svg, ".csv") == NULL);
        CHECK(t, strstr(svg, "nan") == NULL && strstr(svg, "inf") == NULL);
        CHECK(t, strstr(svg, ">seconds (CPU)</text>") && strstr(svg, ">relative MSE</text>"));
    }
    free(svg);
    remove(a);
    remove(b);
    remove(svg_name);
}

/* One CSV that plot_files must refuse. */
struct bad_csv {
    const char *text;
    int line;            /* the line the error names, 0 for the file as a whole */
    const char *keyword; /* a word the message must contain */
};

/* Checks that plotting csv_name (holding text) fails naming file and line, writes
 * nothing, and leaves an existing output untouched. */
static void check_refused(struct check *t, const char *csv_name, const struct bad_csv *c)
{
    const struct plot_spec errors = plot_spec_errors();
    char svg[NAME_MAX_BYTES];
    temp_name(svg, sizeof svg, "plot", "refused.svg");
    write_text_file(svg, "precious");
    const char *files[1] = {csv_name};
    struct error err;
    err.message[0] = '\0';
    int ok = plot_files(files, 1, &errors, svg, &err) == -1 && strcmp(err.file, csv_name) == 0
             && err.line == c->line && strstr(err.message, c->keyword) != NULL;
    CHECK(t, ok);
    if (!ok)
        fprintf(stderr, "  expected line %d '%s', got %s:%d: %s\n", c->line, c->keyword,
                err.file, err.line, err.message);
    CHECK(t, file_equals_text(svg, "precious") && no_temporaries(svg));
    remove(svg);
}

/* truth: the input rules in plot.c; each file breaks one.
 * tolerance: none; each must be refused with the file's name, the line, the reason.
 * catches: strtod's partial parses ("0.5x", "") and its nan, inf and overflow taken as
 *   numbers, a short or long row read anyway, negative times or errors plotted, a header
 *   missing, blank lines or CR LF miscounting lines, an overlong line split in two, an
 *   empty or header-only file drawn as an empty plot, a directory read as empty. */
static void test_plot_refuses_bad_csv(struct check *t)
{
    static const struct bad_csv cases[] = {
        {"", 0, "empty"}, {"\n \n\t\n", 0, "empty"}, {HEADER, 1, "no rows"},
        {HEADER "\n\n", 1, "no rows"}, {"time,error\n1,2\n", 1, "header"},
        {"1,2,3,4\n", 1, "header"}, {HEADER "1,2,3\n", 2, "expected 4 fields"},
        {HEADER "1,2,3,4,5\n", 2, "found 5"}, {HEADER "1,2,3,x\n", 2, "finite number"},
        {HEADER "1,2,3,nan\n", 2, "finite"}, {HEADER "1,2,3,inf\n", 2, "finite"},
        {HEADER "1,2,3,1e999\n", 2, "finite"}, {HEADER "1,2,3,0.5x\n", 2, "'0.5x'"},
        {HEADER "1,2,3,\n", 2, "field 4 ''"}, {HEADER "1,2,3,0.1\n-1,2,3,0.1\n", 3, "seconds"},
        {HEADER "1,2,3,-0.1\n", 2, "relmse must be >= 0"},
        {HEADER "\n\n1,2,3,0.1\n2,2,3,x\n", 5, "finite"},
        {"seconds,work,rmse,relmse\r\n1,2,3,0.1\r\n2,2,3,x\r\n", 3, "finite"},
        {"a,b,c,d,e,f,g,h,i,j,k,l,m,n,o,p,seconds,relmse\n", 1, "more than 16 columns"},
    };
    char name[NAME_MAX_BYTES];
    temp_name(name, sizeof name, "plot", "bad.csv");
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        write_text_file(name, cases[i].text);
        check_refused(t, name, &cases[i]);
    }
    char *long_line = malloc(4096);
    if (long_line != NULL) {
        snprintf(long_line, 4096, HEADER "1,2,3,0.%02000d1\n", 0); /* 2010 bytes */
        write_text_file(name, long_line);
        struct bad_csv c = {NULL, 2, "longer than"};
        check_refused(t, name, &c);
        free(long_line);
    }
    remove(name);
    struct bad_csv missing = {NULL, 0, "cannot open"}, directory = {NULL, 0, "directory"};
    check_refused(t, name, &missing);
    check_refused(t, "/tmp", &directory);
}

/* truth: the rules across files in plot.c: 1 to PLOT_MAX_SERIES runs, and at least one
 *   point a log-log plot can show.
 * tolerance: none.
 * catches: a ninth run indexing past the style table, an all-zero input drawn with a
 *   degenerate axis, no runs at all accepted. */
static void test_plot_refuses_bad_sets(struct check *t)
{
    const struct plot_spec errors = plot_spec_errors();
    char csv[NAME_MAX_BYTES], svg[NAME_MAX_BYTES];
    temp_name(csv, sizeof csv, "plot", "set.csv");
    temp_name(svg, sizeof svg, "plot", "set.svg");
    const char *files[PLOT_MAX_SERIES + 1];
    for (int i = 0; i <= PLOT_MAX_SERIES; i++)
        files[i] = csv;
    struct error err;
    write_text_file(csv, HEADER "1,1,1,0.5\n");
    CHECK(t, plot_files(files, PLOT_MAX_SERIES, &errors, svg, &err) == 0);
    remove(svg);
    CHECK(t, plot_files(files, PLOT_MAX_SERIES + 1, &errors, svg, &err) == -1);
    CHECK(t, strstr(err.message, "1 to 8") != NULL && !file_exists(svg));
    CHECK(t, plot_files(files, 0, &errors, svg, &err) == -1 && !file_exists(svg));
    write_text_file(csv, HEADER "0,1,1,0.5\n1,1,1,0\n");
    CHECK(t, plot_files(files, 2, &errors, svg, &err) == -1);
    CHECK(t, strstr(err.message, "nothing to plot") != NULL && !file_exists(svg));
    struct plot_spec columns = errors;
    columns.y[1] = columns.y[2] = "rmse";
    columns.n_y = 3;
    CHECK(t, plot_files(files, 3, &columns, svg, &err) == -1); /* 9 runs */
    CHECK(t, strstr(err.message, "1 to 8") != NULL && !file_exists(svg));
    columns.y[1] = "work";
    write_text_file(csv, HEADER "1,-1,1,0.5\n");
    CHECK(t, plot_files(files, 1, &columns, svg, &err) == -1 && err.line == 2);
    CHECK(t, strstr(err.message, "work must be >= 0") != NULL && !file_exists(svg));
    columns.y[2] = "-0.5";
    CHECK(t, plot_files(files, 1, &columns, svg, &err) == -1 && err.line == 1);
    CHECK(t, strstr(err.message, "no column named '-0.5'") != NULL && !file_exists(svg));
    remove(csv);
}

/* Runs "PHOTON plot args" with its output in log; the exit status. */
static int photon_plot(const char *args, const char *log)
{
    return photon_logged("plot", args, log);
}

/* truth: the command-line contract (README): bad input exits 2 with "file:line:
 *   message" or "photon: message", and writes nothing; good input exits 0 silently and
 *   writes the SVG.
 * tolerance: none.
 * catches: -o missing or not .svg accepted, an unknown option taken as a file, a
 *   malformed file reported without its line, a success status with no file. */
static void test_plot_command_line(struct check *t)
{
    char log[NAME_MAX_BYTES], csv[NAME_MAX_BYTES], svg[NAME_MAX_BYTES];
    char args[COMMAND_MAX], message[COMMAND_MAX];
    temp_name(log, sizeof log, "plot", "plot.log");
    temp_name(csv, sizeof csv, "plot", "cli.csv");
    temp_name(svg, sizeof svg, "plot", "cli.svg");
    write_text_file(csv, HEADER "1,1,1,0.5\n2,1,1,0.25\n");
    CHECK(t, photon_plot("", log) == 2 && file_contains(log, "photon: plot: no output"));
    CHECK(t, photon_plot("--help", log) == 0 && file_contains(log, "usage: photon plot"));
    snprintf(args, sizeof args, "%s", csv);
    CHECK(t, photon_plot(args, log) == 2 && file_contains(log, "-o PLOT.svg"));
    snprintf(args, sizeof args, "%s -o %s.png", csv, svg);
    CHECK(t, photon_plot(args, log) == 2 && file_contains(log, ".svg file"));
    snprintf(args, sizeof args, "-o %s", svg);
    CHECK(t, photon_plot(args, log) == 2 && file_contains(log, "no CSV files"));
    snprintf(args, sizeof args, "%s -o", csv);
    CHECK(t, photon_plot(args, log) == 2 && file_contains(log, "-o needs"));
    snprintf(args, sizeof args, "--log %s -o %s", csv, svg);
    CHECK(t, photon_plot(args, log) == 2 && file_contains(log, "unknown option '--log'"));
    snprintf(args, sizeof args, "%s -o %s --y", csv, svg);
    CHECK(t, photon_plot(args, log) == 2 && file_contains(log, "--y needs one value"));
    snprintf(args, sizeof args, "%s -o %s --y relmse --y relmse --y relmse --y relmse --y "
                                "relmse --y relmse --y relmse --y relmse --y relmse", csv, svg);
    CHECK(t, photon_plot(args, log) == 2 && file_contains(log, "more than 8 --y"));
    snprintf(args, sizeof args, "%s.missing -o %s", csv, svg);
    CHECK(t, photon_plot(args, log) == 2 && file_contains(log, ".missing: cannot open"));
    CHECK(t, !file_exists(svg));
    snprintf(args, sizeof args, "%s -o %s", csv, svg);
    CHECK(t, photon_plot(args, log) == 0 && file_exists(svg));
    CHECK(t, file_equals_text(log, ""));
    remove(svg);
    snprintf(args, sizeof args, "--linear --x work --y rmse --y relmse --x-title 'the <x>' "
                                "%s -o %s", csv, svg);
    CHECK(t, photon_plot(args, log) == 0 && file_contains(svg, ">the &lt;x&gt;</text>"));
    CHECK(t, file_contains(svg, ">rmse</text>") && file_equals_text(log, ""));
    remove(svg);
    write_text_file(csv, HEADER "1,1,1,0.5\n2,1,1,0.25,9\n");
    snprintf(args, sizeof args, "%s -o %s", csv, svg);
    snprintf(message, sizeof message, "%s:3: expected 4 fields", csv);
    CHECK(t, photon_plot(args, log) == 2 && file_contains(log, message) && !file_exists(svg));
    remove(csv);
    remove(log);
}

/* truth: mirror-caustic.scene's floor is the square |x|, |z| <= 1 at y = 0 and its light
 *   a point: a probe line from z = -0.9 to 2.1 in 7 steps of 0.5 is on the floor for
 *   z = -0.9 .. 0.6 (4 points) and off every surface for z = 1.1, 1.6, 2.1, where no
 *   illumination map covers it (caustic_illumination: none) while the exact direct
 *   irradiance of a point light has a value everywhere. plot reads what probe wrote: 4
 *   points on caustic_illumination's line, the 3 left out counted in its legend, 7 on
 *   exact_direct's; a field left empty is still refused (test_plot_refuses_bad_csv).
 * catches: probe's empty cells, which plot refused as a whole file; a missing value
 *   drawn as 0 or as a point at all; the count left out of the legend. */
static void test_plot_reads_probe_off_the_surfaces(struct check *t)
{
    char csv[NAME_MAX_BYTES], svg_name[NAME_MAX_BYTES], log[NAME_MAX_BYTES];
    char args[COMMAND_MAX];
    temp_name(csv, sizeof csv, "plot", "probe.csv");
    temp_name(svg_name, sizeof svg_name, "plot", "probe.svg");
    temp_name(log, sizeof log, "plot", "probe.log");
    snprintf(args, sizeof args, "scenes/mirror-caustic.scene --line 0.3 0 -0.9 0.3 0 2.1 "
             "--samples 7 --photons 20000 -o %s", csv);
    CHECK(t, photon_logged("probe", args, log) == 0);
    char *text = read_text_file(csv);
    CHECK(t, text != NULL && count_of(text, ",none\n") == 3 && count_of(text, "none") == 3);
    free(text);
    snprintf(args, sizeof args, "--linear --x z --y caustic_illumination --y exact_direct "
             "%s -o %s", csv, svg_name);
    CHECK(t, photon_logged("plot", args, log) == 0);
    char *svg = read_text_file(svg_name);
    double xy[2 * 8];
    CHECK(t, svg != NULL && read_polyline(svg, 0, xy, 8) == 4 &&
             read_polyline(svg, 1, xy, 8) == 7 &&
             strstr(svg, "caustic_illumination (3 rows with none)") != NULL);
    free(svg);
    remove(csv);
    remove(svg_name);
    remove(log);
}

void test_plot(struct check *t)
{
    RUN_TEST(t, test_log_axis_fit);
    RUN_TEST(t, test_linear_axis_fit);
    RUN_TEST(t, test_points_land_on_decades);
    RUN_TEST(t, test_linear_profile);
    RUN_TEST(t, test_legend_and_skipped_rows);
    RUN_TEST(t, test_plot_refuses_bad_csv);
    RUN_TEST(t, test_plot_refuses_bad_sets);
    RUN_TEST(t, test_plot_command_line);
    RUN_TEST(t, test_plot_reads_probe_off_the_surfaces);
}
