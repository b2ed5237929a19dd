/*
 * tests/check.h -- the test harness: CHECK records a failed expression with file:line,
 * RUN_TEST runs one test function and counts it as passed when none of its CHECKs failed.
 * tests/run_tests.c prints "N passed, N failed" and exits non-zero on any failure.
 */
#ifndef PHOTON_CHECK_H
#define PHOTON_CHECK_H

#include <stdio.h>

struct check {
    int passed;          /* test functions with no failed CHECK */
    int failed;          /* test functions with at least one    */
    int failures_in_test; /* failed CHECKs in the running test   */
    int reports_in_test; /* failures printed, capped so a loop cannot flood the log */
};

void check_failed(struct check *t, const char *file, int line, const char *expr);

#define CHECK(t, expr) \
    ((expr) ? (void)0 : check_failed((t), __FILE__, __LINE__, #expr))

/* CHECK_CLOSE: |a - b| <= tol, with both values printed on failure. */
#define CHECK_CLOSE(t, a, b, tol) \
    check_close((t), (a), (b), (tol), __FILE__, __LINE__, #a " ~ " #b)
void check_close(struct check *t, double a, double b, double tol, const char *file, int line,
                 const char *expr);

void run_test(struct check *t, void (*test)(struct check *), const char *name);
#define RUN_TEST(t, fn) run_test((t), (fn), #fn)

/* The path of the photon binary under test (environment PHOTON, default ./photon). */
const char *photon_binary(void);
/* Runs a shell command and returns its exit status (0..255), or -1 if it did not exit. */
int run_command(const char *command);

#endif
