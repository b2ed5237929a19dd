# scripts/suite-lib.sh -- what scripts/reference.sh, consistency.sh and calibration.sh
# share, sourced by each after it sets $table (the table of scenes it reads). It sets
# $all (the table's names), $rewrite (yes after a leading --rewrite) and $names (the
# names given, each checked against the table, or all of them) from the script's
# arguments, read by suite_names "$@".

# The table's lines without comments or blank lines.
rows() { sed -e '/^[[:space:]]*#/d' -e '/^[[:space:]]*$/d' "$table"; }

# field LINE I: the I-th `|`-separated field of LINE, trimmed.
field() {
    printf '%s\n' "$1" | awk -F'|' -v i="$2" '{ f = $i; gsub(/^[ \t]+|[ \t]+$/, "", f); print f }'
}

# stat_of LOG KEY: the value of KEY=VALUE among photon's --stats lines in LOG.
stat_of() { sed -n "s/^$2=//p" "$1" | tail -n 1; }

# key LINE KEY: the value of KEY=VALUE in one line of photon compare.
key() { printf '%s\n' "$1" | tr ' ' '\n' | sed -n "s/^$2=//p"; }

# line_of NAME: the table's line of NAME.
line_of() { rows | awk -F'|' -v n="$1" '{ f = $1; gsub(/[ \t]/, "", f) } f == n'; }

# suite_names WHO [--rewrite] [NAME ...]: $all, $rewrite and $names as above; exits 2
# with the table's names when a name is not among them.
suite_names() {
    who=$1
    shift
    all=$(rows | awk -F'|' '{ gsub(/[ \t]/, "", $1); print $1 }')
    rewrite=
    if [ "${1:-}" = --rewrite ]; then
        rewrite=yes
        shift
    fi
    names=${*:-$all}
    for name in $names; do
        printf '%s\n' "$all" | grep -qx "$name" || {
            echo "$who: no scene named '$name' in $table; the names are:" \
                "$(printf '%s\n' "$all" | tr '\n' ' ')" >&2
            exit 2
        }
    done
}

# kept MARKER NAME I: the I-th cell of NAME's row in the table of $out between the lines
# <!-- MARKER --> and <!-- /MARKER -->, as the last run wrote it, or "not run": a run of
# some scenes or modes leaves the cells it did not render as they were.
kept() {
    [ -f "$out" ] || { echo "not run"; return; }
    sed -n "/^<!-- $1 -->\$/,/^<!-- \/$1 -->\$/p" "$out" |
        awk -F' [|] ' -v n="| \`$2\`" -v i="$3" '$1 == n { c = $(i + 1); sub(/ [|]$/, "", c); print c; found = 1 }
            END { if (!found) print "not run" }'
}

# scene_of NAME: $scene, $reference (its PFM), $options and $noise (photon compare's
# --ref-variance of the reference's variance image, or --ref-block-error of the block
# statement of one made by 2008 or 2009, when it has one) from NAME's line of
# reference/consistency.txt.
scene_of() {
    line=$(line_of "$1")
    scene=$(field "$line" 2)
    reference=reference/$(field "$line" 3).pfm
    options=$(field "$line" 4)
    variance=reference/$(field "$line" 3)-var.pfm
    blocks=reference/$(field "$line" 3)-blocks.pfm
    noise=
    if [ -f "$variance" ]; then
        noise="--ref-variance $variance"
    elif [ -f "$blocks" ]; then
        noise="--ref-block-error $blocks"
    fi
}
