/*
 * tests/check.h -- the test harness: CHECK records a failed expression with file:line,
 * REQUIRE does the same and then returns from the test function, RUN_TEST runs one test
 * function and counts it as passed when none of its checks failed.
 * tests/run_tests.c prints "N passed, N failed" and exits non-zero on any failure.
 */
#ifndef PHOTON_CHECK_H
#define PHOTON_CHECK_H

#include <stdio.h>

#define CHECK_MAX_REPORTS 10 /* failures printed per test: enough to see a pattern */

struct check {
    int passed;          /* test functions with no failed check */
    int failed;          /* test functions with at least one    */
    int failures_in_test; /* failed checks in the running test   */
    int reports_in_test; /* failures printed, capped so a loop cannot flood the log */
    const char *running; /* the running test's name; NULL between tests */
};

void check_failed(struct check *t, const char *file, int line, const char *expr);

#define CHECK(t, expr) \
    ((expr) ? (void)0 : check_failed((t), __FILE__, __LINE__, #expr))

/* REQUIRE: a precondition the rest of the test depends on (a file that loaded, a count
 * later used as a size). When it fails it counts as a failed check and the test function
 * returns there, so nothing after it runs on a NULL pointer or a wrong size. For use in
 * the test function itself (it returns void), not in helpers that return a value. */
#define REQUIRE(t, expr) \
    do { \
        if (!(expr)) { \
            check_failed((t), __FILE__, __LINE__, #expr); \
            return; \
        } \
    } while (0)

/* CHECK_CLOSE: |a - b| <= tol, with both values printed on failure. */
#define CHECK_CLOSE(t, a, b, tol) \
    check_close((t), (a), (b), (tol), __FILE__, __LINE__, #a " ~ " #b)
void check_close(struct check *t, double a, double b, double tol, const char *file, int line,
                 const char *expr);

void run_test(struct check *t, void (*test)(struct check *), const char *name);
#define RUN_TEST(t, fn) run_test((t), (fn), #fn)

/* Prints "N passed, N failed". When a test is still running (the program is exiting from
 * inside it: fatal() in the code under test), that test is first reported and counted as
 * failed, so the log always ends with the summary. */
void check_summary(struct check *t);

/* The path of the photon binary under test (environment PHOTON, default ./photon). */
const char *photon_binary(void);
/* Runs a shell command and returns its exit status (0..255), or -1 if it did not exit. */
int run_command(const char *command);

#endif
