/*
 * image/plot.c -- `photon plot A.csv [B.csv ...] -o PLOT.svg`: relative MSE against CPU
 * seconds, log-log, one line per run, written as plain SVG 1.1 by hand.
 *
 * Input: the renderer's --report files, a header line naming the columns
 * ("seconds,work,rmse,relmse") and one row of numbers per checkpoint. Columns are found
 * by name, so more may be added; every field of every row must be a finite number, and
 * seconds and relmse must be >= 0. Blank lines are ignored. Limits: lines of CSV_LINE_MAX
 * bytes, CSV_FIELDS_MAX columns, SERIES_MAX_ROWS rows, PLOT_MAX_SERIES files. A row with
 * seconds = 0 or relmse = 0 has no place on a log axis: it is skipped, and the legend says
 * how many were ("3 rows at 0 not shown"). It is not refused, because a render compared
 * with itself, or a checkpoint within the clock's resolution, is not bad input; but a
 * plot with no point at all is.
 *
 * Output: the plot area is FRAME_WIDTH x FRAME_HEIGHT units, each axis whole decades
 * (log_axis_fit), labelled 10^k (thinned so labels never crowd), with minor ticks at
 * 2..9 x 10^k where a decade is wide enough, and grid lines at both; the legend sits to
 * the right of the plot, so it never hides data, and the picture's width follows it. Run
 * i is drawn with STYLES[i]: an Okabe-Ito colour (told apart with colour-blindness), a
 * marker shape and a dash pattern (told apart in greyscale). Fonts are generic
 * sans-serif; numbers are printed with "%.2f" in the C locale (no setlocale anywhere).
 * Labels show the file's base name without ".csv", with bytes outside printable ASCII
 * shown as '?', so the document is valid XML whatever the file name.
 *
 * Nothing is written until every CSV has been read; the SVG goes through output_open()
 * and output_commit(), so it is whole or absent. Each struct series owns its arrays.
 */
#include "plot.h"

#include <assert.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../base/alloc.h"

#define CSV_LINE_MAX 1024       /* longest line read; a report row is under 100 bytes */
#define CSV_FIELDS_MAX 16       /* columns in a header; a report has 4 */
#define SERIES_MAX_ROWS 1000000 /* rows per file: a report has one per checkpoint */
#define LABEL_CHARS 40          /* longest legend label kept, before "..." */
#define PLOT_USAGE "usage: photon plot A.csv [B.csv ...] -o PLOT.svg"

/* One run: the points of one CSV file that a log-log plot can show. */
struct series {
    char label[LABEL_CHARS + 4]; /* base name without ".csv", printable ASCII only */
    double *seconds;             /* owned; n_points values > 0, in file order */
    double *relmse;              /* owned; n_points values > 0 */
    size_t n_points, capacity;   /* n_points <= capacity, the arrays' length */
    size_t n_skipped;            /* rows with seconds = 0 or relmse = 0 */
};

/* A CSV file being read, one line at a time. */
struct csv {
    FILE *f;                          /* owned by series_read(), which opens and closes it */
    const char *name;                 /* borrowed: the file's name, for messages */
    int line;                         /* 1-based number of the line in text */
    char text[CSV_LINE_MAX + 2];      /* the line, without its end; fields point into it */
    char *field[CSV_FIELDS_MAX];      /* the line's comma-separated fields, trimmed */
    int n_fields;
    int n_columns;                    /* the header's fields: every row must have as many */
    int col_seconds, col_relmse;      /* the header's columns named seconds and relmse */
};

static void series_free_arrays(struct series *s)
{
    free(s->seconds);
    free(s->relmse);
    s->seconds = s->relmse = NULL;
}

/* The base name of path without a ".csv" ending, cut to LABEL_CHARS with "...". */
static void series_label(const char *path, char *label)
{
    const char *base = strrchr(path, '/') != NULL ? strrchr(path, '/') + 1 : path;
    size_t n = strlen(base);
    if (n > 4 && strcmp(base + n - 4, ".csv") == 0)
        n -= 4;
    size_t kept = n > LABEL_CHARS ? LABEL_CHARS : n;
    for (size_t i = 0; i < kept; i++) {
        unsigned char c = (unsigned char)base[i];
        label[i] = c >= 0x20 && c < 0x7F ? (char)c : '?';
    }
    strcpy(label + kept, n > kept ? "..." : "");
}

static void series_add(struct series *s, double seconds, double relmse)
{
    if (s->n_points == s->capacity) {
        s->capacity = s->capacity == 0 ? 64 : 2 * s->capacity;
        s->seconds = xrealloc(s->seconds, s->capacity, sizeof *s->seconds, "plot points");
        s->relmse = xrealloc(s->relmse, s->capacity, sizeof *s->relmse, "plot points");
    }
    s->seconds[s->n_points] = seconds;
    s->relmse[s->n_points] = relmse;
    s->n_points++;
}

static int is_blank(int c)
{
    return c == ' ' || c == '\t';
}

/* Reads the next line that is not blank into csv->text, without its end. Returns 1 for
 * a line, 0 at the end of the file, -1 with *err filled. */
static int csv_read_line(struct csv *csv, struct error *err)
{
    do {
        if (fgets(csv->text, sizeof csv->text, csv->f) == NULL) {
            if (ferror(csv->f))
                return error_set(err, csv->name, 0, "cannot read the file (is it a "
                                                    "directory?)");
            return 0;
        }
        csv->line++;
        size_t n = strcspn(csv->text, "\r\n");
        if (n > CSV_LINE_MAX) /* text has room for CSV_LINE_MAX bytes and the line end */
            return error_set(err, csv->name, csv->line, "line longer than %d bytes",
                             CSV_LINE_MAX);
        csv->text[n] = '\0';
    } while (csv->text[strspn(csv->text, " \t")] == '\0');
    return 1;
}

/* Splits csv->text at its commas into csv->field[], each trimmed of spaces and tabs. */
static int csv_split(struct csv *csv, struct error *err)
{
    csv->n_fields = 0;
    for (char *p = csv->text; p != NULL; csv->n_fields++) {
        if (csv->n_fields == CSV_FIELDS_MAX)
            return error_set(err, csv->name, csv->line, "more than %d columns",
                             CSV_FIELDS_MAX);
        char *comma = strchr(p, ',');
        if (comma != NULL)
            *comma = '\0';
        while (is_blank(*p))
            p++;
        for (char *end = p + strlen(p); end > p && is_blank(end[-1]); end--)
            end[-1] = '\0';
        csv->field[csv->n_fields] = p;
        p = comma != NULL ? comma + 1 : NULL;
    }
    return 0;
}

/* The next line that is not blank, split into fields: 1, 0 at the end, -1 on error. */
static int csv_next_line(struct csv *csv, struct error *err)
{
    int status = csv_read_line(csv, err);
    if (status == 1 && csv_split(csv, err) != 0)
        return -1;
    return status;
}

/* The header: the number of columns and which are named "seconds" and "relmse". */
static int csv_read_header(struct csv *csv, struct error *err)
{
    int status = csv_next_line(csv, err);
    if (status < 0)
        return -1;
    if (status == 0)
        return error_set(err, csv->name, 0, "empty file: expected a --report CSV "
                                            "(header seconds,work,rmse,relmse)");
    csv->n_columns = csv->n_fields;
    csv->col_seconds = csv->col_relmse = -1;
    for (int i = 0; i < csv->n_fields; i++) {
        if (strcmp(csv->field[i], "seconds") == 0)
            csv->col_seconds = i;
        if (strcmp(csv->field[i], "relmse") == 0)
            csv->col_relmse = i;
    }
    if (csv->col_seconds < 0 || csv->col_relmse < 0)
        return error_set(err, csv->name, csv->line, "expected a header naming the columns "
                                                    "seconds and relmse, such as "
                                                    "seconds,work,rmse,relmse");
    return 0;
}

/* Every field a finite number (strtod's whole syntax, nothing after it). */
static int csv_parse_row(const struct csv *csv, double *value, struct error *err)
{
    if (csv->n_fields != csv->n_columns)
        return error_set(err, csv->name, csv->line, "expected %d fields as in the header, "
                                                    "found %d", csv->n_columns, csv->n_fields);
    for (int i = 0; i < csv->n_columns; i++) {
        char *end;
        value[i] = strtod(csv->field[i], &end);
        if (end == csv->field[i] || *end != '\0' || !isfinite(value[i]))
            return error_set(err, csv->name, csv->line, "field %d '%s' is not a finite "
                                                        "number", i + 1, csv->field[i]);
    }
    return 0;
}

/* One data row into s: refused when negative, skipped (counted) when 0. */
static int csv_add_row(const struct csv *csv, const double *value, struct series *s,
                       struct error *err)
{
    double seconds = value[csv->col_seconds], relmse = value[csv->col_relmse];
    if (seconds < 0 || relmse < 0)
        return error_set(err, csv->name, csv->line, "%s must be >= 0, found %g",
                         seconds < 0 ? "seconds" : "relmse", seconds < 0 ? seconds : relmse);
    if (s->n_points + s->n_skipped == SERIES_MAX_ROWS)
        return error_set(err, csv->name, csv->line, "more than %d rows", SERIES_MAX_ROWS);
    if (seconds == 0 || relmse == 0)
        s->n_skipped++;
    else
        series_add(s, seconds, relmse);
    return 0;
}

static int csv_read_rows(struct csv *csv, struct series *s, struct error *err)
{
    if (csv_read_header(csv, err) != 0)
        return -1;
    int header_line = csv->line, status;
    double value[CSV_FIELDS_MAX];
    while ((status = csv_next_line(csv, err)) == 1) {
        if (csv_parse_row(csv, value, err) != 0 || csv_add_row(csv, value, s, err) != 0)
            return -1;
    }
    if (status == 0 && s->n_points + s->n_skipped == 0)
        return error_set(err, csv->name, header_line, "no rows after the header");
    return status;
}

/* Reads one --report file into *s (zeroed here); -1 with *err filled and s emptied. */
static int series_read(const char *name, struct series *s, struct error *err)
{
    memset(s, 0, sizeof *s);
    s->seconds = s->relmse = NULL;
    series_label(name, s->label);
    struct csv csv;
    csv.name = name;
    csv.line = 0;
    csv.f = fopen(name, "rb");
    if (csv.f == NULL)
        return error_set(err, name, 0, "cannot open for reading: %s", strerror(errno));
    int status = csv_read_rows(&csv, s, err);
    fclose(csv.f);
    if (status != 0)
        series_free_arrays(s);
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

/* The plot area and its axes. */
struct frame {
    double left, top, width, height; /* the area inside the axes */
    struct log_axis x, y;            /* seconds, relmse */
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

/* Where log10(v) = log_v lies along the axis, in user units. */
static double axis_position(const struct frame *fr, enum axis_dir dir, double log_v)
{
    const struct log_axis *a = dir == AXIS_X ? &fr->x : &fr->y;
    double t = (log_v - a->k_lo) / (a->k_hi - a->k_lo); /* k_hi > k_lo: log_axis_fit */
    return dir == AXIS_X ? fr->left + t * fr->width : fr->top + (1.0 - t) * fr->height;
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

/* One layer of one axis. Labelled decades get a major tick, a grid line and a label;
 * other decades a minor tick (where decades are >= 3 units apart); wide decades also get
 * minor ticks at 2..9 x 10^k, and wider ones light grid lines there. */
static void write_axis(FILE *f, const struct frame *fr, enum axis_dir dir, enum layer layer)
{
    struct axis_pass p = {fr, dir, layer};
    const struct log_axis *a = dir == AXIS_X ? &fr->x : &fr->y;
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
    fprintf(f, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\" font-size=\"13\">"
               "seconds (CPU)</text>\n", fr->left + 0.5 * fr->width,
            fr->top + fr->height + MARGIN_BOTTOM - 10);
    fprintf(f, "<text transform=\"translate(%.2f,%.2f) rotate(-90)\" text-anchor=\"middle\" "
               "font-size=\"13\">relative MSE</text>\n", 18.0, fr->top + 0.5 * fr->height);
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
                axis_position(fr, AXIS_X, log10(s->seconds[p])),
                axis_position(fr, AXIS_Y, log10(s->relmse[p])));
    fprintf(f, "\"/>\n<g fill=\"%s\" stroke=\"%s\" stroke-width=\"1.2\">\n",
            st->filled ? st->colour : "#ffffff", st->colour);
    for (size_t p = 0; p < s->n_points; p++)
        fprintf(f, "<use xlink:href=\"#marker%d\" x=\"%.2f\" y=\"%.2f\"/>\n", i,
                axis_position(fr, AXIS_X, log10(s->seconds[p])),
                axis_position(fr, AXIS_Y, log10(s->relmse[p])));
    fprintf(f, "</g>\n");
}

/* The legend text of s: its label, and how many rows a log axis could not show. */
static void legend_text(const struct series *s, char *text, size_t size)
{
    if (s->n_skipped == 0)
        snprintf(text, size, "%.*s", LABEL_CHARS + 3, s->label);
    else
        snprintf(text, size, "%.*s (%lu row%s at 0 not shown)", LABEL_CHARS + 3, s->label,
                 (unsigned long)s->n_skipped, s->n_skipped == 1 ? "" : "s");
}

/* XML character data: &, < and > escaped; labels hold printable ASCII only. */
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
            putc(*text, f);
    }
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

/* The frame around every plotted point of every run; -1 when there is none. */
static int fit_frame(const struct series *s, int n_series, struct frame *fr,
                     struct error *err)
{
    double x_lo = HUGE_VAL, x_hi = 0, y_lo = HUGE_VAL, y_hi = 0;
    for (int i = 0; i < n_series; i++) {
        for (size_t p = 0; p < s[i].n_points; p++) {
            x_lo = fmin(x_lo, s[i].seconds[p]);
            x_hi = fmax(x_hi, s[i].seconds[p]);
            y_lo = fmin(y_lo, s[i].relmse[p]);
            y_hi = fmax(y_hi, s[i].relmse[p]);
        }
    }
    if (!(x_hi > 0))
        return error_set(err, "", 0, "plot: nothing to plot: no row has seconds > 0 and "
                                     "relmse > 0");
    fr->left = FRAME_LEFT;
    fr->top = FRAME_TOP;
    fr->width = FRAME_WIDTH;
    fr->height = FRAME_HEIGHT;
    fr->x = log_axis_fit(x_lo, x_hi);
    fr->y = log_axis_fit(y_lo, y_hi);
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

int plot_files(const char *const *csv, int n_csv, const char *svg, struct error *err)
{
    struct series s[PLOT_MAX_SERIES];
    int n_read = 0, status = 0;
    if (n_csv < 1 || n_csv > PLOT_MAX_SERIES)
        return error_set(err, "", 0, "plot: %d CSV files; a plot shows 1 to %d runs", n_csv,
                         PLOT_MAX_SERIES);
    for (; n_read < n_csv; n_read++) {
        status = series_read(csv[n_read], &s[n_read], err); /* on -1, frees its own */
        if (status != 0)
            break;
    }
    struct frame fr;
    if (status == 0)
        status = fit_frame(s, n_csv, &fr, err);
    if (status == 0)
        status = write_plot(svg, &fr, s, n_csv, err);
    for (int i = 0; i < n_read; i++)
        series_free_arrays(&s[i]);
    return status;
}

/* What `photon plot` was asked to do. */
struct plot_args {
    const char **csv; /* owned by plot_command(); room for argc names, n_csv used */
    int n_csv;
    const char *svg;  /* -o PLOT.svg */
};

/* Files and -o from the command line; -1 with *err filled. */
static int parse_plot_args(int argc, char **argv, struct plot_args *args, struct error *err)
{
    args->n_csv = 0;
    args->svg = NULL;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "-o") == 0) {
            if (i + 1 == argc || args->svg != NULL)
                return error_set(err, "", 0, "plot: -o needs one file name; " PLOT_USAGE);
            args->svg = argv[++i];
        } else if (argv[i][0] == '-') {
            return error_set(err, "", 0, "plot: unknown option '%s'; " PLOT_USAGE, argv[i]);
        } else {
            args->csv[args->n_csv++] = argv[i];
        }
    }
    if (args->svg == NULL)
        return error_set(err, "", 0, "plot: no output file: give -o PLOT.svg; " PLOT_USAGE);
    size_t n = strlen(args->svg);
    if (n < 5 || strcmp(args->svg + n - 4, ".svg") != 0)
        return error_set(err, "", 0, "plot: -o '%s': the output must be a .svg file",
                         args->svg);
    if (args->n_csv == 0)
        return error_set(err, "", 0, "plot: no CSV files; " PLOT_USAGE);
    return 0;
}

int plot_command(int argc, char **argv)
{
    assert(argc >= 1 && strcmp(argv[0], "plot") == 0);
    struct error err;
    struct plot_args args;
    args.csv = xmalloc((size_t)argc, sizeof *args.csv, "plot arguments");
    int status = parse_plot_args(argc, argv, &args, &err);
    if (status == 0)
        status = plot_files(args.csv, args.n_csv, args.svg, &err);
    if (status != 0)
        error_print(&err);
    free(args.csv);
    return status != 0 ? 2 : 0;
}
