/*
 * image/plot_command.c -- `photon plot`'s command line: the CSV files, the columns and
 * the SVG to write, handed to plot_files() (plot.c), which draws them. The SVG is checked
 * before anything is read and published only when whole (base/output.h).
 */
#include "plot.h"

#include <assert.h>
#include <stdio.h>
#include <string.h>

#include "../base/alloc.h"
#include "../base/option_once.h"
#include "../base/output.h"

#define PLOT_USAGE "usage: photon plot [--x COL] [--y COL]... [--linear] A.csv [B.csv ...] " \
                   "-o PLOT.svg"

/* What `photon plot` was asked to do. */
struct plot_args {
    const char **csv; /* owned by plot_command(); room for argc names, n_csv used */
    int n_csv;
    const char *svg;  /* -o PLOT.svg */
    struct plot_spec spec;
};

const struct option_arity plot_options[] = {
    {"-o", 1}, {"--x", 1}, {"--y", 1}, {"--x-title", 1}, {"--y-title", 1}, {"--linear", 0},
    {"--help", 0}, {NULL, 0},
};

/* The value after option argv[*i] into *value (advancing *i); -1 with *err filled when
 * it is missing, or when once is not NULL and the option was recorded there before. */
static int option_value(int argc, char **argv, int *i, const char **value,
                        struct option_once *once, struct error *err)
{
    if (once != NULL && option_once(once, "plot", argc, argv, *i, 1, err) < 0)
        return -1;
    if (*i + 1 == argc)
        return error_set(err, "", 0, "plot: %s needs one value; " PLOT_USAGE, argv[*i]);
    *value = argv[++*i];
    return 0;
}

/* One option at argv[*i] into args; -1 with *err filled. */
static int parse_plot_option(int argc, char **argv, int *i, struct plot_args *args,
                             int *y_given, struct option_once *once, struct error *err)
{
    struct plot_spec *spec = &args->spec;
    const char *name = argv[*i];
    if (strcmp(name, "-o") == 0)
        return option_value(argc, argv, i, &args->svg, once, err);
    if (strcmp(name, "--x") == 0) /* once, though it has a default (seconds) */
        return option_value(argc, argv, i, &spec->x, once, err);
    if (strcmp(name, "--x-title") == 0)
        return option_value(argc, argv, i, &spec->x_title, once, err);
    if (strcmp(name, "--y-title") == 0)
        return option_value(argc, argv, i, &spec->y_title, once, err);
    if (strcmp(name, "--linear") == 0) {
        spec->linear = 1;
        return 0;
    }
    if (strcmp(name, "--y") == 0) {
        if (*y_given == PLOT_MAX_SERIES)
            return error_set(err, "", 0, "plot: more than %d --y columns", PLOT_MAX_SERIES);
        spec->n_y = ++*y_given; /* the first --y replaces the default relmse */
        return option_value(argc, argv, i, &spec->y[*y_given - 1], NULL, err);
    }
    return error_set(err, "", 0, "plot: unknown option '%s'; " PLOT_USAGE, name);
}

/* Files and options from the command line; 1 when --help was printed, -1 with *err
 * filled. */
static int parse_plot_args(int argc, char **argv, struct plot_args *args, struct error *err)
{
    args->n_csv = 0;
    args->svg = NULL;
    args->spec = plot_spec_errors();
    int y_given = 0;
    struct option_once once = {{0}, 0};
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            printf("%s\n\nDraws columns of CSV files (first line: the column names) as an "
                   "SVG plot, one line\nper file and --y column (at most %d): by default "
                   "relmse against seconds, log-log,\nfrom --report files; --linear for "
                   "linear axes (profiles from photon probe);\n--x-title and --y-title name "
                   "the axes.\n", PLOT_USAGE, PLOT_MAX_SERIES);
            return 1;
        }
        if (argv[i][0] != '-')
            args->csv[args->n_csv++] = argv[i];
        else if (parse_plot_option(argc, argv, &i, args, &y_given, &once, err) != 0)
            return -1;
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
        status = output_check_one(args.svg, "-o", &err);
    if (status == 0)
        status = plot_files(args.csv, args.n_csv, &args.spec, args.svg, &err);
    if (status == 0)
        status = outputs_publish(&err);
    if (status < 0)
        error_print(&err);
    xfree(args.csv);
    return status < 0 ? error_exit_status(&err) : 0; /* 1: --help was printed */
}
