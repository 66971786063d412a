#!/usr/bin/env bash
# The proof on the wire: for each description, a master configured only from
# its device file exchanges telegrams with firmware built only from its
# layout.
#
#   scripts/wire-test.sh [--files DIR] [--bus dp|pn] [--results FILE] DESC.toml...
#
# - PROFIBUS-DP, for a description with [profibus]: profirust's DP master,
#   configured from the GSD through gsd-parser, and the DP slave of wire/dp,
#   built from the layout, on profirust's simulated bus (no root needed).
# - PROFINET, for a description with [profinet]: the IO controller and the
#   device of wire/pn, between two network namespaces (root needed; without
#   root the script says so and exits 2).
#
# The device files are built from each description with `gsdc build`; with
# --files DIR the master reads the GSD of the same name in DIR instead (the
# file shipped last year, against today's firmware). --bus runs one bus only.
#
# --results FILE appends a line for each exchange that passed: the bus, the
# device file the master read, the SHA-256 of its bytes, how many exchanges
# passed and the stacks with their pinned versions (`gsdc doc
# --wire-results FILE` shows them on the datasheet of the description that
# gives those very files; src/wire.rs reads them).
#
# Exit 0 when every exchange passed, 1 when one failed (it prints the module,
# the byte offset and both values where it can tell), 2 on a usage or I/O
# error, or when an exchange cannot run (PROFINET without root).
#
# GSDC names a gsdc binary to use (else cargo builds one); WIRE_TARGET_DIR the
# wire workspace's target directory (else wire/target).
set -uo pipefail

usage() {
  echo "usage: $0 [--files DIR] [--bus dp|pn] [--results FILE] DESC.toml..." >&2
  exit 2
}

root="$(cd "$(dirname "$0")/.." && pwd)"
files=""
results=""
buses="dp pn"
descriptions=()
while [ $# -gt 0 ]; do
  case "$1" in
    --files) [ $# -ge 2 ] || usage; files="$2"; shift 2 ;;
    --results) [ $# -ge 2 ] || usage; results="$2"; shift 2 ;;
    --bus) [ $# -ge 2 ] || usage
           case "$2" in dp|pn) buses="$2" ;; *) usage ;; esac
           shift 2 ;;
    -h|--help) usage ;;
    -*) usage ;;
    *) descriptions+=("$1"); shift ;;
  esac
done
[ ${#descriptions[@]} -gt 0 ] || usage
if [ -n "$files" ] && [ ! -d "$files" ]; then
  echo "$0: --files $files: not a directory" >&2
  exit 2
fi

# Absolute paths: the builds run in other directories.
absolute=()
for description in "${descriptions[@]}"; do
  if [ ! -f "$description" ]; then
    echo "$0: $description: no such file" >&2
    exit 2
  fi
  absolute+=("$(cd "$(dirname "$description")" && pwd)/$(basename "$description")")
done

cargo="${CARGO:-cargo}"
gsdc="${GSDC:-}"
if [ -z "$gsdc" ]; then
  "$cargo" build --quiet --manifest-path "$root/Cargo.toml" --bin gsdc || exit 2
  gsdc="$root/target/debug/gsdc"
fi

scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT

# Each description's device files, as `gsdc build` writes them: the file
# names the master looks for, and what it reads without --files.
for i in "${!absolute[@]}"; do
  if ! "$gsdc" build "${absolute[$i]}" --out "$scratch/$i" >"$scratch/$i.log" 2>&1; then
    cat "$scratch/$i.log"
    echo "${descriptions[$i]}: gsdc build refuses the description"
    exit 1
  fi
done

# The firmware, built from the layouts of these descriptions. Those of the
# checkout (descriptions/, tests/fixtures/valid/) are all in the firmware's
# default build, which every run of them shares, so that one build serves
# them all (the test suite's runs, wire/'s own tests); any other description
# gets a build of exactly the ones given. The binary is copied out under a
# lock: another run with other descriptions rebuilds it in the same target
# directory.
export WIRE_DESCRIPTIONS=""
for description in "${absolute[@]}"; do
  case "$(dirname "$description")" in
    "$root/descriptions" | "$root/tests/fixtures/valid") ;;
    *) WIRE_DESCRIPTIONS="$(IFS=:; echo "${absolute[*]}")"; break ;;
  esac
done
export CARGO_TARGET_DIR="${WIRE_TARGET_DIR:-$root/wire/target}"
wire_dp="$scratch/wire-dp"
if [[ " $buses " == *" dp "* ]]; then
  mkdir -p "$CARGO_TARGET_DIR"
  (
    flock 9
    "$cargo" build --quiet --manifest-path "$root/wire/Cargo.toml" -p wire-dp &&
      cp "$CARGO_TARGET_DIR/debug/wire-dp" "$wire_dp"
  ) 9>"$CARGO_TARGET_DIR/.wire-test.lock" 2>"$scratch/build.log" || {
    cat "$scratch/build.log" >&2
    exit 2
  }
fi

# The device file DIR holds under the name the description gives it, or the
# one gsdc built.
device_file() { # built-file
  if [ -n "$files" ]; then
    echo "$files/$(basename "$1")"
  else
    echo "$1"
  fi
}

failed=0
unable=0

# The version wire/Cargo.lock pins a crate at.
locked() { # crate
  grep -A1 "^name = \"$1\"$" "$root/wire/Cargo.lock" | sed -n 's/^version = "\(.*\)"$/\1/p'
}

# With --results: a line for an exchange that passed, with the count its
# last line gives (`...: 33 exchanges passed, 0 failed`).
record() { # bus device-file output stack version stack version
  [ -n "$results" ] || return 0
  local passed
  passed="$(tail -n 1 "$3" | sed -n 's/.*: \([0-9][0-9]*\) \(exchanges \)\{0,1\}passed, 0 failed.*/\1/p')"
  [ -n "$passed" ] || return 0
  [ -s "$results" ] || echo "# gsdc wire results 1" >"$results"
  echo "$1 $(basename "$2") $(sha256sum <"$2" | cut -d' ' -f1) $passed $4 $5 $6 $7" >>"$results"
}

dp_exchange() { # description built-gsd
  local gsd
  gsd="$(device_file "$2")"
  if [ ! -f "$gsd" ]; then
    echo "$1: $gsd: no such file (the description's GSD is $(basename "$2"))"
    unable=1
    return
  fi
  "$wire_dp" --description "$1" --gsd "$gsd" --gsdc "$gsdc" | tee "$scratch/dp.out"
  case ${PIPESTATUS[0]} in
    0) record dp "$gsd" "$scratch/dp.out" profirust "$(locked profirust)" \
         gsd-parser "$(locked gsd-parser)" ;;
    1) failed=1 ;;
    *) unable=1 ;;
  esac
}

# The PROFINET exchange (wire/pn/exchange.sh): every module of the GSDML
# between the controller, which reads only the GSDML, and the device built
# from the layout, in network namespaces of its own. It needs root; without
# it, it says so and this script exits 2.
pn_exchange() { # description built-gsdml
  local flags=()
  [ -n "$files" ] && flags=(--files "$files")
  GSDC="$gsdc" "$root/wire/pn/exchange.sh" "${flags[@]}" "$1" | tee "$scratch/pn.out"
  case ${PIPESTATUS[0]} in
    0) record pn "$(device_file "$2")" "$scratch/pn.out" profinet-py \
         "$(sed -n 's/^pin="profinet-py==\(.*\)"$/\1/p' "$root/wire/pn/venv.sh")" \
         pnio "$(locked pnio)" ;;
    1) failed=1 ;;
    *) unable=1 ;;
  esac
}

for i in "${!absolute[@]}"; do
  for bus in $buses; do
    case "$bus" in
      dp) gsd="$(find "$scratch/$i" -maxdepth 1 -iname '*.gsd' | head -n 1)"
          if [ -n "$gsd" ]; then
            dp_exchange "${descriptions[$i]}" "$gsd"
          else
            echo "${descriptions[$i]}: no [profibus], no DP exchange"
          fi ;;
      pn) gsdml="$(find "$scratch/$i" -maxdepth 1 -name 'GSDML-*.xml' | head -n 1)"
          if [ -n "$gsdml" ]; then
            pn_exchange "${descriptions[$i]}" "$gsdml"
          else
            echo "${descriptions[$i]}: no [profinet], no PROFINET exchange"
          fi ;;
    esac
  done
done

if [ $failed -ne 0 ]; then
  exit 1
elif [ $unable -ne 0 ]; then
  exit 2
fi
exit 0
