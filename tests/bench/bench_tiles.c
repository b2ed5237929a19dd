/*
 * tests/bench/bench_tiles.c -- the wall-time speed-up of 2 tile processes on 2 cores
 * against 1 process, for --mode pt and --mode 2008: runs tests/bench/tiles.sh.
 *
 * Why a shell script: the figure is wall time across processes, and C99 has no wall clock
 * finer than time()'s whole seconds (clock() is this process's CPU time, blind to the
 * renders it would start); POSIX `time -p` gives hundredths of a second and starts and
 * waits for the processes itself. The script reads PHOTON (the binary) and BENCH_TMP (its
 * scratch directory) from the environment, which the Makefile's bench target sets, and
 * prints the tiles.* name=value lines itself.
 */
#include "bench.h"

#include <stdio.h>
#include <stdlib.h>

void bench_tiles(void)
{
    fflush(stdout); /* our lines first, then the script's, in order */
    int status = system("sh tests/bench/tiles.sh");
    if (status != 0)
        fprintf(stderr, "bench: tiles: tests/bench/tiles.sh failed (status %d)\n", status);
}
