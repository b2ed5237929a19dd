#!/bin/sh
# scripts/reference.sh [NAME ...] -- renders the reference suite of reference/suite.txt and
# writes what it measured into reference/suite.md. Run by `make reference` (ONLY=NAME, or
# ONLY="NAME NAME ...", for some of them) from the top of the repository after ./photon is
# built; PHOTON=PATH runs another binary. `scripts/reference.sh --rewrite` renders nothing
# and writes reference/suite.md again from its rows and the table's notes.
#
# For each reference, one at a time (a render takes a core; the machine may have others
# busy):
#   1. seed 1 with the table's options: the file kept, with its variance image in every
#      mode that writes one (all but 2008 and 2009), and in those two its error image and
#      block statement (--error, --block-error), which the calibration and the
#      consistency table read as the reference's own noise;
#   2. seed 2, the same options otherwise: `photon compare` of the two measures the noise;
#   3. for a reference made by a photon mode, the table's check (a second mode, seed 1),
#      compared with the reference: the seeds show only a consistent mode's noise, the
#      check also how far its remaining bias is from another method's picture.
# Then the files move into reference/ and the reference's row of reference/suite.md is
# replaced; the rows of references not rendered this time are kept as they were.
#
# The estimated relmse against the truth is half the relmse between the seeds. Two
# independent renders a and b of the same settings have errors e_a and e_b about the truth
# t, of equal variance v and uncorrelated, so E[(a - b)^2] = 2 v while E[(a - t)^2] = v;
# relmse divides by b^2 + 1e-2 where the truth's t^2 + 1e-2 would be, which changes little
# once the noise is small beside the signal. Hence relmse(a, b) is about 2 relmse(a, t).
# For pt, which is unbiased, that is the whole error; for a consistent photon mode it is
# the noise part, and the check bounds the bias.
#
# Renders write into build/reference/ and only complete files are moved (mv within one
# file system is a rename), so an interrupted run leaves every reference as it was.
set -eu
cd "$(dirname "$0")/.."
photon=${PHOTON:-./photon}
table=reference/suite.txt
out=reference/suite.md
work=build/reference
mkdir -p "$work"
. scripts/suite-lib.sh

# run LOG COMMAND...: runs a render with photon's stderr (the progress line, then --stats)
# shown and kept in LOG; fails when the render does.
run() {
    log=$1
    shift
    { "$@" 2>&1 >/dev/null || echo "photon failed with status $?"; } | tee "$log" >&2
    if grep -q '^photon failed' "$log"; then
        echo "reference: failed: $*" >&2
        exit 1
    fi
}

# Which references: the names given, each of which must be in the table, or all.
suite_names reference "$@"

# percent FRACTION: 0.0123 as 1.2%.
percent() { awk -v f="$1" 'BEGIN { printf "%.1f%%", 100 * f }'; }

# shown FORMAT NUMBER: the number as printf's FORMAT prints it (two digits of a relmse are
# all its noise lets mean; whole CPU seconds).
shown() { awk -v f="$1" -v x="$2" 'BEGIN { printf f, x }'; }

# write_suite NAME ROW: writes reference/suite.md, the header, a row per reference in the
# table's order (ROW for NAME, for the others the row suite.md had) and the table's notes.
write_suite() {
    {
        echo "# The reference suite"
        echo
        echo "Written by \`make reference\` (\`scripts/reference.sh\`) from \`reference/suite.txt\`;"
        echo "\`reference/README.md\` says how to use and regenerate it. Each reference is seed 1"
        echo "of its command; seed 2, the same command otherwise, measures its noise: the"
        echo "estimated relmse against the truth is half the relmse between the two seeds (two"
        echo "independent renders' difference has twice the variance of either's error). Blocks"
        echo "are the 16 × 16 blocks of \`photon compare --block 16\`, within 3% when their mean"
        echo "luminance is. CPU seconds are \`--stats\`' \`seconds_total\` of the seed-1 render, on"
        echo "one core of a 2-core AMD EPYC virtual machine. For a reference made by a photon mode,"
        echo "which is consistent but biased, the seeds measure only its noise: \"how checked\" also"
        echo "compares it with a second mode, rendered once; one made by 2008 or 2009 also states its"
        echo "error, noise and bias, in \`NAME-error.pfm\` and, block by block, \`NAME-blocks.pfm\`."
        echo "Rows measured when their file was made, before this table, say so."
        echo
        echo "| file | scene | command | samples | CPU s | relmse between seeds | estimated relmse vs truth | how checked |"
        echo "|---|---|---|---|---|---|---|---|"
        for each in $all; do
            if [ "$each" = "$1" ]; then
                printf '%s\n' "$2"
            elif [ -f "$out" ] && grep -q "^| \`$each.pfm\` |" "$out"; then
                grep "^| \`$each.pfm\` |" "$out"
            else
                echo "| \`$each.pfm\` | \`$(field "$(line_of "$each")" 2)\` | not rendered yet | | | | | |"
            fi
        done
        echo
        echo "## Notes"
        echo
        for each in $all; do
            echo "- \`$each.pfm\`: $(field "$(line_of "$each")" 7)."
        done
        # make calibration's and make consistency's tables (scripts/calibration.sh,
        # scripts/consistency.sh), kept as they were
        for section in calibration consistency; do
            if [ -f "$out" ] && grep -q "^<!-- $section -->\$" "$out"; then
                echo
                sed -n "/^<!-- $section -->\$/,/^<!-- \/$section -->\$/p" "$out"
            fi
        done
    } > "$out.tmp"
    mv "$out.tmp" "$out"
}

if [ -n "$rewrite" ]; then
    write_suite "" ""
    echo "reference: $out written again from its rows and $table's notes"
    exit 0
fi

# The plan, before anything starts: each render's expected CPU seconds and the total.
n=0
total=0
echo "reference: expected CPU seconds (seed 1 + seed 2 + check), one render at a time:"
for name in $names; do
    line=$(line_of "$name")
    s=$(field "$line" 4)
    c=$(field "$line" 6)
    t=$((2 * s + c))
    n=$((n + 1))
    total=$((total + t))
    printf '  %-26s %6d s  (%s + %s + %s)\n' "$name" "$t" "$s" "$s" "$c"
done
printf '  %-26s %6d s, about %d h %02d min\n' "total" "$total" $((total / 3600)) \
    $((total % 3600 / 60))

# blocks LINE: photon compare's block statistics in words. The worst block is infinitely
# far off when it is black in the reference and not in the image compared.
blocks() {
    worst=$(key "$1" worst_block)
    at="($(key "$1" worst_block_at | sed 's/,/, /'))"
    case $worst in
    inf) worst="the worst, $at, black in the reference and not here" ;;
    *) worst="worst $(percent "$worst") at $at" ;;
    esac
    echo "$(key "$1" blocks_within_3pct) of $(key "$1" blocks) blocks within 3%, $worst"
}

k=0
for name in $names; do
    k=$((k + 1))
    line=$(line_of "$name")
    scene=$(field "$line" 2)
    options=$(field "$line" 3)
    check=$(field "$line" 5)
    dir=$work/$name
    rm -rf "$dir"
    mkdir -p "$dir"
    echo
    echo "[$k/$n] $name: $scene $options, about $(field "$line" 4) CPU s a render"

    # 2008 and 2009 write no variance image but state their error, block by block (their
    # pixels share photons); every other mode writes one here.
    case " $options " in
    *" --mode 2008 "* | *" --mode 2009 "*) statement=blocks ;;
    *) statement=variance ;;
    esac
    if [ $statement = variance ]; then
        kept1="--variance $dir/1-var.pfm"
        kept2="--variance $dir/2-var.pfm"
        noise="--ref-variance $dir/1-var.pfm --test-variance $dir/2-var.pfm"
    else
        kept1="--error $dir/1-error.pfm --block-error $dir/1-blocks.pfm"
        kept2="--error $dir/2-error.pfm --block-error $dir/2-blocks.pfm"
        noise="--ref-block-error $dir/1-blocks.pfm --test-block-error $dir/2-blocks.pfm"
    fi

    echo "[$k/$n] $name: seed 1"
    # shellcheck disable=SC2086 # the options are words
    run "$dir/1.log" "$photon" $options --seed 1 --stats --progress "$scene" -o "$dir/1.pfm" $kept1
    echo "[$k/$n] $name: seed 2"
    # shellcheck disable=SC2086
    run "$dir/2.log" "$photon" $options --seed 2 --stats --progress "$scene" -o "$dir/2.pfm" $kept2
    # shellcheck disable=SC2086
    seeds=$("$photon" compare "$dir/2.pfm" "$dir/1.pfm" --block 16 $noise)
    echo "[$k/$n] $name: seed 2 against seed 1: $seeds"

    log=$dir/1.log
    seconds=$(shown %.0f "$(stat_of "$log" seconds_total)")
    case " $options " in
    *" --mode 2008 "*)
        passes=$(stat_of "$log" passes)
        samples="$passes passes of $(($(stat_of "$log" photons_emitted) / passes)) photons,"
        samples="$samples $(stat_of "$log" spp) eye rays a pixel" ;;
    *" --mode 2009 "*)
        passes=$(stat_of "$log" passes)
        samples="$passes passes of $(($(stat_of "$log" photons_emitted) / passes)) photons,"
        samples="$samples an eye path a pixel each" ;;
    *)
        samples="$(stat_of "$log" spp) a pixel" ;;
    esac
    relmse=$(key "$seeds" relmse)
    truth=$(shown %.2g "$(awk -v r="$relmse" 'BEGIN { print r / 2 }')")
    relmse=$(shown %.2g "$relmse")
    how="seed 2: $(blocks "$seeds")"
    failed=$(key "$seeds" blocks_failed)
    tested=$(key "$seeds" blocks_tested)
    how="$how; $((tested - failed)) of $tested blocks consistent at α = 0.01 by the two"
    if [ $statement = variance ]; then
        how="$how variance images"
    else
        how="$how block statements"
    fi

    if [ "$check" != "-" ]; then
        echo "[$k/$n] $name: check, $check"
        # shellcheck disable=SC2086
        run "$dir/check.log" "$photon" $check --seed 1 --stats --progress "$scene" \
            -o "$dir/check.pfm"
        against=$("$photon" compare "$dir/check.pfm" "$dir/1.pfm" --block 16)
        echo "[$k/$n] $name: check against the reference: $against"
        how="$how. Against \`$check\` ($(shown %.0f "$(stat_of "$dir/check.log" seconds_total)") s):"
        how="$how relmse $(shown %.2g "$(key "$against" relmse)"), $(blocks "$against")"
    fi

    # The command that makes the kept file, as a user would type it.
    command="./photon $options --seed 1 $scene -o reference/$name.pfm"
    if [ $statement = variance ]; then
        command="$command --variance reference/$name-var.pfm"
    else
        command="$command --error reference/$name-error.pfm --block-error reference/$name-blocks.pfm"
    fi
    row="| \`$name.pfm\` | \`$scene\` | \`$command\` | $samples | $seconds | $relmse | $truth | $how |"

    # Only now do the files replace the old ones, the image last.
    mv "$dir/1.png" "reference/$name.png"
    if [ $statement = variance ]; then
        mv "$dir/1-var.pfm" "reference/$name-var.pfm"
    else
        mv "$dir/1-error.pfm" "reference/$name-error.pfm"
        mv "$dir/1-blocks.pfm" "reference/$name-blocks.pfm"
    fi
    mv "$dir/1.pfm" "reference/$name.pfm"
    write_suite "$name" "$row"
    echo "[$k/$n] $name: done, reference/$name.pfm; estimated relmse against the truth $truth"
done
echo
echo "reference: $n written; see $out"
