#!/bin/sh
# scripts/figures.sh [presets] [bench] -- re-measures the figures README.md states and writes
# them into it, between the lines <!-- figures:NAME --> and <!-- /figures:NAME -->. Run by
# `make figures` (ONLY=presets or ONLY=bench for one part) from the top of the repository,
# after ./photon and build/bench are built.
#
#   presets  scripts/presets.sh: every mode's presets on both Cornell boxes against the
#            references (about 15 minutes of CPU; two renders run at once)
#   bench    make bench's name=value lines, one row a workload: those named in WORKLOADS
#            (default all: rays knn shapes photons ppm tte tiles; tte, time to error,
#            takes the longest), SPD=DIR for the SPD scenes
#
# Each part prints how long it took. Nothing in README.md changes unless the part succeeded.
set -eu
cd "$(dirname "$0")/.."
parts=${*:-presets bench}
mkdir -p build

# Replaces README.md's block NAME by the lines of FILE, stamped with the date of the run.
splice() {
    awk -v name="$1" -v file="$2" -v day="$(date +%Y-%m-%d)" '
        $0 == "<!-- figures:" name " -->" {
            print
            print ""
            print "Measured on " day " by `make figures`."
            print ""
            while ((getline line < file) > 0) print line
            print ""
            skip = 1
            next
        }
        $0 == "<!-- /figures:" name " -->" { skip = 0 }
        !skip { print }' README.md > README.md.tmp
    mv README.md.tmp README.md
}

# make bench's name=value lines as a table: one row a workload (the key's first word).
bench_table() {
    echo "| workload | figures (name=value, medians of 3 runs, CPU seconds, one thread) |"
    echo "|---|---|"
    awk -F= '/^[a-z0-9_]+\.[^=]*=/ {
            split($1, part, ".")
            w = part[1]
            if (!(w in row)) order[++n] = w
            key = substr($1, length(w) + 2)
            row[w] = row[w] (row[w] == "" ? "" : ", ") "`" key "` " $2
        }
        END { for (i = 1; i <= n; i++) print "| " order[i] " | " row[order[i]] " |" }' "$1"
}

for part in $parts; do
    start=$(date +%s)
    case $part in
    presets)
        sh scripts/presets.sh ./photon build/figures-presets.md
        splice presets build/figures-presets.md
        ;;
    bench)
        : > build/figures-bench.txt
        for workload in ${WORKLOADS:-rays knn shapes photons ppm tte tiles}; do
            make --no-print-directory bench ONLY="$workload" ${SPD:+SPD="$SPD"} \
                >> build/figures-bench.txt
        done
        bench_table build/figures-bench.txt > build/figures-bench.md
        splice bench build/figures-bench.md
        ;;
    *)
        echo "figures: unknown part '$part' (presets, bench)" >&2
        exit 2
        ;;
    esac
    echo "figures: $part written into README.md in $(($(date +%s) - start)) s"
done
