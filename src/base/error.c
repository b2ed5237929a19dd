/*
 * base/error.c -- error records, fatal(), and outputs written under a temporary name.
 *
 * Invariant: outputs[] holds every stream opened by output_open() that has not yet been
 * committed or abandoned, with the final name; fatal() removes their temporaries.
 */
#include "error.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#define MAX_OPEN_OUTPUTS 8 /* a render writes at most image, display copy, variance, report */
#define OUTPUT_NAME_MAX 1024

struct open_output {
    FILE *stream;
    char name[OUTPUT_NAME_MAX];     /* final name */
    char tmp_name[OUTPUT_NAME_MAX]; /* name + ".tmp", where the bytes go until commit */
};

static struct open_output outputs[MAX_OPEN_OUTPUTS];

/* text into out[size] with every byte outside printable ASCII (a control byte, DEL, or
 * any byte >= 0x80) written as \xNN, so that a message echoing a file's bytes or a
 * command line's cannot move the terminal's cursor or change its colours; cut, whole
 * bytes and escapes only, where out is full. */
static void copy_quoted(char *out, size_t size, const char *text)
{
    size_t n = 0;
    for (const unsigned char *c = (const unsigned char *)text; *c != '\0'; c++) {
        int printable = *c >= 0x20 && *c < 0x7F;
        if (n + (printable ? 1 : 4) >= size)
            break;
        if (printable)
            out[n++] = (char)*c;
        else
            n += (size_t)sprintf(out + n, "\\x%02x", *c);
    }
    out[n] = '\0';
}

int error_set(struct error *err, const char *file, int line, const char *format, ...)
{
    if (err == NULL)
        return -1;
    char message[ERROR_MESSAGE_MAX];
    va_list args;
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    copy_quoted(err->message, sizeof err->message, message);
    copy_quoted(err->file, sizeof err->file, file != NULL ? file : "");
    err->line = line;
    err->failed_write = 0;
    return -1;
}

/* error_set() for a write that failed. */
static int write_failed(struct error *err, const char *file, const char *message,
                        const char *reason)
{
    error_set(err, file, 0, "%s%s%s", message, reason[0] != '\0' ? ": " : "", reason);
    if (err != NULL)
        err->failed_write = 1;
    return -1;
}

int error_exit_status(const struct error *err)
{
    return err->failed_write ? 1 : 2;
}

void error_print(const struct error *err)
{
    if (err->file[0] == '\0')
        fprintf(stderr, "photon: %s\n", err->message);
    else if (err->line > 0)
        fprintf(stderr, "%s:%d: %s\n", err->file, err->line, err->message);
    else
        fprintf(stderr, "%s: %s\n", err->file, err->message);
}

static struct open_output *find_output(FILE *f)
{
    for (int i = 0; i < MAX_OPEN_OUTPUTS; i++)
        if (outputs[i].stream == f && f != NULL)
            return &outputs[i];
    return NULL;
}

void fatal(const char *format, ...)
{
    for (int i = 0; i < MAX_OPEN_OUTPUTS; i++)
        if (outputs[i].stream != NULL)
            output_abandon(outputs[i].stream);
    va_list args;
    va_start(args, format);
    fputs("photon: ", stderr);
    vfprintf(stderr, format, args);
    fputc('\n', stderr);
    va_end(args);
    exit(1);
}

FILE *output_open(const char *name, struct error *err)
{
    struct open_output *slot = find_output(NULL);
    for (int i = 0; slot == NULL && i < MAX_OPEN_OUTPUTS; i++)
        if (outputs[i].stream == NULL)
            slot = &outputs[i];
    if (slot == NULL) {
        error_set(err, name, 0, "too many outputs open at once");
        return NULL;
    }
    if (strlen(name) + 5 > OUTPUT_NAME_MAX) {
        write_failed(err, name, "output file name is too long", "");
        return NULL;
    }
    snprintf(slot->name, sizeof slot->name, "%s", name);
    snprintf(slot->tmp_name, sizeof slot->tmp_name, "%s.tmp", name);
    errno = 0;
    slot->stream = fopen(slot->tmp_name, "wb");
    if (slot->stream == NULL) {
        write_failed(err, name, "cannot create output file", errno != 0 ? strerror(errno) : "");
        return NULL;
    }
    return slot->stream;
}

int output_check(const char *name, struct error *err)
{
    FILE *f = output_open(name, err);
    if (f == NULL) {
        if (err != NULL)
            err->failed_write = 0; /* asked before any work: the name is at fault */
        return -1;
    }
    output_abandon(f);
    return 0;
}

int output_commit(FILE *f, struct error *err)
{
    struct open_output *slot = find_output(f);
    if (slot == NULL)
        return error_set(err, "", 0, "output_commit: stream was not opened by output_open");
    int failed = ferror(f) != 0;
    failed |= fclose(f) != 0;
    slot->stream = NULL;
    if (failed || rename(slot->tmp_name, slot->name) != 0) {
        remove(slot->tmp_name);
        return write_failed(err, slot->name, "cannot write output file", "");
    }
    return 0;
}

void output_abandon(FILE *f)
{
    struct open_output *slot = find_output(f);
    if (slot == NULL)
        return;
    fclose(f);
    remove(slot->tmp_name);
    slot->stream = NULL;
}
