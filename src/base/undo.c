/*
 * base/undo.c -- the list of files to put right, and the signal handler that does it
 * (undo.h).
 *
 * Invariants: head links every entry undo_new() made and undo_free() has not taken out;
 * an entry is linked in only whole. holds counts the undo_hold() not yet released, and
 * while it is above 0 the main program may be changing the list, so the handler only
 * notes its signal in pending, for undo_release() to act on.
 */
/* On a POSIX system, sigaction() (see catch_signal()); its declaration needs this first. */
#if defined(__unix__) || defined(__APPLE__)
#define _POSIX_C_SOURCE 200112L
#define UNDO_SIGACTION 1
#endif

#include "undo.h"

#include <assert.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>

#include "alloc.h"

struct undo {
    volatile sig_atomic_t action;     /* an enum undo_action                     */
    volatile char path[UNDO_PATH_MAX]; /* the file on disk the action is about    */
    volatile char back[UNDO_PATH_MAX]; /* UNDO_RENAME_BACK: the user's own name    */
    struct undo *volatile next;
};

static struct undo *volatile head;
static volatile sig_atomic_t holds;   /* undo_hold()s not yet released             */
static volatile sig_atomic_t pending; /* a signal that came under a hold; 0: none  */
static int installed;

/* The signals whose default action ends the program (C99's three, then those POSIX adds
 * where <signal.h> has them). Not SIGPROF, SIGVTALRM: profilers use them. */
static const int stop_signals[] = {
    SIGINT, SIGTERM, SIGABRT,
#ifdef SIGHUP
    SIGHUP,
#endif
#ifdef SIGQUIT
    SIGQUIT,
#endif
#ifdef SIGPIPE
    SIGPIPE,
#endif
#ifdef SIGALRM
    SIGALRM,
#endif
#ifdef SIGUSR1
    SIGUSR1,
#endif
#ifdef SIGUSR2
    SIGUSR2,
#endif
#ifdef SIGXCPU
    SIGXCPU,
#endif
#ifdef SIGXFSZ
    SIGXFSZ,
#endif
};

/* from[] into to[UNDO_PATH_MAX]: a library function takes no volatile string. */
static void copy_out(char *to, const volatile char *from)
{
    size_t i = 0;
    while (i + 1 < UNDO_PATH_MAX && (to[i] = from[i]) != '\0')
        i++;
    to[i] = '\0';
}

static void copy_in(volatile char *to, const char *from)
{
    size_t i = 0;
    for (; from[i] != '\0' && i + 1 < UNDO_PATH_MAX; i++)
        to[i] = from[i];
    to[i] = '\0';
}

/* Does what u says: 0, and u says nothing more; -1 when that failed. Called by the
 * handler too, so it uses only remove() and rename() (undo.h). */
static int act(struct undo *u)
{
    char path[UNDO_PATH_MAX], back[UNDO_PATH_MAX];
    int failed = 0;
    copy_out(path, u->path);
    if (u->action == UNDO_REMOVE) {
        failed = remove(path) != 0;
    } else if (u->action == UNDO_RENAME_BACK) {
        copy_out(back, u->back);
        failed = rename(path, back) != 0;
    }
    if (failed)
        return -1;
    u->action = UNDO_NOTHING;
    return 0;
}

/* Puts every entry right, then ends the program with sig as its default action would. A
 * second signal meanwhile waits (holds), and the first ends the program. */
static void stop(int sig)
{
    holds = 1;
    for (struct undo *u = head; u != NULL; u = u->next)
        act(u);
    signal(sig, SIG_DFL);
    raise(sig); /* delivered at once, or as the handler returns (sigaction() blocks sig) */
}

static void on_signal(int sig);

/* Makes on_signal() sig's handler. C99's signal() may set the action back to the default
 * as the handler is entered (glibc's does under -std=c99, System V's rule), so a second
 * signal (a ^C pressed twice; timeout(1) signals the process, then its group) could end
 * photon halfway through putting the files right. POSIX's sigaction() keeps the handler
 * and blocks every stop signal while it runs; elsewhere the handler sets itself again as
 * its first step, which leaves the few instructions before it open (undo.h). */
static void catch_signal(int sig)
{
#ifdef UNDO_SIGACTION
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    for (size_t i = 0; i < sizeof stop_signals / sizeof stop_signals[0]; i++)
        sigaddset(&action.sa_mask, stop_signals[i]);
    sigaction(sig, &action, NULL);
#else
    signal(sig, on_signal);
#endif
}

static void on_signal(int sig)
{
    catch_signal(sig);
    if (holds > 0)
        pending = sig;
    else
        stop(sig);
}

/* Whether sig's action is to be left as photon was started with it: ignored (nohup,
 * `trap '' HUP`), or unreadable. POSIX's sigaction() reads the action without changing
 * it, so a ^C that comes meanwhile still stops photon. C99's signal() reads it only by
 * setting one: SIG_IGN, so that a signal in between is not taken for a stop, but is lost
 * (undo.h). */
static int left_alone(int sig)
{
#ifdef UNDO_SIGACTION
    struct sigaction now;
    return sigaction(sig, NULL, &now) != 0 || now.sa_handler == SIG_IGN;
#else
    void (*before)(int) = signal(sig, SIG_IGN);
    return before == SIG_IGN || before == SIG_ERR;
#endif
}

/* Catches every stop signal but those left alone. */
static void install(void)
{
    for (size_t i = 0; i < sizeof stop_signals / sizeof stop_signals[0]; i++)
        if (!left_alone(stop_signals[i]))
            catch_signal(stop_signals[i]);
}

void undo_hold(void)
{
    holds = holds + 1;
}

void undo_release(void)
{
    assert(holds > 0);
    holds = holds - 1;
    if (holds == 0 && pending != 0)
        stop(pending);
}

struct undo *undo_new(void)
{
    if (!installed) {
        install();
        installed = 1;
    }
    struct undo *u = xmalloc(1, sizeof *u, "undo entry");
    u->action = UNDO_NOTHING;
    u->path[0] = '\0';
    u->back[0] = '\0';
    undo_hold();
    u->next = head;
    head = u;
    undo_release();
    return u;
}

void undo_set(struct undo *u, enum undo_action action, const char *path, const char *back)
{
    assert(action == UNDO_NOTHING || strlen(path) < UNDO_PATH_MAX);
    assert(action != UNDO_RENAME_BACK || strlen(back) < UNDO_PATH_MAX);
    undo_hold();
    u->action = UNDO_NOTHING;
    if (action != UNDO_NOTHING)
        copy_in(u->path, path);
    if (action == UNDO_RENAME_BACK)
        copy_in(u->back, back);
    u->action = action;
    undo_release();
}

int undo_now(struct undo *u)
{
    undo_hold();
    int status = act(u);
    undo_release();
    return status;
}

void undo_free(struct undo *u)
{
    if (u == NULL)
        return;
    undo_hold();
    struct undo *volatile *link = &head;
    while (*link != u)
        link = &(*link)->next;
    *link = u->next;
    undo_release();
    xfree(u);
}
