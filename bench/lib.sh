# Helpers for scripts/bench (sourced, not run). Timing is done by hyperfine; this file only runs it
# in interleaved rounds and turns its JSON into medians.
#
# Why rounds: the machine is shared, and its load drifts over minutes. hyperfine run once with
# `--runs 5` times all runs of A, then all runs of B, so a change of load between the two blocks
# biases the ratio. Here each round runs every command once, back to back, and the order rotates
# from round to round; the medians over rounds are then compared.

# bench_rounds NAME ROUNDS WARMUP  LABEL COMMAND PREPARE  [LABEL COMMAND PREPARE]...
#   Runs WARMUP discarded rounds, then ROUNDS recorded rounds. PREPARE runs (untimed) before each
#   run of its COMMAND; use ':' for none. Per-run times land in $BENCH_WORK/json/NAME.rK.json.
bench_rounds() {
  local name=$1 rounds=$2 warmup=$3
  shift 3
  local -a labels=() commands=() prepares=()
  while (($# >= 3)); do
    labels+=("$1")
    commands+=("$2")
    prepares+=("$3")
    shift 3
  done
  local n=${#labels[@]} r i j
  mkdir -p "$BENCH_WORK/json"
  rm -f "$BENCH_WORK/json/$name".r*.json
  for ((r = 1 - warmup; r <= rounds; r++)); do
    local -a args=()
    for ((i = 0; i < n; i++)); do
      j=$(((i + r + warmup) % n))
      args+=(--command-name "${labels[j]}" --prepare "${prepares[j]}")
    done
    for ((i = 0; i < n; i++)); do
      j=$(((i + r + warmup) % n))
      args+=("${commands[j]}")
    done
    local json="$BENCH_WORK/json/$name.r$r.json"
    ((r < 1)) && json="$BENCH_WORK/json/$name.warmup.json"
    if ! hyperfine --runs 1 --style none --export-json "$json" "${args[@]}" \
      >"$BENCH_WORK/log/$name.r$r.log" 2>&1; then
      echo "bench: $name: a command failed; see $BENCH_WORK/log/$name.r$r.log" >&2
      tail -5 "$BENCH_WORK/log/$name.r$r.log" >&2
      return 1
    fi
    printf '.' >&2
  done
  printf '\n' >&2
}

# bench_median NAME LABEL: "WALL CPU N MIN MAX": the medians (seconds) over the recorded rounds of
# NAME of the wall time and of the CPU time (user + system, all threads and children), the count,
# and the fastest and slowest wall time.
bench_median() {
  "$BENCH_PYTHON" - "$BENCH_WORK/json" "$1" "$2" <<'EOF'
import glob, json, statistics, sys
folder, name, label = sys.argv[1:]
times, cpu = [], []
for path in sorted(glob.glob(f"{folder}/{name}.r*.json")):
    for result in json.load(open(path))["results"]:
        if result["command"] == label:
            times += result["times"]
            cpu.append(result["user"] + result["system"])  # one run per round: that run's
print(f"{statistics.median(times):.6f} {statistics.median(cpu):.6f} {len(times)} "
      f"{min(times):.6f} {max(times):.6f}")
EOF
}

# bench_ratio A B: A / B to 3 significant digits.
bench_ratio() {
  "$BENCH_PYTHON" -c "import sys; a, b = map(float, sys.argv[1:]); print(f'{a / b:#.3g}')" "$1" "$2"
}

# bench_met VALUE OP LIMIT: prints "met" or "not met" (OP is <=, ≤, >= or ≥).
bench_met() {
  "$BENCH_PYTHON" -c "
import sys
v, op, limit = float(sys.argv[1]), sys.argv[2], float(sys.argv[3])
print('met' if (v <= limit if op in ('<=', '≤') else v >= limit) else 'not met')" "$1" "$2" "$3"
}

# bench_row BENCHMARK COLLIDE PEER RATIO CPU_RATIO TARGET STATUS: one row of the results table.
bench_row() {
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$@" >>"$BENCH_WORK/rows.tsv"
  printf '  %-36s %-30s %-32s %-8s %-8s %-10s %s\n' "$@" >&2
}

# bench_seconds SECONDS: "12.3 s" / "245 ms".
bench_seconds() {
  "$BENCH_PYTHON" -c "
import sys
s = float(sys.argv[1])
print(f'{s * 1000:.0f} ms' if s < 1 else f'{s:.2f} s' if s < 10 else f'{s:.1f} s')" "$1"
}
