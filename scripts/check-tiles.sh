#!/bin/sh
# scripts/check-tiles.sh -- runs the tile recipes of scripts/README.md on small renders and
# checks with cmp that every merge is the whole render's bytes: the PFM, and the display
# file beside it.
#
#   scripts/check-tiles.sh        (from the top of the repository, after make)
#
# Checked: tiles-xargs.sh (path tracing in bands; 1996 on a grid with --work), tiles.mk
# (a grid, then again after a tile is deleted; 1994 with illumination maps and WORK), GNU
# parallel on this machine and with a second login (through a stand-in for ssh that runs
# the job in another directory, so --basefile, --return and --cleanup really copy), and
# slurm-tiles.sh (through a stand-in for sbatch that runs each job at once, here: a task
# made to fail, then --only). GNU parallel's checks are skipped when it is not installed.
# Prints "ok NAME" or "FAIL NAME" a check, and exits 1 when one failed. POSIX sh, set -eu.

set -eu

top=$(pwd)
photon=$top/photon
here=$top/scripts
if [ ! -x "$photon" ] || [ ! -f "$here/tile-windows.sh" ]; then
    echo "check-tiles.sh: run it from the top of the repository, after make" >&2
    exit 2
fi
tmp=${TMPDIR:-/tmp}/check-tiles.$$
mkdir "$tmp"
trap 'rm -rf "$tmp"' EXIT
failed=0
small="--width 64 --height 64"
pt="--mode pt --spp 4 $small"

# The display file photon writes beside NAME.pfm: NAME.png, or NAME.ppm in older builds.
"$photon" --no-progress --mode direct --spp 1 --crop 0 0 1 1 -o "$tmp/probe.pfm" \
    scenes/cornell.scene
display=png
[ -f "$tmp/probe.png" ] || display=ppm

# check NAME A.pfm B.pfm: the two PFMs and their display files are the same bytes.
check() {
    if cmp "$2" "$3" && cmp "${2%.pfm}.$display" "${3%.pfm}.$display"; then
        echo "ok   $1"
    else
        echo "FAIL $1"
        failed=$((failed + 1))
    fi
}

# run COMMAND...: a recipe; when it fails, the check after it fails (its image is missing).
run() {
    "$@" || echo "check-tiles.sh: failed ($?): $*" >&2
}

# whole NAME.pfm SCENE OPTIONS: the whole render that the tiles must reproduce.
whole() {
    # shellcheck disable=SC2086 # the options are words, split on purpose
    "$photon" --no-progress $3 "$2" -o "$1"
}

# A photon that fails for one window (" --crop 0 16 ", the second of 4 bands of 64 rows).
cat >"$tmp/flaky" <<EOF
#!/bin/sh
case " \$* " in *" --crop 0 16 "*) echo "flaky photon: this tile fails" >&2; exit 1 ;; esac
exec "$photon" "\$@"
EOF
chmod +x "$tmp/flaky"

# ---- tiles-xargs.sh ----
whole "$tmp/pt.pfm" scenes/cornell.scene "$pt"
# shellcheck disable=SC2086
run "$here/tiles-xargs.sh" scenes/cornell.scene "$tmp/x.pfm" 4 $pt
check "tiles-xargs.sh, pt, 4 bands" "$tmp/x.pfm" "$tmp/pt.pfm"

o1996="--mode 1996 --spp 4 --photons 20000 --caustic-photons 5000 --gather-rays 32 $small"
whole "$tmp/1996.pfm" scenes/cornell-specular.scene "$o1996"
# shellcheck disable=SC2086
run "$here/tiles-xargs.sh" --work "$tmp/1996.work" scenes/cornell-specular.scene "$tmp/x96.pfm" 2x2 $o1996
check "tiles-xargs.sh --work, 1996, 2x2" "$tmp/x96.pfm" "$tmp/1996.pfm"

# ---- tiles.mk ----
run make -s -f "$here/tiles.mk" -j2 PHOTON="$photon" SCENE=scenes/cornell.scene OUT="$tmp/m.pfm" \
    TILES=2x2 OPTIONS="$pt"
check "tiles.mk, pt, 2x2" "$tmp/m.pfm" "$tmp/pt.pfm"
rm -f "$tmp/m.tiles/32_0_64_32".* "$tmp/m.pfm"
run make -s -f "$here/tiles.mk" -j2 PHOTON="$photon" SCENE=scenes/cornell.scene OUT="$tmp/m.pfm" \
    TILES=2x2 OPTIONS="$pt"
check "tiles.mk, a deleted tile made again" "$tmp/m.pfm" "$tmp/pt.pfm"

o1994="--mode 1994 --spp 4 --photons 20000 --gather-rays 32 --irradiance-store illumination $small"
whole "$tmp/1994.pfm" scenes/ppm-box.scene "$o1994"
run make -s -f "$here/tiles.mk" -j2 PHOTON="$photon" SCENE=scenes/ppm-box.scene OUT="$tmp/m94.pfm" \
    TILES=3 OPTIONS="$o1994" WORK="$tmp/1994.work"
check "tiles.mk WORK, 1994 illumination maps, 3 bands" "$tmp/m94.pfm" "$tmp/1994.pfm"

# ---- GNU parallel ----
if command -v parallel >/dev/null 2>&1; then
    mkdir "$tmp/here" "$tmp/there"
    cp "$photon" "$tmp/here/photon"
    mkdir "$tmp/here/scenes"
    cp scenes/cornell.scene "$tmp/here/scenes/"
    # A stand-in for ssh: drops ssh's options, the host and "--", and runs the command in
    # "there", as ssh runs it in the second host's home.
    cat >"$tmp/ssh" <<EOF
#!/bin/sh
while [ \$# -gt 0 ]; do case \$1 in -*) shift ;; *) break ;; esac; done
shift
[ "\${1:-}" != -- ] || shift
cd "$tmp/there" && exec sh -c "\$*"
EOF
    chmod +x "$tmp/ssh"
    (
        cd "$tmp/here"
        # shellcheck disable=SC2086 # the options are words, split on purpose
        "$here/tile-windows.sh" scenes/cornell.scene 2x2 $small >windows.txt
        render="./photon --no-progress $pt scenes/cornell.scene"
        mkdir -p tiles
        parallel -j 2 --colsep ' ' "$render --crop {1} {2} {3} {4} -o tiles/x{1}y{2}.pfm" \
            :::: windows.txt
        ./photon merge -o local.pfm tiles/*.pfm
        rm -rf tiles
        parallel --ssh "$tmp/ssh" --sshlogin 1/:,1/there --basefile photon \
            --basefile scenes/cornell.scene --return 'tiles/x{1}y{2}.pfm' \
            --return 'tiles/x{1}y{2}.pfm.window' --return "tiles/x{1}y{2}.$display" \
            --cleanup --colsep ' ' --joblog joblog \
            "mkdir -p tiles && $render --crop {1} {2} {3} {4} -o tiles/x{1}y{2}.pfm" \
            :::: windows.txt
        ./photon merge -o remote.pfm tiles/*.pfm
    ) || echo "check-tiles.sh: a GNU parallel recipe failed" >&2
    check "GNU parallel -j 2, pt, 2x2" "$tmp/here/local.pfm" "$tmp/pt.pfm"
    check "GNU parallel --sshlogin 1/:,1/there, pt, 2x2" "$tmp/here/remote.pfm" "$tmp/pt.pfm"
    if ! grep -q '	there	' "$tmp/here/joblog" || [ -n "$(ls -A "$tmp/there")" ]; then
        echo "FAIL GNU parallel: no tile made by the second login, or files left there"
        failed=$((failed + 1))
    fi
else
    echo "skip GNU parallel (not installed)"
fi

# ---- slurm-tiles.sh ----
mkdir "$tmp/bin"
echo 0 >"$tmp/bin/last-job"
# A stand-in for sbatch: runs the job at once, on this host, an array's tasks one after
# another, each with Slurm's variables and its --output log; prints the job's number.
cat >"$tmp/bin/sbatch" <<EOF
#!/bin/sh
job=\$((\$(cat "$tmp/bin/last-job") + 1))
echo "\$job" >"$tmp/bin/last-job"
array="" output=""
while [ \$# -gt 0 ]; do
    case \$1 in --array=*) array=\${1#*=} ;; --output=*) output=\${1#*=} ;; --*) ;; *) break ;; esac
    shift
done
if [ -z "\$array" ]; then
    SLURM_JOB_ID=\$job sh "\$@" >"\$(echo "\$output" | sed "s/%j/\$job/")" 2>&1 || true
fi
for item in \$(echo "\$array" | tr , ' '); do
    k=\${item%-*}
    while [ "\$k" -le "\${item#*-}" ]; do
        SLURM_ARRAY_JOB_ID=\$job SLURM_ARRAY_TASK_ID=\$k sh "\$@" \
            >"\$(echo "\$output" | sed "s/%A/\$job/; s/%a/\$k/")" 2>&1 || true
        k=\$((k + 1))
    done
done
echo "\$job"
EOF
chmod +x "$tmp/bin/sbatch"
# shellcheck disable=SC2086
run env PATH="$tmp/bin:$PATH" "$here/slurm-tiles.sh" --photon "$tmp/flaky" scenes/cornell.scene \
    "$tmp/s.pfm" 4 $pt >/dev/null
if [ -f "$tmp/s.pfm" ] || [ -f "$tmp/s.tiles/tile-1.pfm" ]; then
    echo "FAIL slurm-tiles.sh: a failed task left a tile or the merge an image"
    failed=$((failed + 1))
fi
# shellcheck disable=SC2086
run env PATH="$tmp/bin:$PATH" "$here/slurm-tiles.sh" --only 1 --photon "$photon" scenes/cornell.scene \
    "$tmp/s.pfm" 4 $pt >/dev/null
check "slurm-tiles.sh, pt, 4 bands, task 1 failed then --only 1" "$tmp/s.pfm" "$tmp/pt.pfm"

[ "$failed" = 0 ] || {
    echo "check-tiles.sh: $failed check(s) failed"
    exit 1
}
