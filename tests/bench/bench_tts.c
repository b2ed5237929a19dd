/*
 * tests/bench/bench_tts.c -- time to a stated error: the CPU seconds pt, 2008 and 2009 take
 * to render the Cornell boxes and the scenes with caustics at --target-error 0.02; runs
 * tests/bench/tts.sh.
 *
 * Why a shell script: the figure is what a user's command line does (its option checks,
 * its stopping rule, its --stats seconds), and the errors are photon compare's against the
 * references, so the script runs the binary (PHOTON, which the Makefile's bench target
 * sets) and prints the tts.* name=value lines itself.
 */
#include "bench.h"

#include <stdio.h>
#include <stdlib.h>

void bench_tts(void)
{
    fflush(stdout); /* our lines first, then the script's, in order */
    int status = system("sh tests/bench/tts.sh");
    if (status != 0)
        fprintf(stderr, "bench: tts: tests/bench/tts.sh failed (status %d)\n", status);
}
