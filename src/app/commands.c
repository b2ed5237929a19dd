/*
 * app/commands.c -- the table of the commands beside rendering (commands.h).
 */
#include "commands.h"

#include "../image/compare.h"
#include "../image/plot.h"
#include "convert.h"
#include "export.h"
#include "merge.h"
#include "probe.h"

/* In the order main.c has always tried them (a near miss's ties go to the first); the
 * summaries are the first screen's, each within the 71 columns its text has there. */
const struct command commands[] = {
    {"compare", compare_command, "two images' error (rmse, relmse, worst block) and whether "
                                 "they agree", compare_options},
    {"plot", plot_command, "reports' relmse against CPU seconds (or any columns) as an SVG",
     plot_options},
    {"probe", probe_command, "1994's irradiance estimate sampled along a line, as CSV",
     probe_options},
    {"merge", merge_command, "tiles rendered with --crop put together into the whole image",
     merge_options},
    {"export", export_command, "the scene for pbrt-v4, Mitsuba 3 or Blender (Cycles)",
     export_options},
    {"convert", convert_command, "an image (a render, an error image) as a PNG or PPM picture",
     convert_options},
};

/* An array of -1 chars, which does not compile, unless N_COMMANDS counts the rows. */
typedef char command_count_is_right[sizeof commands / sizeof commands[0] == N_COMMANDS ? 1
                                                                                        : -1];
