#!/bin/sh
# scripts/tiles-xargs.sh -- render an image as tiles on one machine, J photon processes at
# a time (xargs -P), then merge them into the image a whole render writes.
#
#   scripts/tiles-xargs.sh [--jobs J] [--work FILE] [--tiles-dir DIR] SCENE OUT.pfm TILES
#                          [photon options ...]
#
# TILES is N (N horizontal bands) or CxR (a grid), cut by tile-windows.sh. Each tile is
# rendered with the photon options and its own --crop into TILEDIR/X0_Y0_X1_Y1.pfm (with
# its record .pfm.window and display file), J at a time (default 2); then
# `photon merge -o OUT.pfm` puts them together. TILEDIR is OUT.pfm with .tiles for .pfm
# unless --tiles-dir names it; the tiles this run renders lose their old files first.
#
# --work FILE (--mode photons, 1994, 1996): the mode's global work is done once, not once
# a tile. The first tile renders alone with --save-photons FILE, the others then read it
# with --load-photons FILE; the pixels are the same bytes either way.
#
# POSIX sh, set -eu; xargs -P is not in POSIX but GNU, BSD and busybox xargs have it.

set -eu

die() {
    echo "tiles-xargs.sh: $*" >&2
    exit 2
}

jobs=2 work="" tiles_dir="" photon="${PHOTON:-}"
while [ $# -gt 0 ]; do
    case $1 in
    -h | --help)
        sed -n '4,18s/^# \{0,1\}//p' "$0"
        exit 0
        ;;
    --jobs) [ $# -ge 2 ] || die "--jobs needs a number"; jobs=$2; shift 2 ;;
    --work) [ $# -ge 2 ] || die "--work needs a file name"; work=$2; shift 2 ;;
    --tiles-dir) [ $# -ge 2 ] || die "--tiles-dir needs a directory"; tiles_dir=$2; shift 2 ;;
    --photon) [ $# -ge 2 ] || die "--photon needs a path"; photon=$2; shift 2 ;;
    --) shift; break ;;
    -*) die "unknown option '$1' (before SCENE; -h for help)" ;;
    *) break ;;
    esac
done
[ $# -ge 3 ] || die "usage: tiles-xargs.sh [--jobs J] [--work FILE] [--tiles-dir DIR] SCENE OUT.pfm TILES [photon options ...]"
scene=$1 out=$2 tiles=$3
shift 3
case $jobs in '' | *[!0-9]* | 0) die "--jobs: expected a positive number, not '$jobs'" ;; esac
case $out in *.pfm) ;; *) die "OUT must end in .pfm: '$out'" ;; esac
for a in "$@"; do
    case $a in
    --crop | -o | --save-photons | --load-photons)
        die "photon option $a: the script gives each tile its own (--work shares the global work)" ;;
    --time-limit)
        die "photon option --time-limit: photon merge refuses such tiles; give --spp (and --passes)" ;;
    esac
done

here=$(dirname "$0")
if [ -z "$photon" ]; then
    photon=$here/../photon
    [ -x "$photon" ] || photon=photon
fi
[ -n "$tiles_dir" ] || tiles_dir=${out%.pfm}.tiles
mkdir -p "$tiles_dir"
windows=$tiles_dir/windows.txt
"$here/tile-windows.sh" --photon "$photon" "$scene" "$tiles" "$@" >"$windows"

while read -r window; do
    rm -f "$tiles_dir/$(echo "$window" | tr ' ' _)".*
done <"$windows"

# One tile: sh -c's arguments are photon, the directory, the scene, the window (one word,
# split on purpose for --crop), then the photon options.
# shellcheck disable=SC2016 # expanded by that sh, not this one
render_tile='photon=$1 dir=$2 scene=$3 window=$4
shift 4
exec "$photon" --no-progress "$@" --crop $window -o "$dir/$(echo "$window" | tr " " _).pfm" "$scene"'

status=0
if [ -n "$work" ]; then
    head -n 1 "$windows" | xargs -I {} sh -c "$render_tile" sh "$photon" "$tiles_dir" "$scene" {} \
        "$@" --save-photons "$work" || status=$?
    if [ "$status" = 0 ]; then
        sed 1d "$windows" | xargs -P "$jobs" -I {} sh -c "$render_tile" sh "$photon" "$tiles_dir" \
            "$scene" {} "$@" --load-photons "$work" || status=$?
    fi
else
    xargs -P "$jobs" -I {} sh -c "$render_tile" sh "$photon" "$tiles_dir" "$scene" {} "$@" \
        <"$windows" || status=$?
fi

# The merge's tiles, in order; a tile whose record is missing failed (photon writes the
# record after the image, and writes each file whole or not at all).
set --
missing=0
while read -r window; do
    tile=$tiles_dir/$(echo "$window" | tr ' ' _).pfm
    if [ ! -f "$tile.window" ]; then
        echo "tiles-xargs.sh: tile --crop $window failed (see above)" >&2
        missing=$((missing + 1))
    fi
    set -- "$@" "$tile"
done <"$windows"
[ "$missing" = 0 ] || die "$missing of $# tiles failed (xargs status $status); run the script again"
exec "$photon" merge -o "$out" "$@"
