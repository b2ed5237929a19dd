/*
 * tests/option_words.h -- the option parser fed a command line written as one string, for
 * the tests that check what options parse to (test_paper.c, test_presets.c, test_merge.c).
 *
 * Writing "--mode 1996 --quality preview" reads better in a table of cases than an argv
 * array; these split such a string at spaces and run parse_options() on it as `photon` would.
 */
#ifndef PHOTON_TEST_OPTION_WORDS_H
#define PHOTON_TEST_OPTION_WORDS_H

#include <stdint.h>

#include "../src/app/options.h"

/* parse_options() of "photon WORDS scenes/cornell.scene", WORDS split at spaces (the first
 * 511 characters, 62 words at most); its status (0 to render), with the options in *o. */
int options_of(const char *words, struct options *o);

/* options_hash() of the parsed words; 0 (which no test expects) when they do not parse. */
uint64_t hash_of(const char *words);

#endif
