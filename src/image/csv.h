/*
 * image/csv.h -- reading the numeric CSV files photon writes (--report, `photon probe`)
 * for `photon plot`: a header line naming the columns, then rows of numbers.
 *
 * Rules (csv.c): fields are separated by commas and trimmed of spaces and tabs; blank
 * lines are ignored; CR LF ends a line as LF does; every row has as many fields as the
 * header, each a number in base/number.h's syntax or CSV_NONE, no value (`photon probe`
 * writes it where a column has none: an exact value the scene's lights do not allow, a
 * map that does not cover the point), read as NaN. An empty field is refused: it is as
 * likely a value lost as one meant to be missing. Limits: lines of CSV_LINE_MAX
 * bytes, CSV_FIELDS_MAX columns. Every error names the file and the line.
 */
#ifndef PHOTON_CSV_H
#define PHOTON_CSV_H

#include <stdio.h>

#include "../base/error.h"

#define CSV_NONE "none" /* the field of a row that has no value in its column */
#include "../base/input.h"

#define CSV_LINE_MAX 1024 /* longest line read; a report row is under 100 bytes */
#define CSV_FIELDS_MAX 16 /* columns in a header; a probe writes 9 */

/* A CSV file being read, one line at a time; csv_open() fills it, csv_close() ends it. */
struct csv {
    struct input in;             /* owned: opened by csv_open(), closed by csv_close()  */
    const char *name;            /* borrowed: the file's name, for messages             */
    int line;                    /* 1-based number of the line in text                  */
    char text[CSV_LINE_MAX + 3]; /* the line, without its end; fields point into it     */
    char *field[CSV_FIELDS_MAX]; /* the line's comma-separated fields, trimmed          */
    int n_fields;
    int n_columns;               /* the header's fields: every row must have as many   */
    int header_line;             /* the header's line number                            */
    char header[CSV_LINE_MAX + 2];  /* the header line, split; column[] points into it */
    char *column[CSV_FIELDS_MAX];   /* the header's names                              */
};

/* Opens name and reads its header. 0, or -1 with *err filled (the file then closed):
 * a file that cannot be read, is empty, or has an overlong line or too many columns. */
int csv_open(struct csv *csv, const char *name, struct error *err);

/* The index of the column called name, or -1. */
int csv_column(const struct csv *csv, const char *name);

/* The next row's csv->n_columns numbers into value[] (NaN for CSV_NONE): 1, 0 at the end, -1
 * with *err filled for a row that breaks the rules above. */
int csv_next_row(struct csv *csv, double *value, struct error *err);

void csv_close(struct csv *csv);

#endif
