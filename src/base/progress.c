/*
 * base/progress.c -- the progress line of a phase of work (progress.h).
 */
#include "progress.h"

#include <stdarg.h>
#include <string.h>

#define PROGRESS_LINE_MAX 256 /* the longest line: a mode's words are well under 200 */

int progress_lines_to(FILE *out)
{
    return ftell(out) >= 0; /* a file has a position; a terminal or a pipe has none */
}

void progress_begin(struct progress *p, FILE *out, const char *phase, double total,
                    time_t now)
{
    memset(p, 0, sizeof *p);
    p->out = out;
    p->phase = phase;
    p->total = total > 0 ? total : 0.0;
    p->lines = out != NULL && progress_lines_to(out);
    p->start = now;
    p->shown = now;
    p->now = now;
}

/* Notes the work done by now, and whether it is the phase's last update. */
static void record(struct progress *p, double done, time_t now, int last)
{
    p->done = done;
    p->now = now;
    p->last = last;
}

int progress_update(struct progress *p, double done, time_t now)
{
    if (p->out == NULL)
        return 0;
    record(p, done, now, 0);
    double every = p->lines ? PROGRESS_FILE_EVERY : PROGRESS_SCREEN_EVERY;
    return difftime(now, p->shown) >= every;
}

int progress_end(struct progress *p, double done, time_t now)
{
    if (p->out == NULL)
        return 0;
    record(p, done, now, 1);
    if (difftime(p->shown, p->start) > 0 && p->shown_done == done) {
        if (p->width > 0)
            fputc('\n', p->out);
        p->width = 0;
        return 0;
    }
    return 1;
}

double progress_seconds_left(const struct progress *p)
{
    if (p->total <= 0 || p->done <= 0)
        return -1.0;
    double left = p->total > p->done ? p->total - p->done : 0.0;
    return difftime(p->now, p->start) * left / p->done;
}

void progress_print(struct progress *p, const char *format, ...)
{
    if (p->out == NULL)
        return;
    char words[PROGRESS_LINE_MAX], line[2 * PROGRESS_LINE_MAX];
    va_list args;
    va_start(args, format);
    vsnprintf(words, sizeof words, format, args); /* a longer line is cut, never overrun */
    va_end(args);
    int n = snprintf(line, sizeof line, "photon: %s: %s, %.0f s", p->phase, words,
                     difftime(p->now, p->start));
    double left = progress_seconds_left(p);
    if (left >= 0 && n >= 0 && (size_t)n < sizeof line)
        snprintf(line + n, sizeof line - (size_t)n, ", about %.0f s left", left);
    if (p->lines) {
        fprintf(p->out, "%s\n", line);
    } else {
        /* In place: blank what a longer line before left beyond this one's end. */
        int width = (int)strlen(line);
        fprintf(p->out, "\r%s%*s", line, p->width > width ? p->width - width : 0, "");
        p->width = width;
        if (p->last) {
            fputc('\n', p->out);
            p->width = 0;
        }
    }
    fflush(p->out);
    p->shown = p->now;
    p->shown_done = p->done;
}
