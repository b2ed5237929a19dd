#!/bin/sh
# scripts/consistency.sh [NAME ...] -- renders every shipped scene of
# reference/consistency.txt with every photon mode at its defaults and compares each image
# with the scene's reference, then writes the table of what it found into
# reference/suite.md (between its <!-- consistency --> markers). Run by `make consistency`
# (ONLY=NAME, or ONLY="NAME NAME ...", for some scenes; MODES="1996 2009" for some modes;
# QUALITY=reference for the reference preset) from the top of the repository after
# ./photon is built; PHOTON=PATH runs another binary. `scripts/consistency.sh --rewrite`
# renders nothing and writes the table again from what build/consistency/ holds (cells
# rendered elsewhere can be copied there first).
#
# KINDS="defaults target" by default: each mode at its defaults (QUALITY), and 2008 and
# 2009 also at --target-error 0.02, stopped at TARGET_LIMIT CPU seconds (default 600);
# KINDS=target renders only those. Cells a run does not render keep what suite.md held.
#
# A cell passes when the image mean is within 1% of the reference's and every 16 x 16
# block's mean within 3% (photon compare --block 16). Blocks below the reference's noise
# floor -- the standard error of the block's mean, from the reference's variance image or,
# for one made by 2008 or 2009, its block statement (the bound over z_c), above 1% of it
# (photon compare's rule, BLOCK_NOISE_FLOOR) -- are left out and named. A mode that says at its start that it cannot
# render the scene (a warning on stderr) is marked so. Every cell's image, log and compare
# line stay in build/consistency/, and the table is written again from them after each
# scene, so that an interrupted run keeps what it measured.
set -eu
cd "$(dirname "$0")/.."
photon=${PHOTON:-./photon}
table=reference/consistency.txt
out=reference/suite.md
work=build/consistency
modes=${MODES:-photons 1994 1996 2008 2009}
quality=${QUALITY:-default}
kinds=${KINDS:-defaults target}
target=0.02
limit=${TARGET_LIMIT:-600}
mkdir -p "$work"
. scripts/suite-lib.sh
suite_names consistency "$@"

# The plan: the table's estimate of each scene's CPU seconds for all five modes.
if [ -z "$rewrite" ]; then
    total=0
    echo "consistency: expected CPU seconds (the modes $modes at --quality $quality):"
    for name in $names; do
        s=$(field "$(line_of "$name")" 5)
        total=$((total + s))
        printf '  %-22s %6d s\n' "$name" "$s"
    done
    printf '  %-22s %6d s, about %d h %02d min (five modes at their defaults)\n' "total" "$total" \
        $((total / 3600)) $((total % 3600 / 60))
fi

# column MODE: the mode's column in the table of the defaults.
column() {
    case $1 in photons) echo 1 ;; 1994) echo 2 ;; 1996) echo 3 ;; 2008) echo 4 ;; 2009) echo 5 ;; esac
}

# cell NAME MODE[-target]: the table's cell from what build/consistency/NAME-MODE.* holds.
# A target render that fails the 3% rule but said at its end that blocks missed the target
# (the time limit came first) is "short, stated", not a failure of its statement.
cell() {
    c=$work/$1-$2.compare
    if [ ! -f "$c" ]; then
        case $2 in
            *-target) kept "consistency target" "$1" $(($(column "${2%-target}") - 3)) ;;
            *) kept "consistency defaults" "$1" "$(column "$2")" ;;
        esac
        return
    fi
    line=$(cat "$c")
    log=$work/$1-$2.log
    seconds=$(awk -v s="$(stat_of "$log" seconds_total)" 'BEGIN { printf "%.0f", s }')
    within=$(key "$line" blocks_within_3pct)
    blocks=$(key "$line" blocks)
    worst=$(key "$line" worst_block)
    ratio=$(key "$line" mean_ratio)
    verdict=$(awk -v w="$worst" -v r="$ratio" \
        'BEGIN { print (w <= 0.03 && r >= 0.99 && r <= 1.01) ? "pass" : "**fail**" }')
    short=
    case $2 in *-target)
        reached=$(stat_of "$log" target_blocks_within)
        judged=$(stat_of "$log" target_blocks)
        [ "$reached" = "$judged" ] || {
            short=", stopped with $reached of $judged blocks at $target"
            [ "$verdict" = pass ] || verdict="short, stated"
        }
        short="$short, $(stat_of "$log" passes) passes" ;;
    esac
    grep -q '^photon: warning:' "$log" && verdict="$verdict, warns"
    noisy=$(key "$line" blocks_noisy)
    excluded=
    [ -z "$noisy" ] || [ "$noisy" = 0 ] ||
        excluded=", $noisy noisy left out ($(key "$line" noisy_blocks | tr ';' '\n' |
            head -n 4 | sed -e ':a' -e 'N' -e '$!ba' -e 's/\n/; /g')$([ "$noisy" -le 4 ] ||
            printf '; ...'))"
    printf '%s: %s/%s, worst %s at (%s), mean %s, %s s%s%s' "$verdict" "$within" "$blocks" \
        "$(awk -v w="$worst" 'BEGIN { printf "%.1f%%", 100 * w }')" \
        "$(key "$line" worst_block_at | sed 's/,/, /')" \
        "$(awk -v r="$ratio" 'BEGIN { printf "%.4f", r }')" "$seconds" "$short" "$excluded"
}

# write_table: the consistency section of reference/suite.md, in place of the old one.
write_table() {
    section=$work/section.md
    {
        echo "<!-- consistency -->"
        echo "## Consistency: every photon mode on every shipped scene"
        echo
        echo "Written by \`make consistency\` (\`scripts/consistency.sh\`, the scenes of"
        echo "\`reference/consistency.txt\`): each mode at its defaults against the scene's"
        echo "reference. A cell passes when the image mean is within 1% of the reference's and"
        echo "every 16 × 16 block's mean within 3%; it gives the blocks within 3%, the worst block"
        echo "(its top-left pixel), the mean's ratio and the mode's CPU seconds. Blocks whose"
        echo "reference mean has a standard error above 1% (its variance image, or the block"
        echo "statement of one made by 2008 or 2009) are left out and"
        echo "named; \"warns\" marks a mode that says at its start what it cannot find there."
        echo
        echo "<!-- consistency defaults -->"
        printf '| scene |'
        for mode in photons 1994 1996 2008 2009; do printf ' %s |' "$mode"; done
        echo
        echo "|---|---|---|---|---|---|"
        for name in $all; do
            printf '| `%s` |' "$name"
            for mode in photons 1994 1996 2008 2009; do printf ' %s |' "$(cell "$name" "$mode")"; done
            echo
        done
        echo "<!-- /consistency defaults -->"
        echo
        echo "The modes that render to a stated error, at \`--target-error $target\` (a render"
        echo "stops at $limit CPU seconds): a cell passes as above; \"short, stated\" when it"
        echo "does not but the mode said at its end which blocks had not reached the target."
        echo
        echo "<!-- consistency target -->"
        echo "| scene | 2008, --target-error $target | 2009, --target-error $target |"
        echo "|---|---|---|"
        for name in $all; do
            printf '| `%s` | %s | %s |\n' "$name" "$(cell "$name" 2008-target)" \
                "$(cell "$name" 2009-target)"
        done
        echo "<!-- /consistency target -->"
        echo "<!-- /consistency -->"
    } > "$section"
    {
        if [ -f "$out" ]; then
            sed '/^<!-- consistency -->$/,$d' "$out" | sed -e :a -e '/^\n*$/{$d;N;ba' -e '}'
            echo
        fi
        cat "$section"
    } > "$out.tmp"
    mv "$out.tmp" "$out"
}

if [ -n "$rewrite" ]; then
    write_table
    echo "consistency: the table is in $out, written again from $work"
    exit 0
fi

# render NAME MODE CELL OPTIONS...: one cell's render and its comparison.
render() {
    base=$work/$1-$3
    how=$4
    echo "consistency: $1, --mode $2 $how $options"
    # shellcheck disable=SC2086 # the options are words
    "$photon" --mode "$2" $how $options --seed 1 --stats --no-progress "$scene" \
        -o "$base.pfm" 2> "$base.log" || {
        echo "consistency: --mode $2 failed on $scene: $(tail -n 1 "$base.log")" >&2
        exit 1
    }
    # shellcheck disable=SC2086
    "$photon" compare "$base.pfm" "$reference" --block 16 $noise > "$base.compare"
    echo "consistency: $1, $3: $(cell "$1" "$3")"
}

for name in $names; do
    scene_of "$name"
    for mode in $modes; do
        case $kinds in *defaults*) render "$name" "$mode" "$mode" "--quality $quality" ;; esac
        case $mode:$kinds in 2008:*target* | 2009:*target*)
            render "$name" "$mode" "$mode-target" "--target-error $target --time-limit $limit"
        esac
    done
    write_table
done
echo "consistency: the table is in $out"
