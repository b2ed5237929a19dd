/*
 * base/undo.h -- the files photon has on disk that are not final, and what puts each right
 * when photon is stopped: by a signal, or at exit.
 *
 * The output registry (output.h) keeps one entry here for each such file, set before the
 * file appears and cleared once it is gone or final: a file photon made (a temporary, a
 * probe), to remove; or a user's file photon moved aside for a moment (to test a name, or
 * to keep it while a command's outputs are put in place), to rename back. At exit,
 * outputs_abandon() (run by atexit()) does what each entry says, through undo_now().
 *
 * A signal that would end photon (SIGINT, SIGTERM, SIGABRT and, where <signal.h> defines
 * them, SIGHUP, SIGQUIT, SIGPIPE, SIGALRM, SIGUSR1, SIGUSR2, SIGXCPU, SIGXFSZ) does the
 * same, then ends photon as its default action would: the handler sets that action back
 * and raises the signal again, so the exit status still names it. A signal photon was
 * started ignoring (nohup, `trap '' HUP`) stays ignored.
 *
 * What C99 allows, and what this relies on beyond it. C99 lets a handler for a signal
 * that did not come from raise() or abort() only assign a volatile sig_atomic_t and call
 * abort(), _Exit() and signal(). A handler that only set a flag would leave the render,
 * which photon cannot interrupt at a safe point, running for minutes or hours; one that
 * called _Exit() would leave the files. So the handler reads this list and calls remove()
 * and rename(), which POSIX makes safe in a handler (its unlink() and rename() are
 * async-signal-safe; glibc's remove() is unlink(), then rmdir() for a directory, and
 * neither allocates nor locks), then signal() and raise(). What keeps the list readable
 * at any instant: every field the handler reads is volatile, so the compiler keeps the
 * order of the writes; an entry is linked in only once whole; and every change to the
 * list is made under undo_hold(), while which a signal only sets a flag and is acted on
 * at undo_release(). The holds are short and never wait (a rename, a link in a list).
 *
 * On a POSIX system the handler is set by sigaction(), photon's one use of POSIX beyond
 * C99: C99's signal() may set the default action back as a handler is entered, and a
 * second signal then (^C pressed twice) would end photon before the files are right.
 *
 * Not covered: SIGKILL and SIGSTOP, which no handler sees; without POSIX, a second signal
 * in the few instructions before the handler sets itself again, and a signal in the
 * instant a handler is installed, ignored then, since C99 reads an action only by
 * setting one; and a crash (SIGSEGV, SIGBUS, SIGILL, SIGFPE), after which the list itself
 * may be damaged: those leave a temporary (NAME.XXXXXXXX.tmp), which no later run
 * removes, as it cannot tell it from a user's.
 */
#ifndef PHOTON_UNDO_H
#define PHOTON_UNDO_H

#define UNDO_PATH_MAX 1024 /* longest path an entry holds, '\0' included */

enum undo_action {
    UNDO_NOTHING,    /* nothing of ours on disk                                    */
    UNDO_REMOVE,     /* path is a file photon made                                 */
    UNDO_RENAME_BACK /* path is a user's file photon moved aside from back         */
};

struct undo;

/* A new entry, UNDO_NOTHING, in the list (the handlers are installed on the first). */
struct undo *undo_new(void);

/* Sets u to action on path (and back, for UNDO_RENAME_BACK; else NULL). Both paths are
 * copied and shorter than UNDO_PATH_MAX. Call it under undo_hold() when the file system
 * changes together with it (a rename and the entry that says where the file went). */
void undo_set(struct undo *u, enum undo_action action, const char *path, const char *back);

/* Takes u out of the list and frees it; NULL is ignored. */
void undo_free(struct undo *u);

/* From undo_hold() to its undo_release() a signal waits; holds nest. */
void undo_hold(void);
void undo_release(void);

/* Does what u says now, under a hold: 0, and u is set to UNDO_NOTHING; -1 when the
 * remove() or rename() failed, errno as it left it, and u still says it (a later
 * undo_now() may try again). */
int undo_now(struct undo *u);

#endif
