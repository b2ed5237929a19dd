/*
 * base/temporary_name.c -- the names of the files photon makes beside an output
 * (temporary_name.h).
 */
#include "temporary_name.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "alloc.h"
#include "hash.h"

/* This run's token, in its probes' markers and its temporaries' names: the clock, the
 * time and where the OS put a static and the stack (C99 has no process id). Two runs may
 * still draw the same: what keeps them apart is the exclusive create (output.c's
 * create_ours()). */
uint64_t temporary_run_token(void)
{
    static uint64_t token = 0;
    int on_stack = 0;
    if (token == 0) {
        uintptr_t where[2] = {(uintptr_t)(void *)&token, (uintptr_t)(void *)&on_stack};
        time_t now = time(NULL);
        clock_t ticks = clock();
        token = fnv1a(FNV1A_OFFSET_BASIS, where, sizeof where);
        token = fnv1a(token, &now, sizeof now);
        token = fnv1a(fnv1a(token, &ticks, sizeof ticks), "", 1) | 1;
    }
    return token;
}

/* The number of this run's first temporary name: 32 bits of temporary_run_token(), or
 * the 8 hex digits of PHOTON_TEMPORARY_MARK, with which the tests make two runs try the
 * same names (as two runs started in one clock tick without address randomisation
 * would). */
static unsigned long run_mark(void)
{
    static int known = 0;
    static unsigned long mark;
    if (!known) {
        const char *fixed = getenv("PHOTON_TEMPORARY_MARK");
        char *end = NULL;
        mark = fixed != NULL ? strtoul(fixed, &end, 16) : 0;
        if (fixed == NULL || end == fixed || *end != '\0')
            mark = (unsigned long)(temporary_run_token() >> 32);
        mark &= 0xffffffffUL;
        known = 1;
    }
    return mark;
}

/* The hash a cut name keeps of its output's last part: FNV-1a's low 32 bits, ASCII case
 * folded (temporary_name.h says why). */
static unsigned long folded_hash(const char *base)
{
    uint64_t hash = FNV1A_OFFSET_BASIS;
    for (const char *c = base; *c != '\0'; c++) {
        unsigned char folded = (unsigned char)tolower((unsigned char)*c);
        hash = fnv1a(hash, &folded, 1);
    }
    return (unsigned long)(hash & 0xffffffffUL);
}

/* A last part longer than TEMPORARY_BASE_MAX is cut, and keeps folded_hash(): a name of
 * ours stays within NAME_BYTES_MAX, so that an output may have a name as long as its file
 * system takes. */
char *temporary_name(const char *name, unsigned long attempt)
{
    const char *slash = strrchr(name, '/');
    const char *base = slash != NULL ? slash + 1 : name;
    int cut = strlen(base) > TEMPORARY_BASE_MAX;
    size_t keep = strlen(name);
    if (cut) {
        keep = (size_t)(base - name) + TEMPORARY_BASE_MAX - TEMPORARY_HASH_BYTES;
        while (keep > (size_t)(base - name) && ((unsigned char)name[keep] & 0xc0) == 0x80)
            keep--; /* name[keep], the first byte left out, continues a UTF-8 character */
    }
    char *t = xmalloc(strlen(name) + sizeof TEMPORARY_SUFFIX, 1, "temporary name");
    int n = sprintf(t, "%.*s", (int)keep, name);
    if (cut)
        n += sprintf(t + n, "-%08lx", folded_hash(base));
    sprintf(t + n, ".%08lx.tmp", (run_mark() + attempt) & 0xffffffffUL);
    return t;
}
