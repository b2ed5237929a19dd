/*
 * image/plot.c -- the plot of `photon plot` (its command line: plot_command.c): columns of
 * CSV files against one another, one line per run, written as plain SVG 1.1 by hand. By
 * default relative MSE against CPU seconds, log-log, from the renderer's --report files;
 * `--x`, `--y` and `--linear` draw other columns, such as a `photon probe` profile, on
 * linear axes.
 *
 * Input: CSV files read by csv.c (a header naming the columns, rows of finite numbers).
 * Columns are found by name, so files may hold more. A run is one file's column y[i]
 * against its column x: n_files x n_y runs, at most PLOT_MAX_SERIES. On log axes a
 * negative value is refused, and a row with a 0 in x or y has no place: it is skipped,
 * and the legend says how many were ("3 rows at 0 not shown"). It is not refused,
 * because a render compared with itself, or a checkpoint within the clock's resolution,
 * is not bad input; but a plot with no point at all is.
 *
 * Output: the plot area is FRAME_WIDTH x FRAME_HEIGHT units. A log axis spans whole
 * decades (log_axis_fit), labelled 10^k (thinned so labels never crowd), with minor ticks
 * at 2..9 x 10^k where a decade is wide enough, and grid lines at both; a linear axis
 * (linear_axis_fit) has labelled ticks at multiples of a step of 1, 2 or 5 x 10^k. The
 * legend sits to the right of the plot, so it never hides data, and the picture's width
 * follows it. Run i is drawn with STYLES[i]: an Okabe-Ito colour (told apart with
 * colour-blindness), a marker shape and a dash pattern (told apart in greyscale). Fonts
 * are generic sans-serif; numbers are printed with "%.2f" and "%g" in the C locale (no
 * setlocale anywhere). Labels show the file's base name without ".csv" (and the column
 * when several are drawn), with bytes outside printable ASCII shown as '?', so the
 * document is valid XML whatever the names.
 *
 * Nothing is written until every CSV has been read; the SVG goes through output_open()
 * and output_commit(), so it is whole or absent. Each struct series owns its arrays.
 */
#include "plot.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../base/alloc.h"
#include "../base/output.h"
#include "csv.h"

#define SERIES_MAX_ROWS 1000000 /* rows per file: a report has one per checkpoint */
#define LABEL_CHARS 40          /* longest name kept in a label, before "..." */
#define LINEAR_MAX_STEPS 8      /* a linear axis's range / step is at most about this */

/* One run: the points of one column of one CSV file. */
struct series {
    char label[2 * LABEL_CHARS + 16]; /* printable ASCII only */
    double *x, *y;                    /* owned; n_points values each, in file order */
    size_t n_points, capacity;        /* n_points <= capacity, the arrays' length */
    size_t n_skipped;                 /* rows a log axis cannot show (a 0 in x or y) */
    size_t n_missing;                 /* rows with no value in x or y (CSV_NONE)     */
};

struct plot_spec plot_spec_errors(void)
{
    struct plot_spec spec;
    memset(&spec, 0, sizeof spec);
    spec.x = "seconds";
    spec.y[0] = "relmse";
    spec.n_y = 1;
    spec.x_title = spec.y_title = NULL;
    return spec;
}

static void series_free_arrays(struct series *s)
{
    xfree(s->x);
    xfree(s->y);
    s->x = s->y = NULL;
}

/* text, cut to LABEL_CHARS with "...", with bytes outside printable ASCII as '?',
 * appended to label. */
static void append_printable(char *label, const char *text, size_t n)
{
    size_t at = strlen(label), kept = n > LABEL_CHARS ? LABEL_CHARS : n;
    for (size_t i = 0; i < kept; i++) {
        unsigned char c = (unsigned char)text[i];
        label[at + i] = c >= 0x20 && c < 0x7F ? (char)c : '?';
    }
    strcpy(label + at + kept, n > kept ? "..." : "");
}

/* The run's label: the base name of path without a ".csv" ending, or the column's name,
 * or both, whichever tells the runs of this plot apart. */
static void series_label(const char *path, const char *column, int n_files, int n_columns,
                         char *label)
{
    const char *base = strrchr(path, '/') != NULL ? strrchr(path, '/') + 1 : path;
    size_t n = strlen(base);
    if (n > 4 && strcmp(base + n - 4, ".csv") == 0)
        n -= 4;
    label[0] = '\0';
    if (n_files > 1 || n_columns == 1)
        append_printable(label, base, n);
    if (n_files > 1 && n_columns > 1)
        strcat(label, ": ");
    if (n_columns > 1)
        append_printable(label, column, strlen(column));
}

static void series_add(struct series *s, double x, double y)
{
    if (s->n_points == s->capacity) {
        s->capacity = s->capacity == 0 ? 64 : 2 * s->capacity;
        s->x = xrealloc(s->x, s->capacity, sizeof *s->x, "plot points");
        s->y = xrealloc(s->y, s->capacity, sizeof *s->y, "plot points");
    }
    s->x[s->n_points] = x;
    s->y[s->n_points] = y;
    s->n_points++;
}

/* One row's point (x, y) into s: left out (counted) when either has no value (NaN, a
 * CSV_NONE field: a probe line leaving the surfaces); on log axes refused when negative,
 * skipped (counted) when 0. */
static int add_row(const struct csv *csv, const struct plot_spec *spec, double x, double y,
                   const char *y_name, struct series *s, struct error *err)
{
    if (isnan(x) || isnan(y)) {
        s->n_missing++;
        return 0;
    }
    if (!spec->linear && (x < 0 || y < 0))
        return error_set(err, csv->name, csv->line, "%s must be >= 0 on a log axis, "
                                                    "found %g", x < 0 ? spec->x : y_name,
                         x < 0 ? x : y);
    if (!spec->linear && (x == 0 || y == 0))
        s->n_skipped++;
    else
        series_add(s, x, y);
    return 0;
}

/* The header's column called name; -1 with *err filled when there is none. */
static int find_column(const struct csv *csv, const char *name, struct error *err)
{
    int column = csv_column(csv, name);
    if (column < 0)
        return error_set(err, csv->name, csv->header_line, "the header has no column "
                                                           "named '%s' (a --report file's "
                                                           "is seconds,work,rmse,relmse)",
                         name);
    return column;
}

/* The rows of an open file into s[0 .. spec->n_y - 1]. */
static int read_rows(struct csv *csv, const struct plot_spec *spec, struct series *s,
                     struct error *err)
{
    int col_x = find_column(csv, spec->x, err), col_y[PLOT_MAX_SERIES];
    if (col_x < 0)
        return -1;
    for (int i = 0; i < spec->n_y; i++) {
        if ((col_y[i] = find_column(csv, spec->y[i], err)) < 0)
            return -1;
    }
    double value[CSV_FIELDS_MAX];
    int status, rows = 0;
    while ((status = csv_next_row(csv, value, err)) == 1) {
        if (++rows > SERIES_MAX_ROWS)
            return error_set(err, csv->name, csv->line, "more than %d rows",
                             SERIES_MAX_ROWS);
        for (int i = 0; i < spec->n_y; i++) {
            if (add_row(csv, spec, value[col_x], value[col_y[i]], spec->y[i], &s[i], err))
                return -1;
        }
    }
    if (status == 0 && rows == 0)
        return error_set(err, csv->name, csv->header_line, "no rows after the header");
    return status;
}

/* Reads one file's runs into s[0 .. spec->n_y - 1] (zeroed here); -1 with *err filled
 * and the runs emptied. */
static int series_read(const char *name, const struct plot_spec *spec, int n_files,
                       struct series *s, struct error *err)
{
    for (int i = 0; i < spec->n_y; i++) {
        memset(&s[i], 0, sizeof s[i]);
        s[i].x = s[i].y = NULL;
        series_label(name, spec->y[i], n_files, spec->n_y, s[i].label);
    }
    struct csv csv;
    if (csv_open(&csv, name, err) != 0)
        return -1;
    int status = read_rows(&csv, spec, s, err);
    csv_close(&csv);
    for (int i = 0; i < spec->n_y && status != 0; i++)
        series_free_arrays(&s[i]);
    return status;
}

struct log_axis log_axis_fit(double lo, double hi)
{
    assert(isfinite(lo) && isfinite(hi) && 0 < lo && lo <= hi);
    struct log_axis axis;
    /* log10 is exactly k at the double nearest 10^k in the libms we build with (the tests
     * check 1e-9, 1e-3, 1, 1e3, 1e300), so a value on a decade sits on the axis's end
     * instead of adding an empty decade. */
    axis.k_lo = (int)floor(log10(lo));
    axis.k_hi = (int)ceil(log10(hi));
    if (axis.k_lo == axis.k_hi) {
        axis.k_lo--;
        axis.k_hi++;
    }
    return axis;
}

struct linear_axis linear_axis_fit(double lo, double hi)
{
    assert(isfinite(lo) && isfinite(hi) && lo <= hi);
    if (lo == hi) {
        double widen = lo != 0 ? 0.5 * fabs(lo) : 1.0;
        lo -= widen;
        hi += widen;
    }
    double least = (hi - lo) / LINEAR_MAX_STEPS, decade = pow(10.0, floor(log10(least)));
    static const double mantissa[4] = {1, 2, 5, 10};
    struct linear_axis axis;
    axis.step = 10 * decade;
    for (int i = 0; i < 4; i++) {
        if (mantissa[i] * decade >= least) {
            axis.step = mantissa[i] * decade;
            break;
        }
    }
    axis.lo = floor(lo / axis.step) * axis.step;
    axis.hi = ceil(hi / axis.step) * axis.step;
    return axis;
}

/* ---------------------------------------------------------------- the picture */

/* Layout in SVG user units (px at 100%). */
#define FRAME_LEFT 74.0            /* room for labels such as 10^-12 and the axis title */
#define FRAME_TOP 14.0
#define FRAME_WIDTH 480.0
#define FRAME_HEIGHT 340.0
#define MARGIN_BOTTOM 54.0         /* tick labels and the axis title below the frame */
#define TICK_MAJOR 6.0             /* tick lengths, drawn outward from the frame */
#define TICK_MINOR 3.0
#define MINOR_MIN_DECADE 30.0      /* a decade narrower than this gets no 2..9 ticks, */
#define MINOR_GRID_MIN_DECADE 60.0 /* and narrower than this no grid lines at them */
#define LABEL_MIN_GAP_X 44.0       /* labels "10^-12" closer than this would touch */
#define LABEL_MIN_GAP_Y 22.0
#define LEGEND_GAP 18.0            /* between the frame and the legend box */
#define LEGEND_ROW 20.0
#define LEGEND_CHAR 6.6            /* average advance of a 12 px sans-serif character */
#define FONT_SIZE 12.0
#define GRID_MAJOR "#d0d0d0"
#define GRID_MINOR "#efefef"

enum axis_dir { AXIS_X, AXIS_Y };

/* The kinds of mark along an axis, and the layers they are drawn in, bottom first. */
enum mark { MARK_MAJOR, MARK_MINOR, MARK_MINOR_GRID };
enum layer { LAYER_MINOR_GRID, LAYER_MAJOR_GRID, LAYER_TICKS };

/* One axis: logarithmic or linear. */
struct axis {
    int linear;
    struct log_axis log;       /* when !linear */
    struct linear_axis lin;    /* when linear */
    const char *title;         /* borrowed */
};

/* The plot area and its axes. */
struct frame {
    double left, top, width, height; /* the area inside the axes */
    struct axis x, y;
};

/* How run i is drawn. Colours: Okabe & Ito (2008) for the first seven, then Tol's wine
 * instead of their yellow, which is too faint on white. Markers are paths around (0, 0). */
struct style {
    const char *colour;
    const char *dash;   /* stroke-dasharray */
    const char *marker; /* path data */
    int filled;         /* marker filled with the colour, else white with a coloured edge */
};

static const struct style STYLES[PLOT_MAX_SERIES] = {
    {"#0072B2", "none", "M3.6,0A3.6,3.6 0 1,1 -3.6,0A3.6,3.6 0 1,1 3.6,0Z", 1},
    {"#D55E00", "7,3", "M-3.2,-3.2H3.2V3.2H-3.2Z", 1},
    {"#009E73", "2,2.5", "M0,-4.4L3.9,2.6H-3.9Z", 1},
    {"#CC79A7", "9,3,2,3", "M0,-4.6L4.6,0L0,4.6L-4.6,0Z", 1},
    {"#E69F00", "none", "M3.4,0A3.4,3.4 0 1,1 -3.4,0A3.4,3.4 0 1,1 3.4,0Z", 0},
    {"#56B4E9", "7,3", "M-3,-3H3V3H-3Z", 0},
    {"#000000", "2,2.5", "M0,4.4L3.9,-2.6H-3.9Z", 0},
    {"#882255", "9,3,2,3", "M-3.5,-3.5L3.5,3.5M-3.5,3.5L3.5,-3.5", 0},
};

/* Where u lies along the axis, in user units; u is log10 of the value on a log axis, the
 * value itself on a linear one. */
static double axis_position(const struct frame *fr, enum axis_dir dir, double u)
{
    const struct axis *a = dir == AXIS_X ? &fr->x : &fr->y;
    double t = a->linear ? (u - a->lin.lo) / (a->lin.hi - a->lin.lo) /* lo < hi: fitted */
                         : (u - a->log.k_lo) / (a->log.k_hi - a->log.k_lo);
    return dir == AXIS_X ? fr->left + t * fr->width : fr->top + (1.0 - t) * fr->height;
}

/* Where the value v lies along the axis, in user units. */
static double value_position(const struct frame *fr, enum axis_dir dir, double v)
{
    const struct axis *a = dir == AXIS_X ? &fr->x : &fr->y;
    return axis_position(fr, dir, a->linear ? v : log10(v));
}

/* One layer of one axis being drawn. */
struct axis_pass {
    const struct frame *fr;
    enum axis_dir dir;
    enum layer layer;
};

/* What a mark of this kind draws in p's layer at position t along the axis: its grid line
 * across the frame in the grid layer it belongs to, its tick outward from the frame (in
 * the enclosing group's black) in LAYER_TICKS, else nothing. */
static void write_mark(FILE *f, const struct axis_pass *p, double t, enum mark kind)
{
    const struct frame *fr = p->fr;
    const char *grid = NULL;
    if (p->layer == LAYER_MAJOR_GRID && kind == MARK_MAJOR)
        grid = GRID_MAJOR;
    if (p->layer == LAYER_MINOR_GRID && kind == MARK_MINOR_GRID)
        grid = GRID_MINOR;
    if (grid == NULL && p->layer != LAYER_TICKS)
        return;
    double tick = kind == MARK_MAJOR ? TICK_MAJOR : TICK_MINOR;
    double from, to; /* the line's extent across the axis */
    if (p->dir == AXIS_X) {
        from = grid != NULL ? fr->top : fr->top + fr->height;
        to = fr->top + fr->height + (grid != NULL ? 0 : tick);
        fprintf(f, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"", t, from, t, to);
    } else {
        from = fr->left - (grid != NULL ? 0 : tick);
        to = grid != NULL ? fr->left + fr->width : fr->left;
        fprintf(f, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"", from, t, to, t);
    }
    if (grid != NULL)
        fprintf(f, " stroke=\"%s\"", grid);
    fprintf(f, "/>\n");
}

/* "10^k" with k raised, and a true minus sign, at (x, y) with the given text-anchor; not
 * stroked, although it sits in the axes' stroked group. */
static void write_power_of_ten(FILE *f, int k, double x, double y, const char *anchor)
{
    fprintf(f, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"%s\" stroke=\"none\">10<tspan "
               "dy=\"-5\" font-size=\"9\">%s%d</tspan></text>\n", x, y, anchor,
            k < 0 ? "&#8722;" : "", abs(k));
}

/* A linear axis's label: the number in the shortest form, at (x, y). */
static void write_number(FILE *f, double v, double x, double y, const char *anchor)
{
    fprintf(f, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"%s\" stroke=\"none\">%g</text>\n",
            x, y, anchor, v);
}

/* Labels every step-th decade, step in 1, 2, 5, 10, 20, 50, ..., the least that puts
 * labels gap or more apart (decade >= 480 / 633 units: doubles span 633 decades). */
static int label_step(double decade, double gap)
{
    static const int mantissa[3] = {1, 2, 5};
    int step = 1;
    for (int power = 1; power <= 1000; power *= 10) {
        for (int j = 0; j < 3; j++) {
            step = mantissa[j] * power;
            if (step * decade >= gap)
                return step;
        }
    }
    return step;
}

/* One layer of a linear axis: a labelled major tick and grid line at every step. */
static void write_linear_axis(FILE *f, const struct frame *fr, enum axis_dir dir,
                              enum layer layer)
{
    struct axis_pass p = {fr, dir, layer};
    const struct linear_axis *a = dir == AXIS_X ? &fr->x.lin : &fr->y.lin;
    long first = lround(a->lo / a->step), last = lround(a->hi / a->step);
    for (long i = first; i <= last; i++) {
        double v = i == 0 ? 0.0 : (double)i * a->step, t = axis_position(fr, dir, v);
        if (layer == LAYER_TICKS && dir == AXIS_X)
            write_number(f, v, t, fr->top + fr->height + TICK_MAJOR + 15, "middle");
        else if (layer == LAYER_TICKS)
            write_number(f, v, fr->left - TICK_MAJOR - 4, t + 4, "end");
        write_mark(f, &p, t, MARK_MAJOR);
    }
}

/* One layer of one axis. Labelled decades get a major tick, a grid line and a label;
 * other decades a minor tick (where decades are >= 3 units apart); wide decades also get
 * minor ticks at 2..9 x 10^k, and wider ones light grid lines there. */
static void write_axis(FILE *f, const struct frame *fr, enum axis_dir dir, enum layer layer)
{
    if ((dir == AXIS_X ? &fr->x : &fr->y)->linear) {
        write_linear_axis(f, fr, dir, layer);
        return;
    }
    struct axis_pass p = {fr, dir, layer};
    const struct log_axis *a = dir == AXIS_X ? &fr->x.log : &fr->y.log;
    double length = dir == AXIS_X ? fr->width : fr->height;
    double decade = length / (a->k_hi - a->k_lo); /* k_hi > k_lo: log_axis_fit */
    int step = label_step(decade, dir == AXIS_X ? LABEL_MIN_GAP_X : LABEL_MIN_GAP_Y);
    enum mark minor = decade >= MINOR_GRID_MIN_DECADE ? MARK_MINOR_GRID : MARK_MINOR;
    for (int k = a->k_lo; k <= a->k_hi; k++) {
        double t = axis_position(fr, dir, k);
        int labelled = ((k % step) + step) % step == 0;
        if (labelled && layer == LAYER_TICKS && dir == AXIS_X)
            write_power_of_ten(f, k, t, fr->top + fr->height + TICK_MAJOR + 15, "middle");
        else if (labelled && layer == LAYER_TICKS)
            write_power_of_ten(f, k, fr->left - TICK_MAJOR - 4, t + 4, "end");
        if (labelled || decade >= 3)
            write_mark(f, &p, t, labelled ? MARK_MAJOR : MARK_MINOR);
        for (int m = 2; m <= 9 && k < a->k_hi && decade >= MINOR_MIN_DECADE; m++)
            write_mark(f, &p, axis_position(fr, dir, k + log10((double)m)), minor);
    }
}

/* XML character data: &, < and > escaped, bytes outside printable ASCII as '?' (titles
 * come from the command line; labels are printable already). */
static void write_escaped(FILE *f, const char *text)
{
    for (; *text != '\0'; text++) {
        if (*text == '&')
            fputs("&amp;", f);
        else if (*text == '<')
            fputs("&lt;", f);
        else if (*text == '>')
            fputs("&gt;", f);
        else
            putc(*text >= 0x20 && *text < 0x7F ? *text : '?', f);
    }
}

/* Grid lines (light ones under dark ones, both under everything else), ticks and tick
 * labels, the frame, and the axis titles. */
static void write_axes(FILE *f, const struct frame *fr)
{
    fprintf(f, "<g stroke=\"#000000\" stroke-width=\"1\">\n");
    for (int layer = LAYER_MINOR_GRID; layer <= LAYER_TICKS; layer++) {
        write_axis(f, fr, AXIS_X, (enum layer)layer);
        write_axis(f, fr, AXIS_Y, (enum layer)layer);
    }
    fprintf(f, "</g>\n<rect id=\"frame\" x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" "
               "fill=\"none\" stroke=\"#000000\"/>\n", fr->left, fr->top, fr->width,
            fr->height);
    fprintf(f, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\" font-size=\"13\">",
            fr->left + 0.5 * fr->width, fr->top + fr->height + MARGIN_BOTTOM - 10);
    write_escaped(f, fr->x.title);
    fprintf(f, "</text>\n<text transform=\"translate(%.2f,%.2f) rotate(-90)\" "
               "text-anchor=\"middle\" font-size=\"13\">", 18.0, fr->top + 0.5 * fr->height);
    write_escaped(f, fr->y.title);
    fprintf(f, "</text>\n");
}

/* One run: its line, then a marker at each point (on top of the line). */
static void write_series(FILE *f, const struct frame *fr, const struct series *s, int i)
{
    const struct style *st = &STYLES[i];
    fprintf(f, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1.6\" "
               "stroke-dasharray=\"%s\" stroke-linejoin=\"round\" points=\"", st->colour,
            st->dash);
    for (size_t p = 0; p < s->n_points; p++)
        fprintf(f, "%s%.2f,%.2f", p > 0 ? " " : "",
                value_position(fr, AXIS_X, s->x[p]), value_position(fr, AXIS_Y, s->y[p]));
    fprintf(f, "\"/>\n<g fill=\"%s\" stroke=\"%s\" stroke-width=\"1.2\">\n",
            st->filled ? st->colour : "#ffffff", st->colour);
    for (size_t p = 0; p < s->n_points; p++)
        fprintf(f, "<use xlink:href=\"#marker%d\" x=\"%.2f\" y=\"%.2f\"/>\n", i,
                value_position(fr, AXIS_X, s->x[p]), value_position(fr, AXIS_Y, s->y[p]));
    fprintf(f, "</g>\n");
}

/* The legend text of s: its label, and how many rows a log axis could not show and how
 * many had no value. */
static void legend_text(const struct series *s, char *text, size_t size)
{
    size_t n = (size_t)snprintf(text, size, "%.*s", LABEL_CHARS + 3, s->label);
    if (s->n_skipped > 0 && n < size)
        n += (size_t)snprintf(text + n, size - n, " (%lu row%s at 0 not shown)",
                              (unsigned long)s->n_skipped, s->n_skipped == 1 ? "" : "s");
    if (s->n_missing > 0 && n < size)
        snprintf(text + n, size - n, " (%lu row%s with none)", (unsigned long)s->n_missing,
                 s->n_missing == 1 ? "" : "s");
}

/* The legend's width: its longest text at LEGEND_CHAR per character, plus the sample. */
static double legend_width(const struct series *s, int n_series)
{
    size_t longest = 0;
    for (int i = 0; i < n_series; i++) {
        char text[2 * LABEL_CHARS + 64];
        legend_text(&s[i], text, sizeof text);
        longest = strlen(text) > longest ? strlen(text) : longest;
    }
    return 56 + LEGEND_CHAR * (double)longest;
}

/* The legend's left edge: right of the frame. */
static double legend_left(const struct frame *fr)
{
    return fr->left + fr->width + LEGEND_GAP;
}

static void write_legend(FILE *f, const struct frame *fr, const struct series *s,
                         int n_series)
{
    double x = legend_left(fr), width = legend_width(s, n_series), top = fr->top;
    fprintf(f, "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"#ffffff\" "
               "stroke=\"#b0b0b0\"/>\n", x, top, width, n_series * LEGEND_ROW + 8);
    for (int i = 0; i < n_series; i++) {
        const struct style *st = &STYLES[i];
        double y = top + 4 + (i + 0.5) * LEGEND_ROW;
        char text[2 * LABEL_CHARS + 64];
        fprintf(f, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"%s\" "
                   "stroke-width=\"1.6\" stroke-dasharray=\"%s\"/>\n", x + 8, y, x + 38, y,
                st->colour, st->dash);
        fprintf(f, "<use xlink:href=\"#marker%d\" x=\"%.2f\" y=\"%.2f\" fill=\"%s\" "
                   "stroke=\"%s\" stroke-width=\"1.2\"/>\n", i, x + 23, y,
                st->filled ? st->colour : "#ffffff", st->colour);
        legend_text(&s[i], text, sizeof text);
        fprintf(f, "<text x=\"%.2f\" y=\"%.2f\">", x + 46, y + 4);
        write_escaped(f, text);
        fprintf(f, "</text>\n");
    }
}

/* The SVG document: header and marker definitions, axes, runs, legend. */
static void write_svg(FILE *f, const struct frame *fr, const struct series *s, int n_series)
{
    double width = legend_left(fr) + legend_width(s, n_series) + 10;
    double height = fr->top + fr->height + MARGIN_BOTTOM;
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<svg xmlns=\"http://www.w3.org/2000/svg\" "
               "xmlns:xlink=\"http://www.w3.org/1999/xlink\" version=\"1.1\" "
               "width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" "
               "font-family=\"sans-serif\" font-size=\"%.0f\">\n", width, height, width, height,
            FONT_SIZE);
    fprintf(f, "<defs>\n");
    for (int i = 0; i < n_series; i++)
        fprintf(f, "<path id=\"marker%d\" d=\"%s\"/>\n", i, STYLES[i].marker);
    fprintf(f, "</defs>\n<rect width=\"%.0f\" height=\"%.0f\" fill=\"#ffffff\"/>\n", width,
            height);
    write_axes(f, fr);
    for (int i = 0; i < n_series; i++)
        write_series(f, fr, &s[i], i);
    write_legend(f, fr, s, n_series);
    fprintf(f, "</svg>\n");
}

/* An axis title: the column's name, or for the --report columns what they measure. */
static const char *column_title(const char *column)
{
    if (strcmp(column, "seconds") == 0)
        return "seconds (CPU)";
    if (strcmp(column, "relmse") == 0)
        return "relative MSE";
    return column;
}

/* An axis of the given kind over [lo, hi]. */
static struct axis axis_fit(int linear, double lo, double hi, const char *title)
{
    struct axis a;
    memset(&a, 0, sizeof a);
    a.linear = linear;
    if (linear)
        a.lin = linear_axis_fit(lo, hi);
    else
        a.log = log_axis_fit(lo, hi);
    a.title = title;
    return a;
}

/* The frame around every plotted point of every run; -1 when there is none. */
static int fit_frame(const struct series *s, int n_series, const struct plot_spec *spec,
                     struct frame *fr, struct error *err)
{
    double x_lo = HUGE_VAL, x_hi = -HUGE_VAL, y_lo = HUGE_VAL, y_hi = -HUGE_VAL;
    for (int i = 0; i < n_series; i++) {
        for (size_t p = 0; p < s[i].n_points; p++) {
            x_lo = fmin(x_lo, s[i].x[p]);
            x_hi = fmax(x_hi, s[i].x[p]);
            y_lo = fmin(y_lo, s[i].y[p]);
            y_hi = fmax(y_hi, s[i].y[p]);
        }
    }
    if (x_lo > x_hi && spec->linear)
        return error_set(err, "", 0, "plot: nothing to plot: no row has values of both %s "
                         "and %s", spec->x, spec->n_y == 1 ? spec->y[0] : "y");
    if (x_lo > x_hi)
        return error_set(err, "", 0, "plot: nothing to plot: no row has %s > 0 and %s > 0 "
                                     "(log axes)", spec->x, spec->n_y == 1 ? spec->y[0] : "y");
    fr->left = FRAME_LEFT;
    fr->top = FRAME_TOP;
    fr->width = FRAME_WIDTH;
    fr->height = FRAME_HEIGHT;
    const char *y_title = spec->n_y == 1 ? column_title(spec->y[0]) : "value";
    fr->x = axis_fit(spec->linear, x_lo, x_hi, spec->x_title ? spec->x_title
                                                              : column_title(spec->x));
    fr->y = axis_fit(spec->linear, y_lo, y_hi, spec->y_title ? spec->y_title : y_title);
    return 0;
}

/* Writes the plot to svg through output_open() and output_commit(). */
static int write_plot(const char *svg, const struct frame *fr, const struct series *s,
                      int n_series, struct error *err)
{
    FILE *f = output_open(svg, err);
    if (f == NULL)
        return -1;
    write_svg(f, fr, s, n_series);
    return output_commit(f, err); /* a failed write shows in ferror(), checked there */
}

int plot_files(const char *const *csv, int n_csv, const struct plot_spec *spec,
               const char *svg, struct error *err)
{
    struct series s[PLOT_MAX_SERIES];
    int n_read = 0, status = 0, n_series = n_csv * spec->n_y;
    if (spec->n_y < 1 || n_csv < 1 || n_series > PLOT_MAX_SERIES)
        return error_set(err, "", 0, "plot: %d CSV files x %d columns; a plot shows 1 to %d "
                                     "runs", n_csv, spec->n_y, PLOT_MAX_SERIES);
    for (; n_read < n_csv; n_read++) { /* on -1, series_read frees its own */
        status = series_read(csv[n_read], spec, n_csv, &s[n_read * spec->n_y], err);
        if (status != 0)
            break;
    }
    struct frame fr;
    memset(&fr, 0, sizeof fr); /* filled by fit_frame(); zeroed so no compiler wonders */
    if (status == 0)
        status = fit_frame(s, n_series, spec, &fr, err);
    if (status == 0)
        status = write_plot(svg, &fr, s, n_series, err);
    for (int i = 0; i < n_read * spec->n_y; i++)
        series_free_arrays(&s[i]);
    return status;
}
