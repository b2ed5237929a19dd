/*
 * base/error.c -- error records, fatal() and the standard output's last check.
 */
#include "error.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

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

void message_print(const char *format, ...)
{
    char message[ERROR_MESSAGE_MAX], quoted[ERROR_MESSAGE_MAX];
    va_list args;
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    copy_quoted(quoted, sizeof quoted, message);
    fprintf(stderr, "%s\n", quoted);
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

int standard_output_status(int status)
{
    errno = 0; /* a failed write earlier set ferror(), and left errno to later calls */
    if (fflush(stdout) == 0 && !ferror(stdout))
        return status;
    int errnum = errno;
    fprintf(stderr, "photon: cannot write the standard output%s%s\n", errnum > 0 ? ": " : "",
            errnum > 0 ? strerror(errnum) : "");
    return status != 0 ? status : 1;
}

void fatal(const char *format, ...)
{
    va_list args;
    va_start(args, format);
    fputs("photon: ", stderr);
    vfprintf(stderr, format, args);
    fputc('\n', stderr);
    va_end(args);
    exit(1);
}
