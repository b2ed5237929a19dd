#!/bin/sh
# scripts/bench_cycles.sh -- make bench-cycles: photon's path tracer (--mode pt) against
# Blender's Cycles, one thread each, at equal CPU seconds, on the two Cornell boxes.
#
#   scripts/bench_cycles.sh [SCENE ...]   (make bench-cycles [ONLY=SCENE]
#                                         [CYCLES_SPP="N ..."]; run from the top of the
#                                         repository; SCENE cornell or cornell-specular,
#                                         both by default)
#
# For each scene (scenes/SCENE.scene, against reference/SCENE-pt.pfm) and each sample count
# N of BENCH_CYCLES_SPP (default "16 64 256"):
#   1. the scene exported as `make crosscheck` exports it, `photon export --format blender
#      --spp N`: the same camera, image size, lights and materials, Cycles' biasing options
#      off (scripts/crosscheck.sh checks that the two renderers agree on both boxes). Its
#      last line, render(), gets two Blender handlers round it, render_pre and render_post,
#      that read the process's CPU seconds (os.times(): user + system, every thread):
#      Cycles' render itself, from its scene sync and BVH build to its last sample, without
#      Blender's start-up, the script's building of the scene or the writing of the image;
#   2. Cycles, `blender -b --factory-startup -t 1`: its CPU seconds T;
#   3. photon --mode pt --time-limit T (photon has one thread), --spp at its most so that
#      the time ends the render: pt starts no sample pass once its clock() (user + system,
#      from the process's start: the scene's reading and BVH build count, as Cycles' sync
#      does) reaches T, so it runs past T by up to a pass (a sample a pixel). When the
#      shell's `times` says it took more than 5% over T, it runs once more with the limit
#      lowered by the excess, and that run is the one reported;
#   4. both images against the reference: `photon compare --block 16`, relmse and the worst
#      16 x 16 block; ratio = pt's relmse over Cycles' (below 1: pt is the closer at that
#      time, the project's goal).
# The reference is a render too: its own noise adds about the same relmse to both images,
# the mean of var / (ref^2 + 0.01) over reference/SCENE-pt-var.pfm (relmse's denominator,
# src/image/compare.c), which pulls the ratio towards 1 as N grows. It is printed as
# reference_noise, and ratio_net is the ratio with it taken from both relmses.
#
# It prints, on stdout, lines cycles.version=, cycles.spp= (the sample counts),
# cycles.SCENE.reference_noise=, cycles.SCENE.approximated= (what the export says Cycles
# only approximates, "-" for nothing; the specular box's glass ball is an icosphere), and
# cycles.SCENE.N.KEY=VALUE: cycles_seconds, cycles_relmse, cycles_worst_block,
# cycles_worst_block_at, pt_seconds, pt_spp (pt's samples a pixel), pt_relmse,
# pt_worst_block, pt_worst_block_at, pt_runs (1, or 2 when step 3 ran again), ratio,
# ratio_net, seconds_ratio (pt's seconds over Cycles': 1 is equal time).
# Progress goes to stderr. Exit 0 when everything was measured, 2 when something is missing
# (Blender older than 3.4 or none, photon, a scene, a reference), 1 when a render failed.
#
# Environment: PHOTON (default ./photon), BLENDER (default blender), BENCH_CYCLES_SPP (the
# sample counts), BENCH_CYCLES_DIR (the scripts, renders and logs, default
# build/bench-cycles).
#
# POSIX sh; needs photon, blender, awk, sed, od, tail and tr.

set -eu

photon=${PHOTON:-./photon}
blender=${BLENDER:-blender}
counts=${BENCH_CYCLES_SPP:-16 64 256}
dir=${BENCH_CYCLES_DIR:-build/bench-cycles}

# Refused at once, as bench-pbrt refuses without pbrt: a benchmark with nothing to measure
# against is no result, so never a silent success (make crosscheck, a check, says so and
# passes).
if ! command -v "$blender" > /dev/null 2>&1; then
    echo "bench-cycles: '$blender' not found: install Blender 3.4 or newer (Debian, Ubuntu:" \
        "apt-get install blender) or set BLENDER=PATH" >&2
    exit 2
fi
version=$("$blender" --version 2> /dev/null | sed -n 's/^Blender \([0-9][0-9]*\.[0-9][0-9.]*\).*/\1/p' | head -n 1)
if [ -z "$version" ] || ! echo "$version" | awk '{ split($1, v, "."); exit !(v[1] > 3 || (v[1] == 3 && v[2] >= 4)) }'; then
    echo "bench-cycles: '$blender' is Blender '${version:-?}'; photon's export needs 3.4 or newer" >&2
    exit 2
fi
if [ ! -x "$photon" ]; then
    echo "bench-cycles: $photon not built (make)" >&2
    exit 2
fi
for n in $counts; do
    case $n in
    '' | *[!0-9]* | 0*)
        echo "bench-cycles: sample count '$n' is not a whole number above 0 (BENCH_CYCLES_SPP)" >&2
        exit 2
        ;;
    esac
done
scenes=${*:-cornell cornell-specular}
for s in $scenes; do
    for f in "scenes/$s.scene" "reference/$s-pt.pfm" "reference/$s-pt-var.pfm"; do
        if [ ! -f "$f" ]; then
            echo "bench-cycles: $f is missing (scenes: cornell, cornell-specular)" >&2
            exit 2
        fi
    done
done
mkdir -p "$dir"

bench=bench-cycles
. scripts/bench-lib.sh

# The relmse the noise of reference $1 adds, expected, to an independent image's: the mean
# over its values of var / (ref^2 + 0.01), var from $1's variance image (photon's variance
# of each pixel's mean). A PFM's floats are its last width x height x 3 x 4 bytes, little
# endian (scale -1, as photon writes them), read here in the machine's order by od.
reference_noise() {
    size=$(sed -n '2p' "$1.pfm" | awk '{ print $1 * $2 * 12 }')
    tail -c "$size" "$1.pfm" | od -An -v -t f4 > "$dir/ref.txt"
    tail -c "$size" "$1-var.pfm" | od -An -v -t f4 > "$dir/var.txt"
    awk 'NR == FNR { for (i = 1; i <= NF; i++) b[n++] = $i; next }
        { for (i = 1; i <= NF; i++) { s += $i / (b[m] * b[m] + 0.01); m++ } }
        END { if (m != n || n == 0) exit 1; printf "%.4g\n", s / n }' "$dir/ref.txt" "$dir/var.txt"
}

# Cycles on scene $1 at $2 samples a pixel: $dir/$1-cycles-$2.pfm, its render's CPU seconds
# in $cycles_seconds; the export's notes in $dir/$1-$2.export.
cycles_run() {
    name=$dir/$1-cycles-$2
    "$photon" export --format blender --spp "$2" "scenes/$1.scene" -o "$name.py" \
        < /dev/null 2> "$name.export" || { cat "$name.export" >&2; exit 1; }
    if [ "$(tail -n 1 "$name.py")" != "render()" ]; then
        echo "bench-cycles: $name.py does not end in render(): the export changed; time it anew" >&2
        exit 1
    fi
    sed '$d' "$name.py" > "$name.tmp"
    cat >> "$name.tmp" << 'EOF'
# bench-cycles: the CPU seconds of the render itself, every thread of the process, from
# Blender's render_pre to its render_post (scene sync, BVH, samples; not the image's writing)
CPU = []
def cpu_seconds(*args):
    t = os.times()
    CPU.append(t.user + t.system)
bpy.app.handlers.render_pre.append(cpu_seconds)
bpy.app.handlers.render_post.append(cpu_seconds)
render()
if len(CPU) != 2:
    raise RuntimeError('bench-cycles: render_pre and render_post ran %d times, not 2' % len(CPU))
with open(OUT + '.seconds', 'w') as f:
    f.write('%.3f\n' % (CPU[1] - CPU[0]))
EOF
    mv "$name.tmp" "$name.py"
    rm -f "$name.pfm" "$name.pfm.seconds"
    if ! "$blender" -b --factory-startup --python-exit-code 1 -t 1 -P "$name.py" -- "$name.pfm" \
        < /dev/null > "$name.log" 2>&1 || [ ! -f "$name.pfm" ] || [ ! -f "$name.pfm.seconds" ]; then
        echo "bench-cycles: blender failed on $name.py (log: $name.log)" >&2
        tail -n 3 "$name.log" >&2
        exit 1
    fi
    cycles_seconds=$(awk '{ printf "%.2f\n", $1 }' "$name.pfm.seconds")
    if ! awk -v t="$cycles_seconds" 'BEGIN { exit !(t > 0) }'; then
        echo "bench-cycles: Cycles' render took $cycles_seconds CPU seconds: cannot time it" >&2
        exit 1
    fi
}

# pt on scene $1 for $2 CPU seconds (--time-limit $2), named for $3 samples: its image
# $dir/$1-pt-$3.pfm, its seconds in $took, its samples a pixel in $pt_spp.
pt_run() {
    name=$dir/$1-pt-$3
    timed "$name.log" "$photon" "scenes/$1.scene" --mode pt --spp 1048576 --time-limit "$2" \
        --no-progress --stats -o "$name.pfm"
    pt_spp=$(sed -n 's/^samples_per_pixel=//p' "$name.log")
}

echo "cycles.version=$version"
echo "cycles.spp=$counts"
for s in $scenes; do
    ref=reference/$s-pt
    noise=$(reference_noise "$ref") || { echo "bench-cycles: cannot read $ref.pfm and $ref-var.pfm" >&2; exit 1; }
    echo "cycles.$s.reference_noise=$noise"
    noted=
    for n in $counts; do
        echo "bench-cycles: $s: Cycles, $n samples a pixel" >&2
        cycles_run "$s" "$n"
        t=$cycles_seconds
        if [ -z "$noted" ]; then
            notes=$(sed 's/^photon: export: blender: //' "$dir/$s-cycles-$n.export" | tr '\n' ' ' | sed 's/ *$//')
            echo "cycles.$s.approximated=${notes:--}"
            noted=1
        fi
        echo "bench-cycles: $s: pt for Cycles' $t CPU seconds" >&2
        pt_run "$s" "$t" "$n"
        runs=1
        # Past T by more than 5% (the last pass ran on): once more, the limit lowered by
        # the excess, so that the two renders' seconds are as equal as a pass allows.
        lower=$(awk -v t="$t" -v took="$took" 'BEGIN { l = 2 * t - took; print (took > 1.05 * t && l > 0) ? l : 0 }')
        if [ "$lower" != 0 ]; then
            echo "bench-cycles: $s: pt took $took s for $t: again with --time-limit $lower" >&2
            pt_run "$s" "$lower" "$n"
            runs=2
        fi
        cline=$("$photon" compare "$dir/$s-cycles-$n.pfm" "$ref.pfm" --block 16)
        pline=$("$photon" compare "$dir/$s-pt-$n.pfm" "$ref.pfm" --block 16)
        crel=$(field relmse "$cline")
        prel=$(field relmse "$pline")
        echo "cycles.$s.$n.cycles_seconds=$t"
        echo "cycles.$s.$n.cycles_relmse=$crel"
        echo "cycles.$s.$n.cycles_worst_block=$(field worst_block "$cline")"
        echo "cycles.$s.$n.cycles_worst_block_at=$(field worst_block_at "$cline")"
        echo "cycles.$s.$n.pt_seconds=$took"
        echo "cycles.$s.$n.pt_spp=$pt_spp"
        echo "cycles.$s.$n.pt_relmse=$prel"
        echo "cycles.$s.$n.pt_worst_block=$(field worst_block "$pline")"
        echo "cycles.$s.$n.pt_worst_block_at=$(field worst_block_at "$pline")"
        echo "cycles.$s.$n.pt_runs=$runs"
        echo "cycles.$s.$n.ratio=$(awk -v a="$prel" -v b="$crel" 'BEGIN { printf "%.3f\n", a / b }')"
        echo "cycles.$s.$n.ratio_net=$(awk -v a="$prel" -v b="$crel" -v f="$noise" 'BEGIN { if (b > f) printf "%.3f\n", (a - f) / (b - f); else print "-" }')"
        echo "cycles.$s.$n.seconds_ratio=$(awk -v a="$took" -v b="$t" 'BEGIN { printf "%.3f\n", a / b }')"
    done
done
