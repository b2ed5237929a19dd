/*
 * app/presets.h -- `--quality preview|default|reference`: per mode, a list of option words
 * that stands before the command line's (presets.c holds the table).
 *
 * A preset is nothing but option words: parse_options() applies them through the same
 * parser and limits as the user's, after the defaults and before the user's own words, so
 * an option the user gives wins wherever it stands. "default" is the defaults themselves
 * (no words). --help prints the table, so the help and the behaviour cannot disagree.
 */
#ifndef PHOTON_PRESETS_H
#define PHOTON_PRESETS_H

#include "../base/error.h"
#include "help.h"
#include "render_options.h"

#define PRESET_MAX_WORDS 24  /* longest word list in the table, with room to spare */
#define PRESET_MAX_CHARS 256 /* longest word list's characters, with its final '\0' */

/* A preset's words split for the option parser, as argv would hold them. */
struct preset_words {
    char text[PRESET_MAX_CHARS];  /* the list, its spaces replaced by '\0' */
    char *word[PRESET_MAX_WORDS]; /* word[i] points into text              */
    int n_words;
};

const char *quality_name(enum quality quality);

/* A --quality value: preview, default or reference; -1 with *err filled (naming the three)
 * otherwise. */
int read_quality(const char *text, enum quality *quality, struct error *err);

/* The words of mode's preset at quality into *out; none for QUALITY_DEFAULT. */
void preset_words(enum mode mode, enum quality quality, struct preset_words *out);

/* The words --paper stands for in mode (none when paper is 0): its departures off. */
void paper_words(enum mode mode, int paper, struct preset_words *out);

/* Prints the tables for --help: one line for each mode's preview and reference presets,
 * and each mode's --paper words; only the mode `only` (an enum mode) when it is >= 0. */
void print_presets(enum help_format format, int only);

#endif
