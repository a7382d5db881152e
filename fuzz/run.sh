#!/usr/bin/env bash
# Coverage-guided fuzzing of the blossom CLI and library (cargo-fuzz, libFuzzer, stable toolchain).
#
#   fuzz/run.sh TARGET SECONDS    one of job_entry, number_reader, restrict_shapes
#   fuzz/run.sh all SECONDS       each target in turn, SECONDS each
#
# Installs cargo-fuzz when missing, then runs the target for SECONDS with its dictionary,
# starting from the committed seeds of corpus/TARGET (read only) and writing what it finds
# to work-corpus/TARGET (git-ignored); a crash is written to artifacts/TARGET/. Prints the
# number of executions. Minimise the work corpus into new seeds with
#   RUSTC_BOOTSTRAP=1 cargo fuzz cmin TARGET -s none work-corpus/TARGET
# (and a crash with `cargo fuzz tmin TARGET -s none artifacts/TARGET/crash-...`).
# FUZZ_FEATURES=carried-grid also fuzzes `--method specialised` (a much longer build).
#
# restrict_shapes is built with --no-trace-compares, in target/untraced (so that the two
# builds do not rebuild each other): the comparison tracing of num-bigint's gcd loops took
# about 70% of its time (perf), and its input is decoded by `%`, which the tracing cannot
# steer. With that and the exact degree caps of cli/src/fuzzing.rs it runs about 900
# inputs/s on one core when alone (521/s averaged over the run below, with builds beside
# it), against 35/s before.
#
# Measured (one core of this 2-core machine, one target at a time, -timeout=10):
#   job_entry        10^6 inputs in 70 s (14,492/s), no crash, timeout or unit over 1 s
#   number_reader    10^6 inputs in 106 s (9,433/s), no crash, timeout or unit over 1 s
#   restrict_shapes  10^6 inputs in 1,918 s (521/s), no crash, timeout or unit over 1 s
# (the binaries run with -runs=1000000 -timeout=10 -report_slow_units=1 and the dictionary).
# e.g. `fuzz/run.sh restrict_shapes 1200` for 10^6 inputs of restrict_shapes.
set -euo pipefail
cd "$(dirname "$0")"

usage() { echo "usage: $0 job_entry|number_reader|restrict_shapes|all SECONDS" >&2; exit 2; }
[ $# -eq 2 ] || usage
target=$1
seconds=$2
case "$seconds" in '' | *[!0-9]*) usage ;; esac

if ! cargo fuzz --version >/dev/null 2>&1; then
    cargo install cargo-fuzz --locked
fi

dictionary() {
    case "$1" in
        job_entry) echo dict/job.dict ;;
        number_reader) echo dict/number.dict ;;
        restrict_shapes) echo "" ;;
        *) usage ;;
    esac
}

run_one() {
    local name=$1 dict log
    dict=$(dictionary "$name")
    mkdir -p "work-corpus/$name" "artifacts/$name"
    log="artifacts/$name/run.log"
    local features=()
    if [ -n "${FUZZ_FEATURES:-}" ]; then features=(--features "$FUZZ_FEATURES"); fi
    local args=(-max_total_time="$seconds" -print_final_stats=1 -timeout=10 -rss_limit_mb=2048
        -report_slow_units=1)
    local build=()
    if [ "$name" = restrict_shapes ]; then build=(--no-trace-compares --target-dir target/untraced); fi
    if [ -n "$dict" ]; then args+=(-dict="$dict"); fi
    echo "== $name: $seconds s" >&2
    local status=0
    RUSTC_BOOTSTRAP=1 cargo fuzz run "$name" -s none "${build[@]}" "${features[@]}" \
        "work-corpus/$name" "corpus/$name" -- "${args[@]}" 2>&1 | tee "$log" >&2 || status=$?
    local execs
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
    echo "$name: ${execs:-?} executions in $seconds s (exit $status; log $log)"
    return "$status"
}

if [ "$target" = all ]; then
    failed=0
    for name in job_entry number_reader restrict_shapes; do
        run_one "$name" || failed=1
    done
    exit "$failed"
else
    dictionary "$target" >/dev/null
    run_one "$target"
fi
