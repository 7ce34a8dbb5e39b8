# Shared by scripts/run-icarus.sh and scripts/run-verilator.sh (sourced, not run).
# Parses:  <unit_file.v> <vectors.hex> [--latency N] [--name UNIT] [--top MODULE]
#          [--fields "a b y"] [--preload "en addr data"] [--trace] [--out DIR] [--extra FILE.v]... [+plusarg]...
# and runs scripts/verilog/prepare.py into $OUT. Sets UNIT, OUT, TRACE, EXTRA[], PLUSARGS[].

ROOT=$(cd "$SCRIPTS/.." && pwd)
PY=${PYTHON:-python3}

usage() {
  sed -n '2,/^$/p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
}

need() {
  command -v "$1" >/dev/null || { echo "$(basename "$0"): $1 not found (apt-get install -y $2)" >&2; exit 127; }
}

parse_args() {
  [ $# -ge 2 ] || usage
  UNIT_FILE=$1 VECTORS=$2; shift 2
  [ -f "$UNIT_FILE" ] || { echo "$(basename "$0"): no such file: $UNIT_FILE" >&2; exit 2; }
  [ -f "$VECTORS" ] || { echo "$(basename "$0"): no such file: $VECTORS" >&2; exit 2; }
  UNIT=$(basename "$UNIT_FILE" .v) OUT="" TRACE=0 EXTRA=() PLUSARGS=() PREP=()
  while [ $# -gt 0 ]; do
    case $1 in
      --latency|--top|--fields|--preload|--clock|--in-valid|--out-valid) PREP+=("$1" "$2"); shift 2 ;;
      --name) UNIT=$2; shift 2 ;;
      --out) OUT=$2; shift 2 ;;
      --extra) EXTRA+=("$2"); shift 2 ;;
      --trace) TRACE=1; shift ;;
      +*) PLUSARGS+=("$1"); shift ;;
      -h|--help) usage ;;
      *) echo "$(basename "$0"): unknown argument: $1" >&2; usage ;;
    esac
  done
  OUT=${OUT:-$ROOT/target/verilog/$SIM/$UNIT}
  mkdir -p "$OUT"
  OUT=$(cd "$OUT" && pwd)
  "$PY" "$SCRIPTS/verilog/prepare.py" "$UNIT_FILE" "$VECTORS" --out "$OUT" --name "$UNIT" --sim "$SIM" "${PREP[@]}"
}

# Runs the simulation command "$@", tees its output to $OUT/sim.log, and exits like CI wants:
# 0 only if the `N passed, M failed` line is there with M = 0 and N > 0.
check_run() {
  set +e
  "$@" 2>&1 | tee "$OUT/sim.log"
  local rc=${PIPESTATUS[0]}
  set -e
  local line
  line=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$OUT/sim.log" | tail -n 1)
  if [ -z "$line" ]; then
    echo "$(basename "$0"): $UNIT: no 'N passed, M failed' line (simulator exit $rc)" >&2
    exit 1
  fi
  local passed=${line%% passed*} failed=${line#*, }; failed=${failed%% failed}
  if [ "$failed" != 0 ] || [ "$passed" = 0 ] || [ "$rc" != 0 ]; then
    echo "$(basename "$0"): $UNIT: FAIL ($line, simulator exit $rc)" >&2
    exit 1
  fi
  if [ "$TRACE" = 1 ]; then
    echo "$(basename "$0"): $UNIT: VCD $OUT/$UNIT.vcd; view: gtkwave $OUT/$UNIT.vcd $OUT/$UNIT.gtkw" >&2
  fi
}
