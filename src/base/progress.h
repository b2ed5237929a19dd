/*
 * base/progress.h -- the progress line of a phase of work (photon tracing, the irradiance
 * cache's pre-pass, sample passes, progressive passes): what it says, how often, and the
 * time left.
 *
 * The time is wall-clock seconds, C99's time(): what a user waits for. (The renderer's
 * other timings, --stats and the reports, count CPU seconds, which a busy machine or a
 * checkpoint write keep from matching the clock on the wall.) The time left is forecast
 * from this phase's work alone: elapsed x (total - done) / done, so a slow first phase does
 * not colour the next one's forecast. time() counts whole seconds, so no line but the last
 * is shown before the first second has passed; the forecast is then about one second
 * coarse, less and less in proportion as the phase goes on.
 *
 * Two forms, chosen by where the line goes, since C99 cannot ask whether a stream is a
 * terminal: ftell() succeeds on a regular file (stderr redirected to a log) and fails on a
 * terminal or a pipe. On a file: a whole line per update, at most one every
 * PROGRESS_FILE_EVERY seconds, and the phase's last line; a log holds no carriage return.
 * Otherwise: one line rewritten in place with a carriage return, at most once a second,
 * ended by the phase's last line.
 *
 * A caller asks whether a line is due (progress_update(), progress_end()) before it
 * works out what the line says, which may cost something (a mean over hit points), then
 * prints it with progress_print(). The current time is passed in, so that the tests can
 * drive the rule and the forecast with a clock of their own.
 */
#ifndef BASE_PROGRESS_H
#define BASE_PROGRESS_H

#include <stdio.h>
#include <time.h>

#define PROGRESS_FILE_EVERY 10.0 /* seconds between lines in a file: a long render's log
                                    stays short, a stuck one still shows it moves        */
#define PROGRESS_SCREEN_EVERY 1.0 /* seconds between rewrites of the line in place: as
                                     often as time() can tell apart                      */

struct progress {
    FILE *out;         /* where lines go; NULL: progress off, every call does nothing     */
    const char *phase; /* what the phase is called on its line, e.g. "photon tracing"     */
    double total;      /* the phase's work, in the caller's units; 0: not known, and no
                          forecast is shown                                               */
    int lines;         /* 1: a whole line per update (out is a file); 0: rewritten in place */
    time_t start;      /* when the phase began                                            */
    time_t shown;      /* when the last line was shown (start before the first)           */
    time_t now;        /* the last update's time and work: what progress_print() shows    */
    double done;
    int last;          /* the update being shown is the phase's last                      */
    int width;         /* characters of the line in place, to blank a longer one's tail;
                          0: none is open                                                 */
    double shown_done; /* the work the last line shown said was done                      */
};

/* Begins a phase at time now: total units of work (0 when not known), lines to out
 * (NULL: off) in the form its kind chooses (above). */
void progress_begin(struct progress *p, FILE *out, const char *phase, double total,
                    time_t now);

/* Records done units of work at time now; 1 when a line is due (then print it with
 * progress_print()), 0 when not or when progress is off. */
int progress_update(struct progress *p, double done, time_t now);

/* The phase's last update: due when progress is on, and the line it prints ends the
 * phase's line in place; not due when the last line shown already said as much (the
 * line in place is then ended here), so that a log holds no line twice. */
int progress_end(struct progress *p, double done, time_t now);

/* Prints the line of the last update: "photon: PHASE: " then format's words, then the
 * seconds elapsed and, when the total is known, "about N s left". */
void progress_print(struct progress *p, const char *format, ...);

/* The forecast of the last update: elapsed x (total - done) / done, wall-clock seconds;
 * -1 when it cannot be made (no total, nothing done yet). */
double progress_seconds_left(const struct progress *p);

/* Whether lines to out take the form of a file's log (1) or a line in place (0). */
int progress_lines_to(FILE *out);

#endif
