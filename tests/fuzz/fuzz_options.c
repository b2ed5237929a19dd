/*
 * tests/fuzz/fuzz_options.c -- libFuzzer target for the render command's option parser
 * (app/options.c), built by `make fuzz`; a development tool only.
 *
 * The input is a command line: its bytes cut into words at every '\n' (so that a word
 * may hold spaces, as argv's can), at most MAX_WORDS of them, after "photon". What
 * parse_options() prints for --help and --version goes to stdout, which is fine.
 *   build/fuzz/fuzz_options CORPUS_DIR tests/fuzz/seeds/options
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/app/options.h"
#include "input.h"

#define MAX_WORDS 64

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    char *argv[MAX_WORDS + 2];
    int argc = 0;
    if (text == NULL)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    argv[argc++] = "photon";
    for (char *word = text; argc <= MAX_WORDS;) {
        argv[argc++] = word;
        char *end = strchr(word, '\n');
        if (end == NULL)
            break;
        *end = '\0';
        word = end + 1;
    }
    argv[argc] = NULL;
    struct options o;
    struct error err;
    if (parse_options(argc, argv, &o, &err) == 0)
        (void)options_hash(&o, 0);
    free(text);
    return 0;
}
