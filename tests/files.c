/*
 * tests/files.c -- the helpers behind files.h: temporary names, whole-file writes and reads.
 *
 * Text read back is capped at TEXT_MAX_BYTES, more than any log or SVG the tests produce;
 * a longer file is compared on its first TEXT_MAX_BYTES only.
 */
#include "files.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../src/base/rng.h"
#include "../src/image/image.h"
#include "check.h"

#define TEXT_MAX_BYTES (1 << 20) /* larger than any file these tests read as text */
#define COMMAND_MAX 4096         /* the longest command line the tests build */

/* C99 has no process id, so runs are told apart by the clock and by where the OS placed
 * the stack (randomised per process on the systems we test on), hashed through the test
 * stream. No result depends on it. */
void temp_name(char *out, size_t size, const char *group, const char *what)
{
    static uint64_t run = 0;
    if (run == 0) {
        int on_stack = 0;
        uint64_t key = (uint64_t)time(NULL) ^ (uint64_t)clock()
                       ^ (uint64_t)(uintptr_t)(void *)&on_stack;
        struct rng r = rng_stream(key, STREAM_TEST, 0, 0);
        run = rng_next(&r) | 1;
    }
    snprintf(out, size, "/tmp/photon_test_%s_%016llx_%s", group, (unsigned long long)run,
             what);
}

void write_text_file(const char *name, const char *text)
{
    write_bytes_file(name, (const unsigned char *)text, strlen(text));
}

void write_bytes_file(const char *name, const unsigned char *bytes, size_t n)
{
    FILE *f = fopen(name, "wb");
    if (f == NULL)
        return; /* the read that follows fails and says so */
    if (n > 0)
        fwrite(bytes, 1, n, f);
    fclose(f);
}

int file_exists(const char *name)
{
    FILE *f = fopen(name, "rb");
    if (f != NULL)
        fclose(f);
    return f != NULL;
}

char *read_text_file(const char *name)
{
    FILE *f = fopen(name, "rb");
    if (f == NULL)
        return NULL;
    char *text = malloc(TEXT_MAX_BYTES + 1);
    size_t n = text != NULL ? fread(text, 1, TEXT_MAX_BYTES, f) : 0;
    fclose(f);
    if (text != NULL)
        text[n] = '\0';
    return text;
}

int file_contains(const char *name, const char *text)
{
    char *s = read_text_file(name);
    int found = s != NULL && strstr(s, text) != NULL;
    free(s);
    return found;
}

int file_equals_text(const char *name, const char *text)
{
    char *s = read_text_file(name);
    int equal = s != NULL && strcmp(s, text) == 0;
    free(s);
    return equal;
}

void join_option_rows(char *help)
{
    char *out = help;
    for (const char *c = help; *c != '\0'; c++) {
        size_t spaces = c[0] == '\n' ? strspn(c + 1, " ") : 0;
        if (spaces > 2 && strncmp(c + 1 + spaces, "--", 2) == 0) {
            *out++ = ' ';
            c += spaces;
        } else {
            *out++ = *c;
        }
    }
    *out = '\0';
}

int files_equal(const char *a, const char *b)
{
    FILE *fa = fopen(a, "rb"), *fb = fopen(b, "rb");
    int same = fa != NULL && fb != NULL;
    while (same) {
        int ca = fgetc(fa), cb = fgetc(fb);
        same = ca == cb;
        if (ca == EOF || cb == EOF)
            break;
    }
    if (fa != NULL)
        fclose(fa);
    if (fb != NULL)
        fclose(fb);
    return same;
}

int count_temporaries(const char *name)
{
    char command[COMMAND_MAX];
    snprintf(command, sizeof command, "n=0; for f in '%s'.tmp '%s'.????????.tmp; do "
             "if [ -e \"$f\" ] || [ -L \"$f\" ]; then n=$((n + 1)); fi; done; exit $n",
             name, name);
    return run_command(command);
}

int no_temporaries(const char *name)
{
    return count_temporaries(name) == 0;
}

double file_stat(const char *log, const char *key)
{
    char *text = read_text_file(log);
    size_t n = strlen(key);
    double value = -1;
    for (const char *line = text; line != NULL && value < 0; line = strchr(line, '\n')) {
        line += *line == '\n';
        if (strncmp(line, key, n) == 0 && line[n] == '=')
            value = atof(line + n + 1);
    }
    free(text);
    return value;
}

int photon_logged(const char *subcommand, const char *args, const char *log)
{
    char command[COMMAND_MAX];
    if (snprintf(command, sizeof command, "%s %s %s >%s 2>&1", photon_binary(), subcommand,
                 args, log) >= (int)sizeof command)
        return -1;
    return run_command(command);
}

struct image *photon_render(const char *group, const char *options, const char *scene)
{
    char out[256], png[256], log[256], args[1024];
    temp_name(out, sizeof out, group, "render.pfm");
    temp_name(png, sizeof png, group, "render.png");
    temp_name(log, sizeof log, group, "render.log");
    struct image *img = NULL;
    if (snprintf(args, sizeof args, "%s --no-progress %s -o %s", options, scene, out) <
            (int)sizeof args &&
        photon_logged("", args, log) == 0) {
        struct error err;
        img = pfm_read(out, &err);
    }
    remove(out);
    remove(png);
    remove(log);
    return img;
}
