#!/bin/sh
# scripts/calibration.sh [NAME ...] -- whether each mode's stated error holds: renders every
# shipped scene of reference/consistency.txt with each mode that states a bound (--error),
# at its defaults and at --target-error 0.02, compares each image with the scene's
# reference (photon compare --test-error: the reference's own noise allowed for by its
# variance image or, for one made by 2008 or 2009, its block statement, where it has one)
# and writes the table into reference/suite.md (between
# its <!-- calibration --> markers, before the consistency table). Run by
# `make calibration` (ONLY=NAME ... for some scenes, MODES=... for some modes) from the top
# of the repository after ./photon is built; PHOTON=PATH runs another binary.
# `scripts/calibration.sh --rewrite` renders nothing and writes the table again from
# build/calibration/.
#
# MODES is pt and 2009 by default. compare judges pt's blocks from its pixels' bounds,
# their noise in quadrature, which holds for pt's independent pixels; 2008's and 2009's
# pixels share photons, so their blocks are judged by the mode's own block statement
# (--block-error, src/image/error_image.h); so are photons', whose pixels share one map.
# photons has no --target-error: its one map cannot refine.
#
# The renders take seed 7, which no bound was measured on. A --target-error render stops
# at CALIBRATION_LIMIT CPU seconds (default 600) if it has not reached the target, and the
# cell says how many blocks had. A mode that refuses --error on a scene (pt where a point
# light's caustic needs a path it cannot find) is marked so.
set -eu
cd "$(dirname "$0")/.."
photon=${PHOTON:-./photon}
table=reference/consistency.txt
out=reference/suite.md
work=build/calibration
modes=${MODES:-pt 2009}
limit=${CALIBRATION_LIMIT:-600}
target=0.02
mkdir -p "$work"
. scripts/suite-lib.sh
suite_names calibration "$@"

# cell NAME MODE KIND: the table's cell from build/calibration/NAME-MODE-KIND.*.
cell() {
    base=$work/$1-$2-$3
    if [ "$2-$3" = photons-target ]; then
        echo "none: its one map cannot refine"
        return
    fi
    if [ ! -f "$base.log" ]; then
        kept "calibration $2" "$1" "$([ "$3" = defaults ] && echo 1 || echo 2)"
        return
    fi
    if [ ! -f "$base.compare" ]; then
        echo "refuses --error"
        return
    fi
    line=$(cat "$base.compare")
    covered=$(key "$line" bound_covered)
    # misses: so few blocks within the bound that a 95% bound would leave as many out with
    # a chance under 1% (the binomial tail of n blocks, p = 0.05, from k misses on)
    verdict=$(awk -v c="$covered" -v n="$(key "$line" bound_blocks)" \
        -v m="$(key "$line" bound_median_ratio)" 'BEGIN {
            k = n - int(c * n + 0.5); pmf = 0.95 ^ n; below = 0
            for (i = 0; i < k; i++) { below += pmf; pmf *= (n - i) / (i + 1) * 0.05 / 0.95 }
            if (1 - below < 0.01) print "**misses**"
            else if (m == "none") print "holds, exact"
            else print m + 0 <= 4.4 ? "holds" : "loose" }')
    printf '%s: %s of %s blocks, ratio %s (rms %s), %s s' "$verdict" \
        "$(awk -v c="$covered" 'BEGIN { printf "%.3f", c }')" "$(key "$line" bound_blocks)" \
        "$(key "$line" bound_median_ratio)" "$(key "$line" bound_rms_ratio)" \
        "$(awk -v s="$(stat_of "$base.log" seconds_total)" 'BEGIN { printf "%.0f", s }')"
    if [ "$3" = target ]; then
        within=$(stat_of "$base.log" target_blocks_within)
        blocks=$(stat_of "$base.log" target_blocks)
        [ "$within" = "$blocks" ] || printf ', stopped with %s of %s blocks at %s' \
            "$within" "$blocks" "$target"
        case $2 in
            2008 | 2009) printf ', %s passes' "$(stat_of "$base.log" passes)" ;;
            *) printf ', %s samples' "$(stat_of "$base.log" spp)" ;;
        esac
    fi
}

# mode_table MODE: MODE's table, between its own markers, from build/calibration/.
mode_table() {
    echo "<!-- calibration $1 -->"
    echo "\`--mode $1\`, seed 7; a target render stops at $limit CPU seconds."
    echo
    echo "| scene | $1, defaults | $1, --target-error $target |"
    echo "|---|---|---|"
    for name in $all; do
        printf '| `%s` | %s | %s |\n' "$name" "$(cell "$name" "$1" defaults)" \
            "$(cell "$name" "$1" target)"
    done
    echo "<!-- /calibration $1 -->"
}

# write_table: the calibration section of reference/suite.md, in place of the old one or
# before the consistency section: the modes run now get new tables, the others keep the
# tables they had (a run of some modes, MODES=..., leaves the rest as measured).
write_table() {
    section=$work/section.md
    {
        echo "<!-- calibration -->"
        echo "## Calibration: whether the stated error holds"
        echo
        echo "Written by \`make calibration\` (\`scripts/calibration.sh\`, the scenes of"
        echo "\`reference/consistency.txt\`): each mode that states a bound (\`--error\`), at its"
        echo "defaults and at \`--target-error $target\`, seed 7, against the scene's reference. A cell"
        echo "gives the share of 16 × 16 blocks whose mean lies within the stated 95% bound of the"
        echo "reference's (its own error allowed for where it has a variance image or, made by 2008"
        echo "or 2009, a block statement), the median"
        echo "over blocks of bound / error (and the ratio of their rms), and the CPU seconds. An"
        echo "exact normal bound has a median ratio of 2.91 and an rms ratio of 1.96. A cell"
        echo "\"misses\" when so many blocks lie outside the bound that a true 95% bound would"
        echo "leave as many out with a chance under 1% (the binomial tail: 3 of 48 is no miss, 25"
        echo "of 256 is); otherwise it \"holds\" at a median ratio of 4.4 or less (1.5 times the"
        echo "exact bound's, as an rms ratio of 3 is of 1.96), and is \"loose\" above. pt's"
        echo "blocks are judged by its pixels' bounds in quadrature (\`compare --test-error\`), 2008's"
        echo "and 2009's and photons', whose pixels share photons, by their block statements"
        echo "(\`--block-error\`, \`compare --test-block-error\`)."
        for mode in pt photons 2008 2009; do
            if printf ' %s ' "$modes" | grep -q " $mode "; then
                echo
                mode_table "$mode"
            elif grep -q "^<!-- calibration $mode -->\$" "$out"; then
                echo
                sed -n "/^<!-- calibration $mode -->\$/,/^<!-- \/calibration $mode -->\$/p" "$out"
            fi
        done
        echo "<!-- /calibration -->"
    } > "$section"
    if grep -q '^<!-- calibration -->$' "$out"; then
        awk -v f="$section" '
            /^<!-- calibration -->$/ { while ((getline l < f) > 0) print l; skip = 1; next }
            /^<!-- \/calibration -->$/ { skip = 0; next }
            !skip' "$out" > "$out.tmp"
    else
        awk -v f="$section" '
            /^<!-- consistency -->$/ { while ((getline l < f) > 0) print l; print "" }
            { print }' "$out" > "$out.tmp"
    fi
    mv "$out.tmp" "$out"
}

if [ -n "$rewrite" ]; then
    write_table
    echo "calibration: the table is in $out, written again from $work"
    exit 0
fi

for name in $names; do
    scene_of "$name"
    for mode in $modes; do
        for kind in defaults target; do
            [ "$mode-$kind" != photons-target ] || continue
            base=$work/$name-$mode-$kind
            rm -f "$base.compare"
            how=
            [ "$kind" = defaults ] || how="--target-error $target --time-limit $limit"
            echo "calibration: $name, --mode $mode $how $options"
            statement="--error $base-error.pfm"
            judged="--test-error $base-error.pfm"
            case $mode in photons | 2008 | 2009)
                statement="$statement --block-error $base-blocks.pfm"
                judged="--test-block-error $base-blocks.pfm" ;;
            esac
            # shellcheck disable=SC2086 # the options are words
            if "$photon" --mode "$mode" $how $options --seed 7 --stats --no-progress "$scene" \
                -o "$base.pfm" $statement 2> "$base.log"; then
                # shellcheck disable=SC2086
                "$photon" compare "$base.pfm" "$reference" $judged $noise > "$base.compare"
            elif ! grep -q -- '--error' "$base.log"; then
                echo "calibration: --mode $mode failed on $scene: $(tail -n 1 "$base.log")" >&2
                exit 1
            fi
            echo "calibration: $name, $mode, $kind: $(cell "$name" "$mode" "$kind")"
        done
    done
    write_table
done
echo "calibration: the table is in $out"
