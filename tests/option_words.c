/*
 * tests/option_words.c -- the helpers behind option_words.h.
 */
#include "option_words.h"

#include <stdio.h>
#include <string.h>

#include "../src/base/error.h"
#include "../src/base/hash.h"

#define WORDS_MAX 64 /* argv's room: "photon", the words, the scene */

int options_of(const char *words, struct options *o)
{
    char text[512], *argv[WORDS_MAX];
    int argc = 0;
    argv[argc++] = "photon";
    snprintf(text, sizeof text, "%s", words); /* strtok writes into the words it splits */
    for (char *w = strtok(text, " "); w != NULL && argc < WORDS_MAX - 1; w = strtok(NULL, " "))
        argv[argc++] = w;
    argv[argc++] = "scenes/cornell.scene";
    struct error err;
    return parse_options(argc, argv, o, &err);
}

uint64_t hash_of(const char *words)
{
    struct options o;
    return options_of(words, &o) == 0 ? options_hash(&o, FNV1A_OFFSET_BASIS) : 0;
}
