/*
 * tests/check.c -- the harness behind check.h.
 */
#include "check.h"

#include <math.h>
#include <stdlib.h>

void check_failed(struct check *t, const char *file, int line, const char *expr)
{
    t->failures_in_test++;
    if (t->reports_in_test++ < CHECK_MAX_REPORTS)
        fprintf(stderr, "%s:%d: check failed: %s\n", file, line, expr);
}

void check_close(struct check *t, double a, double b, double tol, const char *file, int line,
                 const char *expr)
{
    if (fabs(a - b) <= tol)
        return;
    t->failures_in_test++;
    if (t->reports_in_test++ < CHECK_MAX_REPORTS)
        fprintf(stderr, "%s:%d: check failed: %s (%.17g vs %.17g, tolerance %.3g)\n", file,
                line, expr, a, b, tol);
}

void run_test(struct check *t, void (*test)(struct check *), const char *name)
{
    t->failures_in_test = 0;
    t->reports_in_test = 0;
    t->running = name;
    test(t);
    t->running = NULL;
    if (t->failures_in_test == 0) {
        t->passed++;
    } else {
        t->failed++;
        fprintf(stderr, "FAILED: %s\n", name);
    }
}

void check_summary(struct check *t)
{
    if (t->running != NULL) {
        t->failed++;
        fprintf(stderr, "FAILED: %s (the program exited inside it)\n", t->running);
        t->running = NULL;
    }
    printf("%d passed, %d failed\n", t->passed, t->failed);
    fflush(stdout);
}

const char *photon_binary(void)
{
    const char *path = getenv("PHOTON");
    return path != NULL ? path : "./photon";
}

/* system() returns a wait status; on POSIX systems the exit code is its second byte.
 * The C standard leaves the value implementation-defined, so tests run only on POSIX. */
int run_command(const char *command)
{
    fflush(stdout);
    fflush(stderr);
    int status = system(command);
    if (status == -1 || (status & 0x7f) != 0)
        return -1;
    return (status >> 8) & 0xff;
}
