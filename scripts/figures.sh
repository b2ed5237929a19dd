#!/bin/sh
# scripts/figures.sh [presets] [bench] [tts] [rays] [pbrt] [cycles] -- re-measures the figures
# README.md (and, for bench, rays, pbrt and cycles, tests/bench/README.md) states
# and writes them in, between the lines <!-- figures:NAME --> and <!-- /figures:NAME -->.
# Run by `make figures` (ONLY=presets, bench, tts, rays, pbrt or cycles for one part) from the
# top of the repository, after ./photon and build/bench are built.
#
#   presets  scripts/presets.sh: every mode's presets on both Cornell boxes against the
#            references (about 15 minutes of CPU; two renders run at once)
#   bench    `make bench ONLY=tte`, time to error, into tests/bench/README.md: one row a
#            photon mode and scene, its CPU seconds, its relmse, pt's CPU seconds to that
#            relmse and their ratio; and where each mode's seconds went (about half an hour of
#            CPU; PHOTON_TTE_TRIAL=1 tries the pipeline in a minute, on figures that mean
#            nothing, and says so in the table)
#   tts      `make bench ONLY=tts`, time to a stated error: one row a scene, the CPU seconds
#            pt, 2008 and 2009 take to --target-error 0.02 (TTS_LIMIT each at most, default
#            120) and what the image's worst block was then (about half an hour of CPU)
#   rays     `make bench-embree`, photon's ray casting beside Embree 3's on the rays
#            workload, into tests/bench/README.md (needs Embree and SPD=DIR, the folder of
#            the SPD files; a few minutes; not part of the default parts)
#   pbrt     `make bench-pbrt`, --mode 2009 beside pbrt-v4's SPPM at equal CPU seconds on
#            both Cornell boxes, into tests/bench/README.md (needs PBRT=PATH, pbrt-v4's
#            pbrt; about 6 minutes of CPU; not part of the default parts)
#   cycles   `make bench-cycles`, --mode pt beside Blender's Cycles at equal CPU seconds on
#            both Cornell boxes at a few sample counts, into tests/bench/README.md (needs
#            Blender 3.4+, BLENDER=PATH where it is not `blender`; CYCLES_SPP="N ..." for
#            other counts; about 4 minutes of CPU; not part of the default parts)
#
# Each part prints how long it took. Nothing in README.md changes unless the part succeeded.
set -eu
cd "$(dirname "$0")/.."
parts=${*:-presets bench tts}
mkdir -p build

# Replaces the block NAME of the file DOC (README.md unless given) by the lines of FILE,
# stamped with the date of the run.
splice() {
    doc=${3:-README.md}
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
        !skip { print }' "$doc" > "$doc.tmp"
    mv "$doc.tmp" "$doc"
}

# The tte workload's tte.MODE.SCENE.KEY=VALUE lines (tests/bench/README.md) as a table: one
# row a mode and scene, in the order printed; pt's seconds say when they were extrapolated,
# and when pt's fit never reaches the mode's relmse they and the ratio are lower bounds.
tte_table() {
    echo "| scene | mode | CPU s | relmse | pt: CPU s to that relmse | ratio (pt s / mode s) | peak MB |"
    echo "|---|---|---|---|---|---|---|"
    awk -F= '/^tte\.[^.]+\.[^.]+\.[a-z_]+=/ {
            split($1, part, ".")
            if (part[2] == "pt") next
            row = part[3] " | " part[2]
            if (!(row in seen)) { seen[row] = 1; order[++n] = row }
            value[row, part[4]] = $2
        }
        END {
            for (i = 1; i <= n; i++) {
                r = order[i]
                pt = value[r, "pt_seconds"]
                ratio = value[r, "ratio"]
                if (value[r, "extrapolated"] == 1) pt = pt " (extrapolated)"
                if (value[r, "extrapolated"] == "unreachable") {
                    pt = "never by the fit; more than " pt
                    ratio = "at least " ratio
                }
                print "| " r " | " value[r, "seconds"] " | " value[r, "relmse"] " | " pt \
                    " | " ratio " | " sprintf("%.1f", value[r, "bytes_peak"] / 1e6) " |"
            }
            exit n == 0
        }' "$1"
}

# Where each mode's seconds went: its tte.MODE.SCENE.seconds_PHASE lines (the --stats keys of
# its phases), one row a mode and scene.
phase_table() {
    echo "| scene | mode | where the CPU seconds went (\`--stats\` keys) |"
    echo "|---|---|---|"
    awk -F= '/^tte\.[^.]+\.[^.]+\.seconds_[a-z_]+=/ {
            split($1, part, ".")
            row = part[3] " | " part[2]
            if (!(row in seen)) { seen[row] = 1; order[++n] = row }
            text[row] = text[row] (text[row] == "" ? "" : ", ") "`" part[4] "` " $2
        }
        END { for (i = 1; i <= n; i++) print "| " order[i] " | " text[order[i]] " |" }' "$1"
}

# The tts workload's tts.MODE.SCENE.KEY=VALUE lines (tests/bench/README.md) as a table: one
# row a scene, in the order printed, a cell a mode: its CPU seconds and work when every
# block reached the target, else the blocks that had when the time limit stopped it; and
# the worst block's error against the reference, what the statement was worth.
tts_table() {
    echo "| scene | pt | 2008 | 2009 |"
    echo "|---|---|---|---|"
    awk -F= '/^tts\.[^.]+\.[^.]+\.[a-z_]+=/ {
            split($1, part, ".")
            if (!(part[3] in seen)) { seen[part[3]] = 1; order[++n] = part[3] }
            value[part[3], part[2], part[4]] = $2
        }
        function cell(s, m,    unit) {
            if (value[s, m, "refused"] == 1) return "states no bound"
            if (value[s, m, "seconds"] == "") return "not run"
            unit = m == "pt" ? " samples" : " passes"
            if (value[s, m, "reached"] == 1)
                return sprintf("%.0f s, %s%s; worst block %.1f%%", value[s, m, "seconds"],
                               value[s, m, "work"], unit, 100 * value[s, m, "worst_block"])
            return sprintf("stopped at %.0f s with %s of %s blocks; worst %.1f%%",
                           value[s, m, "seconds"], value[s, m, "blocks_within"],
                           value[s, m, "blocks"], 100 * value[s, m, "worst_block"])
        }
        END {
            for (i = 1; i <= n; i++)
                print "| " order[i] " | " cell(order[i], "pt") " | " cell(order[i], "2008") \
                    " | " cell(order[i], "2009") " |"
            exit n == 0
        }' "$1"
}

# bench-embree's embree.SCENE.KEY=VALUE lines as a table: a row a scene and ray set, photon's
# and Embree's Mrays/s (defaults and robust), the ratios, and the memory of each side.
rays_table() {
    echo "| scene | rays | photon Mrays/s | Embree Mrays/s | ratio | robust Embree Mrays/s | ratio to robust | photon MB (bytes a primitive) | Embree MB |"
    echo "|---|---|---|---|---|---|---|---|---|"
    awk -F= '/^embree\.[^.]+\.[a-z_]+=/ {
            split($1, part, ".")
            if (!(part[2] in seen)) { seen[part[2]] = 1; order[++n] = part[2] }
            value[part[2], part[3]] = $2
        }
        END {
            for (i = 1; i <= n; i++) {
                s = order[i]
                for (k = 0; k < 3; k++) {
                    set = k == 0 ? "primary" : k == 1 ? "secondary" : "shuffled"
                    mem = k == 0 ? sprintf("%.1f (%.1f)", value[s, "photon_bytes"] / 1e6,
                                           value[s, "photon_bytes"] / value[s, "primitives"]) : ""
                    emem = k == 0 ? sprintf("%.1f", value[s, "embree_bytes"] / 1e6) : ""
                    print "| " s " | " set " | " value[s, "photon_" set "_mrays"] " | " \
                        value[s, "embree_" set "_mrays"] " | " value[s, set "_ratio"] " | " \
                        value[s, "embree_robust_" set "_mrays"] " | " \
                        value[s, set "_ratio_robust"] " | " mem " | " emem " |"
                }
            }
            exit n == 0
        }' "$1"
}

# bench-pbrt's pbrt.SCENE.KEY=VALUE lines as a table: a row a scene, photon's figures and
# pbrt's, and the ratio of their errors.
pbrt_table() {
    echo "| scene | 2009: CPU s | 2009: relmse | 2009: worst 16 × 16 block (at) | pbrt SPPM: CPU s (3 channels) | iterations | radius | pbrt: relmse | pbrt: worst 16 × 16 block (at) | relmse ratio (pbrt / 2009) |"
    echo "|---|---|---|---|---|---|---|---|---|---|"
    awk -F= '/^pbrt\.[^.]+\.[a-z_]+=/ {
            split($1, part, ".")
            if (!(part[2] in seen)) { seen[part[2]] = 1; order[++n] = part[2] }
            value[part[2], part[3]] = $2
        }
        END {
            for (i = 1; i <= n; i++) {
                s = order[i]
                printf "| %s | %s | %s | %.2f%% (%s) | %s | %s | %s | %s | %.2f%% (%s) | %s |\n", s,
                    value[s, "photon_seconds"], value[s, "photon_relmse"],
                    100 * value[s, "photon_worst_block"], value[s, "photon_worst_block_at"],
                    value[s, "pbrt_seconds"], value[s, "pbrt_iterations"], value[s, "radius"],
                    value[s, "pbrt_relmse"], 100 * value[s, "pbrt_worst_block"],
                    value[s, "pbrt_worst_block_at"], value[s, "ratio"]
            }
            exit n == 0
        }' "$1"
}

# bench-cycles' cycles.SCENE.N.KEY=VALUE lines as a table: a row a scene and Cycles' sample
# count N, in the order printed, each renderer's figures and the ratio of the errors, raw
# and with the reference's own noise (cycles.SCENE.reference_noise) taken from both.
cycles_table() {
    echo "| scene | Cycles: samples | Cycles: CPU s | Cycles: relmse | Cycles: worst 16 × 16 block (at) | pt: CPU s | pt: samples | pt: relmse | pt: worst 16 × 16 block (at) | relmse ratio (pt / Cycles) | less the reference's noise |"
    echo "|---|---|---|---|---|---|---|---|---|---|---|"
    awk '/^cycles\.[^.=]+\.[0-9]+\.[a-z_]+=/ {
            i = index($0, "=")
            split(substr($0, 1, i - 1), part, ".")
            row = part[2] SUBSEP part[3]
            if (!(row in seen)) { seen[row] = 1; order[++n] = row }
            value[row, part[4]] = substr($0, i + 1)
        }
        END {
            for (k = 1; k <= n; k++) {
                r = order[k]
                split(r, sn, SUBSEP)
                printf "| %s | %s | %s | %s | %.2f%% (%s) | %s | %d | %s | %.2f%% (%s) | %s | %s |\n",
                    sn[1], sn[2], value[r, "cycles_seconds"], value[r, "cycles_relmse"],
                    100 * value[r, "cycles_worst_block"], value[r, "cycles_worst_block_at"],
                    value[r, "pt_seconds"], value[r, "pt_spp"], value[r, "pt_relmse"],
                    100 * value[r, "pt_worst_block"], value[r, "pt_worst_block_at"],
                    value[r, "ratio"], value[r, "ratio_net"]
            }
            exit n == 0
        }' "$1"
}

# The words under bench-cycles' table: the version, how the seconds were taken, each
# reference's noise and what the export approximates.
cycles_notes() {
    version=$(sed -n 's/^cycles\.version=//p' "$1")
    noise=$(sed -n 's/^cycles\.\([^.]*\)\.reference_noise=\(.*\)/\2 (\1)/p' "$1" |
        awk '{ s = s (NR > 1 ? ", " : "") $0 } END { print s }')
    echo "Blender $version's Cycles (\`blender -b -t 1\`, the scene of \`photon export" \
        "--format blender\`, as \`make crosscheck\` renders it) and photon's pt, one thread" \
        "each; seconds are user + system CPU seconds, Cycles' from its render_pre to its" \
        "render_post handler (scene sync, BVH and samples; not Blender's start-up), pt's" \
        "those of its whole run with \`--time-limit\` at Cycles' seconds. Both against" \
        "\`reference/SCENE-pt.pfm\`, whose own noise adds about $noise to every relmse;" \
        "the last column takes it from both."
    sed -n 's/^cycles\.\([^.]*\)\.approximated=\(.*\)/\1 \2/p' "$1" | while read -r scene what; do
        [ "$what" = - ] || echo "In $scene the export says: $what."
    done
}

for part in $parts; do
    start=$(date +%s)
    case $part in
    presets)
        sh scripts/presets.sh ./photon build/figures-presets.md
        splice presets build/figures-presets.md
        ;;
    bench)
        make --no-print-directory bench ONLY=tte > build/figures-bench.txt
        tte_table build/figures-bench.txt > build/figures-bench.md
        phase_table build/figures-bench.txt > build/figures-phases.md
        if [ -n "${PHOTON_TTE_TRIAL:-}" ]; then
            printf '\nA trial run (PHOTON_TTE_TRIAL): these figures mean nothing.\n' \
                >> build/figures-bench.md
        fi
        splice bench build/figures-bench.md tests/bench/README.md
        splice phases build/figures-phases.md tests/bench/README.md
        ;;
    tts)
        make --no-print-directory bench ONLY=tts > build/figures-tts.txt
        tts_table build/figures-tts.txt > build/figures-tts.md
        echo "" >> build/figures-tts.md
        echo "Seed 1, one core; a render stops at ${TTS_LIMIT:-120} CPU seconds (at least 16" \
            "passes for 2008 and 2009). The worst block is against the scene's reference" \
            "(\`photon compare --block 16\`)." >> build/figures-tts.md
        splice tts build/figures-tts.md
        ;;
    rays)
        make --no-print-directory bench-embree SPD="${SPD:-}" > build/figures-rays.txt
        rays_table build/figures-rays.txt > build/figures-rays.md
        agreed=$(grep -c 'checksums_agree=1' build/figures-rays.txt || true)
        scenes=$(grep -c 'checksums_agree=' build/figures-rays.txt || true)
        version=$(sed -n 's/^embree\.version=//p' build/figures-rays.txt)
        echo "" >> build/figures-rays.md
        echo "Embree $version, one thread, beside photon in the same run; robust Embree's" \
            "checksums agree with photon's on $agreed of $scenes scenes." >> build/figures-rays.md
        splice rays build/figures-rays.md tests/bench/README.md
        ;;
    pbrt)
        # ONLY= : the ONLY=pbrt of `make figures` reaches this make too, and names no scene
        make --no-print-directory bench-pbrt PBRT="${PBRT:-}" ONLY= > build/figures-pbrt.txt
        pbrt_table build/figures-pbrt.txt > build/figures-pbrt.md
        settings=$(sed -n 's/^pbrt\.settings=//p' build/figures-pbrt.txt)
        echo "" >> build/figures-pbrt.md
        echo "One thread each; pbrt-v4's \`Integrator \"sppm\" $settings\` and the radius" \
            "(\`float radius\`, mm) of the table; seconds are user + system CPU seconds," \
            "pbrt's the sum of its three channels' renders." >> build/figures-pbrt.md
        splice pbrt build/figures-pbrt.md tests/bench/README.md
        ;;
    cycles)
        # ONLY= : as for pbrt, the ONLY=cycles of `make figures` would reach this make too
        make --no-print-directory bench-cycles BLENDER="${BLENDER:-blender}" ONLY= \
            > build/figures-cycles.txt
        cycles_table build/figures-cycles.txt > build/figures-cycles.md
        echo "" >> build/figures-cycles.md
        cycles_notes build/figures-cycles.txt >> build/figures-cycles.md
        splice cycles build/figures-cycles.md tests/bench/README.md
        ;;
    *)
        echo "figures: unknown part '$part' (presets, bench, tts, rays, pbrt, cycles)" >&2
        exit 2
        ;;
    esac
    echo "figures: $part written in $(($(date +%s) - start)) s"
done
