/*
 * base/output.c -- the registry of a command's outputs and inputs (output.h).
 *
 * Invariants: outputs[0 .. n_outputs - 1] are the declared outputs (and lone files being
 * written), each with its state; a temporary exists on disk exactly for the OPEN and
 * COMMITTED ones, and outputs_abandon() removes those. inputs[] holds the name of every
 * file input_open() let through. Both lists own their strings.
 */
#include "output.h"

#include <assert.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "alloc.h"
#include "file_kind.h"
#include "hash.h"

#define PROBE_MARKER_MAX 64 /* "photon-output-check" + two numbers */
#define COMPARE_CHUNK 65536 /* bytes compared at a time when an output may be an input */

enum output_state {
    OUTPUT_DECLARED,  /* nothing on disk of ours                                   */
    OUTPUT_OPEN,      /* stream writes tmp_name                                    */
    OUTPUT_COMMITTED  /* tmp_name complete, waiting for outputs_publish()          */
};

struct output {
    char *name;             /* owned: the final name                              */
    char *tmp_name;         /* owned: name + ".tmp", where the bytes go first      */
    const char *role;       /* borrowed (a literal): "-o", "--variance", ...       */
    enum output_state state;
    FILE *stream;           /* while OUTPUT_OPEN                                  */
    int checked;            /* outputs_check() passed it                          */
    int lone;               /* opened with nothing declared: renamed at commit    */
    int renamed_now;        /* put in place by the outputs_publish() running      */
};

static struct output *outputs;
static size_t n_outputs, cap_outputs;
static char **inputs;
static size_t n_inputs, cap_inputs;
static int cleanup_registered;

static void register_cleanup(void)
{
    if (!cleanup_registered && atexit(outputs_abandon) == 0)
        cleanup_registered = 1;
}

static struct output *find_name(const char *name)
{
    for (size_t i = 0; i < n_outputs; i++)
        if (strcmp(outputs[i].name, name) == 0)
            return &outputs[i];
    return NULL;
}

static struct output *find_stream(FILE *f)
{
    for (size_t i = 0; f != NULL && i < n_outputs; i++)
        if (outputs[i].stream == f)
            return &outputs[i];
    return NULL;
}

static struct output *add_output(const char *name, const char *role, int lone)
{
    register_cleanup();
    if (n_outputs == cap_outputs) {
        cap_outputs = cap_outputs < 8 ? 8 : 2 * cap_outputs;
        outputs = xrealloc(outputs, cap_outputs, sizeof *outputs, "outputs");
    }
    struct output *o = &outputs[n_outputs];
    size_t n = strlen(name);
    o->name = xstrdup(name);
    o->tmp_name = xmalloc(n + 5, 1, "output name");
    memcpy(o->tmp_name, name, n);
    memcpy(o->tmp_name + n, ".tmp", 5);
    o->role = role;
    o->state = OUTPUT_DECLARED;
    o->stream = NULL;
    o->checked = 0;
    o->lone = lone;
    o->renamed_now = 0;
    n_outputs++; /* last: fatal() inside the allocations above sees a consistent list */
    return o;
}

void output_declare(const char *name, const char *role)
{
    add_output(name, role, 0);
}

/* ---- identity -------------------------------------------------------------------------- */

/* This run's mark in the probes: the clock, the time and where the OS put a static and
 * the stack (C99 has no process id). Only told apart from other runs' leftovers. */
static uint64_t run_token(void)
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

/* The size of the regular file name, or -1 when it does not open. */
static long file_size(const char *name)
{
    FILE *f = fopen(name, "rb");
    if (f == NULL)
        return -1;
    long size = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    fclose(f);
    return size;
}

/* Whether files a and b hold the same bytes (both readable). */
static int same_bytes(const char *a, const char *b)
{
    FILE *fa = fopen(a, "rb"), *fb = fopen(b, "rb");
    unsigned char *ca = xmalloc(2, COMPARE_CHUNK, "file comparison"), *cb = ca + COMPARE_CHUNK;
    int same = fa != NULL && fb != NULL;
    while (same) {
        size_t na = fread(ca, 1, COMPARE_CHUNK, fa), nb = fread(cb, 1, COMPARE_CHUNK, fb);
        same = na == nb && memcmp(ca, cb, na) == 0 && !ferror(fa) && !ferror(fb);
        if (na < COMPARE_CHUNK)
            break;
    }
    xfree(ca);
    if (fa != NULL)
        fclose(fa);
    if (fb != NULL)
        fclose(fb);
    return same;
}

/* Whether opening input goes through o's directory entry: o's file moved aside to its
 * temporary name for the moment of one fopen(), then put back. -1 with *err when it
 * cannot be put back (the message says where it is). */
static int input_goes_through(struct output *o, const char *input, struct error *err)
{
    if (rename(o->name, o->tmp_name) != 0)
        return 1; /* cannot tell, and the bytes are the same: refuse rather than risk */
    FILE *f = fopen(input, "rb");
    if (f != NULL)
        fclose(f);
    if (rename(o->tmp_name, o->name) != 0) {
        o->checked = 0;
        return error_set(err, o->name, 0, "moved to %s for a moment and cannot be moved "
                         "back: %s", o->tmp_name, strerror(errno));
    }
    return f == NULL;
}

/* -1 with *err when o is the input file `input` of `size` bytes (output.h). */
static int refuse_if_same(struct output *o, const char *input, long size, struct error *err)
{
    if (o->lone || o->state != OUTPUT_DECLARED || file_size(o->name) != size ||
        file_is_directory(o->name) || !same_bytes(o->name, input))
        return 0;
    int through = input_goes_through(o, input, err);
    if (through < 0)
        return -1;
    if (through)
        return error_set(err, o->name, 0, "%s is the input %s of this command: writing it "
                         "would destroy that input", o->role, input);
    return 0;
}

int output_refuse_input(const char *name, long size, struct error *err)
{
    for (size_t i = 0; i < n_outputs; i++)
        if (refuse_if_same(&outputs[i], name, size, err) < 0)
            return -1;
    register_cleanup();
    if (n_inputs == cap_inputs) {
        cap_inputs = cap_inputs < 8 ? 8 : 2 * cap_inputs;
        inputs = xrealloc(inputs, cap_inputs, sizeof *inputs, "inputs");
    }
    inputs[n_inputs] = xstrdup(name);
    n_inputs++;
    return 0;
}

/* ---- the check ------------------------------------------------------------------------- */

/* The name alone: not empty, not a directory, short enough. */
static int check_name(const struct output *o, struct error *err)
{
    size_t n = strlen(o->name);
    if (n == 0)
        return error_set(err, "", 0, "%s: an empty file name", o->role);
    if (o->name[n - 1] == '/' || file_is_directory(o->name))
        return error_set(err, o->name, 0, "is a directory (%s)", o->role);
    if (n + 5 > OUTPUT_NAME_MAX)
        return error_set(err, o->name, 0, "the file name is too long (%s)", o->role);
    return 0;
}

/* outputs[k]'s temporary, made with its marker, unless it is already there as an earlier
 * output's: then that output is the same file. */
static int make_probe(size_t k, struct error *err)
{
    struct output *o = &outputs[k];
    char marker[PROBE_MARKER_MAX], found[PROBE_MARKER_MAX] = "";
    FILE *f = fopen(o->tmp_name, "rb");
    if (f != NULL) {
        size_t n = fread(found, 1, sizeof found - 1, f);
        found[n] = '\0';
        fclose(f);
    }
    for (size_t j = 0; j < k; j++) {
        snprintf(marker, sizeof marker, "photon-output-check %016llx %zu\n",
                 (unsigned long long)run_token(), j);
        if (!outputs[j].lone && strcmp(found, marker) == 0)
            return error_set(err, o->name, 0, "%s names the same file as %s (%s)", o->role,
                             outputs[j].role, outputs[j].name);
    }
    errno = 0;
    f = fopen(o->tmp_name, "wb");
    if (f == NULL)
        return error_set(err, o->name, 0, "cannot create output file%s%s (%s)",
                         errno != 0 ? ": " : "", errno != 0 ? strerror(errno) : "", o->role);
    fprintf(f, "photon-output-check %016llx %zu\n", (unsigned long long)run_token(), k);
    int failed = ferror(f) != 0;
    failed |= fclose(f) != 0;
    if (failed)
        return error_set(err, o->name, 0, "cannot write output file (%s)", o->role);
    return 0;
}

/* An existing output must open for writing (without being changed). */
static int check_writable(const struct output *o, struct error *err)
{
    FILE *f = fopen(o->name, "rb");
    if (f == NULL)
        return 0; /* absent: its directory took the probe */
    fclose(f);
    errno = 0;
    f = fopen(o->name, "ab");
    if (f == NULL)
        return error_set(err, o->name, 0, "the file exists and cannot be written%s%s (%s)",
                         errno != 0 ? ": " : "", errno != 0 ? strerror(errno) : "", o->role);
    fclose(f);
    return 0;
}

int outputs_check(struct error *err)
{
    size_t made = 0;
    int status = 0;
    for (size_t k = 0; k < n_outputs && status == 0; k++) {
        assert(outputs[k].state == OUTPUT_DECLARED); /* checked before any is opened */
        if (outputs[k].lone)
            continue;
        status = check_name(&outputs[k], err);
        if (status == 0 && (status = make_probe(k, err)) == 0)
            made = k + 1;
    }
    for (size_t k = 0; k < made; k++)
        if (!outputs[k].lone)
            remove(outputs[k].tmp_name);
    for (size_t k = 0; k < n_outputs && status == 0; k++) {
        if (outputs[k].lone)
            continue;
        status = check_writable(&outputs[k], err);
        for (size_t i = 0; i < n_inputs && status == 0; i++)
            status = refuse_if_same(&outputs[k], inputs[i], file_size(inputs[i]), err);
        outputs[k].checked = status == 0;
    }
    return status;
}

int output_check_one(const char *name, const char *role, struct error *err)
{
    output_declare(name, role);
    return outputs_check(err);
}

/* ---- writing --------------------------------------------------------------------------- */

/* error_set() for a write that failed (exit status 1). */
static int write_failed(struct error *err, const char *file, const char *message,
                        const char *reason)
{
    error_set(err, file, 0, "%s%s%s", message, reason[0] != '\0' ? ": " : "", reason);
    if (err != NULL)
        err->failed_write = 1;
    return -1;
}

static int any_declared(void)
{
    for (size_t i = 0; i < n_outputs; i++)
        if (!outputs[i].lone)
            return 1;
    return 0;
}

FILE *output_open(const char *name, struct error *err)
{
    struct output *o = find_name(name);
    assert(o != NULL ? o->checked || o->lone : !any_declared()); /* declared, checked */
    if (strlen(name) + 5 > OUTPUT_NAME_MAX) {
        write_failed(err, name, "output file name is too long", "");
        return NULL;
    }
    if (o == NULL)
        o = add_output(name, "", 1);
    if (o->state == OUTPUT_OPEN)
        output_abandon(o->stream);
    errno = 0;
    o->stream = fopen(o->tmp_name, "wb");
    if (o->stream == NULL) {
        write_failed(err, name, "cannot create output file", errno != 0 ? strerror(errno) : "");
        o->state = OUTPUT_DECLARED;
        return NULL;
    }
    o->state = OUTPUT_OPEN;
    return o->stream;
}

/* Renames o's temporary to its name: 0, or the errno of the failed rename (-1 without
 * one), after which the temporary is removed. */
static int put_in_place(struct output *o)
{
    errno = 0;
    int failed = rename(o->tmp_name, o->name) != 0;
    int reason = failed ? (errno != 0 ? errno : -1) : 0;
    if (failed)
        remove(o->tmp_name);
    o->state = OUTPUT_DECLARED;
    return reason;
}

/* Forgets outputs[i], a lone output done with. */
static void forget(size_t i)
{
    xfree(outputs[i].name);
    xfree(outputs[i].tmp_name);
    outputs[i] = outputs[--n_outputs];
}

int output_commit(FILE *f, struct error *err)
{
    struct output *o = find_stream(f);
    if (o == NULL)
        return error_set(err, "", 0, "output_commit: stream was not opened by output_open");
    int failed = ferror(f) != 0;
    failed |= fclose(f) != 0;
    o->stream = NULL;
    o->state = OUTPUT_COMMITTED;
    if (failed) {
        remove(o->tmp_name);
        o->state = OUTPUT_DECLARED;
    } else if (o->lone) {
        failed = put_in_place(o) != 0;
    }
    int status = failed ? write_failed(err, o->name, "cannot write output file", "") : 0;
    if (o->lone)
        forget((size_t)(o - outputs));
    return status;
}

void output_abandon(FILE *f)
{
    struct output *o = find_stream(f);
    if (o == NULL)
        return;
    fclose(f);
    remove(o->tmp_name);
    o->stream = NULL;
    o->state = OUTPUT_DECLARED;
    if (o->lone)
        forget((size_t)(o - outputs));
}

int outputs_publish(struct error *err)
{
    for (size_t i = 0; i < n_outputs; i++)
        outputs[i].renamed_now = 0;
    for (size_t i = 0; i < n_outputs; i++) {
        if (outputs[i].state != OUTPUT_COMMITTED)
            continue;
        int reason = put_in_place(&outputs[i]);
        if (reason == 0) {
            outputs[i].renamed_now = 1;
            continue;
        }
        write_failed(err, outputs[i].name, "cannot write output file",
                     reason > 0 ? strerror(reason) : "");
        for (size_t j = 0; j < n_outputs; j++) {
            if (outputs[j].renamed_now)
                remove(outputs[j].name); /* all or none */
            if (outputs[j].state == OUTPUT_COMMITTED)
                remove(outputs[j].tmp_name);
            outputs[j].state = outputs[j].state == OUTPUT_OPEN ? OUTPUT_OPEN : OUTPUT_DECLARED;
        }
        return -1;
    }
    return 0;
}

void outputs_abandon(void)
{
    for (size_t i = 0; i < n_outputs; i++) {
        if (outputs[i].state == OUTPUT_OPEN)
            fclose(outputs[i].stream);
        if (outputs[i].state != OUTPUT_DECLARED)
            remove(outputs[i].tmp_name);
        xfree(outputs[i].name);
        xfree(outputs[i].tmp_name);
    }
    for (size_t i = 0; i < n_inputs; i++)
        xfree(inputs[i]);
    xfree(outputs);
    xfree(inputs);
    outputs = NULL;
    inputs = NULL;
    n_outputs = cap_outputs = n_inputs = cap_inputs = 0;
}
