#!/bin/sh
# scripts/slurm-tiles.sh -- render an image as a Slurm array job of tiles, then merge them in
# a job that depends on the array (README: Tiles and merging, "Slurm").
#
#   scripts/slurm-tiles.sh [script options] SCENE OUT.pfm TILES [photon options ...]
#
# Submits two jobs with sbatch and prints their ids:
#   1. an array job, one task per tile: task K renders its --crop window of the image into
#      TILEDIR/tile-K.pfm (with tile-K.png and tile-K.pfm.window), one CPU each;
#   2. the merge, `photon merge -o OUT.pfm TILEDIR/tile-*.pfm`, submitted with
#      --dependency=afterok:ARRAYJOB (it starts once every task has succeeded).
# The same file is the job script: sbatch runs it again with an internal first argument
# (--run-tile or --run-merge), so one file holds the whole recipe.
#
# POSIX sh (dash, bash, ...), set -eu. Needs a file system shared by the submitting host
# and the compute nodes (the tiles directory, the scene and its included files, photon).

set -eu

usage() {
    cat <<'EOF'
usage: scripts/slurm-tiles.sh [script options] SCENE OUT.pfm TILES [photon options ...]

Renders SCENE with photon as a Slurm array job of tiles and merges them into OUT.pfm (and
OUT.png) with a job that depends on the array. Prints the two job ids.

  TILES              N     N horizontal bands of (nearly) equal height, task K = band K
                           from the top;
                     CxR   a grid of C columns and R rows, task K = column K % C, row K / C
  photon options     passed to every tile unchanged, e.g. --mode pt --spp 64; not --crop,
                     -o or --time-limit (tiles must render the same pixels wherever they run)

script options (before SCENE):
  --tiles-dir DIR    where the tiles and the jobs' logs go (default: OUT.pfm's name with
                     .tiles in place of .pfm, e.g. out/img.tiles)
  --only LIST        submit only these tasks, e.g. 3 or 1,4-5, and a new merge of the whole
                     tiles directory: re-renders a tile that failed, alone
  --after ok|any     the merge's dependency: afterok (default) starts it only when every task
                     succeeded, and cancels it if one failed (--kill-on-invalid-dep=yes);
                     afterany starts it whatever happened, so its log names missing tiles
  --size WxH         the whole image's size; default: asked of photon (a one-pixel --mode
                     direct render of SCENE with your --width/--height, on this host)
  --photon PATH      the photon binary (default: $PHOTON, else the photon built beside this
                     script's directory, else photon on PATH); must be reachable at the same
                     path on the compute nodes
  --dry-run          print the sbatch commands instead of running them
  -h, --help         print this and exit

sbatch options (partition, account, time limit, memory) come from the environment sbatch
reads, e.g. SBATCH_PARTITION=debug SBATCH_TIMELIMIT=1:00:00, or from SBATCH_EXTRA, a
space-separated list of more options given to both sbatch calls.

example, 4 bands of a path-traced Cornell box, then tile 2 again after it failed:
  scripts/slurm-tiles.sh scenes/cornell.scene out/cornell.pfm 4 --mode pt --spp 64
  scripts/slurm-tiles.sh --only 2 scenes/cornell.scene out/cornell.pfm 4 --mode pt --spp 64
EOF
}

die() {
    echo "slurm-tiles.sh: $*" >&2
    exit 2
}

# Tile K's window "X0 Y0 X1 Y1" of a W x H image cut into C columns and R rows: the edges
# at floor(i * W / C) and floor(j * H / R), so the tiles cover the image exactly.
tile_window() { # K C R W H
    col=$(($1 % $2))
    row=$(($1 / $2))
    echo "$((col * $4 / $2)) $((row * $5 / $3)) $(((col + 1) * $4 / $2)) $(((row + 1) * $5 / $3))"
}

# ---- job roles (run by sbatch on a compute node) ----

# --run-tile PHOTON DIR C R W H SCENE [photon options]: render task SLURM_ARRAY_TASK_ID.
if [ "${1:-}" = --run-tile ]; then
    [ $# -ge 8 ] || die "--run-tile: too few arguments"
    photon=$2 dir=$3 cols=$4 rows=$5 width=$6 height=$7 scene=$8
    shift 8
    k=${SLURM_ARRAY_TASK_ID:?--run-tile: SLURM_ARRAY_TASK_ID is not set (run by sbatch --array)}
    [ "$k" -lt $((cols * rows)) ] || die "task $k: there are only $((cols * rows)) tiles"
    window=$(tile_window "$k" "$cols" "$rows" "$width" "$height")
    echo "slurm-tiles.sh: job ${SLURM_ARRAY_JOB_ID:-?} task $k on $(hostname): --crop $window"
    # shellcheck disable=SC2086 # the window is four numbers, split on purpose
    exec "$photon" --no-progress "$@" --crop $window -o "$dir/tile-$k.pfm" "$scene"
fi

# --run-merge PHOTON DIR C R W H OUT.pfm: merge what the tasks left; name the missing tasks.
if [ "${1:-}" = --run-merge ]; then
    [ $# -eq 8 ] || die "--run-merge: expected 7 arguments"
    photon=$2 dir=$3 cols=$4 rows=$5 width=$6 height=$7 out=$8
    missing="" k=0
    while [ "$k" -lt $((cols * rows)) ]; do
        if [ ! -f "$dir/tile-$k.pfm" ] || [ ! -f "$dir/tile-$k.pfm.window" ]; then
            echo "slurm-tiles.sh: tile $k missing (--crop $(tile_window "$k" "$cols" "$rows" "$width" "$height"))" >&2
            missing="$missing${missing:+,}$k"
        fi
        k=$((k + 1))
    done
    [ -z "$missing" ] || echo "slurm-tiles.sh: re-run them alone with: scripts/slurm-tiles.sh --only $missing (and the same arguments)" >&2
    # photon merge names any gap as --crop windows itself and refuses foreign tiles.
    set --
    k=0
    while [ "$k" -lt $((cols * rows)) ]; do
        [ ! -f "$dir/tile-$k.pfm" ] || set -- "$@" "$dir/tile-$k.pfm"
        k=$((k + 1))
    done
    [ $# -gt 0 ] || die "no tiles in $dir"
    echo "slurm-tiles.sh: job ${SLURM_JOB_ID:-?} on $(hostname): $photon merge -o $out ($# tiles of $((cols * rows)))"
    exec "$photon" merge -o "$out" "$@"
fi

# ---- submission (run by you, on the submitting host) ----

tiles_dir="" only="" after=ok size="" photon="${PHOTON:-}" dry_run=0
while [ $# -gt 0 ]; do
    case $1 in
    -h | --help) usage; exit 0 ;;
    --tiles-dir) [ $# -ge 2 ] || die "--tiles-dir needs a directory"; tiles_dir=$2; shift 2 ;;
    --only) [ $# -ge 2 ] || die "--only needs a list of tasks"; only=$2; shift 2 ;;
    --after) [ $# -ge 2 ] || die "--after needs ok or any"; after=$2; shift 2 ;;
    --size) [ $# -ge 2 ] || die "--size needs WxH"; size=$2; shift 2 ;;
    --photon) [ $# -ge 2 ] || die "--photon needs a path"; photon=$2; shift 2 ;;
    --dry-run) dry_run=1; shift ;;
    --) shift; break ;;
    -*) die "unknown option '$1' (before SCENE; -h for help)" ;;
    *) break ;;
    esac
done
if [ $# -lt 3 ]; then
    usage >&2
    exit 2
fi
scene=$1 out=$2 tiles=$3
shift 3

case $after in ok | any) ;; *) die "--after: expected ok or any, not '$after'" ;; esac
case $out in *.pfm) ;; *) die "OUT must end in .pfm: '$out'" ;; esac
[ -f "$scene" ] || die "$scene: no such file"
case $tiles in
*x*) cols=${tiles%%x*} rows=${tiles#*x} ;;
*) cols=1 rows=$tiles ;;
esac
case $cols$rows in '' | *[!0-9]*) die "TILES: expected N or CxR, not '$tiles'" ;; esac
if [ "$cols" -lt 1 ] || [ "$rows" -lt 1 ]; then die "TILES: at least one column and one row"; fi
n=$((cols * rows))
case $only in *[!0-9,-]*) die "--only: expected a list like 3 or 1,4-5, not '$only'" ;; esac

# Options the script sets itself, or that would make tiles disagree.
width_opt="" height_opt="" prev=""
for a in "$@"; do
    case $a in
    --crop | -o) die "photon option $a: the script gives each tile its own --crop and -o" ;;
    --time-limit) die "photon option --time-limit: photon merge refuses such tiles (their pixels depend on the machine's speed); give --spp (and --passes)" ;;
    esac
    case $prev in --width) width_opt=$a ;; --height) height_opt=$a ;; esac
    prev=$a
done

# photon, as an absolute path, since the jobs run from sbatch's copy of this script.
here=$(cd "$(dirname "$0")" && pwd)
if [ -z "$photon" ]; then
    if [ -x "$here/../photon" ]; then
        photon=$(cd "$here/.." && pwd)/photon
    else
        photon=$(command -v photon) || die "no photon: build it (make) or give --photon PATH"
    fi
fi
case $photon in /*) ;; */*) photon=$(cd "$(dirname "$photon")" && pwd)/$(basename "$photon") ;; esac
[ -x "$photon" ] || die "$photon: not an executable"

[ -n "$tiles_dir" ] || tiles_dir=${out%.pfm}.tiles
mkdir -p "$tiles_dir"

# The whole image's size: given, or read from the record of a one-pixel render.
if [ -n "$size" ]; then
    width=${size%%x*} height=${size#*x}
else
    probe=$tiles_dir/size-probe.pfm
    "$photon" --no-progress --mode direct --spp 1 ${width_opt:+--width "$width_opt"} \
        ${height_opt:+--height "$height_opt"} --crop 0 0 1 1 -o "$probe" "$scene" >/dev/null ||
        die "photon could not render a pixel of $scene (see above); give --size WxH to skip this"
    size=$(sed -n 's/^image //p' "$probe.window") # "W H"
    width=${size% *} height=${size#* }
    rm -f "$probe" "${probe%.pfm}.png" "$probe.window"
fi
case $width$height in '' | *[!0-9]*) die "image size: expected WxH, not '${width}x$height'" ;; esac
if [ "$cols" -gt "$width" ] || [ "$rows" -gt "$height" ]; then
    die "TILES $tiles: more columns or rows than the ${width}x$height image has pixels"
fi

array=${only:-0-$((n - 1))}

# The tasks submitted now lose their old tiles first, so a task that fails leaves its tile
# missing (and the merge says so), never a stale one from an earlier run.
for item in $(echo "$array" | tr ',' ' '); do
    case $item in
    *-*) k=${item%-*} last=${item#*-} ;;
    *) k=$item last=$item ;;
    esac
    if [ -z "$k" ] || [ -z "$last" ] || [ "$k" -gt "$last" ] || [ "$last" -ge "$n" ]; then
        die "--only: '$item' is not a task or range of tasks 0..$((n - 1))"
    fi
    while [ "$dry_run" = 0 ] && [ "$k" -le "$last" ]; do
        rm -f "$tiles_dir/tile-$k.pfm" "$tiles_dir/tile-$k.png" "$tiles_dir/tile-$k.pfm.window"
        k=$((k + 1))
    done
done

# shellcheck disable=SC2086 # SBATCH_EXTRA is a list of options, split on purpose
set -- sbatch --parsable --job-name=photon-tiles --array="$array" --ntasks=1 --cpus-per-task=1 \
    --output="$tiles_dir/slurm-%A_%a.out" ${SBATCH_EXTRA:-} \
    "$here/slurm-tiles.sh" --run-tile "$photon" "$tiles_dir" "$cols" "$rows" "$width" "$height" \
    "$scene" "$@"
# (sbatch copies the script it is given; "$here/slurm-tiles.sh" is this file.)

if [ "$dry_run" = 1 ]; then
    printf '%s\n' "$*"
    array_job=ARRAYJOB
else
    array_job=$("$@") || die "sbatch refused the array job"
    array_job=${array_job%%;*} # --parsable prints "id" or "id;cluster"
fi

# shellcheck disable=SC2086
set -- sbatch --parsable --job-name=photon-merge --dependency="after$after:$array_job" \
    --kill-on-invalid-dep=yes --ntasks=1 --cpus-per-task=1 \
    --output="$tiles_dir/slurm-merge-%j.out" ${SBATCH_EXTRA:-} \
    "$here/slurm-tiles.sh" --run-merge "$photon" "$tiles_dir" "$cols" "$rows" "$width" "$height" "$out"
if [ "$dry_run" = 1 ]; then
    printf '%s\n' "$*"
    exit 0
fi
merge_job=$("$@") || die "sbatch refused the merge job (array job $array_job is submitted: scancel $array_job)"
merge_job=${merge_job%%;*}
echo "tiles: job $array_job, tasks $array of $n (${cols}x$rows over ${width}x$height), logs and tiles in $tiles_dir"
echo "merge: job $merge_job, after$after:$array_job, writes $out"
