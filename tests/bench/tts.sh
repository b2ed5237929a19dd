#!/bin/sh
# tests/bench/tts.sh -- the `tts` workload of `make bench` (bench_tts.c runs it): time to a
# stated error. Each mode that can render to an error (pt, 2008, 2009) renders the Cornell
# boxes and the shipped scenes with caustics at --target-error 0.02, seed 1, with
# --time-limit TTS_LIMIT CPU seconds (default 120), as a user would: until every 16 x 16
# block's stated 95% bound is at most 2% of its mean. Printed, as bench/README.md's
# name=value lines, for each mode and scene:
#   tts.MODE.SCENE.seconds        the render's CPU seconds (--stats seconds_total)
#   tts.MODE.SCENE.reached        1 when every block reached the target, 0 when the time
#                                 limit stopped it first
#   tts.MODE.SCENE.blocks_within  the blocks at the target, of tts.MODE.SCENE.blocks
#   tts.MODE.SCENE.work           samples a pixel (pt) or photon passes (2008, 2009)
#   tts.MODE.SCENE.relmse, worst_block
#                                 the image against the scene's reference (photon compare
#                                 --block 16): what the stated error was worth
# or tts.MODE.SCENE.refused=1 where the mode states no bound on the scene (pt where a
# point light's caustic needs a path it cannot find), which exits 2 at once.
#
# Why a script: the figure is what the command line does, option checks and all, and the
# seconds are its own --stats. Environment: PHOTON (the binary, default ./photon),
# BENCH_TMP (a scratch directory, whose tts/ it takes; default build/bench), TTS_LIMIT. Run from the top of
# the repository.

set -eu

photon=${PHOTON:-./photon}
tmp=${BENCH_TMP:-build/bench}/tts
limit=${TTS_LIMIT:-120}
table=reference/consistency.txt
. scripts/suite-lib.sh

mkdir -p "$tmp"

for name in cornell cornell-specular ppm-box cardioid-ring mirror-caustic defocused-caustic; do
    scene_of "$name"
    for mode in pt 2008 2009; do
        at=tts.$mode.$name
        echo "bench: tts: $name: --mode $mode --target-error 0.02" >&2
        image=$tmp/$name-$mode.pfm
        log=$tmp/$name-$mode.log
        # shellcheck disable=SC2086 # $options holds several words
        if ! "$photon" --no-progress --stats --seed 1 --mode "$mode" --target-error 0.02 \
            --time-limit "$limit" $options "$scene" -o "$image" > "$log" 2>&1; then
            if [ "$mode" = pt ] && grep -q 'cannot find the caustics' "$log"; then
                echo "$at.refused=1"
                continue
            fi
            echo "bench: tts: $at failed (log: $log)" >&2
            tail -n 3 "$log" >&2
            exit 1
        fi
        within=$(stat_of "$log" target_blocks_within)
        blocks=$(stat_of "$log" target_blocks)
        case $mode in
            pt) work=$(stat_of "$log" spp) ;;
            *) work=$(stat_of "$log" passes) ;;
        esac
        line=$("$photon" compare "$image" "$reference" --block 16)
        echo "$at.seconds=$(stat_of "$log" seconds_total)"
        echo "$at.reached=$([ "$within" = "$blocks" ] && echo 1 || echo 0)"
        echo "$at.blocks_within=$within"
        echo "$at.blocks=$blocks"
        echo "$at.work=$work"
        echo "$at.relmse=$(key "$line" relmse)"
        echo "$at.worst_block=$(key "$line" worst_block)"
    done
done
