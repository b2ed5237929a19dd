#!/bin/sh
# tests/bench/tiles.sh -- the `tiles` workload of `make bench` (bench_tiles.c runs it): the
# wall-time speed-up of rendering an image as 2 tiles in 2 concurrent processes against
# rendering it whole in 1, for --mode pt and --mode 2008 on the Cornell box at 128 x 128.
#
# For each mode, BENCH_REPEATS (3) times: the whole image by one process, then the two
# halves (bands 0..63 and 64..127) by two processes at once, merged with `photon merge`;
# the merge must equal the whole render byte for byte (cmp of the PFMs, the images of
# record), else the workload fails. Printed, as bench/README.md's name=value lines: the medians of
# the wall seconds (seconds_1, seconds_2, their ratio speedup), of the CPU seconds the
# processes used (cpu_seconds_1, cpu_seconds_2: a tile repeats the mode's global work, the
# photon passes of 2008, so cpu_seconds_2 > cpu_seconds_1 bounds the speed-up below 2 even
# on an idle machine), and identical=1. The merge is not timed (it reads two files).
#
# The clock. A wall clock finer than a second is not in C99 (time() counts whole seconds,
# clock() is CPU time of the calling process only) nor in POSIX date (`date +%s.%N` is
# GNU's). So this is a shell script timed by POSIX's `time -p` (XCU "time"): "real S.SS"
# on stderr with hundredths of a second, from the utility (/usr/bin/time) under dash, or the
# keyword under bash and ksh, which print the same format. Each run takes ~10 s alone, so
# the hundredths are ample.
#
# Environment: PHOTON (the binary, default ./photon), BENCH_TMP (scratch directory, default
# build/bench-tiles), BENCH_REPEATS (default 3). Run from the top of the repository.

set -eu

photon=${PHOTON:-./photon}
tmp=${BENCH_TMP:-build/bench-tiles}
repeats=${BENCH_REPEATS:-3}
scene=scenes/cornell.scene
size="--width 128 --height 128"

mkdir -p "$tmp"

# Runs "$@" (output discarded) under time -p; prints "WALL CPU" (CPU = user + sys of all
# the processes it waited for). Fails if the command failed.
timed() {
    report=$({ time -p sh -c 'exec "$@" >/dev/null 2>&1' sh "$@"; } 2>&1) || {
        echo "bench: tiles: failed: $*" >&2
        return 1
    }
    echo "$report" | awk '$1 == "real" {r = $2} $1 == "user" {u = $2} $1 == "sys" {s = $2}
                          END {printf "%s %.2f\n", r, u + s}'
}

# The median of the numbers on stdin.
median() {
    sort -n | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'
}

# bench_mode NAME PHOTON-OPTIONS: one mode's figures.
bench_mode() {
    name=$1 options=$2
    whole=$tmp/$name-whole.pfm
    : >"$tmp/$name.times1"
    : >"$tmp/$name.times2"
    r=0
    while [ "$r" -lt "$repeats" ]; do
        # shellcheck disable=SC2086 # the options are words, split on purpose
        timed "$photon" --no-progress $options $size "$scene" -o "$whole" >>"$tmp/$name.times1"
        rm -f "$tmp/$name-top.pfm" "$tmp/$name-bottom.pfm"
        # shellcheck disable=SC2016,SC2086 # $1.. are the inner shell's; split on purpose
        timed sh -c '"$1" --no-progress $2 $3 "$4" --crop 0 0 128 64 -o "$5" &
                     top=$!
                     "$1" --no-progress $2 $3 "$4" --crop 0 64 128 128 -o "$6" &
                     bottom=$!
                     wait $top && wait $bottom' \
            sh "$photon" "$options" "$size" "$scene" "$tmp/$name-top.pfm" "$tmp/$name-bottom.pfm" \
            >>"$tmp/$name.times2"
        "$photon" merge -o "$tmp/$name-merged.pfm" "$tmp/$name-top.pfm" "$tmp/$name-bottom.pfm"
        cmp "$tmp/$name-merged.pfm" "$whole" >&2 || {
            echo "bench: tiles: $name: the merged tiles differ from the whole render" >&2
            return 1
        }
        r=$((r + 1))
    done
    s1=$(cut -d' ' -f1 "$tmp/$name.times1" | median)
    s2=$(cut -d' ' -f1 "$tmp/$name.times2" | median)
    c1=$(cut -d' ' -f2 "$tmp/$name.times1" | median)
    c2=$(cut -d' ' -f2 "$tmp/$name.times2" | median)
    echo "tiles.$name.seconds_1=$s1"
    echo "tiles.$name.seconds_2=$s2"
    awk -v a="$s1" -v b="$s2" -v n="$name" 'BEGIN {printf "tiles.%s.speedup=%.3f\n", n, (b > 0 ? a / b : 0)}'
    echo "tiles.$name.cpu_seconds_1=$c1"
    echo "tiles.$name.cpu_seconds_2=$c2"
    echo "tiles.$name.identical=1"
}

bench_mode pt "--mode pt --spp 384"
bench_mode 2008 "--mode 2008 --passes 32 --photons-per-pass 50000"
