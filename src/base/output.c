/*
 * base/output.c -- the registry of a command's outputs and inputs (output.h).
 *
 * Invariants: outputs[0 .. n_outputs - 1] are the declared outputs (and lone files being
 * written), each with its state. Every file of ours on disk is in an undo entry (undo.h)
 * from the moment it exists: an output's temporary, or outputs_check()'s probe, is
 * tmp_name, in tmp_undo (to remove) until it is renamed or removed; during an
 * outputs_publish(), aside_undo says how to take back what putting the output in place
 * did. Removing a file of ours is undo_now() of its entry, so an exit and a signal remove
 * exactly what a normal path would. inputs[] holds the name of every file input_open()
 * let through. Both lists own their strings.
 */
#include "output.h"

#include <assert.h>
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "alloc.h"
#include "file_kind.h"
#include "temporary_name.h"
#include "undo.h"

#define PROBE_MARKER_MAX 64 /* "photon-output-check" + two numbers */
#define COMPARE_CHUNK 65536 /* bytes compared at a time when an output may be an input */
#define TEMPORARY_TRIES 16  /* names tried for one file of ours before giving up     */
#define NO_OUTPUT SIZE_MAX  /* "no output" where an index of outputs[] is expected   */

enum output_state {
    OUTPUT_DECLARED,  /* no temporary of ours                                      */
    OUTPUT_OPEN,      /* stream writes tmp_name                                    */
    OUTPUT_COMMITTED  /* tmp_name complete, waiting for outputs_publish()          */
};

struct output {
    char *name;             /* owned: the final name                              */
    char *tmp_name;         /* owned: the temporary or probe on disk, else NULL    */
    char *aside_name;       /* owned: in a publish, where the replaced file waits  */
    const char *role;       /* borrowed (a literal): "-o", "--variance", ...       */
    enum output_state state;
    FILE *stream;           /* while OUTPUT_OPEN                                  */
    int checked;            /* outputs_check() passed it                          */
    int lone;               /* opened with nothing declared: renamed at commit    */
    int published;          /* put in place by the outputs_publish() running      */
    struct undo *tmp_undo;  /* tmp_name's entry                                   */
    struct undo *aside_undo; /* in a publish: what takes this output's step back  */
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
    o->name = xstrdup(name);
    o->tmp_name = NULL;
    o->aside_name = NULL;
    o->role = role;
    o->state = OUTPUT_DECLARED;
    o->stream = NULL;
    o->checked = 0;
    o->lone = lone;
    o->published = 0;
    o->tmp_undo = undo_new();
    o->aside_undo = undo_new();
    n_outputs++; /* last: fatal() inside the allocations above sees a consistent list */
    return o;
}

void output_declare(const char *name, const char *role)
{
    add_output(name, role, 0);
}

/* Removes o's temporary (or probe), if it has one. A probe that holds a user's file moved
 * aside is renamed back instead (undo.h); when that fails it keeps its name. */
static void drop_temporary(struct output *o)
{
    if (o->tmp_name != NULL && undo_now(o->tmp_undo) == 0) {
        xfree(o->tmp_name);
        o->tmp_name = NULL;
    }
}

/* Forgets outputs[i], a lone output done with. */
static void forget(size_t i)
{
    xfree(outputs[i].name);
    xfree(outputs[i].tmp_name);
    xfree(outputs[i].aside_name);
    undo_free(outputs[i].tmp_undo);
    undo_free(outputs[i].aside_undo);
    outputs[i] = outputs[--n_outputs];
}

/* ---- files of ours ------------------------------------------------------------------- */

/* What outputs_check() writes in outputs[k]'s probe: this run and k. */
static void probe_marker(size_t k, char marker[PROBE_MARKER_MAX])
{
    snprintf(marker, PROBE_MARKER_MAX, "photon-output-check %016llx %zu\n",
             (unsigned long long)temporary_run_token(), k);
}

/* The earlier output (j < k) whose probe f holds, or NO_OUTPUT. */
static size_t probe_owner(FILE *f, size_t k)
{
    char found[PROBE_MARKER_MAX], marker[PROBE_MARKER_MAX];
    size_t n = fread(found, 1, sizeof found - 1, f);
    found[n] = '\0';
    for (size_t j = 0; j < k; j++) {
        probe_marker(j, marker);
        if (!outputs[j].lone && strcmp(found, marker) == 0)
            return j;
    }
    return NO_OUTPUT;
}

/* A new file of ours beside name, open for binary writing, its name in *made (a new
 * string) and in u, as a file to remove: the first of this run's temporary names that no
 * file has and, but for a probe, no output is declared as, made by an exclusive create
 * (output.h). A name that is taken is passed over: when it holds the probe of an earlier
 * output than probe_k (NO_OUTPUT: not a probe), *same is set to that output and NULL
 * returned. NULL with *errnum the last errno (0 when every name was taken) when no name
 * could be made. */
static FILE *create_ours(const char *name, struct undo *u, char **made, size_t probe_k,
                         size_t *same, int *errnum)
{
    *errnum = 0;
    for (unsigned long attempt = 0; attempt < TEMPORARY_TRIES; attempt++) {
        char *t = temporary_name(name, attempt);
        if (probe_k == NO_OUTPUT && find_name(t) != NULL) {
            xfree(t); /* an output's name (nothing need be there yet): a temporary there
                         would be taken for it, or a replaced file kept aside there removed
                         in its stead. Probes, gone by the end of the check, try every
                         name, so that two spellings of one file meet (output.h) */
            continue;
        }
        if (file_is_there(t)) { /* taken, a FIFO too, found without opening it (C11's "x"
                                   below is the check that counts) */
            int pipe;
            FILE *f = probe_k != NO_OUTPUT ? file_open_no_wait(t, &pipe) : NULL;
            size_t owner = f != NULL ? probe_owner(f, probe_k) : NO_OUTPUT;
            if (f != NULL)
                fclose(f);
            xfree(t);
            if (owner != NO_OUTPUT) {
                *same = owner;
                return NULL;
            }
            continue;
        }
        undo_hold(); /* the file and its entry appear together for a signal */
        errno = 0;
        FILE *f = fopen(t, "wbx");
        *errnum = errno;
        if (f != NULL)
            undo_set(u, UNDO_REMOVE, t, NULL);
        undo_release();
        if (f != NULL) {
            *made = t;
            return f;
        }
        xfree(t);
    }
    return NULL;
}

/* The message's ": reason" for an errno, "" for none (0, or -1: none known). */
static const char *colon(int errnum)
{
    return errnum > 0 ? ": " : "";
}

static const char *reason(int errnum)
{
    return errnum > 0 ? strerror(errnum) : "";
}

/* Closes f, a file of ours written to: 0, or why a write or the close failed, an errno
 * (-1 when none is known). C99's stdio keeps that a write failed (ferror()), not why, and
 * errno may have changed since; so the file is asked again: one byte more, written at its
 * end and flushed, fails as the first write did (a full disk, a file size limit, an I/O
 * error) and errno says why. The byte goes to a file of ours that is then removed. */
static int close_written(FILE *f)
{
    int why = 0;
    if (ferror(f)) {
        clearerr(f);
        errno = 0;
        if (fseek(f, 0, SEEK_END) != 0 || putc(0, f) == EOF || fflush(f) != 0)
            why = errno;
        why = why > 0 ? why : -1;
    }
    errno = 0;
    if (fclose(f) != 0 && why == 0)
        why = errno > 0 ? errno : -1;
    return why;
}

/* ---- identity -------------------------------------------------------------------------- */

/* The size of the regular file name, or -1 when it does not open for update (an output
 * that does not is refused by the check) or is a FIFO: asked so, it never waits. */
static long file_size(const char *name)
{
    int pipe;
    FILE *f = file_open_no_wait(name, &pipe);
    if (f == NULL)
        return -1;
    long size = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    fclose(f);
    return size;
}

/* Whether the output a and the input b hold the same bytes: a opens for update (a regular
 * file, as file_size() found), b for reading (as input_open() did). */
static int same_bytes(const char *a, const char *b)
{
    int pipe_a, pipe_b;
    FILE *fa = file_open_no_wait(a, &pipe_a), *fb = file_open_read(b, &pipe_b);
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

/* Whether inputs[i] opens (for reading, as input_open() opened it). */
static int input_opens(size_t i)
{
    int pipe;
    FILE *f = file_open_read(inputs[i], &pipe);
    if (f != NULL)
        fclose(f);
    return f != NULL;
}

/* Moves o's file aside, onto a file of ours (its probe, or a new one), and back
 * (output.h). -1 with *err when the file there cannot be moved, so that o could not be put
 * in place either; when one of inputs[from ..] opens only while o's file is in place (it
 * is that file); or when o's file cannot be moved back (the message says where it is, and
 * its entry will try again at exit). Nothing there (or a new file of ours that cannot be
 * made): 0. */
static int round_trip(struct output *o, size_t from, struct error *err)
{
    int errnum = 0;
    FILE *f = NULL;
    if (o->tmp_name == NULL &&
        (f = create_ours(o->name, o->tmp_undo, &o->tmp_name, NO_OUTPUT, NULL, &errnum)) == NULL)
        return 0; /* the check or the write will say why */
    if (f != NULL)
        fclose(f);
    undo_hold(); /* the rename and the entry that says where the file is, together */
    errno = 0;
    int moved = rename(o->name, o->tmp_name) == 0;
    errnum = errno;
    if (moved)
        undo_set(o->tmp_undo, UNDO_RENAME_BACK, o->tmp_name, o->name);
    undo_release();
    if (!moved) {
        drop_temporary(o);
        if (!file_is_there(o->name))
            return 0; /* nothing there to move */
        return error_set(err, o->name, 0, "the file exists and cannot be replaced%s%s (%s)",
                         colon(errnum), reason(errnum), o->role);
    }
    char *gone = xcalloc(n_inputs > from ? n_inputs - from : 1, 1, "inputs");
    for (size_t i = from; i < n_inputs; i++)
        gone[i - from] = !input_opens(i);
    errno = 0;
    if (undo_now(o->tmp_undo) != 0) {
        xfree(gone);
        o->checked = 0;
        return error_set(err, o->name, 0, "moved to %s for a moment and cannot be moved "
                         "back: %s", o->tmp_name, strerror(errno));
    }
    xfree(o->tmp_name);
    o->tmp_name = NULL;
    size_t through = from;
    while (through < n_inputs && !(gone[through - from] && input_opens(through)))
        through++;
    xfree(gone);
    if (through < n_inputs)
        return error_set(err, o->name, 0, "%s is the input %s of this command: writing it "
                         "would destroy that input", o->role, inputs[through]);
    return 0;
}

/* -1 with *err when o is inputs[i], of `size` bytes (output.h). */
static int refuse_if_same(struct output *o, size_t i, long size, struct error *err)
{
    if (o->lone || o->state != OUTPUT_DECLARED || file_size(o->name) != size ||
        file_is_directory(o->name) || !same_bytes(o->name, inputs[i]))
        return 0;
    return round_trip(o, i, err);
}

int output_refuse_input(const char *name, long size, struct error *err)
{
    register_cleanup();
    if (n_inputs == cap_inputs) {
        cap_inputs = cap_inputs < 8 ? 8 : 2 * cap_inputs;
        inputs = xrealloc(inputs, cap_inputs, sizeof *inputs, "inputs");
    }
    inputs[n_inputs] = xstrdup(name);
    n_inputs++;
    for (size_t i = 0; i < n_outputs; i++)
        if (refuse_if_same(&outputs[i], n_inputs - 1, size, err) < 0)
            return -1;
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
    if (file_is_pipe(o->name))
        return error_set(err, o->name, 0, "is a FIFO or a terminal, not a regular file (%s): "
                         "photon writes whole files, each renamed into place", o->role);
    if (n + sizeof TEMPORARY_SUFFIX > OUTPUT_NAME_MAX)
        return error_set(err, o->name, 0, "the file name is too long (%s)", o->role);
    return 0;
}

/* outputs[k]'s probe, a new file of ours beside it holding its marker, unless an earlier
 * output's probe is there already: then that output is the same file. */
static int make_probe(size_t k, struct error *err)
{
    struct output *o = &outputs[k];
    size_t same = NO_OUTPUT;
    int errnum;
    FILE *f = create_ours(o->name, o->tmp_undo, &o->tmp_name, k, &same, &errnum);
    if (same != NO_OUTPUT)
        return error_set(err, o->name, 0, "%s names the same file as %s (%s)", o->role,
                         outputs[same].role, outputs[same].name);
    if (f == NULL)
        return error_set(err, o->name, 0, "cannot create output file%s%s (%s)", colon(errnum),
                         reason(errnum), o->role);
    char marker[PROBE_MARKER_MAX];
    probe_marker(k, marker);
    fputs(marker, f);
    int why = close_written(f);
    if (why != 0)
        return error_set(err, o->name, 0, "cannot write output file%s%s (%s)", colon(why),
                         reason(why), o->role);
    return 0;
}

/* An existing output must open for writing (without being changed): for update, which
 * never waits (file_kind.h; check_name() refused a FIFO that opens so). */
static int check_writable(const struct output *o, struct error *err)
{
    int pipe;
    errno = 0;
    FILE *f = file_open_no_wait(o->name, &pipe);
    int errnum = errno;
    if (f != NULL) {
        fclose(f);
        return 0;
    }
    if (!file_is_there(o->name))
        return 0; /* absent: its directory took the probe */
    return error_set(err, o->name, 0, "the file exists and cannot be written%s%s (%s)",
                     colon(errnum), reason(errnum), o->role);
}

int outputs_check(struct error *err)
{
    int status = 0;
    for (size_t k = 0; k < n_outputs && status == 0; k++) {
        assert(outputs[k].state == OUTPUT_DECLARED); /* checked before any is opened */
        if (!outputs[k].lone && (status = check_name(&outputs[k], err)) == 0)
            status = make_probe(k, err);
    }
    for (size_t k = 0; k < n_outputs && status == 0; k++)
        if (!outputs[k].lone && (status = check_writable(&outputs[k], err)) == 0)
            status = round_trip(&outputs[k], 0, err);
    for (size_t k = 0; k < n_outputs; k++) {
        if (outputs[k].lone)
            continue;
        drop_temporary(&outputs[k]);
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
                        const char *why)
{
    error_set(err, file, 0, "%s%s%s", message, why[0] != '\0' ? ": " : "", why);
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
    if (strlen(name) + sizeof TEMPORARY_SUFFIX > OUTPUT_NAME_MAX) {
        write_failed(err, name, "output file name is too long", "");
        return NULL;
    }
    if (o == NULL)
        o = add_output(name, "", 1);
    if (o->state == OUTPUT_OPEN)
        fclose(o->stream); /* opened again before its commit: the first one is dropped */
    drop_temporary(o);
    o->state = OUTPUT_DECLARED;
    int errnum;
    o->stream = create_ours(name, o->tmp_undo, &o->tmp_name, NO_OUTPUT, NULL, &errnum);
    if (o->stream == NULL) {
        write_failed(err, name, "cannot create output file", reason(errnum));
        if (o->lone)
            forget((size_t)(o - outputs));
        return NULL;
    }
    o->state = OUTPUT_OPEN;
    return o->stream;
}

/* Renames o's committed temporary to its name: 0, or the errno of what failed (-1
 * without one), and then o's temporary is still there. With keep, what the rename would
 * destroy is first made something o->aside_undo can give back: the file there is moved
 * aside, onto a file of ours (aside_name); or, with nothing there, the name is taken by
 * an exclusive create, so that o once in place is a file of ours to remove. */
static int put_in_place(struct output *o, int keep)
{
    int errnum = 0;
    FILE *f;
    if (keep && (f = fopen(o->name, "wbx")) != NULL) { /* never waits, never follows */
        fclose(f);
        undo_set(o->aside_undo, UNDO_REMOVE, o->name, NULL);
    } else if (keep) {
        f = create_ours(o->name, o->aside_undo, &o->aside_name, NO_OUTPUT, NULL, &errnum);
        if (f == NULL)
            return errnum != 0 ? errnum : -1;
        fclose(f);
        errno = 0;
        if (rename(o->name, o->aside_name) != 0)
            return errno != 0 ? errno : -1; /* what cannot be moved cannot be replaced */
        undo_set(o->aside_undo, UNDO_RENAME_BACK, o->aside_name, o->name);
    }
    errno = 0;
    if (rename(o->tmp_name, o->name) != 0)
        return errno != 0 ? errno : -1;
    undo_set(o->tmp_undo, UNDO_NOTHING, NULL, NULL);
    xfree(o->tmp_name);
    o->tmp_name = NULL;
    o->state = OUTPUT_DECLARED;
    return 0;
}

int output_commit(FILE *f, struct error *err)
{
    struct output *o = find_stream(f);
    if (o == NULL)
        return error_set(err, "", 0, "output_commit: stream was not opened by output_open");
    int why = close_written(f);
    o->stream = NULL;
    o->state = OUTPUT_COMMITTED;
    if (why == 0 && o->lone)
        why = put_in_place(o, 0);
    if (why != 0) {
        drop_temporary(o);
        o->state = OUTPUT_DECLARED;
    }
    int status = why != 0 ? write_failed(err, o->name, "cannot write output file", reason(why))
                          : 0;
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
    drop_temporary(o);
    o->stream = NULL;
    o->state = OUTPUT_DECLARED;
    if (o->lone)
        forget((size_t)(o - outputs));
}

/* *err, which says why a publish failed, made to say first what its rollback could not
 * undo for o, and why (errnum, the failed rename's or remove's errno): the user must learn
 * where a replaced file waits, or that a new file stayed, not only that a write failed. */
static void rollback_failed(const struct output *o, int errnum, struct error *err)
{
    if (err == NULL)
        return;
    char cause[ERROR_FILE_MAX + 2 + ERROR_MESSAGE_MAX]; /* "FILE: MESSAGE" */
    snprintf(cause, sizeof cause, "%s%s%s", err->file, err->file[0] != '\0' ? ": " : "",
             err->message);
    if (o->aside_name != NULL)
        error_set(err, o->name, 0, "the file it replaced cannot be put back%s%s; the new "
                  "file stays, and the one it replaced is kept as %s (the write that "
                  "failed: %s)", colon(errnum), reason(errnum), o->aside_name, cause);
    else
        error_set(err, o->name, 0, "this new file cannot be removed%s%s; it stays where "
                  "there was none (the write that failed: %s)", colon(errnum),
                  reason(errnum), cause);
    err->failed_write = 1;
}

/* The end of a publish: each output it put in place keeps it (the file it replaced,
 * kept aside, is removed), or, when it failed, gives back what was there (the file kept
 * aside is renamed back; a name that held nothing is removed). -1 with *err when that
 * cannot be done for an output: rollback_failed() says so for the first such output (a
 * file kept aside stays where it is, never removed). */
static int end_publish(int failed, struct error *err)
{
    int status = 0;
    for (size_t i = 0; i < n_outputs; i++) {
        struct output *o = &outputs[i];
        if (!o->published)
            continue;
        if (!failed && o->aside_name != NULL)
            undo_set(o->aside_undo, UNDO_REMOVE, o->aside_name, NULL);
        else if (!failed)
            undo_set(o->aside_undo, UNDO_NOTHING, NULL, NULL);
        errno = 0;
        if (undo_now(o->aside_undo) != 0 && failed) {
            if (status == 0)
                rollback_failed(o, errno, err);
            status = -1;
            undo_set(o->aside_undo, UNDO_NOTHING, NULL, NULL); /* the user's: never removed */
        }
        xfree(o->aside_name);
        o->aside_name = NULL;
        o->published = 0;
    }
    return status;
}

int outputs_publish(struct error *err)
{
    size_t last = NO_OUTPUT;
    for (size_t i = 0; i < n_outputs; i++)
        if (outputs[i].state == OUTPUT_COMMITTED)
            last = i;
    int status = 0;
    undo_hold(); /* a signal waits until every output is in place, or none */
    for (size_t i = 0; last != NO_OUTPUT && i <= last && status == 0; i++) {
        if (outputs[i].state != OUTPUT_COMMITTED)
            continue;
        outputs[i].published = 1;
        int why = put_in_place(&outputs[i], i < last); /* the last has nothing after it to
                                                          fail, and is replaced at once */
        if (why != 0)
            status = write_failed(err, outputs[i].name, "cannot write output file",
                                  reason(why));
    }
    if (end_publish(status != 0, err) < 0)
        status = -1;
    for (size_t i = 0; status != 0 && i < n_outputs; i++)
        if (outputs[i].state == OUTPUT_COMMITTED) {
            drop_temporary(&outputs[i]);
            outputs[i].state = OUTPUT_DECLARED;
        }
    undo_release();
    return status;
}

void outputs_abandon(void)
{
    for (size_t i = 0; i < n_outputs; i++) {
        if (outputs[i].state == OUTPUT_OPEN)
            fclose(outputs[i].stream);
        drop_temporary(&outputs[i]);
        undo_now(outputs[i].aside_undo);
        xfree(outputs[i].name);
        xfree(outputs[i].tmp_name);
        xfree(outputs[i].aside_name);
        undo_free(outputs[i].tmp_undo);
        undo_free(outputs[i].aside_undo);
    }
    for (size_t i = 0; i < n_inputs; i++)
        xfree(inputs[i]);
    xfree(outputs);
    xfree(inputs);
    outputs = NULL;
    inputs = NULL;
    n_outputs = cap_outputs = n_inputs = cap_inputs = 0;
}
