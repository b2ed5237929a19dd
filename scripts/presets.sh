#!/bin/sh
# scripts/presets.sh -- measure the quality presets (photon --help all, "quality presets") on
# the two Cornell boxes and write them as a markdown table (README, "Presets").
#
#   scripts/presets.sh PHOTON OUT.md [MODE ...]
#
# Run from the top of the repository. For each mode (default: all seven) and each preset
# named in PRESETS (default "preview default"; "reference" takes minutes to an hour a
# render), renders scenes/cornell.scene and scenes/cornell-specular.scene at 256 x 256
# with `--mode MODE --quality PRESET --stats`, and puts in the table the preset's words as
# --help all prints them, the render's CPU seconds (its own seconds_total), its relmse
# against reference/cornell-pt.pfm or reference/cornell-specular-pt.pfm, and how many of
# the 256 blocks of 16 x 16 pixels are within 3% of the reference (photon compare
# --block 16). The renders run one after another; CPU seconds do not depend on what else
# the machine runs, as long as it does not run out of memory.
#
# POSIX sh (dash, bash, ...), set -eu; needs only photon itself, grep, sed, cut and awk.

set -eu

if [ $# -lt 2 ]; then
    echo "usage: scripts/presets.sh PHOTON OUT.md [MODE ...]" >&2
    exit 2
fi
photon=$1
out=$2
shift 2
modes=${*:-direct pt photons 1994 1996 2008 2009}
presets=${PRESETS:-preview default}
work=$(mktemp -d "${TMPDIR:-/tmp}/photon-presets.XXXXXX")
trap 'rm -rf "$work"' EXIT

# The preset's words, from the table --help all prints ("--mode MODE QUALITY WORDS...", a
# long row's words going on in the lines below it that start with spaces and "--").
settings() {
    words=$("$photon" --help all | awk -v mode="$1" -v preset="$2" '
        $1 == "--mode" { row = $2 == mode && $3 == preset }
        row && $1 == "--mode" { sub(/^ *--mode +[^ ]+ +[^ ]+ +/, ""); words = $0; next }
        row && /^   +--/ { sub(/^ +/, ""); words = words " " $0; next }
        { row = 0 }
        END { print words }')
    if [ -n "$words" ]; then echo "\`$words\`"; else echo "(the defaults)"; fi
}

# One render of box ($1) in mode $2 at preset $3: "seconds | relmse | blocks".
measure() {
    "$photon" --no-progress --stats --mode "$2" --quality "$3" "scenes/$1.scene" \
        -o "$work/image.pfm" 2> "$work/stats"
    seconds=$(grep '^seconds_total=' "$work/stats" | cut -d= -f2)
    errors=$("$photon" compare "$work/image.pfm" "reference/$1-pt.pfm" --block 16)
    relmse=$(echo "$errors" | sed 's/.* relmse=\([^ ]*\) .*/\1/')
    blocks=$(echo "$errors" | sed 's/.* blocks_within_3pct=\([^ ]*\).*/\1/')
    echo "$seconds | $relmse | $blocks"
}

{
    echo "| mode | preset | settings | Cornell: CPU s | relmse | blocks within 3% |" \
         "specular: CPU s | relmse | blocks within 3% |"
    echo "|---|---|---|---|---|---|---|---|---|"
    for mode in $modes; do
        for preset in $presets; do
            cornell=$(measure cornell "$mode" "$preset")
            specular=$(measure cornell-specular "$mode" "$preset")
            echo "| $mode | $preset | $(settings "$mode" "$preset") | $cornell |" \
                 "$specular |"
        done
    done
} > "$work/table.md"
mv "$work/table.md" "$out"
