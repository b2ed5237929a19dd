#!/bin/sh
# scripts/bench_pbrt.sh -- make bench-pbrt: photon's --mode 2009 against pbrt-v4's SPPM, one
# thread each, at equal CPU seconds, on the two Cornell boxes.
#
#   scripts/bench_pbrt.sh [SCENE ...]   (make bench-pbrt PBRT=PATH [ONLY=SCENE]; run from
#                                       the top of the repository; SCENE cornell or
#                                       cornell-specular, both by default)
#
# For each scene (scenes/SCENE.scene, against reference/SCENE-pt.pfm):
#   1. photon --mode 2009 at its defaults: its CPU seconds T, its relmse and its worst 16 x 16
#      block (photon compare --block 16) against the reference;
#   2. for every pbrt render below, the scene exported, `photon export --format pbrt
#      --channel R|G|B --spp N`, a grey scene whose render's luminance is that channel of
#      ours (reference/README.md, "Colour in pbrt-v4"), its Integrator line replaced by
#      pbrt's SPPM (SPPM_SETTINGS), whose iterations are the N samples a pixel;
#   3. calibration: each channel for 4 iterations and one for 8, and the three channels'
#      seconds taken as growing as iterations^p, p from the 4 and the 8 (an iteration grows
#      cheaper as the radii shrink: p came out 0.65 to 0.9). The iteration count N gives
#      the three together T seconds by that law;
#   4. the three channels for N iterations each, made into one image (build's
#      pbrt-channels: channel c is the luminance of channel c's render) and compared like
#      photon's. When the three took more than 10% from T (the shared machine's load moved,
#      or the law missed), they run once more at the count the law gives through the
#      seconds they took, and that second run is the one reported.
# Seconds are the user + system CPU seconds of the commands (the shell's `times`), never wall time.
#
# It prints, on stdout, lines pbrt.SCENE.KEY=VALUE: radius, photon_seconds, photon_relmse,
# photon_worst_block, photon_worst_block_at, pbrt_iterations, pbrt_seconds, pbrt_relmse,
# pbrt_worst_block, pbrt_worst_block_at, ratio (pbrt's relmse over photon's: above 1 photon
# is the closer at that time), seconds_ratio (pbrt's seconds over photon's: 1 is equal
# time), calibration_seconds, calibration_exponent, pbrt_runs (1, or 2 when step 4 ran
# again); and pbrt.settings= SPPM's other parameters.
# Progress goes to stderr. Exit 0 when every scene was measured, 2 when something is
# missing, 1 when a render failed.
#
# Environment: PHOTON (default ./photon), PBRT (pbrt-v4's pbrt; required), PBRT_CHANNELS
# (default build/pbrt-channels, `make bench-pbrt` builds it), BENCH_PBRT_DIR (the scene
# files, renders and logs, default build/bench-pbrt).
#
# POSIX sh; needs photon, pbrt, awk, sed and grep.

set -u

photon=${PHOTON:-./photon}
pbrt=${PBRT:-}
channels=${PBRT_CHANNELS:-build/pbrt-channels}
dir=${BENCH_PBRT_DIR:-build/bench-pbrt}

# pbrt's SPPM: 100,000 photons an iteration, and the initial radius (in mm, the scenes'
# unit) of radius() below. maxdepth 248, not 1000: pbrt-v4's SPPM photon loop
# (SPPMIntegrator::Render) draws four Halton dimensions a bounce, after 5 for the light,
# from its table of 1000 primes and digit permutations and never wraps round, so a photon
# that makes more than 248 bounces reads past the table and pbrt dies with signal 11. In
# the specular box such photons are held inside the glass ball: entering near grazing,
# they meet its inside near the critical angle, reflect with probability near 1, and
# Russian roulette, which sees beta unchanged at a dielectric, never ends them (with the
# ball made diffuse the crash goes; with the mirror made black it stays). 248 is the most
# that stays within the table; only light past a photon's 248th bounce is lost.
SPPM_SETTINGS='"integer photonsperiteration" [100000] "integer maxdepth" [248]'

# The initial radius of scene $1, pbrt's best per CPU second of those tried: on the Cornell
# box 20 of 5, 10, 20 and 40 at 32 iterations (relmse 3.9e-3, 1.2e-3, 5.1e-4, 5.3e-4 in one
# channel); on the specular box 10 of 5, 10 and 20 at 15 to 16 iterations (4.6e-3 in 29 s,
# 2.9e-3 in 33 s, 5.8e-3 in 56 s, the three channels), whose caustic 20 blurs.
radius() {
    case $1 in
    cornell-specular) echo 10 ;;
    *) echo 20 ;;
    esac
}

if [ -z "$pbrt" ]; then
    echo "bench-pbrt: PBRT is not set: give pbrt-v4's pbrt program (make bench-pbrt PBRT=PATH)" >&2
    exit 2
fi
if [ ! -f "$pbrt" ] || [ ! -x "$pbrt" ]; then
    echo "bench-pbrt: PBRT=$pbrt is not an executable file (pbrt-v4's pbrt program)" >&2
    exit 2
fi
for tool in "$photon" "$channels"; do
    if [ ! -x "$tool" ]; then
        echo "bench-pbrt: $tool not built (make bench-pbrt builds it)" >&2
        exit 2
    fi
done
scenes=${*:-cornell cornell-specular}
for s in $scenes; do
    for f in "scenes/$s.scene" "reference/$s-pt.pfm"; do
        if [ ! -f "$f" ]; then
            echo "bench-pbrt: $f is missing (scenes: cornell, cornell-specular)" >&2
            exit 2
        fi
    done
done
mkdir -p "$dir" || exit 2

bench=bench-pbrt
. scripts/bench-lib.sh

# pbrt on scene $1, channel $2, $3 iterations: the export with --spp $3 (SPPM's iterations
# are its sampler's samples a pixel, and the export picks a sampler that keeps the count),
# its Integrator line SPPM's; $dir/$1-$2-$3.pfm, the seconds in $took.
pbrt_run() {
    name=$dir/$1-$2-$3
    "$photon" export --format pbrt "scenes/$1.scene" -o "$name.pbrt" --channel $2 --spp $3 \
        < /dev/null 2> "$name.export" || { cat "$name.export" >&2; exit 1; }
    sed "s|^Integrator .*|Integrator \"sppm\" $SPPM_SETTINGS \"float radius\" [$(radius $1)]|" \
        "$name.pbrt" > "$name.tmp" &&
        mv "$name.tmp" "$name.pbrt" || exit 1
    if ! grep -q '^Integrator "sppm"' "$name.pbrt" ||
        ! grep -q "\"integer pixelsamples\" \[$3\]" "$name.pbrt"; then
        echo "bench-pbrt: $name.pbrt has no Integrator line to set or no $3 samples a pixel" >&2
        exit 1
    fi
    timed "$name.log" "$pbrt" --quiet --nthreads 1 --outfile "$name.pfm" "$name.pbrt"
}

echo "pbrt.settings=$SPPM_SETTINGS"
for s in $scenes; do
    ref=reference/$s-pt.pfm
    echo "bench-pbrt: $s: photon --mode 2009 at its defaults" >&2
    timed "$dir/$s-2009.log" "$photon" "scenes/$s.scene" --mode 2009 --no-progress \
        -o "$dir/$s-2009.pfm"
    t=$took
    line=$("$photon" compare "$dir/$s-2009.pfm" "$ref" --block 16) || exit 1
    echo "pbrt.$s.radius=$(radius $s)"
    echo "pbrt.$s.photon_seconds=$t"
    echo "pbrt.$s.photon_relmse=$(field relmse "$line")"
    echo "pbrt.$s.photon_worst_block=$(field worst_block "$line")"
    echo "pbrt.$s.photon_worst_block_at=$(field worst_block_at "$line")"


    echo "bench-pbrt: $s: pbrt SPPM calibration (4 iterations a channel, 8 for G)" >&2
    pbrt_run "$s" R 4; r4=$took
    pbrt_run "$s" G 4; g4=$took
    pbrt_run "$s" B 4; b4=$took
    pbrt_run "$s" G 8; g8=$took
    calibration=$(awk -v a="$r4" -v b="$g4" -v c="$b4" -v d="$g8" 'BEGIN { printf "%.2f\n", a + b + c + d }')
    set -- $(awk -v t="$t" -v r="$r4" -v g="$g4" -v b="$b4" -v g8="$g8" 'BEGIN {
        p = log(g8 / g) / log(2)
        if (p < 0.5) p = 0.5
        if (p > 1) p = 1
        n = int(4 * (t / (r + g + b)) ^ (1 / p) + 0.5)
        printf "%d %.3f\n", n < 1 ? 1 : n, p
    }')
    n=$1 p=$2
    echo "bench-pbrt: $s: pbrt SPPM, $n iterations a channel (T = $t s, calibration $r4 + $g4 + $b4 s at 4, $g8 s at 8: exponent $p)" >&2
    runs=0
    while :; do
        runs=$((runs + 1))
        total=0
        for c in R G B; do
            pbrt_run "$s" $c "$n"
            echo "bench-pbrt: $s: channel $c, $n iterations: $took s" >&2
            total=$(awk -v a="$total" -v b="$took" 'BEGIN { printf "%.2f\n", a + b }')
        done
        # Off T by more than 10% (the machine's load changed since the calibration, or the
        # law missed): once more, at the count the law gives through this run's seconds.
        again=$(awk -v t="$t" -v total="$total" -v n="$n" -v p="$p" 'BEGIN {
            m = int(n * (t / total) ^ (1 / p) + 0.5)
            if (m < 1) m = 1
            print (total > 1.1 * t || total < 0.9 * t) && m != n ? m : 0
        }')
        [ "$runs" -eq 1 ] && [ "$again" -ne 0 ] || break
        echo "bench-pbrt: $s: $total s is not within 10% of $t s: again at $again iterations" >&2
        n=$again
    done
    "$channels" "$dir/$s-pbrt.pfm" "$dir/$s-R-$n.pfm" "$dir/$s-G-$n.pfm" "$dir/$s-B-$n.pfm" || exit 1
    pline=$("$photon" compare "$dir/$s-pbrt.pfm" "$ref" --block 16) || exit 1
    echo "pbrt.$s.pbrt_iterations=$n"
    echo "pbrt.$s.pbrt_seconds=$total"
    echo "pbrt.$s.pbrt_relmse=$(field relmse "$pline")"
    echo "pbrt.$s.pbrt_worst_block=$(field worst_block "$pline")"
    echo "pbrt.$s.pbrt_worst_block_at=$(field worst_block_at "$pline")"
    echo "pbrt.$s.ratio=$(awk -v a="$(field relmse "$pline")" -v b="$(field relmse "$line")" 'BEGIN { printf "%.2f\n", a / b }')"
    echo "pbrt.$s.seconds_ratio=$(awk -v a="$total" -v b="$t" 'BEGIN { printf "%.2f\n", a / b }')"
    echo "pbrt.$s.calibration_seconds=$calibration"
    echo "pbrt.$s.calibration_exponent=$p"
    echo "pbrt.$s.pbrt_runs=$runs"
done
