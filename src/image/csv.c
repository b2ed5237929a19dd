/*
 * image/csv.c -- the numeric CSV reader behind `photon plot` (rules in csv.h).
 *
 * A line is read whole into csv->text and split in place at its commas, so fields are
 * pointers into it; the header's copy stays in csv->header for the column names.
 */
#include "csv.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../base/number.h"

static int is_blank(int c)
{
    return c == ' ' || c == '\t';
}

/* Reads the next line that is not blank into csv->text, without its end. Returns 1 for
 * a line, 0 at the end of the file, -1 with *err filled. */
static int read_line(struct csv *csv, struct error *err)
{
    do {
        int status = input_line(&csv->in, csv->text, sizeof csv->text, err);
        if (status <= 0)
            return status;
        csv->line = csv->in.line;
        size_t n = strcspn(csv->text, "\r\n");
        if (n > CSV_LINE_MAX) /* text has room for CSV_LINE_MAX bytes and the line end */
            return error_set(err, csv->name, csv->line, "line longer than %d bytes",
                             CSV_LINE_MAX);
        csv->text[n] = '\0';
    } while (csv->text[strspn(csv->text, " \t")] == '\0');
    return 1;
}

/* Splits text at its commas into field[], each trimmed of spaces and tabs; the count,
 * or -1 with *err filled when there are more than CSV_FIELDS_MAX. */
static int split_fields(const struct csv *csv, char *text, char **field, struct error *err)
{
    int n = 0;
    for (char *p = text; p != NULL; n++) {
        if (n == CSV_FIELDS_MAX)
            return error_set(err, csv->name, csv->line, "more than %d columns",
                             CSV_FIELDS_MAX);
        char *comma = strchr(p, ',');
        if (comma != NULL)
            *comma = '\0';
        while (is_blank(*p))
            p++;
        for (char *end = p + strlen(p); end > p && is_blank(end[-1]); end--)
            end[-1] = '\0';
        field[n] = p;
        p = comma != NULL ? comma + 1 : NULL;
    }
    return n;
}

/* The header: the first line that is not blank, kept in csv->header. */
static int read_header(struct csv *csv, struct error *err)
{
    int status = read_line(csv, err);
    if (status < 0)
        return -1;
    if (status == 0)
        return error_set(err, csv->name, 0, "empty file: expected a CSV whose first line "
                                            "names its columns (such as a --report file)");
    memcpy(csv->header, csv->text, sizeof csv->header);
    csv->n_columns = split_fields(csv, csv->header, csv->column, err);
    csv->header_line = csv->line;
    return csv->n_columns < 0 ? -1 : 0;
}

int csv_open(struct csv *csv, const char *name, struct error *err)
{
    csv->name = name;
    csv->line = 0;
    if (input_open(&csv->in, name, err) < 0)
        return -1;
    if (read_header(csv, err) != 0) {
        csv_close(csv);
        return -1;
    }
    return 0;
}

int csv_column(const struct csv *csv, const char *name)
{
    for (int i = 0; i < csv->n_columns; i++) {
        if (strcmp(csv->column[i], name) == 0)
            return i;
    }
    return -1;
}

int csv_next_row(struct csv *csv, double *value, struct error *err)
{
    int status = read_line(csv, err);
    if (status != 1)
        return status;
    csv->n_fields = split_fields(csv, csv->text, csv->field, err);
    if (csv->n_fields < 0)
        return -1;
    if (csv->n_fields != csv->n_columns)
        return error_set(err, csv->name, csv->line, "expected %d fields as in the header, "
                                                    "found %d", csv->n_columns, csv->n_fields);
    for (int i = 0; i < csv->n_columns; i++) {
        if (strcmp(csv->field[i], CSV_NONE) == 0) /* no value (photon probe writes it) */
            value[i] = NAN;
        else if (!number_parse(csv->field[i], 0, &value[i]))
            return error_set(err, csv->name, csv->line, "field %d '%s' is not a finite "
                                                        "number", i + 1, csv->field[i]);
    }
    return 1;
}

void csv_close(struct csv *csv)
{
    input_close(&csv->in);
}
