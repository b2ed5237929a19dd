#!/bin/sh
# scripts/tile-windows.sh -- the --crop windows that cut an image into tiles, one a line.
#
#   scripts/tile-windows.sh [--size WxH] [--photon PATH] SCENE TILES [photon options ...]
#
# Prints "X0 Y0 X1 Y1" for each tile, tile 0 first: TILES is N (N horizontal bands, top
# first) or CxR (C columns and R rows, row by row). The edges lie at floor(i * W / C) and
# floor(j * H / R), so the windows cover the W x H image exactly, without overlap. The
# size is asked of photon (a one-pixel --mode direct render of SCENE, with the --width and
# --height among the photon options, whose record's "image" line says it) unless --size
# gives it. Used by tiles-xargs.sh and tiles.mk; its output is GNU parallel's input too.
#
# POSIX sh, set -eu.

set -eu

die() {
    echo "tile-windows.sh: $*" >&2
    exit 2
}

size="" photon="${PHOTON:-}"
while [ $# -gt 0 ]; do
    case $1 in
    -h | --help)
        sed -n '4,11s/^# \{0,1\}//p' "$0"
        exit 0
        ;;
    --size) [ $# -ge 2 ] || die "--size needs WxH"; size=$2; shift 2 ;;
    --photon) [ $# -ge 2 ] || die "--photon needs a path"; photon=$2; shift 2 ;;
    --) shift; break ;;
    -*) die "unknown option '$1' (before SCENE; -h for help)" ;;
    *) break ;;
    esac
done
[ $# -ge 2 ] || die "usage: tile-windows.sh [--size WxH] [--photon PATH] SCENE TILES [photon options ...]"
scene=$1 tiles=$2
shift 2

case $tiles in
*x*) cols=${tiles%%x*} rows=${tiles#*x} ;;
*) cols=1 rows=$tiles ;;
esac
case $cols$rows in '' | *[!0-9]*) die "TILES: expected N or CxR, not '$tiles'" ;; esac
if [ "$cols" -lt 1 ] || [ "$rows" -lt 1 ]; then die "TILES: at least one column and one row"; fi

if [ -z "$size" ]; then
    [ -f "$scene" ] || die "$scene: no such file"
    if [ -z "$photon" ]; then
        photon=$(dirname "$0")/../photon
        [ -x "$photon" ] || photon=photon
    fi
    width_opt="" height_opt="" prev=""
    for a in "$@"; do
        case $prev in --width) width_opt=$a ;; --height) height_opt=$a ;; esac
        prev=$a
    done
    probe=${TMPDIR:-/tmp}/tile-windows.$$
    mkdir "$probe" || die "cannot make the scratch directory $probe"
    trap 'rm -rf "$probe"' EXIT
    "$photon" --no-progress --mode direct --spp 1 ${width_opt:+--width "$width_opt"} \
        ${height_opt:+--height "$height_opt"} --crop 0 0 1 1 -o "$probe/p.pfm" "$scene" ||
        die "photon could not render a pixel of $scene (see above); give --size WxH"
    size=$(sed -n 's/^image \([0-9]*\) \([0-9]*\)$/\1x\2/p' "$probe/p.pfm.window")
fi
width=${size%%x*} height=${size#*x}
case $width$height in '' | *[!0-9]*) die "image size: expected WxH, not '$size'" ;; esac
if [ "$cols" -gt "$width" ] || [ "$rows" -gt "$height" ]; then
    die "TILES $tiles: more columns or rows than the ${width}x$height image has pixels"
fi

k=0
while [ "$k" -lt $((cols * rows)) ]; do
    col=$((k % cols)) row=$((k / cols))
    echo "$((col * width / cols)) $((row * height / rows)) $(((col + 1) * width / cols)) $(((row + 1) * height / rows))"
    k=$((k + 1))
done
