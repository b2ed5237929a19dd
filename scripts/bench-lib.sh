# scripts/bench-lib.sh -- what scripts/bench_pbrt.sh and scripts/bench_cycles.sh share,
# sourced by each after it sets $dir (its folder of work files) and $bench (its name, for
# messages): timing a command by the shell's own clock, and reading photon compare's line.

# The user + system CPU seconds this shell's finished children have taken, from `times`
# (its second line), into $dir/times.$1. `times` runs in this shell: in a subshell, $(...),
# it would see only the subshell's children. User + system, as photon's clock() counts
# its --time-limit and Python's os.times() Cycles' seconds.
cpu() {
    times > "$dir/times.$1"
}
seconds() {
    awk 'NR == 2 {
            split($1, u, "m"); sub(/s$/, "", u[2]); split($2, s, "m"); sub(/s$/, "", s[2])
            printf "%.3f\n", u[1] * 60 + u[2] + s[1] * 60 + s[2]
        }' "$dir/times.$1"
}

# Runs the command, its output into the log $1; leaves its CPU seconds in $took; exits 1
# when it fails or took no time (a clock that does not count).
timed() {
    log=$1
    shift
    cpu before
    if ! "$@" < /dev/null > "$log" 2>&1; then
        echo "$bench: failed: $* (log: $log)" >&2
        tail -n 3 "$log" >&2
        exit 1
    fi
    cpu after
    took=$(awk -v a="$(seconds after)" -v b="$(seconds before)" 'BEGIN { printf "%.2f\n", a - b }')
    if ! awk -v t="$took" 'BEGIN { exit !(t > 0) }'; then
        echo "$bench: $1 took $took CPU seconds by the shell's times: cannot time it" >&2
        exit 1
    fi
}

# The value of key $1 in the compare line $2.
field() {
    echo "$2" | sed -n "s/.* $1=\([^ ]*\).*/\1/p"
}
