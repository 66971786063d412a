#!/usr/bin/env bash
# The PROFINET exchange of one description: every module of its GSDML in its
# slot, then the negative cases, then each device access point after the
# first with its first module, each between two network namespaces of its
# own (netns-exchange.sh). The device is built from the description's layout
# (wire/pn; the firmware holds the layouts WIRE_DESCRIPTIONS names, by
# default every shipped description and valid fixture); the controller reads
# only the GSDML: the one gsdc builds from the description, or with --files
# DIR the one of that name in DIR (a released file). scripts/wire-test.sh
# runs it for every description with [profinet].
#
# GSDC names a gsdc binary (else cargo builds one); CARGO_TARGET_DIR the wire
# workspace's target directory (else wire/target); CARGO the cargo to run.
#
#   wire/pn/exchange.sh [--files DIR] DESC.toml
#
# Exit status: 0 every exchange passed, 1 one failed, 2 it could not run
# (not root, no iproute2 or Python, a build that failed). Needs root: the
# namespaces. The Python venv with profinet-py lives in target/wire-venv.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
here="$root/wire/pn"

files=""
if [ "${1:-}" = "--files" ]; then
  files=${2:?--files needs a directory}
  shift 2
fi
[ $# -eq 1 ] || { echo "usage: $0 [--files DIR] DESC.toml" >&2; exit 2; }
description=$(realpath "$1")
name=$(basename "$description" .toml)

if [ "$(id -u)" -ne 0 ]; then
  echo "PROFINET exchange of $name: needs root (network namespaces and raw sockets); not run" >&2
  exit 2
fi
command -v ip >/dev/null || { echo "PROFINET exchange: iproute2 (ip) is not installed" >&2; exit 2; }

# Built here, once per run: the controller's venv, pinned, then the device
# for this description and the description's own files.
python=$("$here/venv.sh")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# GSDC: the gsdc binary to build the files with (the test suite passes its
# own); by default cargo builds it.
gsdc_build() {
  if [ -n "${GSDC:-}" ]; then
    "$GSDC" build "$@"
  else
    (cd "$root" && cargo run --quiet --release -- build "$@")
  fi
}
gsdc_build "$description" --out "$work/built" >/dev/null 2>"$work/build.err" || {
  cat "$work/build.err" >&2
  echo "PROFINET exchange of $name: gsdc build failed" >&2
  exit 2
}
gsdml=$(ls "$work"/built/GSDML-*.xml 2>/dev/null | head -1)
[ -n "$gsdml" ] || { echo "$description has no [profinet]: no PROFINET exchange" >&2; exit 2; }
if [ -n "$files" ]; then
  gsdml="$files/$(basename "$gsdml")"
  [ -f "$gsdml" ] || { echo "PROFINET exchange of $name: $gsdml does not exist" >&2; exit 2; }
fi
# The device, built from the layouts WIRE_DESCRIPTIONS names and copied out
# under the lock scripts/wire-test.sh takes: another run with other
# descriptions rebuilds it in the same target directory.
target="${CARGO_TARGET_DIR:-$root/wire/target}"
mkdir -p "$target"
(
  flock 9
  CARGO_TARGET_DIR="$target" "${CARGO:-cargo}" build --quiet --manifest-path "$root/wire/Cargo.toml" -p wire-pn &&
    cp "$target/debug/pn-device" "$work/pn-device"
) 9>"$target/.wire-test.lock" 2>"$work/device.err" || {
  cat "$work/device.err" >&2
  echo "PROFINET exchange of $name: the device did not build" >&2
  exit 2
}
device="$work/pn-device"
scenario="$here/scenarios/$name.json"
[ -f "$scenario" ] || scenario=-

echo "PROFINET exchange of $name: controller profinet-py 0.6.6 reads $(basename "$gsdml"), device pnio 0.1.0 runs the layout"
echo "  not checked by the stacks: pnio has no API in its model (the device checks each Connect's APIs"
echo "  against the layout itself) and acknowledges every record (the layout decodes each, and the"
echo "  controller compares); pnio cannot refuse a record, so the layout's refusal is reported, not sent"
[ "$scenario" = - ] && echo "  (no scenario of the manual for $name: records and data only)"
station=""
daps=1
# The modules DAP $1 offers, into `modules`; the name of station, how
# many DAPs the GSDML has, and the first DAP of DAP $1's ident number into
# `station`, `daps` and `presented_by`. Exit 2 (could not run)
# when the controller cannot list them, or the DAP offers none.
list_modules() { # DAP
  local listing
  listing=$("$python" "$here/controller/pn_controller.py" --gsdml "$gsdml" --list-modules --dap "$1") || {
    echo "PROFINET exchange of $name: the controller could not list device access point $1's modules" >&2
    exit 2
  }
  modules=()
  while read -r kind a b c d e f; do
    case "$kind" in
      daps) daps=$a ;;
      presented_by) presented_by=$a ;;
      station) station=$a ;;
      module) modules+=("$a $b $c $d $e $f") ;;
    esac
  done <<<"$listing"
  if [ ${#modules[@]} -eq 0 ]; then
    echo "PROFINET exchange of $name: device access point $1 offers no module" >&2
    exit 2
  fi
}
list_modules 1

passed=0 failed=0 unrun=0
run_case() {
  local label=$1
  shift
  local status=0
  echo "--- $label"
  "$here/netns-exchange.sh" "$device" "$python" "$name" "$gsdml" "$station" "$@" || status=$?
  case "$status" in
    0) passed=$((passed + 1)) ;;
    1) failed=$((failed + 1)) ;;
    *) unrun=$((unrun + 1)) ;;
  esac
}

for entry in "${modules[@]}"; do
  read -r module slot last api data module_name <<<"$entry"
  run_case "$module ($module_name) in slot $slot" "$slot" "$module" "$module_name" "$scenario"
done
# Where the modules may go into more than one slot, each its own telegram:
# the first module with data in its first slot and the last in its last,
# at the same time.
first_with_data=""
for entry in "${modules[@]}"; do
  read -r module slot last api data module_name <<<"$entry"
  [ "$data" -eq 1 ] && { [ -n "$first_with_data" ] || first_with_data=$entry; last_with_data=$entry; }
done
read -r module slot last api data module_name <<<"$first_with_data"
read -r other _ other_last _ _ other_name <<<"$last_with_data"
if [ "$other_last" -gt "$slot" ]; then
  run_case "two modules at once: $module ($module_name) in slot $slot, $other ($other_name) in slot $other_last" \
    "$slot" "$module" "$module_name" "$scenario" --also "$other_last" "$other" "$other_name"
fi
# The soft card (gsdc's README), with the GSDML's first module: found by
# its name of station, stopped by Ctrl-C and by SIGTERM.
read -r module slot last api data module_name <<<"${modules[0]}"
run_case "soft card: $module ($module_name), DCP Identify by name of station, SIGINT, SIGTERM" \
  "$slot" "$module" "$module_name" soft-card
# The negative cases, on the GSDML's last module with data (an empty
# module has no length to get wrong): the device departs from the layout,
# and the controller's Connect must fail with the status that says how.
read -r module slot last api data module_name <<<"$last_with_data"
run_case "negative: $module, the device presents another module ident" "$slot" "$module" "$module_name" - --mismatch module-ident
run_case "negative: $module, the device presents another input length" "$slot" "$module" "$module_name" - --mismatch input-length
for entry in "${modules[@]}"; do
  read -r module slot last api data module_name <<<"$entry"
  if [ "$api" -ne 0 ]; then
    run_case "negative: $module, the device's layout places it in API 0, the GSDML in API $api" "$slot" "$module" "$module_name" - --mismatch api
  fi
done
# Each device access point after the first, with the first module it
# offers: the device presents that DAP in slot 0 (its ident numbers and
# ports from the layout's daps), the controller connects with it. A DAP of
# an earlier one's ident number presents the same slot 0, and the device
# cannot tell them apart: the device presents the earlier one, and takes
# the module the controller's DAP offers.
for ((dap = 2; dap <= daps; dap++)); do
  list_modules "$dap"
  read -r module slot last api data module_name <<<"${modules[0]}"
  if [ "$presented_by" -eq "$dap" ]; then
    run_case "device access point $dap: $module ($module_name) in slot $slot" "$slot" "$module" "$module_name" - --dap "$dap"
  else
    run_case "device access point $dap, the device presenting $presented_by of its ident number: $module ($module_name) in slot $slot" \
      "$slot" "$module" "$module_name" - --dap "$presented_by" --controller-dap "$dap"
  fi
done

echo "PROFINET $name: $passed passed, $failed failed$([ "$unrun" -gt 0 ] && echo ", $unrun could not run")"
[ "$failed" -eq 0 ] || exit 1
[ "$unrun" -eq 0 ] || exit 2
exit 0
