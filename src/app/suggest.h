/*
 * app/suggest.h -- the near miss a mistyped word was meant to be: "did you mean --spp?"
 * for --sp, "compare" for comapre.
 *
 * A word's distance to a name is the optimal string alignment distance: the fewest
 * insertions, deletions, substitutions and swaps of two neighbouring characters that
 * turn one into the other (a swap, the commonest slip of typing, costs 1, where plain
 * Levenshtein counts it 2). A name is suggested when it is the nearest and within 1 for
 * names of 3 or 4 characters, within 2 for longer ones: farther, a suggestion is more
 * often wrong than right (--seed for --spp would be 3 away); names of 1 or 2 characters
 * (-o, pt) only when typed right, since every 2-character slip is 1 or 2 from them.
 */
#ifndef PHOTON_SUGGEST_H
#define PHOTON_SUGGEST_H

#include <stddef.h>

/* The name, of n given by name_at(0) ... name_at(n - 1), nearest to word by the rule
 * above, or NULL when none is near enough (the first of equals) or word is NULL. */
const char *nearest_name(const char *word, const char *(*name_at)(size_t i), size_t n);

/* " (did you mean 'NAME'?)" for the nearest name, or "" for none, into text[size]. */
void did_you_mean(const char *word, const char *(*name_at)(size_t i), size_t n, char *text,
                  size_t size);

#endif
