/*
 * base/temporary_name.h -- the names of the files photon makes beside an output: its
 * temporary, the probe of outputs_check(), the place a replaced file waits (output.h).
 *
 * Each is NAME.XXXXXXXX.tmp, beside NAME so that the final rename stays within its
 * directory (atomic); XXXXXXXX is 8 hex digits, the run's mark + the attempt, so that a
 * name that is taken is passed over for the next. The mark comes from the clock and
 * addresses (C99 has no process id); PHOTON_TEMPORARY_MARK (8 hex digits) sets it, for
 * tests that make runs collide.
 *
 * Long names. A name in a directory may have NAME_BYTES_MAX bytes on most file systems;
 * NAME's last part may have as many, though ".XXXXXXXX.tmp" adds 13: a last part longer
 * than TEMPORARY_BASE_MAX is cut, never inside a UTF-8 character, and followed by
 * "-HHHHHHHH", a hash of all of it, so that the cut names of two outputs stay apart. The
 * hash folds ASCII case, as the uncut names meet where a file system ignores case; so two
 * long names that differ only in the case of the bytes cut away (on a file system that
 * does not ignore case) are taken for one file and refused, never mixed.
 */
#ifndef PHOTON_TEMPORARY_NAME_H
#define PHOTON_TEMPORARY_NAME_H

#include <stdint.h>

#define TEMPORARY_SUFFIX ".XXXXXXXX.tmp" /* what a name of ours adds: 8 hex digits    */
#define NAME_BYTES_MAX 255 /* the longest name in a directory most file systems take */
#define TEMPORARY_BASE_MAX (NAME_BYTES_MAX - (sizeof TEMPORARY_SUFFIX - 1)) /* 242 bytes */
#define TEMPORARY_HASH_BYTES 9 /* "-HHHHHHHH", the hash a cut name keeps             */

/* This run's token, never 0: in the probes' markers, and 32 bits of it the run's mark. */
uint64_t temporary_run_token(void);

/* The name of ours number attempt (0, 1, ...) for the file name, as above: a new string,
 * at most strlen(name) + sizeof TEMPORARY_SUFFIX bytes with its '\0'. */
char *temporary_name(const char *name, unsigned long attempt);

#endif
